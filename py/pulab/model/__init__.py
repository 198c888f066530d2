"""Per-unit model: bases and per-unit values (:mod:`.bases`), PI and PLL gains in SI,
per unit and integers (:mod:`.gains`), datasheet values converted into SI motor fields
(:mod:`.datasheet`)."""
