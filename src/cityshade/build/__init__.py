"""``cityshade build``: CityGML/CityJSON file → triangulated scene (+ kd-tree) → ``.cityshade`` file."""
from __future__ import annotations

import hashlib
import os
import threading
import time
from dataclasses import asdict
from pathlib import Path
from typing import Callable, Iterable

from cityshade.store.cache import PackedStrings, pack_strings
from cityshade.config import Settings
from cityshade.errors import ContractError
from cityshade.runtime.memory import release_freed_memory
from cityshade.geometry.scene import Scene

#: Read size when hashing the source file (large reads keep hashing near disk speed).
_HASH_CHUNK = 8 << 20


def file_sha256(path: str | os.PathLike, stop: threading.Event | None = None) -> str:
    """SHA-256 of a file (hex); with ``stop``, gives up (returns "") once it is set."""
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        while chunk := fh.read(_HASH_CHUNK):
            if stop is not None and stop.is_set():
                return ""
            digest.update(chunk)
    return digest.hexdigest()


class _SourceRecord:
    """:func:`_source_record` of a file, computed in a thread while the build goes on, from
    :meth:`start` on: the build starts it once the file is read, since a large file's read
    keeps both cores busy (two processes, :mod:`cityshade.citygml.split`) and scene assembly
    leaves one mostly free; hashing (2.3 s for the 1.74 GB GML of the 10M city) and reading
    the file release the GIL. :meth:`result` waits for it (and re-raises its error);
    :meth:`cancel` stops it between chunks (a build that failed or was interrupted)."""

    def __init__(self, path: Path):
        self._path = path
        self._stop = threading.Event()
        self._out: dict | BaseException | None = None
        self._thread = threading.Thread(target=self._run, name="cityshade-source-hash",
                                        daemon=True)

    def start(self) -> None:
        if self._thread.ident is None:
            self._thread.start()

    def _run(self) -> None:
        try:
            self._out = _source_record(self._path, self._stop)
        except BaseException as exc:  # handed to result()
            self._out = exc

    def result(self) -> dict:
        self.start()
        self._thread.join()
        if isinstance(self._out, BaseException):
            raise self._out
        return self._out

    def cancel(self) -> None:
        self._stop.set()
        if self._thread.ident is not None:
            self._thread.join()


def default_output(source: str | os.PathLike) -> Path:
    """``city.gml`` → ``city.cityshade`` next to it."""
    return Path(source).with_suffix(".cityshade")


def read_model(source: str | os.PathLike, progress: Callable[[int, int], None] | None = None,
               generic_attributes: Iterable[str] = ()):
    """Read a CityGML, CityJSON or CityJSONSeq file (told apart by its content) into a
    :class:`~cityshade.citygml.reader.RawModel`; ``generic_attributes`` are the attribute
    names ``--time-attribute`` asks for."""
    from cityshade.cityjson.reader import detect_format

    kind = detect_format(source)
    if kind == "citygml":
        from cityshade.citygml.reader import read_citygml

        return read_citygml(source, progress=progress, generic_attributes=generic_attributes)
    from cityshade.cityjson.reader import read_cityjson

    return read_cityjson(source, progress=progress, seq=kind == "cityjsonseq",
                         generic_attributes=generic_attributes)


