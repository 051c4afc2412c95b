"""Streaming CityGML reader (lxml ``iterparse``): file → :class:`RawModel`.

Memory is bounded by the largest city object, never by the file: the parser stops at the end of
every top-level member (``cityObjectMember``, ``featureMember``, ``appearanceMember``), the walker
turns the member into flat records, and the member is cleared. Geometry is kept as ring texts
that are parsed in large batches by a Numba kernel (:mod:`cityshade.citygml.geometry`).

What the walker records
-----------------------
- objects: gml:id, type (local name), parent object, raw time attributes, source line;
- polygons: owning object, surface class, LoD (-1 when no LoD is known), orientation flip
  (``OrientableSurface orientation="-"``), gml:id, first ring;
- rings: coordinate text, dimension, gml:id (for texture coordinates);
- references: every ``xlink:href`` where geometry may stand, with the context it stands in, so
  that forward references anywhere in the file resolve after the last member;
- aggregates: gml:ids of geometry aggregates and thematic surfaces → the polygons and
  references inside them (appearance targets and xlinks may point at them);
- openings: gml:ids of Window/Door elements and their polygons;
- appearances (see :mod:`cityshade.citygml.appearance`), srsName counts, counters.

Safety: no DTD is loaded, no entity is resolved, nothing is fetched from a network; a document
that declares entities is refused before parsing (entity-expansion bombs never start).
"""
from __future__ import annotations

import functools
import os
import re
from collections import Counter
from dataclasses import dataclass, field
from itertools import chain
from pathlib import Path
from typing import Callable, Iterable

import numpy as np

from cityshade.citygml import namespaces as ns
from cityshade.citygml.appearance import AppearanceCollector
from cityshade.citygml.geometry import RingParser
from cityshade.citygml.implicit import ImplicitRecords, parse_numbers, place_instances, point_text
from cityshade.citygml.namespaces import XLINK_HREF
from cityshade.errors import EmptyModelError, InputError, NotCityGMLError, XMLSyntaxError

#: Batch size (characters of coordinate text) handed to the Numba parser at once: large enough
#: to amortise the call, small enough (≈16 MB of text) to bound memory on 200 MB files.
_PARSE_BATCH_CHARS = 16_000_000

#: How far into a file we look for a DOCTYPE with entity declarations (the prolog).
_PROLOG_BYTES = 65536

_LOD_PROPERTY = re.compile(r"^lod([0-4])[A-Z]")
#: Surface classes of openings, whose elements' gml:ids are kept (per-opening results).
_OPENING_CODES = frozenset((ns.SURFACE_CODE["window"], ns.SURFACE_CODE["door"]))

# Walker element kinds (cached per tag string).
K_SKIP, K_DESCEND, K_OBJECT, K_THEMATIC, K_LOD, K_POLYGON, K_AGG, K_ORIENTABLE, K_APPEARANCE, \
    K_GML_BOUNDED, K_IMPLICIT, K_CAVITY = range(12)


@dataclass
class RawModel:
    """Everything read from one CityGML file, before LoD selection and triangulation."""

    path: Path
    versions: set[str] = field(default_factory=set)
    #: Input format: "CityGML", or "CityJSON"/"CityJSONSeq" (:mod:`cityshade.cityjson`).
    format: str = "CityGML"
    #: LoD codes in poly_lod/ref_lod are LoD × lod_scale (CityJSON: 10, so "2.2" is 22), and
    #: lod_labels spells a code as the file did where it is not simply the number.
    lod_scale: int = 1
    lod_labels: dict[int, str] = field(default_factory=dict)
    root_namespace: str = ""
    # Objects.
    obj_ids: list[str | None] = field(default_factory=list)
    obj_types: list[str] = field(default_factory=list)
    obj_parent: list[int] = field(default_factory=list)
    obj_time: list[dict[str, str]] = field(default_factory=list)
    obj_line: list[int] = field(default_factory=list)
    #: Per vegetation object (index) its ``class``/``function``/``usage``/``species`` values
    #: as the file spells them (``ns.VEGETATION_CODE_NAMES``; function and usage may repeat).
    obj_codes: dict[int, dict[str, list[str]]] = field(default_factory=dict)
    # Polygons (one entry per polygon element); int64 arrays once reading is finished.
    poly_obj: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    poly_cls: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    poly_lod: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    poly_flip: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    poly_ring0: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    poly_ids: list[str | None] = field(default_factory=list)
    poly_by_id: dict[str, int] = field(default_factory=dict)
    # Rings: parsed coordinates, per-ring point counts and bad flags.
    ring_by_id: dict[str, int] = field(default_factory=dict)
    xyz: np.ndarray = field(default_factory=lambda: np.empty((0, 3)))
    ring_points: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    ring_bad: np.ndarray = field(default_factory=lambda: np.empty(0, np.uint8))
    #: None: ring points are the rows of xyz in order. Else (CityJSON, whose vertex list is
    #: shared) the row of xyz of every ring point, so no point is copied per ring.
    point_vertex: np.ndarray | None = None
    # References (xlink:href in a geometry context); int64 arrays once reading is finished.
    ref_obj: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    ref_cls: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    ref_lod: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    ref_flip: np.ndarray = field(default_factory=lambda: np.empty(0, np.int64))
    ref_target: list[str] = field(default_factory=list)
    # Aggregates: id → (first polygon, end polygon, first ref, end ref).
    aggregates: dict[str, tuple[int, int, int, int]] = field(default_factory=dict)
    # Openings (Window/Door, 3.0 WindowSurface/DoorSurface): (gml:id, first polygon, end polygon).
    openings: list[tuple[str, int, int]] = field(default_factory=list)
    appearance: AppearanceCollector = field(default_factory=AppearanceCollector)
    srs_names: Counter = field(default_factory=Counter)
    counters: Counter = field(default_factory=Counter)
    warnings: list[str] = field(default_factory=list)
    #: Tags of Application Domain Extension elements met (each skipped with its subtree);
    #: ``counters["ade_elements_skipped"]`` counts them.
    ade_tags: set[str] = field(default_factory=set)
    #: ImplicitGeometry prototypes and instances while reading; placed (as ordinary polygons)
    #: and set to None when the whole file is read (:mod:`cityshade.citygml.implicit`).
    implicit: ImplicitRecords | None = None

    @property
    def n_polygons(self) -> int:
        return len(self.poly_ids)


