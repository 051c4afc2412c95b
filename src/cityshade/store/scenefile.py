"""Scene ↔ ``.cityshade`` file: which arrays and tables are stored, and how they come back.

The generic container (atomic write, checksums, memory mapping) is :mod:`cityshade.store.cache`;
this module decides the content. Loaded arrays are read-only views into the memory map.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from cityshade import __version__
from cityshade.store.cache import FORMAT_VERSION, PackedStrings, open_cache, pack_strings, write_cache
from cityshade.geo.crs import CrsInfo, place_record, remember_place
from cityshade.errors import CacheError
from cityshade.geometry.scene import Scene

if TYPE_CHECKING:
    from cityshade.shadows import TechniqueSpec

_KDTREE_PREFIX = "kdtree/"
#: The vegetation's two kd-trees (docs/DESIGN.md §21) under ``vegetation/<part>/kdtree/``.
_VEGETATION_PREFIX = "vegetation/"


def save_scene(scene: Scene, path: str | os.PathLike, source: dict[str, Any],
               build_options: dict[str, Any],
               extra_arrays: dict[str, np.ndarray] | None = None, consume: bool = False,
               vegetation_trees: bool = True) -> int:
    """Write ``scene`` (and its kd-tree, when built) to ``path``; returns the file size.

    Parameters
    ----------
    source : dict
        ``path``, ``size``, ``sha256`` of the source GML (to detect a cache of another file).
    build_options : dict
        The options the scene was built with (stored for ``info`` and cache checks).
    extra_arrays : dict, optional
        Further arrays stored under their names (a tiled cache's global indices,
        :mod:`cityshade.store.tiled`); :func:`scene_from_cache` ignores them.
    consume : bool
        The scene is not used again (a build that returns the file's scene instead): its
        large arrays' memory goes back to the OS as they are written, and they then read as
        zeros (:func:`cityshade.store.cache.write_cache`).
    vegetation_trees : bool
        With the scene's kd-tree, also store the opaque triangles' and the crowns' kd-trees
        of a scene with vegetation (:func:`cityshade.geometry.vegetation.vegetation_kdtrees`),
        so no process that loads it builds them; a tile of a tiled cache has no use for them
        (its vegetation casts as opaque).
    """
    arrays: dict[str, np.ndarray] = {name: getattr(scene, name) for name in Scene.ARRAY_FIELDS}
    type_names = sorted(set(scene.obj_types))
    type_code = {t: i for i, t in enumerate(type_names)}
    arrays["obj_type"] = np.array([type_code[t] for t in scene.obj_types], np.uint16)
    arrays["obj_id_blob"], arrays["obj_id_offsets"] = pack_strings(scene.obj_ids)
    arrays["poly_id_blob"], arrays["poly_id_offsets"] = pack_strings(scene.poly_ids)
    kdtree_stats = None
    if scene.kdtree is not None:
        for name, value in scene.kdtree.to_arrays().items():
            arrays[_KDTREE_PREFIX + name] = value
        kdtree_stats = scene.kdtree.stats
    vegetation_stats = None
    if scene.kdtree is not None and vegetation_trees:
        from cityshade.geometry.vegetation import vegetation_kdtrees

        trees = vegetation_kdtrees(scene)
        if trees is not None:
            vegetation_stats = {}
            for part, tree in trees.items():
                for name, value in tree.to_arrays().items():
                    arrays[f"{_VEGETATION_PREFIX}{part}/{_KDTREE_PREFIX}{name}"] = value
                vegetation_stats[part] = tree.stats
    arrays.update(extra_arrays or {})
    header = {
        "kind": "cityshade-scene",
        "format_version": FORMAT_VERSION,
        "cityshade_version": __version__,
        "source": source,
        "build_options": build_options,
        "crs": scene.crs.to_json(),
        # Its origin's grid convergence and WGS 84 position: a command loading the scene turns
        # its sun without pyproj.
        "place": place_record(scene.crs, float(scene.origin_m[0]), float(scene.origin_m[1])),
        "object_types": type_names,
        "materials": scene.materials,
        "textures": scene.textures,
        "report": scene.report,
        "kdtree_stats": kdtree_stats,
        "vegetation_kdtree_stats": vegetation_stats,
    }
    return write_cache(path, header, arrays, consume=consume)


def load_scene(path: str | os.PathLike, verify: bool | str = "auto",
               with_kdtree: bool = True) -> Scene:
    """Load a scene file written by :func:`save_scene` (memory-mapped, read-only arrays).

    ``verify`` is :func:`cityshade.store.cache.open_cache`'s: by default the arrays' checksums are
    checked unless a verified stamp vouches for this very file; True checks them always.

    Raises
    ------
    CacheError
        Another format version, truncated, tampered, or not a scene file (subclasses say which).
    """
    return scene_from_cache(open_cache(path, verify=verify), with_kdtree)


def scene_from_cache(cache, with_kdtree: bool = True) -> Scene:
    """The scene of an opened cache file (:func:`cityshade.store.cache.open_cache`)."""
    header = cache.header
    if header.get("kind") != "cityshade-scene":
        raise CacheError("not a cityshade scene file; rebuild it with `cityshade build`",
                         path=str(cache.path))
    fields = {name: cache.array(name) for name in Scene.ARRAY_FIELDS}
    type_names = header["object_types"]
    obj_types = [type_names[int(c)] for c in cache.array("obj_type")]
    scene = Scene(
        crs=CrsInfo.from_json(header["crs"]),
        obj_ids=PackedStrings(cache.array("obj_id_blob"), cache.array("obj_id_offsets")),
        obj_types=obj_types,
        poly_ids=PackedStrings(cache.array("poly_id_blob"), cache.array("poly_id_offsets")),
        materials=header["materials"], textures=header["textures"], report=header["report"],
        **fields)
    if with_kdtree and header.get("kdtree_stats") is not None:
        from cityshade.accel import KdTree

        tree_arrays = {name[len(_KDTREE_PREFIX):]: cache.array(name)
                       for name in cache.names() if name.startswith(_KDTREE_PREFIX)}
        scene.kdtree = KdTree.from_arrays(tree_arrays, header["kdtree_stats"])
        # A file of an earlier build has none: they are built when first needed.
        stored = {}
        for part, stats in (header.get("vegetation_kdtree_stats") or {}).items():
            prefix = f"{_VEGETATION_PREFIX}{part}/{_KDTREE_PREFIX}"
            stored[part] = KdTree.from_arrays(
                {name[len(prefix):]: cache.array(name) for name in cache.names()
                 if name.startswith(prefix)}, stats)
        if stored:
            scene.__dict__["stored_vegetation_kdtrees"] = stored
    scene.header = header
    remember_place(scene.crs, header.get("place"))
    return scene


def release_scene_pages(scene) -> int:
    """:func:`cityshade.runtime.memory.release_pages` of a scene's arrays and its kd-tree's: the bytes of
    the memory-mapped cache this process stops holding (0 for a scene built in memory)."""
    from cityshade.runtime.memory import release_pages

    arrays = [getattr(scene, name, None) for name in Scene.ARRAY_FIELDS]
    trees = [getattr(scene, "kdtree", None),
             *(scene.__dict__.get("stored_vegetation_kdtrees") or {}).values()]
    for tree in trees:
        if tree is not None and hasattr(tree, "to_arrays"):
            arrays += list(tree.to_arrays().values())
    return release_pages(*arrays)


def read_header(path: str | os.PathLike) -> dict[str, Any]:
    """The JSON header of a scene file (no array is read or verified)."""
    return open_cache(Path(path), verify=False).header


def open_scene(path: str | os.PathLike):
    """A scene file (:func:`load_scene`) or a tiled cache folder (its index only:
    :func:`cityshade.store.tiled.open_tiled`; :meth:`~cityshade.store.tiled.TiledCache.view`
    gives the scene of the tiles a camera reaches)."""
    from cityshade.store.tiled import open_tiled

    return open_tiled(path) if Path(path).is_dir() else load_scene(path)


def scene_for_camera(scene, camera, technique: "str | TechniqueSpec | None" = None):
    """The scene a frame of ``camera`` draws: ``scene`` itself, or for a tiled cache the view
    of the tiles the camera's frustum reaches (all tiles for ``camera`` None, and for the
    techniques that are not :attr:`~cityshade.shadows.TechniqueSpec.tileable`, whose depth
    pass draws the casters from the scene: a caster outside the frustum still shades what is
    in it, and the light view is fitted to the whole city). ``technique``: a name or its
    :func:`~cityshade.shadows.describe`."""
    from cityshade.store.tiled import TiledCache

    if not isinstance(scene, TiledCache):
        return scene
    if technique is not None:
        from cityshade.shadows import describe

        if not describe(technique).tileable:
            return scene.view()
    return scene.view(None if camera is None else scene.tiles_in_view(camera))


def whole_scene(path: str | os.PathLike):
    """A scene file (:func:`load_scene`), or a tiled cache folder as the view of all its tiles
    (the one-cache scene array for array; shadow rays through the tiles' own trees)."""
    from cityshade.store.tiled import open_tiled

    return open_tiled(path).view() if Path(path).is_dir() else load_scene(path)
