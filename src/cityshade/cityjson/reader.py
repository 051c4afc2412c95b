"""CityJSON (1.0, 1.1, 2.0) and CityJSONSeq reader: file → :class:`~cityshade.citygml.reader.RawModel`.

The records are those of the CityGML reader, so :func:`~cityshade.geometry.scene.build_scene`
applies the same LoD choice, triangulation, repairs, skip counting, CRS handling, appearance and
time rules to both formats. What differs is only how the records are found:

- the vertex list is shared: it is parsed once (the existing Numba coordinate parser of
  :mod:`cityshade.citygml.geometry`, on the raw bytes of the ``vertices`` array that msgspec
  hands over undecoded), scaled and translated in float64, and the rings keep vertex indices
  (``RawModel.point_vertex``) instead of copies of the points;
- rings are closed here (the first index repeated), as GML rings are, so both formats reach
  the triangulator with the same rings and no "closed ring" repair is reported for CityJSON;
- LoDs are strings ("1.2", "2.2"): codes are LoD × 10 (``RawModel.lod_scale``) with the
  spelling of the file kept for the report;
- semantics, materials and textures are index arrays parallel to the boundaries; appearance
  records target synthetic polygon and ring keys (``"\\0p…"``, ``"\\0r…"``) that no file id
  can equal;
- GeometryInstances place a copy of the template's vertices (``M @ v`` + reference point);
- parents come from ``parents``; objects are ordered so that a parent precedes its children
  (the time rules clip a part to its whole in object order).

A CityJSON file is decoded whole (msgspec: measured faster and leaner than ``json``, see
``benchmarks/build_throughput.py --format cityjson``); a CityJSONSeq file line by line, so
memory is bounded by the largest feature plus the records.
"""
from __future__ import annotations

import os
import re
from array import array
from pathlib import Path
from typing import Any, Callable, Iterable

import msgspec
import numpy as np
from numba import njit

from cityshade.citygml import namespaces as ns
from cityshade.citygml.appearance import MaterialRecord, TextureRecord
from cityshade.citygml.geometry import parse_ring_texts
from cityshade.citygml.reader import RawModel
from cityshade.geo.temporal import GENERIC_PREFIX, TIME_ATTRIBUTES
from cityshade.errors import EmptyModelError, InputError, NotCityGMLError
from cityshade.runtime.interpret import InterpretBudget, twin_if

#: CityJSON versions read (a "1.1.3"-style patch suffix is accepted).
VERSIONS = ("1.0", "1.1", "2.0")

#: LoD codes are LoD × 10: "2.2" → 22, "2" → 20 (RawModel.lod_scale).
LOD_SCALE = 10

#: How far we look for the end of the first line when telling CityJSONSeq from CityJSON.
_SNIFF_BYTES = 1 << 16

#: Nesting of surfaces in the boundary array, by geometry type: 1 = list of surfaces,
#: 2 = list of shells (Solid), 3 = list of solids of shells.
_SURFACE_DEPTH = {"MultiSurface": 1, "CompositeSurface": 1, "Solid": 2, "MultiSolid": 3,
                  "CompositeSolid": 3}

#: Semantic surface types of CityJSON that CityGML spells differently.
_EXTRA_SEMANTICS = {"TransportationMarking": "marking", "TransportationHole": "closure"}

#: CityJSON object types whose CityGML name differs (for the default surface class only).
_TYPE_ALIASES = {"TransportSquare": "Square", "TunnelHollowSpace": "HollowSpace",
                 "BuildingStorey": "Storey"}

_BYTE_POSITION = re.compile(r"\(byte (\d+)\)")
_BOM = b"\xef\xbb\xbf"
_BRACKETS_TO_SPACES = bytes.maketrans(b"[]", b"  ")


class _Document(msgspec.Struct):
    """The members of a CityJSON document (or a CityJSONSeq header) that we read."""

    type: Any = None
    version: Any = None
    transform: Any = None
    metadata: Any = None
    # Each object is decoded on its own while it is read, so the Python objects of only one
    # object are alive at a time (a whole decode costs ~10 bytes of objects per file byte).
    CityObjects: dict[str, msgspec.Raw] | None = None
    # Left undecoded: parsed in one Numba pass instead of becoming millions of Python ints.
    vertices: msgspec.Raw = msgspec.Raw()
    appearance: Any = None
    geometry_templates: Any = msgspec.field(default=None, name="geometry-templates")


class _Feature(msgspec.Struct):
    """One CityJSONFeature line of a CityJSONSeq file."""

    type: Any = None
    id: Any = None
    CityObjects: Any = None
    vertices: msgspec.Raw = msgspec.Raw()
    appearance: Any = None


