"""raster stage of cityshade: cameras, the culled tile-parallel rasterizer and the G-buffer.

* :mod:`cityshade.raster.camera` — perspective, overview, preset and georeferenced map cameras;
* :mod:`cityshade.raster.rasterize` — :func:`~cityshade.raster.rasterize.rasterize`, the Numba
  triangle rasterizer (tiles over the cores, top-left fill rule, exact perspective-correct
  barycentrics, near-plane clipping);
* :mod:`cityshade.raster.culling` — front-to-back kd-tree walk with time filtering, frustum
  culling and software occlusion queries against a hierarchical max-depth buffer;
* :mod:`cityshade.raster.gbuffer` — :class:`GBuffer`, :func:`resolve` and the ray-cast twin.

Submodules are imported on use (the package import stays free of numba).
"""
