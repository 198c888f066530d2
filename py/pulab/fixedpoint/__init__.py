"""Fixed-point core: Q formats (:mod:`.qformat`) and C integer arithmetic as the C2000
compiler performs it (:mod:`.cint`).  Imports nothing else of pulab."""