def _split_tag(tag: str) -> tuple[str, str]:
    if tag[0] == "{":
        end = tag.index("}")
        return tag[1:end], tag[end + 1:]
    return "", tag


def _href_target(href: str) -> str:
    """The gml:id an ``xlink:href`` points at (``#id`` → ``id``; other forms kept whole)."""
    return href[1:] if href.startswith("#") else href


def _prescan(path: Path) -> None:
    """Refuse documents that declare entities or an external DTD, before lxml sees them."""
    with path.open("rb") as fh:
        head = fh.read(_PROLOG_BYTES)
    if not head.strip():
        raise InputError("the file is empty", path=str(path))
    doctype = head.find(b"<!DOCTYPE")
    if doctype >= 0:
        prolog = head[doctype:]
        if b"<!ENTITY" in prolog:
            line = head[:doctype].count(b"\n") + 1
            raise XMLSyntaxError("the document declares XML entities, which cityshade refuses "
                                 "to expand (entity-expansion attacks); remove the DOCTYPE",
                                 path=str(path), line=line)
        if b"SYSTEM" in prolog.split(b">", 1)[0] or b"PUBLIC" in prolog.split(b">", 1)[0]:
            line = head[:doctype].count(b"\n") + 1
            raise XMLSyntaxError("the document refers to an external DTD, which cityshade "
                                 "never loads; remove the DOCTYPE", path=str(path), line=line)