def build_scene_from_file(source: str | os.PathLike, settings: Settings | None = None,
                          progress: Callable[[str, int, int], None] | None = None,
                          tree: bool = True, pack_ids: bool = False,
                          after_read: Callable[[], None] | None = None,
                          extend: Callable[[Scene], Scene] | None = None) -> Scene:
    """Read, triangulate and (when the scene needs one) build the kd-tree of a city model file
    (CityGML, CityJSON or CityJSONSeq).

    Parameters
    ----------
    pack_ids : bool
        Give the scene its polygon and object ids packed
        (:class:`~cityshade.store.cache.PackedStrings`, as a loaded scene has them) for a build that
        only writes them: less memory from the kd-tree on, but each id is decoded when read.
    after_read : callable, optional
        Called once the file is read, before the scene is assembled.
    extend : callable(Scene) -> Scene, optional
        Adds objects to the triangulated scene before its kd-tree (``build --trees``:
        :func:`cityshade.meshes.trees.add_trees`).
    progress : callable(stage, done, total), optional
        Called while reading (bytes) and at the start of later stages.
    """
    from cityshade.geometry.scene import build_scene

    settings = settings or Settings()
    timings: dict[str, float] = {}
    t0 = time.perf_counter()
    read_progress = (lambda done, total: progress("read", done, total)) if progress else None
    generic = ()
    if settings.build.time_attribute:
        from cityshade.geo.temporal import parse_time_attribute

        generic = [n for n in parse_time_attribute(settings.build.time_attribute) if n]
    raw = read_model(source, progress=read_progress, generic_attributes=generic)
    release_freed_memory()  # the parser's freed elements, before the scene's arrays
    timings["read_s"] = time.perf_counter() - t0
    if after_read is not None:
        after_read()
    if progress:
        progress("triangulate", 0, 1)
    t1 = time.perf_counter()
    scene = build_scene(raw, settings.build, consume_raw=True)
    if extend is not None:
        scene = extend(scene)
    # The polygon ids as one blob, as a loaded scene has them: with the read model's strings
    # gone, their heap is empty and handed back (millions of small strings would otherwise
    # pin the read's freed dicts and lists through the kd-tree and the write).
    if pack_ids:
        scene.poly_ids = PackedStrings(*pack_strings(scene.poly_ids))
        # The object ids too: made one per building all through the read, a few of them in
        # each of the allocator's arenas keep every arena of the read's freed records alive
        # (10M city: 659 arenas, 690 MB resident through the kd-tree; packed: 297).
        scene.obj_ids = PackedStrings(*pack_strings(scene.obj_ids))
    del raw
    release_freed_memory()
    timings["triangulate_s"] = time.perf_counter() - t1
    if tree:  # a tiled cache builds one tree per tile instead
        scene.kdtree = build_tree(scene, settings, progress, timings)
    scene.report["timings"] = {k: round(v, 4) for k, v in timings.items()}
    return scene


#: File name endings a folder given to ``build`` is searched for (CityGML, CityJSON, CityJSONSeq).
MODEL_SUFFIXES = (".gml", ".xml", ".citygml", ".json", ".jsonl", ".city.json", ".city.jsonl")


def expand_sources(sources: Iterable[str | os.PathLike]) -> list[Path]:
    """The model files a build reads: files as given, folders by their model files (sorted by
    name), each file once, in the order given.

    Raises
    ------
    InputError
        A path that does not exist, or a folder without model files.
    """
    from cityshade.errors import InputError

    out: list[Path] = []
    seen: set[Path] = set()
    for source in sources:
        path = Path(source)
        if path.is_dir():
            found = sorted(p for p in path.iterdir() if p.is_file()
                           and p.name.lower().endswith(MODEL_SUFFIXES))
            if not found:
                raise InputError(f"the folder holds no model file (*{', *'.join(MODEL_SUFFIXES)})",
                                 path=str(path))
        elif path.is_file():
            found = [path]
        else:
            raise InputError("no such file", path=str(path))
        for p in found:
            key = p.resolve()
            if key not in seen:
                seen.add(key)
                out.append(p)
    return out


