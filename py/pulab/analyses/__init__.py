"""Analyses of one input or a family of inputs: loop margins and responses (:mod:`.loop`),
time-domain simulation (:mod:`.sim`), the graded design review (:mod:`.review`), sweeps
and their firmware-integer states (:mod:`.sweep`, :mod:`.integers`), CSV batches
(:mod:`.batch`), and the slicing that lets a long computation yield (:mod:`.slices`).
The report's optional sections are listed once, in the order they run (:mod:`.registry`)."""