class _Walker:
    """Turns one top-level member subtree into records of a :class:`RawModel`."""

    #: Generic attribute names to keep (read_citygml's ``generic_attributes``).
    generic_attributes: frozenset = frozenset()
    #: Whether lxml's line numbers past 65535 need correcting (:func:`_lines_skewed`).
    lines_skewed: bool = False

    def __init__(self, model: RawModel):
        self.m = model
        self.kinds: dict[str, tuple[int, object]] = {}
        self.texts: list[str] = []
        self.dims: list[int] = []
        self.text_chars = 0
        # Batches flushed parse on a second thread while the read goes on.
        self.parser = RingParser()
        self.gml_ns = ns.GML_NAMESPACES[0]
        self.gml_id = ns.GML_ID_ATTRS[0]
        self.other_gml_id: str | None = ns.GML_ID_ATTRS[1]
        self.rings_flushed = 0
        # Records as tuples, one append each; turned into arrays by finish().
        self.polys: list[tuple[int, int, int, int, int]] = []
        self.refs: list[tuple[int, int, int, int]] = []
        gml_tags = [("{%s}" % g) for g in ns.GML_NAMESPACES]
        self.exterior_tags = {t + n for t in gml_tags for n in ("exterior", "outerBoundaryIs")}
        self.interior_tags = {t + n for t in gml_tags for n in ("interior", "innerBoundaryIs")}
        self.poslist_tags = {t + "posList" for t in gml_tags}
        self.uniform_tags = {t + n for t in gml_tags
                             for n in ("MultiSurface", "CompositeSurface", "Shell")}
        self.compile_member_paths()
        #: The walker of ImplicitGeometry prototypes (into a model of their own), made when
        #: the first one is met; None in that walker itself.
        self.templates: _Walker | None = None
        self.is_template = False
    # -- classification -------------------------------------------------------------------
    def kind(self, tag: str) -> tuple[int, object]:
        """(kind, payload) of an element tag, cached: payload is a LoD, class code or type."""
        cached = self.kinds.get(tag)
        if cached is not None:
            return cached
        namespace, local = _split_tag(tag)
        if namespace in ns.GML_NAMESPACES:
            if local in ns.POLYGON_ELEMENTS:
                result = (K_POLYGON, None)
            elif local == "OrientableSurface":
                result = (K_ORIENTABLE, None)
            elif local in ns.AGGREGATE_ELEMENTS:
                result = (K_AGG, None)
            elif local == "boundedBy":
                result = (K_GML_BOUNDED, None)
            elif local == "interior":
                # Met by the walker (polygon holes are read by the polygon fast path), so this
                # is a Solid's inner shell: a cavity, invisible from outside.
                result = (K_CAVITY, None)
            else:
                result = (K_SKIP, None)
        elif namespace == "" or namespace.startswith(ns.CITYGML_NS_PREFIXES):
            version = ns.citygml_version(namespace)
            if version:
                self.m.versions.add(version)
            if any(module in namespace for module in ns.SKIPPED_CITYGML_MODULES):
                result = (K_SKIP, None)
            elif local in ns.CITY_OBJECT_TYPES:
                result = (K_OBJECT, local)
            elif local in ns.THEMATIC_SURFACES:
                result = (K_THEMATIC, ns.SURFACE_CODE[ns.THEMATIC_SURFACES[local]])
            elif local in ns.IMPLICIT_PROPERTIES:
                result = (K_IMPLICIT, int(local[3]))
            elif local in ns.SKIPPED_CITYGML or local in ns.TIME_ATTRIBUTES:
                result = (K_SKIP, None)
            elif local in ("appearance", "Appearance", "appearanceMember"):
                result = (K_APPEARANCE, None)
            else:
                match = _LOD_PROPERTY.match(local)
                result = (K_LOD, int(match.group(1))) if match else (K_DESCEND, None)
        else:
            # An Application Domain Extension (or a foreign element): skipped with its subtree.
            self.m.ade_tags.add(tag)
            result = (K_SKIP, None)
        self.kinds[tag] = result
        return result

    def detect_gml(self, root) -> None:
        """Pick the GML namespace of the file (3.1.1 or 3.2) from the root's declarations."""
        declared = set((root.nsmap or {}).values())
        present = [(g, a) for g, a in zip(ns.GML_NAMESPACES, ns.GML_ID_ATTRS) if g in declared]
        if present:
            self.gml_ns, self.gml_id = present[0]
        # Only files declaring both GML versions need the second look-up of every id.
        self.other_gml_id = present[1][1] if len(present) > 1 else (
            None if present else ns.GML_ID_ATTRS[1])
        self.compile_member_paths()

    def compile_member_paths(self) -> None:
        """XPaths of :meth:`uniform_members` in the file's GML namespace (members in the other
        namespace make the selection come up short, and the generic walk reads them)."""
        from lxml import etree

        names = {"g": self.gml_ns, "x": XLINK_HREF[1:XLINK_HREF.index("}")]}
        #: The xlinks of the members, in document order (plain strings, no elements made).
        self.member_hrefs = etree.XPath("g:surfaceMember/@x:href", namespaces=names,
                                        smart_strings=False)
        #: The polygon of each member that has no attribute and no other child element.
        self.member_polygons = etree.XPath("g:surfaceMember[not(@*)][count(*) = 1]/g:Polygon",
                                           namespaces=names)

    def element_id(self, el) -> str | None:
        value = el.get(self.gml_id)
        if value is None and self.other_gml_id is not None:
            # Files mixing GML versions exist (envelopes in one, geometry in the other).
            value = el.get(self.other_gml_id)
        return value

    # -- members --------------------------------------------------------------------------
    def member(self, member) -> None:
        for child in member:
            tag = child.tag
            if not isinstance(tag, str):
                continue
            kind, payload = self.kind(tag)
            if kind == K_OBJECT:
                self.city_object(child, payload, -1)
            elif kind == K_APPEARANCE:
                self.m.appearance.read_appearance(child, self, owner=-1)
            else:
                self.m.counters["skipped_top_level_features"] += 1
        href = member.get(ns.XLINK_HREF)
        if href is not None:
            self.m.counters["member_references_ignored"] += 1

    def city_object(self, el, obj_type: str, parent: int) -> None:
        m = self.m
        index = len(m.obj_ids)
        m.obj_ids.append(self.element_id(el))
        m.obj_types.append(obj_type)
        m.obj_parent.append(parent)
        m.obj_line.append(_start_line(el, self.lines_skewed))
        times: dict[str, str] = {}
        relief_lod = -1
        for child in el:
            tag = child.tag
            if not isinstance(tag, str):
                continue
            local = tag[tag.rfind("}") + 1:]
            if local in ns.TIME_ATTRIBUTES and child.text:
                times[local] = child.text.strip()
            elif self.generic_attributes and local in _GENERIC_ATTRIBUTE_TAGS:
                self.generic_attribute(child, times)
            elif local == "lod" and child.text and child.text.strip().isdigit():
                relief_lod = int(child.text.strip())  # dem:lod of a relief
            elif (local in ns.VEGETATION_CODE_NAMES and obj_type in ns.VEGETATION_CODE_TYPES
                  and child.text and child.text.strip()):
                m.obj_codes.setdefault(index, {}).setdefault(local, []).append(
                    child.text.strip())
        m.obj_time.append(times)
        default_cls = ns.SURFACE_CODE[ns.OBJECT_DEFAULT_CLASS.get(obj_type, "unclassified")]
        self.walk(el, index, default_cls, relief_lod, 0)

    def generic_attribute(self, el, times: dict[str, str]) -> None:
        """Keep a generic attribute named by ``--time-attribute``: 1.0/2.0
        ``<gen:intAttribute name="N"><gen:value>…`` or 3.0
        ``<genericAttribute><gen:IntAttribute><gen:name>N</gen:name><gen:value>…``."""
        from cityshade.geo.temporal import GENERIC_PREFIX

        if el.get("name") is None:  # 3.0: the property wraps the typed attribute
            inner = [c for c in el if isinstance(c.tag, str)]
            if not inner:
                return
            el = inner[0]
        name = el.get("name")
        value = None
        for child in el:
            if not isinstance(child.tag, str):
                continue
            local = child.tag[child.tag.rfind("}") + 1:]
            if local == "name" and name is None:
                name = (child.text or "").strip()
            elif local == "value":
                value = (child.text or "").strip()
        if name in self.generic_attributes and value:
            times[GENERIC_PREFIX + name] = value

    def walk(self, el, obj: int, cls: int, lod: int, flip: int) -> None:
        """Walk the children of ``el`` in the context (object, class, LoD, orientation flip).

        The hot loop of the reader (every geometry property, aggregate member and polygon
        passes here): a child is classified by one look-up in the tag cache (:meth:`kind` fills
        it on a miss), and the frequent kinds — aggregate members and polygons — come first.
        """
        m = self.m
        kinds = self.kinds
        uniform_tags = self.uniform_tags
        gml_id, other_gml_id = self.gml_id, self.other_gml_id
        for child in el:
            tag = child.tag
            entry = kinds.get(tag)
            if entry is None:
                if not isinstance(tag, str):
                    continue  # a processing instruction or an entity reference
                entry = self.kind(tag)
            kind, payload = entry
            if kind == K_AGG:
                uniform = tag in uniform_tags
                if not len(child.attrib):
                    # The usual member: no reference, CRS or id of its own (counting the
                    # attributes makes no strings; the look-ups below would find nothing).
                    if not (uniform and self.uniform_members(child, obj, cls, lod, flip)):
                        self.walk(child, obj, cls, lod, flip)
                    continue
                href = child.get(XLINK_HREF)
                if href is not None:
                    self.reference(href, obj, cls, lod, flip)
                    continue
                srs = child.get("srsName")
                if srs is not None:
                    m.srs_names[srs] += 1
                agg_id = child.get(gml_id)
                if agg_id is None and other_gml_id is not None:
                    agg_id = child.get(other_gml_id)
                p0, r0 = len(self.polys), len(self.refs)
                if not (uniform and self.uniform_members(child, obj, cls, lod, flip)):
                    self.walk(child, obj, cls, lod, flip)
                if agg_id is not None:
                    m.aggregates.setdefault(agg_id, (p0, len(self.polys), r0, len(self.refs)))
            elif kind == K_POLYGON:
                self.polygon(child, obj, cls, lod, flip)
            elif kind == K_SKIP:
                continue
            elif kind == K_LOD:
                href = child.get(XLINK_HREF)
                if href is not None:
                    self.reference(href, obj, cls, payload, flip)
                else:
                    self.walk(child, obj, cls, payload, flip)
            elif kind == K_DESCEND:
                if child.get(XLINK_HREF) is None:
                    self.walk(child, obj, cls, lod, flip)
            elif kind == K_OBJECT:
                self.city_object(child, payload, obj)
            elif kind == K_THEMATIC:
                surface_id = self.element_id(child)
                p0, r0 = len(self.polys), len(self.refs)
                self.walk(child, obj, payload, lod, flip)
                if surface_id is not None:
                    m.aggregates.setdefault(surface_id, (p0, len(self.polys), r0, len(self.refs)))
                    if payload in _OPENING_CODES:
                        m.openings.append((surface_id, p0, len(self.polys)))
            elif kind == K_ORIENTABLE:
                flipped = flip ^ (1 if child.get("orientation", "+").strip() == "-" else 0)
                agg_id = self.element_id(child)
                p0, r0 = len(self.polys), len(self.refs)
                for base in child:
                    if not isinstance(base.tag, str):
                        continue
                    href = base.get(XLINK_HREF)
                    if href is not None:
                        self.reference(href, obj, cls, lod, flipped)
                    else:
                        self.walk(base, obj, cls, lod, flipped)
                if agg_id is not None:
                    m.aggregates.setdefault(agg_id, (p0, len(self.polys), r0, len(self.refs)))
            elif kind == K_APPEARANCE:
                m.appearance.read_appearance(child, self, owner=obj)
            elif kind == K_GML_BOUNDED:
                for envelope in child:
                    if isinstance(envelope.tag, str):
                        srs = envelope.get("srsName")
                        if srs is not None:
                            m.srs_names[srs] += 1
            elif kind == K_IMPLICIT:
                self.implicit(child, obj, payload)
            elif kind == K_CAVITY:
                m.counters["cavity_polygons"] += sum(
                    1 for p in child.iter() if isinstance(p.tag, str)
                    and p.tag[p.tag.rfind("}") + 1:] in ns.POLYGON_ELEMENTS)

    def implicit(self, el, obj: int, lod: int) -> None:
        """An ``lodNImplicitRepresentation``: its ImplicitGeometry recorded as an instance
        (placed after the read, :func:`cityshade.citygml.implicit.place_instances`)."""
        m = self.m
        if self.is_template or el.get(XLINK_HREF) is not None:
            # A prototype holding instances, or a property pointing at another object's
            # ImplicitGeometry (the same geometry at the same place): nothing new to draw.
            m.counters["implicit_geometries_skipped"] += 1
            return
        for geom in el:
            if isinstance(geom.tag, str) and geom.tag.endswith("ImplicitGeometry"):
                self.implicit_geometry(geom, obj, lod)

    def implicit_geometry(self, geom, obj: int, lod: int) -> None:
        m = self.m
        if m.implicit is None:
            m.implicit = ImplicitRecords()
        matrix, ref, proto, target = None, None, -1, None
        for child in geom:
            tag = child.tag
            if not isinstance(tag, str):
                continue
            local = tag[tag.rfind("}") + 1:]
            if local == "transformationMatrix":
                matrix = parse_numbers(child.text, 16)
                if matrix is None:
                    raise self.implicit_error(geom, obj, "a transformationMatrix that is not "
                                                        "16 numbers")
            elif local in ("relativeGMLGeometry", "relativeGeometry"):
                href = child.get(XLINK_HREF)
                if href is not None:
                    target = _href_target(href)
                else:
                    proto = self.prototype(child)
            elif local == "referencePoint":
                text, srs = point_text(child)
                ref = parse_numbers(text, 3) or parse_numbers(text, 2)
                if ref is None:
                    raise self.implicit_error(geom, obj, "a referencePoint that is not a "
                                                        "gml:Point of 2 or 3 numbers")
                if srs is not None:
                    m.srs_names[srs] += 1
        if ref is None or (proto < 0 and target is None):
            m.counters["implicit_geometries_incomplete"] += 1
            return
        ref = (ref + [0.0])[:3]
        matrix = matrix or [1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0]
        m.implicit.instances.append((obj, lod, matrix, ref, proto, target))

    def implicit_error(self, geom, obj: int, what: str) -> InputError:
        return InputError(f"an ImplicitGeometry has {what}", path=str(self.m.path),
                          line=_start_line(geom, self.lines_skewed), gml_id=self.m.obj_ids[obj])

    def prototype(self, prop) -> int:
        """Read an inline prototype geometry into the template model; its index."""
        tw = self.templates
        if tw is None:
            tw = self.templates = _Walker(RawModel(path=self.m.path))
            tw.gml_ns, tw.gml_id, tw.other_gml_id = self.gml_ns, self.gml_id, self.other_gml_id
            tw.compile_member_paths()
            tw.lines_skewed, tw.is_template = self.lines_skewed, True
            self.m.implicit.templates.append(tw.m)
        rec = self.m.implicit
        p0 = len(tw.polys)
        tw.walk(prop, 0, 0, -1, 0)
        index = len(rec.protos)
        rec.protos.append((0, p0, len(tw.polys)))
        for geom in prop:
            gid = self.element_id(geom) if isinstance(geom.tag, str) else None
            if gid is not None:
                rec.proto_ids.setdefault(gid, index)
        self.m.counters["implicit_prototypes"] += 1
        return index

    def close(self) -> None:
        """Wait for the ring parsers (a failed read calls it too, so no thread lingers)."""
        self.parser.close()
        if self.templates is not None:
            self.templates.parser.close()

    def uniform_members(self, el, obj: int, cls: int, lod: int, flip: int) -> bool:
        """Read a surface aggregate whose members are all alike in bulk; False if they are not.

        Two layouts make most of the members of large files: the ``CompositeSurface`` (or
        ``Shell``) of a Solid whose ``surfaceMember``s are all xlinks, and a ``MultiSurface``
        whose members each hold one ``Polygon`` and nothing else. lxml selects those members in
        C (no element or tag string is made per xlink member, no dispatch per polygon member).
        Each child of ``el`` yields at most one entry, so the selection stands for the whole
        aggregate exactly when it has one entry per child node; the generic :meth:`walk` would
        then do the same — reference every xlink in order, or read every polygon in order in
        the context of ``el``. Otherwise nothing has been recorded and the walk does the work.
        """
        n_children = len(el)  # elements, processing instructions and entity references
        if n_children < 2:
            return False  # nothing to gain, and the selection would cost a look
        if el[0].get(XLINK_HREF) is not None:
            hrefs = self.member_hrefs(el)
            if len(hrefs) != n_children:
                return False
            self.refs.extend([(obj, cls, lod, flip)] * n_children)
            self.m.ref_target.extend(map(_href_target, hrefs))
            return True
        polygons = self.member_polygons(el)
        if len(polygons) != n_children:
            return False
        for polygon in polygons:
            self.polygon(polygon, obj, cls, lod, flip)
        return True

    def reference(self, href: str, obj: int, cls: int, lod: int, flip: int) -> None:
        self.refs.append((obj, cls, lod, flip))
        self.m.ref_target.append(_href_target(href))

    def polygon(self, el, obj: int, cls: int, lod: int, flip: int) -> None:
        """Record one polygon-like element and the text of its rings (the hot path).

        Rings are taken in document order: the first exterior (later ones are ignored) and
        every interior with content. A ring whose first child is a ``posList`` is read inline;
        ``gml:pos`` lists and ``gml:coordinates`` go through :meth:`ring_other`.
        """
        m = self.m
        texts, dims = self.texts, self.dims
        ring_base = self.rings_flushed
        index = len(self.polys)
        self.polys.append((obj, cls, lod, flip, ring_base + len(texts)))
        gml_id = self.gml_id
        pid = el.get(gml_id)
        if pid is None and self.other_gml_id is not None:
            pid = el.get(self.other_gml_id)
        m.poly_ids.append(pid)
        if pid is not None and m.poly_by_id.setdefault(pid, index) != index:
            m.counters["duplicate_gml_ids"] += 1
        dim_default = None
        # Most polygons carry nothing but their id: counting the attributes (no strings made)
        # spares the two look-ups that would find nothing.
        if len(el.attrib) > (pid is not None):
            srs = el.get("srsName")
            if srs is not None:
                m.srs_names[srs] += 1
            dim_default = el.get("srsDimension")
        exterior_tags, interior_tags = self.exterior_tags, self.interior_tags
        poslist_tags = self.poslist_tags
        has_exterior = False
        for boundary in el:
            btag = boundary.tag
            if btag in exterior_tags:
                if has_exterior:
                    continue
                if not len(boundary):
                    # An empty or xlinked exterior: no ring to read (the polygon is skipped).
                    m.counters["rings_without_coordinates"] += 1
                    continue
                has_exterior = True
            elif btag not in interior_tags or not len(boundary):
                continue
            ring = boundary[0]
            first = ring[0] if len(ring) else None
            if first is not None and first.tag in poslist_tags:
                # The common case: one posList.
                text = first.text or ""
                dim = first.get("srsDimension") or dim_default
            else:
                text, dim = self.ring_other(ring, first, dim_default)
            ring_id = ring.get(gml_id)
            if ring_id is not None:
                m.ring_by_id.setdefault(ring_id, ring_base + len(texts))
            texts.append(text)
            dims.append(3 if dim is None or dim == "3" else self._dim(dim))
            self.text_chars += len(text)
        if not has_exterior:
            m.counters["polygons_without_exterior"] += 1
            # Keep the ring numbering consistent: an empty exterior makes the polygon skip.
            self.ring_text("", 3, None)
        if self.text_chars > _PARSE_BATCH_CHARS:
            self.flush()

    @staticmethod
    def _dim(dim: str) -> int:
        try:
            return int(dim)
        except ValueError:
            return 0  # not 2 or 3: the coordinate parser marks the ring bad

    def ring_other(self, ring, first, dim):
        """(text, dimension) of a ring written with gml:pos or gml:coordinates."""
        if first is None or not isinstance(first.tag, str):
            self.m.counters["rings_without_coordinates"] += 1
            return "", dim
        local = first.tag[first.tag.rfind("}") + 1:]
        if local == "pos":
            text = " ".join((c.text or "") for c in ring if isinstance(c.tag, str))
            return text, first.get("srsDimension") or dim
        if local == "coordinates":
            text = first.text or ""
            cs = first.get("cs", ",")
            ts = first.get("ts", " ")
            decimal = first.get("decimal", ".")
            if decimal != ".":
                text = text.replace(cs, "\x00").replace(decimal, ".").replace("\x00", cs)
            return text.replace(cs, " ").replace(ts, " "), dim
        self.m.counters["rings_without_coordinates"] += 1
        return "", dim

    def ring_text(self, text: str, dim: int, ring_id: str | None) -> None:
        if ring_id is not None:
            self.m.ring_by_id.setdefault(ring_id, self.rings_flushed + len(self.dims))
        self.texts.append(text)
        self.dims.append(dim)
        self.text_chars += len(text)

    def flush(self) -> None:
        if not self.texts:
            return
        self.parser.submit(self.texts, self.dims)
        self.rings_flushed += len(self.texts)
        self.texts, self.dims, self.text_chars = [], [], 0

    def finish(self) -> None:
        self.flush()
        chunks = self.parser.results()
        m = self.m
        if chunks:
            xyz, points, bad = zip(*chunks)
            m.xyz = np.concatenate(xyz) if len(xyz) > 1 else xyz[0]
            m.ring_points = np.concatenate(points)
            m.ring_bad = np.concatenate(bad)
        m.poly_obj, m.poly_cls, m.poly_lod, m.poly_flip, m.poly_ring0 = _record_columns(
            self.polys, 5)
        m.ref_obj, m.ref_cls, m.ref_lod, m.ref_flip = _record_columns(self.refs, 4)
        self.polys, self.refs = [], []
        if m.ade_tags:
            m.counters["ade_elements_skipped"] = len(m.ade_tags)
        if self.templates is not None:
            self.templates.finish()


