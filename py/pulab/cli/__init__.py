"""The command line's subcommands beyond ``report``: the families (:mod:`.family`:
``sweep``, ``batch``) and the C tracer (:mod:`.trace`: ``trace``).  The parser and
``main`` are :mod:`pulab.__main__`."""
