"""One frame: the camera pass once and the shadow pass per sun (:mod:`.pipeline`), what a frame
did (:mod:`.diagnostics`), ground plane, shading and textures, and ``render`` with its outputs."""