@functools.cache
def _lines_skewed() -> bool:
    """Whether lxml gives an element from line 65535 on the line where its first child node
    ends (libxml2 2.14, whose 16-bit line field saturates there: ``xmlGetLineNo`` then asks
    the first child, a whitespace text's end line after the start tag's newline). Measured
    once on a small document, so a libxml2 that reports the start tag's line is read as is."""
    from lxml import etree

    doc = b"<r>" + b"\n" * 65537 + b"<a>\n<b/></a></r>"  # <a> is on line 65538
    return etree.fromstring(doc)[0].sourceline == 65539


def _start_line(el, skewed: bool) -> int:
    """The line of ``el``'s start tag (its end), also past line 65535 (:func:`_lines_skewed`)."""
    line = el.sourceline or 0
    if line < 65535 or not skewed:
        return line
    # libxml2 asks the first child, which then starts where this tag ends, and so on down
    # (at most five levels, then it gives 65535): ask the first one with text directly. Where
    # that chain ends in an empty element with no text after it, libxml2's answer stays.
    top = line
    while el.text is None and len(el):
        el = el[0]
    line = el.sourceline or 0
    if el.text is not None:  # the text ends that many lines after the tag
        return line - el.text.count("\n")
    if el.tail is not None:  # no child: the text after the element is asked
        return line - el.tail.count("\n")
    return top


