"""CityGML ImplicitGeometry: prototypes read once, placed once per instance after the read.

An ``lodNImplicitRepresentation`` holds an ``ImplicitGeometry``: a prototype geometry in its
own coordinates (``relativeGMLGeometry``, CityGML 3.0 ``relativeGeometry``), inline or by
``xlink:href`` to another instance's prototype, a 4 × 4 ``transformationMatrix`` (row-major,
16 numbers) and a ``referencePoint``. A world point is ``M · (x, y, z, 1)`` of the prototype
point, then plus the reference point (CityGML 2.0 §10.3.6; the Berlin tree file's matrices
have orthogonal columns scaled by the crown's two diameters, which fixes ``M · v`` rather
than ``v · M``). ``mimeType`` and ``libraryObject`` (external prototypes) are ignored.

The reader walks each inline prototype once into a template model of its own (so its
relative coordinates never mix with world ones) and records every instance; the instances
become ordinary polygons of the model only when the whole file is read (references
forward and backward resolve, and a file read by two processes places them after the two
parts are merged), so the build (LoD, classes, triangulation, counts) treats them as
explicit geometry. Placed polygons carry no gml:id, so appearances that target a
prototype's polygons are not applied to the copies.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from cityshade.citygml import namespaces as ns


@dataclass
class ImplicitRecords:
    """Prototypes and instances of one read (or of the merged parts of a split read)."""

    #: Template models (the reader's ``RawModel``), one per read part.
    templates: list = field(default_factory=list)
    #: Inline prototypes: (template model index, first polygon, end polygon).
    protos: list[tuple[int, int, int]] = field(default_factory=list)
    #: gml:id of a prototype's geometry → prototype index.
    proto_ids: dict[str, int] = field(default_factory=dict)
    #: (object, LoD, matrix (16,), reference point (3,), prototype index or -1, xlink target).
    instances: list[tuple] = field(default_factory=list)


def parse_numbers(text: str | None, count: int) -> list[float] | None:
    """``count`` floats from a whitespace-separated text, None if it holds anything else."""
    parts = (text or "").split()
    if len(parts) != count:
        return None
    try:
        return [float(p) for p in parts]
    except ValueError:
        return None


def point_text(point_property) -> tuple[str | None, str | None]:
    """(coordinate text, srsName) of a ``referencePoint``'s ``gml:Point`` (``pos`` or
    ``coordinates``)."""
    srs = None
    for el in point_property.iter():
        tag = el.tag
        if not isinstance(tag, str):
            continue
        local = tag[tag.rfind("}") + 1:]
        if local == "Point":
            srs = el.get("srsName")
        elif local == "pos":
            return el.text, srs
        elif local == "coordinates":
            cs = el.get("cs", ",")
            return (el.text or "").replace(cs, " "), srs
    return None, srs


def merge_records(a: ImplicitRecords | None, b: ImplicitRecords | None,
                  n_obj: int) -> ImplicitRecords | None:
    """``b`` (read after ``a``, its objects numbered from ``n_obj``) appended to ``a``."""
    if b is None:
        return a
    if a is None:
        a = ImplicitRecords()
    n_templates, n_protos = len(a.templates), len(a.protos)
    a.templates += b.templates
    a.protos += [(t + n_templates, p0, p1) for t, p0, p1 in b.protos]
    for gml_id, index in b.proto_ids.items():
        a.proto_ids.setdefault(gml_id, index + n_protos)
    a.instances += [(obj + n_obj, lod, matrix, ref, proto + n_protos if proto >= 0 else proto,
                     target) for obj, lod, matrix, ref, proto, target in b.instances]
    return a


def _resolve(rec: ImplicitRecords, target: str) -> tuple[int, int, int] | None:
    """(template, first polygon, end polygon) of an xlinked prototype: a prototype's root, or
    a geometry aggregate or polygon inside one."""
    index = rec.proto_ids.get(target)
    if index is not None:
        return rec.protos[index]
    for t, tm in enumerate(rec.templates):
        agg = tm.aggregates.get(target)
        if agg is not None:
            return t, agg[0], agg[1]
        p = tm.poly_by_id.get(target)
        if p is not None:
            return t, p, p + 1
    return None


def place_instances(model) -> None:
    """Turn the implicit instances of a read model into ordinary polygons at the model's end.

    Each instance appends a copy of its prototype's rings, transformed in float64, and its
    polygons (the instance's object and LoD; the object's default class where the prototype
    has none; the winding reversed where the matrix mirrors). Counts go to
    ``model.counters``: ``implicit_instances`` placed, ``implicit_references_unresolved``.
    """
    rec = model.implicit
    model.implicit = None
    if rec is None or not rec.instances:
        return
    tables = []
    for tm in rec.templates:
        ring0 = np.append(tm.poly_ring0, len(tm.ring_points)).astype(np.int64)
        starts = np.concatenate([[0], np.cumsum(tm.ring_points)]).astype(np.int64)
        tables.append((ring0, starts))
    default = [ns.SURFACE_CODE[ns.OBJECT_DEFAULT_CLASS.get(t, "unclassified")]
               for t in model.obj_types]
    xyz, points, bad, cols = [], [], [], []
    ring_base = len(model.ring_points)
    for obj, lod, matrix, ref, proto, target in rec.instances:
        found = rec.protos[proto] if proto >= 0 else _resolve(rec, target)
        if found is None:
            model.counters["implicit_references_unresolved"] += 1
            continue
        t, p0, p1 = found
        tm, (ring0, starts) = rec.templates[t], tables[t]
        r0, r1 = int(ring0[p0]), int(ring0[p1])
        m = np.asarray(matrix, np.float64).reshape(4, 4)
        local = tm.xyz[starts[r0]:starts[r1]]
        # Homogeneous M · (x, y, z, 1), then the reference point.
        placed = ((local @ m[:3, :3].T + m[:3, 3]) / (local @ m[3, :3] + m[3, 3])[:, None]
                  + np.asarray(ref, np.float64))
        xyz.append(placed)
        points.append(tm.ring_points[r0:r1])
        bad.append(tm.ring_bad[r0:r1])
        n = p1 - p0
        cls = tm.poly_cls[p0:p1]
        mirror = int(np.linalg.det(m[:3, :3]) < 0)
        cols.append((np.full(n, obj), np.where(cls == 0, default[obj], cls), np.full(n, lod),
                     tm.poly_flip[p0:p1] ^ mirror, tm.poly_ring0[p0:p1] - r0 + ring_base))
        ring_base += r1 - r0
        model.counters["implicit_instances"] += 1
    if not cols:
        return
    model.xyz = np.concatenate([model.xyz, *xyz])
    model.ring_points = np.concatenate([model.ring_points, *points]).astype(np.int64)
    model.ring_bad = np.concatenate([model.ring_bad, *bad]).astype(np.uint8)
    names = ("poly_obj", "poly_cls", "poly_lod", "poly_flip", "poly_ring0")
    for k, name in enumerate(names):
        setattr(model, name, np.concatenate(
            [getattr(model, name), *(c[k] for c in cols)]).astype(np.int64))
    model.poly_ids += [None] * sum(len(c[0]) for c in cols)