_DOCUMENT = msgspec.json.Decoder(_Document)
_FEATURE = msgspec.json.Decoder(_Feature)
_ANY = msgspec.json.Decoder()


# ---------------------------------------------------------------------------------------------
def detect_format(path: str | os.PathLike) -> str:
    """``"citygml"``, ``"cityjson"`` or ``"cityjsonseq"``, from the content (not the name).

    A document whose first character is ``{`` is JSON; it is a CityJSONSeq when its first line
    is a complete object (ends with ``}``) and another object follows on the next line. Files
    that cannot be opened, are empty or start with anything else go to the CityGML reader,
    which reports them (except ``.json``/``.jsonl`` names, whose JSON error is clearer).
    """
    path = Path(path)
    try:
        with path.open("rb") as fh:
            head = fh.read(_SNIFF_BYTES)
            _refuse_binary(head, path)
            start = len(head) - len(head.removeprefix(_BOM).lstrip(b" \t\r\n"))
            if start == len(head) or head[start:start + 1] != b"{":
                if head[start:start + 1] not in (b"<", b"") and path.suffix.lower() in (
                        ".json", ".jsonl", ".cityjson", ".cjseq"):
                    return "cityjson"
                return "citygml"
            # Find the end of the first line (a long header may exceed the first read).
            offset, newline = 0, head.find(b"\n")
            chunk = head
            while newline < 0 and len(chunk) == _SNIFF_BYTES:
                offset += len(chunk)
                chunk = fh.read(_SNIFF_BYTES)
                newline = chunk.find(b"\n")
            if newline < 0:
                return "cityjson"
            fh.seek(offset + newline)
            around = fh.read(_SNIFF_BYTES)
            fh.seek(max(0, offset + newline - 64))
            before = fh.read(min(64, offset + newline)).rstrip()
    except OSError:
        return "citygml"
    after = around.lstrip()
    if before.endswith(b"}") and after.startswith(b"{"):
        return "cityjsonseq"
    return "cityjson"


#: Signatures of archives a city model is often shipped in: what to say of them.
_ARCHIVES = {b"\x1f\x8b": "a gzip-compressed file: decompress it first",
             b"PK\x03\x04": "a ZIP archive: extract the model from it first"}