def _record_columns(records: list[tuple[int, ...]], width: int) -> list[np.ndarray]:
    """Columns (int64, contiguous) of a list of equal-width integer tuples.

    ``np.fromiter`` over the flattened tuples is about twice as fast as ``np.array`` of the
    list, which inspects every tuple as a nested sequence.
    """
    flat = np.fromiter(chain.from_iterable(records), np.int64, count=width * len(records))
    table = flat.reshape(-1, width)
    return [np.ascontiguousarray(table[:, i]) for i in range(width)]


def _member_tags(root_namespace: str) -> list[str]:
    """Tags of top-level members in every CityGML/GML version (lxml iterparse filter)."""
    cores = {
        "http://www.opengis.net/citygml/1.0", "http://www.opengis.net/citygml/2.0",
        "http://www.opengis.net/citygml/3.0", "http://www.citygml.org/citygml/1/0/0",
        "http://www.opengis.net/citygml/profiles/base/1.0",
        "http://www.opengis.net/citygml/profiles/base/2.0",
        "http://www.citygml.org/citygml/profiles/base/2.0", root_namespace,
    }
    apps = {"http://www.opengis.net/citygml/appearance/1.0",
            "http://www.opengis.net/citygml/appearance/2.0",
            "http://www.opengis.net/citygml/appearance/3.0"}
    tags = []
    for core in sorted(cores):
        prefix = "{%s}" % core if core else ""
        tags += [prefix + "cityObjectMember", prefix + "appearanceMember", prefix + "featureMember"]
    for app in sorted(apps):
        tags.append("{%s}appearanceMember" % app)
    for gml in ns.GML_NAMESPACES:
        tags += ["{%s}featureMember" % gml, "{%s}featureMembers" % gml]
    return tags