def build_scene_from_files(sources: list[Path], settings: Settings | None = None,
                           progress: Callable[[str, int, int], None] | None = None,
                           tree: bool = True,
                           extend: Callable[[Scene], Scene] | None = None) -> Scene:
    """One scene from several city model files (tiles): one origin and CRS, the objects of
    every file, an object whose gml:id an earlier file had kept once (counted in
    ``report["tiles"]``). Files are read one at a time, so memory holds one file's read model
    plus the scene gathered so far.

    With ``settings.build.crs`` every file is projected to that CRS (a file without a known
    CRS is taken to be in it); without it all files must resolve to one CRS.

    Parameters
    ----------
    progress : callable(stage, done, total), optional
        ``("file NAME i/n", bytes read, bytes of the file)`` while reading, then the later
        stages as :func:`build_scene_from_file`.

    Raises
    ------
    CRSError
        Files in different CRSs without ``--crs``, or a ``--crs`` that is not projected.
    """
    from cityshade.build.merge import SceneMerger

    merger, timings = read_files(sources, settings or Settings(), progress, SceneMerger)
    if progress:
        progress("merge", 0, 1)
    t = time.perf_counter()
    scene = merger.finish()
    if extend is not None:  # as build_scene_from_file's
        scene = extend(scene)
    release_freed_memory()
    timings["merge_s"] = time.perf_counter() - t
    if tree:
        scene.kdtree = build_tree(scene, settings or Settings(), progress, timings)
    scene.report["timings"] = {k: round(v, 4) for k, v in timings.items()}
    return scene


def read_files(sources: list[Path], settings: Settings, progress, make_merger):
    """Read the files one at a time, each assembled in float64 model coordinates and handed to
    ``make_merger(crs_given=...)``'s merger (:class:`~cityshade.build.merge.SceneMerger`
    or a subclass), then dropped; returns the merger and the read/triangulate timings.

    Raises
    ------
    CRSError, UsageError
        As :func:`build_scene_from_files`.
    """
    import dataclasses

    from cityshade.geo.crs import parse_srs_name
    from cityshade.errors import UsageError
    from cityshade.geometry.scene import build_scene

    target = None
    if settings.build.crs is not None:
        target = parse_srs_name(settings.build.crs)
        if target.is_geographic or target.local:
            raise UsageError(f"--crs {settings.build.crs}: with several files --crs names the "
                             f"projected CRS to build in ({target.name} is not one)")
    build_settings = dataclasses.replace(settings.build, crs=None)
    generic = ()
    if settings.build.time_attribute:
        from cityshade.geo.temporal import parse_time_attribute

        generic = [n for n in parse_time_attribute(settings.build.time_attribute) if n]
    timings = {"read_s": 0.0, "triangulate_s": 0.0}
    merger = make_merger(crs_given=target is not None)
    for i, source in enumerate(sources):
        stage = f"file {source.name} {i + 1}/{len(sources)}"
        read_progress = (lambda done, total, stage=stage: progress(stage, done, total)
                         ) if progress else None
        t0 = time.perf_counter()
        raw = read_model(source, progress=read_progress, generic_attributes=generic)
        t1 = time.perf_counter()
        part = build_scene(raw, build_settings, target_crs=target, render_space=False,
                           consume_raw=True)
        del raw
        merger.add(part, source)
        del part
        release_freed_memory()
        timings["read_s"] += t1 - t0
        timings["triangulate_s"] += time.perf_counter() - t1
    return merger, timings


def build_tree(scene: Scene, settings: Settings, progress, timings: dict):
    """The scene's kd-tree with the build settings (progress and stage timings filled)."""
    from cityshade.accel.kdtree_build import build_kdtree

    if progress:
        progress("kdtree", 0, 1)
    t = time.perf_counter()
    tree = build_kdtree(scene.vertices, scene.triangles, scene.tri_t_begin_days,
                        scene.tri_t_end_days, scene.tri_material, settings.kdtree)
    timings["kdtree_s"] = time.perf_counter() - t
    return tree


def _source_record(path: Path, stop: threading.Event | None = None) -> dict:
    stat = path.stat()
    return {"path": str(path.resolve()), "size": stat.st_size, "mtime": stat.st_mtime,
            "sha256": file_sha256(path, stop)}


