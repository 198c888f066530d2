"""Input: what a request may contain and how it is read — JSON text with size and nesting
limits (:mod:`.jsontext`), numbers typed as text (:mod:`.textnum`), the report input's
defaults and checks (:mod:`.inputs`), the one error bad input raises (:mod:`.errors`) and
its texts (:mod:`.messages`)."""