def _xml_message(msg: str) -> str:
    """lxml's message of a syntax error, in words a user can act on."""
    if "Excessive depth" in msg:
        # libxml2's nesting limit (2,048 with huge_tree); its advice names a parser flag.
        return ("malformed XML: elements nested more than 2,048 levels deep (a city model "
                "needs a few dozen): the file is damaged or not a city model")
    return f"malformed XML: {msg}"


def _root_of(path: Path, recover: bool):
    """(namespace, local name, nsmap) of the document's root element, reading only its start."""
    from lxml import etree

    with path.open("rb") as fh:
        try:
            for _event, elem in etree.iterparse(fh, events=("start",), resolve_entities=False,
                                                 no_network=True, load_dtd=False,
                                                 recover=recover, huge_tree=True):
                namespace, local = _split_tag(elem.tag)
                return namespace, local
        except etree.XMLSyntaxError as exc:
            raise XMLSyntaxError(_xml_message(exc.msg), path=str(path),
                                 line=exc.lineno) from None
    raise XMLSyntaxError("no XML element found", path=str(path))


#: Elements holding one generic attribute (1.0/2.0 typed elements, the 3.0 property).
_GENERIC_ATTRIBUTE_TAGS = frozenset({
    "stringAttribute", "intAttribute", "doubleAttribute", "dateAttribute", "uriAttribute",
    "measureAttribute", "genericAttribute"})


