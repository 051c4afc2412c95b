"""Place and time, shared by every stage: the CRS model (:mod:`.crs`), the city's dates
(:mod:`.temporal`) and the sun (:mod:`.sun`). Imports nothing of cityshade but errors."""
