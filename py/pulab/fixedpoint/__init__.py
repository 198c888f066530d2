"""Fixed-point core: Q formats (:mod:`.qformat`), C integer arithmetic as the C2000
compiler performs it (:mod:`.cint`), the same over intervals (:mod:`.interval`) and the box
search every proof runs (:mod:`.boxsearch`).  Imports nothing else of pulab."""
