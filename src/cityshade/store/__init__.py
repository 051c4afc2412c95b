"""The scene store: the versioned, memory-mapped file format (:mod:`.cache`), opening a scene
file (:mod:`.scenefile`) and the tiled cache's read side (:mod:`.tiled`)."""
