"""Triangle meshes in and out, through trimesh (docs/DESIGN.md §20).

- :mod:`cityshade.meshes.scene`: objects made of triangle meshes → a :class:`Scene` (surfaces,
  classes, times), and the ground under a point of a scene (terrain, else the ground plane);
- :mod:`cityshade.meshes.trees`: a tree register (GeoJSON or CSV) → crown-and-trunk trees,
  vegetation objects added to a build (``build --trees``);
- :mod:`cityshade.meshes.proposal`: a proposal's mesh file (OBJ, glTF/GLB, PLY, STL) placed in
  the model (``compare --with``);
- :mod:`cityshade.meshes.export`: a scene coloured by a per-surface result as binary glTF and
  PLY (``cityshade export``).

trimesh is imported inside the functions that need it.
"""