def build_file(source: str | os.PathLike | list, output: str | os.PathLike | None = None,
               settings: Settings | None = None,
               progress: Callable[[str, int, int], None] | None = None,
               tile_m: float | None = None,
               extend: Callable[[Scene], Scene] | None = None) -> tuple[Path, Scene, int]:
    """Build the ``.cityshade`` file of a CityGML/CityJSON file, or of several files and
    folders (a list: :func:`build_scene_from_files`); returns (output path, scene, bytes),
    the scene that of the written file (memory-mapped, as :func:`~cityshade.store.scenefile.load_scene`
    gives it: the built one's memory went into the file's pages).
    With ``tile_m`` the output is a tiled cache folder (:mod:`cityshade.store.tiled`): tiles of
    ``tile_m`` × ``tile_m`` CRS metres, each with its own kd-tree (the scene has none; for
    several files the city is never assembled and a :class:`~cityshade.build.tiled.TiledBuild`
    summary stands for the scene). ``extend`` adds objects before the kd-tree (as
    :func:`build_scene_from_file`'s; not with ``tile_m``)."""
    from cityshade.store.scenefile import load_scene, save_scene
    from cityshade.build.tiled import save_tiled

    def save(scene, output, source_info, options):
        """Write the scene; returns (the scene of the file, bytes). A one-file cache is written
        consuming the built scene (its memory becomes the file's pages) and loaded back,
        unchecked: its checksums were just computed from the arrays written, and a check
        would read the whole file into this process (the next load checks it if its stamp
        is not trusted yet)."""
        if tile_m is None:
            size = save_scene(scene, output, source_info, options, consume=True)
            return load_scene(output, verify=False), size
        return scene, save_tiled(scene, output, tile_m, settings, source_info, options, progress)

    settings = settings or Settings()
    if extend is not None and tile_m is not None:
        from cityshade.errors import UsageError

        raise UsageError("--trees cannot go with --tile-m (a tiled cache): build the trees "
                         "into one file")
    if isinstance(source, (list, tuple)):
        sources = expand_sources(source)
        if len(sources) == 1 and not Path(source[0]).is_dir():
            source = sources[0]
    else:
        sources = None
    if sources is not None and not isinstance(source, Path):
        if output is None:
            raise ContractError("several input files need an output path")
        output = Path(output)
        files = [_source_record(p) for p in sources]
        combined = hashlib.sha256("".join(f["sha256"] for f in files).encode()).hexdigest()
        source_info = {"path": files[0]["path"] if len(files) == 1 else
                       f"{len(files)} files in {os.path.commonpath([f['path'] for f in files])}",
                       "size": sum(f["size"] for f in files),
                       "mtime": max(f["mtime"] for f in files), "sha256": combined,
                       "files": files}
        if tile_m is not None:  # file by file into tile spills: memory of one file + one tile
            from cityshade.build.tiled import build_tiled_from_files

            summary, size = build_tiled_from_files(sources, output, tile_m, settings,
                                                   source_info, asdict(settings.build), progress)
            return output, summary, size
        scene = build_scene_from_files(sources, settings, progress, extend=extend)
        if progress:
            progress("write", 0, 1)
        scene, size = save(scene, output, source_info, asdict(settings.build))
        return output, scene, size
    source = Path(source)
    output = Path(output) if output is not None else default_output(source)
    record = _SourceRecord(source)
    try:
        scene = build_scene_from_file(source, settings, progress, tree=tile_m is None,
                                      pack_ids=tile_m is None, after_read=record.start,
                                      extend=extend)
        source_info = record.result()
    finally:
        record.cancel()
    if progress:
        progress("write", 0, 1)
    options = asdict(settings.build)
    scene, size = save(scene, output, source_info, options)
    return output, scene, size


def load_or_build_scene(path, settings=None):
    """A scene with its kd-tree: a ``.cityshade`` file is loaded, a tiled cache gives the view
    of all its tiles, a city model (CityGML, CityJSON: anything else) is built in memory
    (nothing written)."""
    from cityshade.store.cache import is_cache_file
    from cityshade.store.scenefile import whole_scene

    path = Path(path)
    if is_cache_file(path) or path.is_dir() or not path.exists():
        return whole_scene(path)
    return build_scene_from_file(path, settings)