def _refuse_binary(head: bytes, path: Path) -> None:
    """A file that is not text (NUL bytes or many control characters in its first bytes, not
    UTF-16) is neither XML nor JSON: say so, rather than report the first parser's error."""
    for magic, what in _ARCHIVES.items():
        if head.startswith(magic):
            raise NotCityGMLError(f"not CityGML/XML or CityJSON: {what}", path=str(path))
    sample = head[:4096]
    if sample.startswith((b"\xff\xfe", b"\xfe\xff", b"<\x00", b"\x00<")):
        return  # UTF-16 text
    control = sum(sample.count(bytes([c])) for c in range(32) if c not in (9, 10, 12, 13))
    if sample and (b"\x00" in sample or control > len(sample) // 100):
        raise NotCityGMLError("not CityGML/XML or CityJSON: the file holds binary data, "
                              "not text", path=str(path))


def read_cityjson(path: str | os.PathLike, progress: Callable[[int, int], None] | None = None,
                  seq: bool | None = None, generic_attributes: Iterable[str] = ()) -> RawModel:
    """Read a CityJSON or CityJSONSeq file into flat records.

    Parameters
    ----------
    path : path-like
    progress : callable(bytes_read, bytes_total), optional
    seq : bool, optional
        True for CityJSONSeq, False for CityJSON; None detects it from the content.
    generic_attributes : iterable of str
        Further attribute names kept as time text (``--time-attribute``), stored under
        ``temporal.GENERIC_PREFIX + name`` as the CityGML reader stores generic attributes.

    Raises
    ------
    InputError, EmptyModelError
        Not JSON (with the line), not CityJSON, an unsupported version, vertex indices out of
        range, malformed boundary arrays, no city objects.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("no such file" if not path.exists() else "not a regular file",
                         path=str(path))
    if seq is None:
        seq = detect_format(path) == "cityjsonseq"
    total = path.stat().st_size
    if total == 0:
        raise InputError("the file is empty", path=str(path))
    model = RawModel(path=path, format="CityJSONSeq" if seq else "CityJSON",
                     lod_scale=LOD_SCALE)
    reader = _Reader(model, generic_attributes)
    if progress is not None:
        progress(0, total)
    if seq:
        reader.read_sequence(progress, total)
    else:
        reader.read_document()
    reader.finish()
    if not model.obj_ids:
        raise EmptyModelError("the CityJSON model contains no city objects", path=str(path))
    if progress is not None:
        progress(total, total)
    return model


# ---------------------------------------------------------------------------------------------
@njit(cache=True)
def _globalize_indices(flat, block_start, block_base, block_count):
    """Turn block-local vertex indices into global ones, in place; -1 or the first bad position.

    Block b owns ``flat[block_start[b]:block_start[b + 1]]`` (the last runs to the end); its
    indices must lie in ``[0, block_count[b])`` and get ``block_base[b]`` added.
    """
    n_blocks = block_start.shape[0]
    for b in range(n_blocks):
        end = block_start[b + 1] if b + 1 < n_blocks else flat.shape[0]
        base = block_base[b]
        count = block_count[b]
        for j in range(block_start[b], end):
            v = flat[j]
            if v < 0 or v >= count:
                return j
            flat[j] = v + base
    return -1


#: Vertex indices a process globalizes with the kernel's Python source while it is neither
#: compiled nor cached (:mod:`cityshade.runtime.interpret`): 0.23 µs an index interpreted
#: (10^6 indices: 0.23 CPU s) against 0.12 CPU s of compiling on first use (Dec 2026).
_INTERPRET = InterpretBudget(500_000, _globalize_indices)


class _Appearance:
    """The appearance section one geometry's indices refer to (a document's or a feature's)."""

    __slots__ = ("key", "materials", "textures", "uv")

    def __init__(self, key: int, section: Any):
        section = section if isinstance(section, dict) else {}
        self.key = key
        self.materials = section.get("materials") or []
        self.textures = section.get("textures") or []
        self.uv = section.get("vertices-texture") or []


def _sub(values: Any, i: int) -> Any:
    """``values[i]`` of a semantics/material/texture array, None where it has no entry."""
    if isinstance(values, list) and i < len(values):
        return values[i]
    return None


def _color(value: Any, default: tuple[float, float, float]) -> tuple[float, float, float]:
    if isinstance(value, list) and len(value) == 3 and all(
            isinstance(c, (int, float)) for c in value):
        return (float(value[0]), float(value[1]), float(value[2]))
    return default


def _number(value: Any, default: float) -> float:
    return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) \
        else default


def _time_text(value: Any) -> str | None:
    """An attribute value as the text the time rules parse (1904 and 1904.0 → "1904")."""
    if value is None or isinstance(value, (bool, list, dict)):
        return None
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