def read_citygml(path: str | os.PathLike, progress: Callable[[int, int], None] | None = None,
                 generic_attributes: Iterable[str] = ()) -> RawModel:
    """Read a CityGML file into flat records.

    Parameters
    ----------
    path : path-like
        A CityGML 1.0 / 2.0 / 3.0 file (GML 3.1.1 or 3.2).
    progress : callable(bytes_read, bytes_total), optional
        Called after each top-level member.
    generic_attributes : iterable of str
        Names of generic attributes (``gen:stringAttribute name=…``, 3.0 ``genericAttribute``)
        whose values go into each object's time attributes under
        ``temporal.GENERIC_PREFIX + name`` (``--time-attribute``).

    Raises
    ------
    InputError, XMLSyntaxError, NotCityGMLError, EmptyModelError
        With file and line where known.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("no such file" if not path.exists() else "not a regular file",
                         path=str(path))
    _prescan(path)
    root_ns, root_local = _root_of(path, recover=False)
    if root_local != "CityModel" or not (root_ns == "" or root_ns.startswith(ns.CITYGML_NS_PREFIXES)):
        raise NotCityGMLError(f"not a CityGML file: the root element is "
                              f"{'{' + root_ns + '}' if root_ns else ''}{root_local}, "
                              f"not a CityGML CityModel", path=str(path))
    try:
        return _read(path, root_ns, progress, recover=False,
                     generic=frozenset(generic_attributes))
    except XMLSyntaxError as exc:
        # Real files (PLATEAU) use undeclared namespace prefixes: recover with a warning rather
        # than refusing the whole model. Anything else that is malformed stays an error.
        if "Namespace prefix" not in exc.message:
            raise
        model = _read(path, root_ns, progress, recover=True,
                      generic=frozenset(generic_attributes))
        detail = exc.message.removeprefix("malformed XML: ")
        model.warnings.insert(0, f"XML namespace error recovered: {detail}")
        return model


def _read(path: Path, root_ns: str, progress, recover: bool,
          generic: frozenset = frozenset()) -> RawModel:
    total = path.stat().st_size
    model = None
    if not recover:
        from cityshade.citygml import split

        plan = split.plan(path, total)
        if plan is not None:
            model = split.read_split(path, plan, root_ns, progress, generic)
    if model is None:
        with path.open("rb") as fh:
            model = read_stream(fh, total, path, root_ns, progress, recover, generic)
    if model.counters["members"] == 0 or not model.obj_ids:
        raise EmptyModelError("the CityGML model contains no city objects", path=str(path))
    place_instances(model)  # after the whole file (and both parts of a split read)
    if progress is not None:
        progress(total, total)
    return model


def read_stream(fh, total: int, path: Path, root_ns: str, progress, recover: bool,
                generic: frozenset = frozenset()) -> RawModel:
    """The records of a CityGML document read from ``fh`` (a binary file or stream whose
    ``tell()`` is its offset in the file of ``total`` bytes); no check that it holds objects."""
    from lxml import etree

    model = RawModel(path=path, root_namespace=root_ns)
    version = ns.citygml_version(root_ns)
    if version:
        model.versions.add(version)
    walker = _Walker(model)
    walker.generic_attributes = generic
    walker.lines_skewed = _lines_skewed()
    members = 0
    context = etree.iterparse(fh, events=("end",), tag=_member_tags(root_ns),
                              resolve_entities=False, no_network=True, load_dtd=False,
                              recover=recover, huge_tree=True, remove_comments=True)
    try:
        for _event, member in context:
            if members == 0:
                root = member.getparent()
                if root is not None:
                    walker.detect_gml(root)
                    for child in root:
                        if isinstance(child.tag, str) and child.tag.endswith("}boundedBy"):
                            for env in child:
                                if isinstance(env.tag, str) and env.get("srsName"):
                                    model.srs_names[env.get("srsName")] += 1
            if member.getparent() is None or member.getparent().getparent() is not None:
                continue  # a nested element with a member-like name: handled by its owner
            members += 1
            walker.member(member)
            # Free the member and everything before it: memory stays bounded.
            member.clear()
            parent = member.getparent()
            while member.getprevious() is not None:
                del parent[0]
            if progress is not None:
                progress(fh.tell(), total)
    except etree.XMLSyntaxError as exc:
        msg = exc.msg or str(exc)
        if "Premature end" in msg or "EndTag" in msg and fh.tell() >= total:
            msg = f"the file is truncated or malformed ({msg})"
        else:
            msg = _xml_message(msg)
        raise XMLSyntaxError(msg, path=str(path), line=exc.lineno) from None
    finally:
        walker.close()
    walker.finish()
    model.counters["members"] = members
    return model