class _Reader:
    """Turns CityJSON documents and features into the records of a :class:`RawModel`."""

    def __init__(self, model: RawModel, generic_attributes: Iterable[str] = ()):
        self.m = model
        self.generic_attributes = tuple(generic_attributes)
        self.polys: list[tuple[int, int, int, int, int]] = []
        self.flat = array("q")  # block-local vertex index of every ring point
        self.ring_points = array("q")
        # Index blocks: (first position in flat, vertex base, vertex count, object).
        self.blocks: list[tuple[int, int, int, int]] = []
        self.vertex_blocks: list[np.ndarray] = []
        self.n_vertices = 0
        self.lod_cache: dict[Any, int] = {}
        self.obj_index: dict[str, int] = {}
        self.parent_ids: list[str | None] = []
        # Keyed by (appearance, theme, index) and by (theme, encoded definition).
        self.material_records: dict[tuple, MaterialRecord] = {}
        self.texture_records: dict[tuple, TextureRecord] = {}
        self.transform: tuple[np.ndarray, np.ndarray] | None = None
        self.templates: list = []
        self.template_vertices = np.empty((0, 3))
        self.block_vertices = np.empty((0, 3))  # real coordinates of the current block
        self.n_appearances = 0
        self.class_cache: dict[str, int] = {}

    # -- documents ------------------------------------------------------------------------
    def error(self, message: str, line: int | None = None, gml_id: str | None = None):
        return InputError(message, path=str(self.m.path), line=line, gml_id=gml_id)

    def decode(self, decoder, data: bytes, line: int | None):
        try:
            return decoder.decode(data)
        except msgspec.ValidationError as exc:
            detail = str(exc).replace("`", "").replace(" - at $", " at ")
            try:  # a syntax error later in the file is the better message
                _ANY.decode(data)
            except msgspec.DecodeError as syntax:
                self.syntax_error(syntax, data, line)
            raise self.error(f"not a CityJSON file: {detail}", line) from None
        except msgspec.DecodeError as exc:
            self.syntax_error(exc, data, line)

    def syntax_error(self, exc: Exception, data: bytes, line: int | None):
        """Raise the one-line message of a JSON syntax error, with its line."""
        text = str(exc)
        where = line
        match = _BYTE_POSITION.search(text)
        if match and line is None:
            where = data.count(b"\n", 0, int(match.group(1))) + 1
        detail = _BYTE_POSITION.sub("", text).strip().removeprefix("JSON is malformed: ")
        if "truncated" in detail:
            detail = "the file is truncated"
        raise self.error(f"malformed JSON: {detail}", where) from None

    def header(self, doc: _Document, line: int | None) -> None:
        """Check type and version, and take the transform, CRS and templates."""
        m = self.m
        if doc.type != "CityJSON":
            found = f"type {doc.type!r}" if doc.type is not None else "no \"type\" member"
            raise self.error(f"not a CityJSON file: {found}, not \"CityJSON\"", line)
        version = str(doc.version) if doc.version is not None else ""
        if not any(version == v or version.startswith(v + ".") for v in VERSIONS):
            raise self.error(f"CityJSON version {version or '(none)'} is not supported "
                             f"(cityshade reads {', '.join(VERSIONS)})", line)
        m.versions.add(version[:3])
        transform = doc.transform
        if transform is not None:
            try:
                scale = np.array(transform["scale"], np.float64)
                translate = np.array(transform["translate"], np.float64)
                if scale.shape != (3,) or translate.shape != (3,):
                    raise ValueError
            except (KeyError, TypeError, ValueError):
                raise self.error("the \"transform\" must have 3 scale and 3 translate "
                                 "values", line) from None
            self.transform = (scale, translate)
        metadata = doc.metadata if isinstance(doc.metadata, dict) else {}
        crs = metadata.get("referenceSystem")
        if crs is None and isinstance(metadata.get("crs"), dict):
            crs = metadata["crs"].get("epsg")  # CityJSON 0.x/1.0 drafts: {"epsg": 7415}
            crs = f"EPSG:{crs}" if crs is not None else None
        if isinstance(crs, str) and crs.strip():
            m.srs_names[crs.strip()] += 1
        templates = doc.geometry_templates
        if isinstance(templates, dict):
            self.templates = templates.get("templates") or []
            verts = templates.get("vertices-templates") or []
            try:
                tv = np.array(verts, np.float64).reshape(-1, 3)
            except (TypeError, ValueError):
                raise self.error("\"vertices-templates\" must be a list of [x, y, z]",
                                 line) from None
            self.template_vertices = tv
            if self.templates:
                self.m.counters["implicit_prototypes"] = len(self.templates)

    def vertices(self, raw: msgspec.Raw, line: int | None, what: str) -> np.ndarray:
        """The real (scaled, translated, float64) coordinates of a raw ``vertices`` array."""
        data = bytes(raw)
        if not data:
            return np.empty((0, 3))
        expected = data.count(b"[") - 1  # one bracket per vertex plus the list's own
        text = data.translate(_BRACKETS_TO_SPACES).decode("ascii", "replace")
        xyz, points, bad = parse_ring_texts([text], [3])
        if bad[0] or points[0] != max(expected, 0):
            raise self.error(f"the \"vertices\" of the {what} are not all [x, y, z] numbers",
                             line)
        if self.transform is not None:
            scale, translate = self.transform
            xyz *= scale
            xyz += translate
        return xyz

    def add_vertices(self, xyz: np.ndarray) -> int:
        base = self.n_vertices
        if len(xyz):
            self.vertex_blocks.append(xyz)
        self.n_vertices += len(xyz)
        return base

    def begin_block(self, base: int, count: int, obj: int) -> None:
        self.blocks.append((len(self.flat), base, count, obj))

    def read_document(self) -> None:
        path = self.m.path
        data = path.read_bytes().removeprefix(_BOM)
        # The raw members (vertices, objects) point into these bytes: the file stays in memory
        # while it is read, its Python objects one object at a time.
        doc = self.decode(_DOCUMENT, data, None)
        del data
        self.header(doc, None)
        xyz = self.vertices(doc.vertices, None, "file")
        doc.vertices = msgspec.Raw()
        self.block_vertices = xyz
        base = self.add_vertices(xyz)
        self.begin_block(base, len(xyz), -1)
        app = self.appearance(doc.appearance)
        objects = doc.CityObjects
        if not isinstance(objects, dict):
            raise self.error("not a CityJSON file: \"CityObjects\" is missing or not an object")
        self.objects(objects, app, 0)

    def read_sequence(self, progress, total: int) -> None:
        header_app = None
        have_header = False
        with self.m.path.open("rb") as fh:
            for lineno, line in enumerate(fh, 1):
                if not line.strip():
                    continue
                if not have_header:
                    doc = self.decode(_DOCUMENT, line.removeprefix(_BOM), lineno)
                    self.header(doc, lineno)
                    header_app = self.appearance(doc.appearance)
                    have_header = True
                    if doc.CityObjects:
                        xyz = self.vertices(doc.vertices, lineno, "header")
                        self.block_vertices = xyz
                        self.begin_block(self.add_vertices(xyz), len(xyz), -1)
                        self.objects(doc.CityObjects, header_app, lineno)
                    continue
                feature = self.decode(_FEATURE, line, lineno)
                if feature.type != "CityJSONFeature":
                    raise self.error(f"line {lineno} of the CityJSONSeq is not a "
                                     f"CityJSONFeature (type {feature.type!r})", lineno)
                if not isinstance(feature.CityObjects, dict):
                    raise self.error("the feature has no \"CityObjects\" object", lineno)
                xyz = self.vertices(feature.vertices, lineno, "feature")
                self.block_vertices = xyz
                self.begin_block(self.add_vertices(xyz), len(xyz), len(self.m.obj_ids))
                app = self.appearance(feature.appearance) if feature.appearance else header_app
                self.objects(feature.CityObjects, app, lineno)
                if progress is not None and lineno % 256 == 0:
                    progress(fh.tell(), total)
        if not have_header:
            raise self.error("the file is empty")

    def appearance(self, section: Any) -> _Appearance:
        self.n_appearances += 1
        return _Appearance(self.n_appearances, section)

    # -- objects ----------------------------------------------------------------------------
    def objects(self, objects: dict, app: _Appearance, line: int) -> None:
        m = self.m
        for oid, obj in objects.items():
            if obj.__class__ is msgspec.Raw:
                obj = _ANY.decode(obj)
            if not isinstance(obj, dict):
                raise self.error("a city object is not a JSON object", line or None, oid)
            index = len(m.obj_ids)
            if self.obj_index.setdefault(oid, index) != index:
                m.counters["duplicate_object_ids"] += 1
            obj_type = obj.get("type")
            obj_type = obj_type if isinstance(obj_type, str) else "CityObject"
            m.obj_ids.append(oid)
            m.obj_types.append(obj_type)
            m.obj_line.append(line)
            parents = obj.get("parents")
            parent = parents[0] if isinstance(parents, list) and parents else None
            self.parent_ids.append(parent if isinstance(parent, str) else None)
            attrs = obj.get("attributes")
            times: dict[str, str] = {}
            if isinstance(attrs, dict):
                for name in TIME_ATTRIBUTES:
                    if name in attrs:
                        text = _time_text(attrs[name])
                        if text is not None:
                            times[name] = text
                for name in self.generic_attributes:
                    text = _time_text(attrs.get(name))
                    if text is not None:
                        times[GENERIC_PREFIX + name] = text
                if obj_type in ns.VEGETATION_CODE_TYPES:
                    codes = {name: [str(v).strip() for v in (value if isinstance(value, list)
                                                            else [value])
                                    if isinstance(v, (str, int, float)) and str(v).strip()]
                             for name in ns.VEGETATION_CODE_NAMES
                             if (value := attrs.get(name)) is not None}
                    codes = {k: v for k, v in codes.items() if v}
                    if codes:
                        m.obj_codes[index] = codes
            m.obj_time.append(times)
            default_cls = ns.SURFACE_CODE[ns.OBJECT_DEFAULT_CLASS.get(
                _TYPE_ALIASES.get(obj_type, obj_type), "unclassified")]
            geometries = obj.get("geometry") or []
            if not isinstance(geometries, list):
                raise self.error("\"geometry\" is not a list", line or None, oid)
            for geom in geometries:
                try:
                    self.geometry(geom, index, default_cls, app)
                except (TypeError, ValueError, OverflowError, AttributeError, KeyError):
                    gtype = geom.get("type") if isinstance(geom, dict) else None
                    raise self.error(f"the boundaries of a {gtype or 'geometry'} are not "
                                     f"arrays of vertex indices as CityJSON defines them",
                                     line or None, oid) from None

    def lod_code(self, value: Any) -> int:
        """LoD × 10 of a ``lod`` member ("2.2", 2, "1"), -1 when absent or not a LoD."""
        if value is None:
            return -1
        cached = self.lod_cache.get(value)
        if cached is not None:
            return cached
        try:
            code = int(round(float(value) * LOD_SCALE))
        except (TypeError, ValueError):
            code = -1
        if not 0 <= code < 5 * LOD_SCALE:
            self.m.counters["unparseable_lods"] += 1
            code = -1
        else:
            label = value.strip() if isinstance(value, str) else f"{value:g}"
            self.m.lod_labels.setdefault(code, label)
        self.lod_cache[value] = code
        return code

    def surface_class(self, surface: Any, default_cls: int) -> int:
        kind = surface.get("type") if isinstance(surface, dict) else None
        if not isinstance(kind, str):
            return default_cls
        code = self.class_cache.get(kind)
        if code is None:
            name = ns.THEMATIC_SURFACES.get(kind) or _EXTRA_SEMANTICS.get(kind)
            code = ns.SURFACE_CODE[name] if name else -1
            self.class_cache[kind] = code
        return default_cls if code < 0 else code

    def geometry(self, g: dict, obj: int, default_cls: int, app: _Appearance,
                 template: bool = False) -> None:
        m = self.m
        gtype = g.get("type")
        if gtype == "GeometryInstance":
            if template:
                raise ValueError("a template cannot hold an instance")
            self.instance(g, obj, default_cls, app)
            return
        depth = _SURFACE_DEPTH.get(gtype)
        if depth is None:
            key = ("point_and_line_geometries_skipped" if gtype in ("MultiPoint",
                   "MultiLineString") else "unknown_geometry_types_skipped")
            m.counters[key] += 1
            return
        lod = self.lod_code(g.get("lod"))
        boundaries = g["boundaries"]
        semantics = g.get("semantics")
        sem_values = classes = None
        if isinstance(semantics, dict):
            sem_values = semantics.get("values")
            classes = [self.surface_class(s, default_cls)
                       for s in (semantics.get("surfaces") or [])]
        materials = [(theme, spec.get("values") if "values" in spec else spec.get("value"))
                     for theme, spec in self.themed(g, "material")]
        textures = [(theme, spec.get("values")) for theme, spec in self.themed(g, "texture")]
        if depth == 1:
            self.surfaces(boundaries, obj, default_cls, lod, sem_values, classes, materials,
                          textures, app)
            return
        solids = boundaries if depth == 3 else [boundaries]
        for si, solid in enumerate(solids):
            def pick(values):
                return _sub(values, si) if depth == 3 else values
            s_sem = pick(sem_values)
            s_mat = [(t, v if isinstance(v, int) else pick(v)) for t, v in materials]
            s_tex = [(t, pick(v)) for t, v in textures]
            for hi, shell in enumerate(solid):
                if hi > 0:
                    # An inner shell: a cavity, invisible from outside (as in CityGML).
                    m.counters["cavity_polygons"] += len(shell)
                    continue
                self.surfaces(shell, obj, default_cls, lod, _sub(s_sem, hi), classes,
                              [(t, v if isinstance(v, int) else _sub(v, hi)) for t, v in s_mat],
                              [(t, _sub(v, hi)) for t, v in s_tex], app)

    def themed(self, g: dict, member: str) -> list[tuple[str, dict]]:
        """(theme, mapping) pairs of a geometry's ``material`` or ``texture`` member; a member
        of another shape (pre-1.0 drafts wrote plain lists) is counted and ignored."""
        spec = g.get(member)
        if spec is None:
            return []
        if not isinstance(spec, dict):
            self.m.counters[f"malformed_{member}_members_ignored"] += 1
            return []
        return [(theme, value) for theme, value in spec.items() if isinstance(value, dict)]

    def surfaces(self, surfaces: list, obj: int, default_cls: int, lod: int, sem_values,
                 classes, materials, textures, app: _Appearance) -> None:
        """Record the polygons of one list of surfaces (each a list of rings)."""
        m = self.m
        polys, flat, ring_points = self.polys, self.flat, self.ring_points
        if not isinstance(surfaces, list):
            raise TypeError
        has_sem = isinstance(sem_values, list) and classes
        for s, surface in enumerate(surfaces):
            cls = default_cls
            if has_sem and s < len(sem_values):
                v = sem_values[s]
                if v.__class__ is int and 0 <= v < len(classes):
                    cls = classes[v]
            poly = len(polys)
            ring0 = len(ring_points)
            polys.append((obj, cls, lod, 0, ring0))
            if not surface:
                m.counters["polygons_without_exterior"] += 1
                ring_points.append(0)
            for ring in surface:
                n = len(ring)
                if n:
                    flat.extend(ring)
                    flat.append(ring[0])  # closed, as GML rings are
                    ring_points.append(n + 1)
                else:
                    ring_points.append(0)
            for theme, values in materials:
                index = values if values.__class__ is int else _sub(values, s)
                if index.__class__ is int:
                    self.material_target(app, theme, index, poly)
            for theme, values in textures:
                rings = _sub(values, s)
                if isinstance(rings, list):
                    self.texture_target(app, theme, rings, poly, ring0, surface)

    def poly_key(self, poly: int) -> str:
        key = f"\x00p{poly}"
        self.m.poly_by_id[key] = poly
        return key

    def material_target(self, app: _Appearance, theme: str, index: int, poly: int) -> None:
        # Records are shared by equal definitions (CityJSONSeq repeats them in every feature).
        key = (app.key, theme, index)
        rec = self.material_records.get(key)
        if rec is None:
            if not 0 <= index < len(app.materials) or not isinstance(app.materials[index], dict):
                self.m.counters["bad_material_references"] += 1
                return
            spec = app.materials[index]
            same = (theme, msgspec.json.encode(spec))
            rec = self.material_records.get(same)
            if rec is not None:
                self.material_records[key] = rec
                rec.targets.append(self.poly_key(poly))
                self.m.appearance.theme_targets[theme] += 1
                return
            rec = MaterialRecord(
                theme=theme, diffuse=_color(spec.get("diffuseColor"), (0.8, 0.8, 0.8)),
                ambient_intensity=_number(spec.get("ambientIntensity"), 0.2),
                specular=_color(spec.get("specularColor"), (1.0, 1.0, 1.0)),
                emissive=_color(spec.get("emissiveColor"), (0.0, 0.0, 0.0)),
                shininess=_number(spec.get("shininess"), 0.2),
                transparency=_number(spec.get("transparency"), 0.0))
            self.material_records[key] = self.material_records[same] = rec
            self.m.appearance.materials.append(rec)
        rec.targets.append(self.poly_key(poly))
        self.m.appearance.theme_targets[theme] += 1

    def texture_target(self, app: _Appearance, theme: str, rings: list, poly: int, ring0: int,
                       surface: list) -> None:
        m = self.m
        first = rings[0] if rings and isinstance(rings[0], list) and rings[0] else None
        index = first[0] if first else None
        if index.__class__ is not int:
            return  # [[null]]: this surface has no texture in the theme
        key = (app.key, theme, index)
        rec = self.texture_records.get(key)
        if rec is None:
            if not 0 <= index < len(app.textures) or not isinstance(app.textures[index], dict):
                m.counters["bad_texture_references"] += 1
                return
            spec = app.textures[index]
            same = (theme, msgspec.json.encode(spec))
            rec = self.texture_records.get(same)
        if rec is None:
            wrap = spec.get("wrapMode")
            border = spec.get("borderColor")
            rec = TextureRecord(theme=theme, kind="parameterized",
                                image_uri=str(spec.get("image") or ""),
                                wrap_mode=wrap if isinstance(wrap, str) else "none",
                                border_color=tuple(float(c) for c in border)
                                if isinstance(border, list) else ())
            self.texture_records[same] = rec
            m.appearance.textures.append(rec)
        self.texture_records[key] = rec
        uv = app.uv
        ring_uvs = []
        for r, (ring, entry) in enumerate(zip(surface, rings)):
            if isinstance(entry, list) and entry and entry[0] is None:
                continue  # [null]: this ring has no texture
            if not isinstance(entry, list) or len(entry) != len(ring) + 1 or not ring:
                m.counters["texture_coordinate_count_mismatch"] += 1
                continue
            try:
                pairs = [uv[i] for i in entry[1:]]
                pairs.append(pairs[0])
                text = " ".join(f"{float(p[0])!r} {float(p[1])!r}" for p in pairs)
            except (IndexError, TypeError, ValueError):
                m.counters["bad_texture_references"] += 1
                continue
            ring_key = f"\x00r{ring0 + r}"
            m.ring_by_id[ring_key] = ring0 + r
            ring_uvs.append((ring_key, text))
        rec.targets.append((self.poly_key(poly), ring_uvs, None))
        m.appearance.theme_targets[theme] += 1

    def instance(self, g: dict, obj: int, default_cls: int, app: _Appearance) -> None:
        """A GeometryInstance: the template's vertices, transformed and placed at the
        reference point, become a block of their own."""
        t = g["template"]
        if t.__class__ is not int or not 0 <= t < len(self.templates):
            raise ValueError("template index out of range")
        ref = g["boundaries"][0]
        if ref.__class__ is not int or not 0 <= ref < len(self.block_vertices):
            raise ValueError("reference point out of range")
        matrix = np.array(g.get("transformationMatrix") or np.eye(4).ravel(),
                          np.float64).reshape(4, 4)
        tv = self.template_vertices
        # Row-major 4 × 4 matrix on homogeneous template coordinates, then the reference point.
        h = tv @ matrix[:3, :3].T + matrix[:3, 3]
        w = tv @ matrix[3, :3] + matrix[3, 3]
        placed = h / w[:, None] + self.block_vertices[ref]
        resume = self.blocks[-1]
        self.begin_block(self.add_vertices(placed), len(placed), obj)
        self.m.counters["implicit_instances"] += 1
        self.geometry(self.templates[t], obj, default_cls, app, template=True)
        self.begin_block(resume[1], resume[2], resume[3])

    # -- the end ----------------------------------------------------------------------------
    def finish(self) -> None:
        m = self.m
        flat = np.frombuffer(self.flat, np.int64).copy() if len(self.flat) else \
            np.empty(0, np.int64)
        self.flat = array("q")
        if self.blocks:
            starts, bases, counts, owners = (np.array(c, np.int64) for c in zip(*self.blocks))
            bad = twin_if(_INTERPRET.take(flat.size), _globalize_indices)(flat, starts, bases,
                                                                          counts)
            if bad >= 0:
                b = int(np.searchsorted(starts, bad, side="right")) - 1
                # The object owning the failing position: ring → polygon → object.
                ring_end = np.cumsum(np.frombuffer(self.ring_points, np.int64))
                ring = int(np.searchsorted(ring_end, bad, side="right"))
                ring0 = np.fromiter((p[4] for p in self.polys), np.int64, len(self.polys))
                p = int(np.searchsorted(ring0, ring, side="right")) - 1
                gml_id = m.obj_ids[self.polys[p][0]] if 0 <= p < len(self.polys) else None
                raise self.error(f"vertex index {int(flat[bad])} is out of range (only "
                                 f"{int(counts[b])} vertices)", None, gml_id)
        m.point_vertex = flat
        m.ring_points = np.frombuffer(self.ring_points, np.int64).copy()
        m.ring_bad = np.zeros(len(m.ring_points), np.uint8)
        if len(self.vertex_blocks) == 1:
            m.xyz = self.vertex_blocks[0]
        elif self.vertex_blocks:
            m.xyz = np.concatenate(self.vertex_blocks)
        self.vertex_blocks = []
        polys = self.polys
        cols = (np.fromiter((p[k] for p in polys), np.int64, len(polys)) for k in range(5))
        m.poly_obj, m.poly_cls, m.poly_lod, m.poly_flip, m.poly_ring0 = cols
        m.poly_ids = [None] * len(polys)
        self.polys = []
        self.order_objects()

    def order_objects(self) -> None:
        """Resolve parents and put every parent before its children (depth first, input order)."""
        m = self.m
        n = len(m.obj_ids)
        parent = np.full(n, -1, np.int64)
        for i, pid in enumerate(self.parent_ids):
            if pid is None:
                continue
            p = self.obj_index.get(pid)
            if p is None:
                m.counters["unresolved_parents"] += 1
            elif p != i:
                parent[i] = p
        if (parent < np.arange(n)).all():
            m.obj_parent = parent.tolist()
            return
        children: list[list[int]] = [[] for _ in range(n)]
        for i in range(n):
            if parent[i] >= 0:
                children[parent[i]].append(i)
        order: list[int] = []
        seen = np.zeros(n, bool)

        def visit(root: int) -> None:
            stack = [root]
            while stack:
                i = stack.pop()
                if seen[i]:
                    continue
                seen[i] = True
                order.append(i)
                stack.extend(reversed(children[i]))

        for i in range(n):
            if parent[i] < 0:
                visit(i)
        for i in range(n):
            if not seen[i]:  # a cycle of parents: the first met becomes a root
                m.counters["parent_cycles_broken"] += 1
                parent[i] = -1
                visit(i)
        order_arr = np.array(order, np.int64)
        new_of_old = np.empty(n, np.int64)
        new_of_old[order_arr] = np.arange(n)
        m.obj_ids = [m.obj_ids[i] for i in order]
        m.obj_types = [m.obj_types[i] for i in order]
        m.obj_time = [m.obj_time[i] for i in order]
        m.obj_line = [m.obj_line[i] for i in order]
        old_parent = parent[order_arr]
        m.obj_parent = np.where(old_parent >= 0, new_of_old[np.maximum(old_parent, 0)],
                                -1).tolist()
        m.poly_obj = new_of_old[m.poly_obj]
