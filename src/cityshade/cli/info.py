"""``cityshade info FILE``: what a scene file (or a CityGML/CityJSON file, built in memory)
contains."""
from __future__ import annotations

import json
from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand

from cityshade.cli.options import crs_option


def describe(scene, vegetation=None) -> dict:
    """The ``info --json`` object of a scene; ``vegetation`` the ``[vegetation]`` settings
    that say which crowns are evergreen (default: the defaults)."""
    import numpy as np

    from cityshade.citygml.namespaces import SURFACE_CLASSES

    rep = scene.report
    verts = np.asarray(scene.vertices, dtype=np.float64)
    if verts.size:
        lo = (verts.min(axis=0) + scene.origin_m).tolist()
        hi = (verts.max(axis=0) + scene.origin_m).tolist()
    else:
        lo = hi = None
    classes = np.bincount(np.asarray(scene.tri_class), minlength=len(SURFACE_CLASSES))
    header = scene.header or {}
    counts = {"triangles": scene.n_triangles, "vertices": int(scene.vertices.shape[0]),
              "objects": len(scene.obj_ids)}
    out = describe_report(rep, header, counts)
    out.update({
        "surface_classes": {SURFACE_CLASSES[i]: int(c) for i, c in enumerate(classes) if c},
        "crs": scene.crs.to_json(),
        "origin": [float(v) for v in scene.origin_m],
        "bbox": {"min": lo, "max": hi},
        "materials": len(scene.materials),
        "textures": [t["uri"] for t in scene.textures],
        "kdtree": scene.kdtree.stats if scene.kdtree is not None else None,
    })
    crowns = _crowns(scene, vegetation)
    if crowns:
        out["vegetation"] = crowns
    return out


def _crowns(scene, settings) -> dict | None:
    """Crowns (vegetation objects with triangles), how many are evergreen and how many carry
    class/function/usage/species codes in the data (docs/DESIGN.md §21)."""
    import numpy as np

    from cityshade.config import VegetationSettings
    from cityshade.geometry.vegetation import evergreen_objects, object_codes, vegetation_mask

    mask = vegetation_mask(scene)
    if not mask.any():
        return None
    crowns = np.unique(np.asarray(scene.tri_object)[mask])
    codes = object_codes(scene)
    evergreen = evergreen_objects(scene, settings or VegetationSettings())[crowns]
    return {"crowns": int(crowns.size), "evergreen": int(evergreen.sum()),
            "with_codes": sum(1 for c in crowns.tolist() if c in codes)}


def describe_tiled(tiled) -> dict:
    """The ``info --json`` object of a tiled cache, from its index alone (no tile is read)."""
    from cityshade.citygml.namespaces import SURFACE_CLASSES

    index = tiled.index
    rep = dict(tiled.report)
    box = index["box_m"]
    origin = tiled.origin_m
    counts = index["counts"]
    out = describe_report(rep, index, counts)
    out.update({
        "crs": tiled.crs.to_json(), "origin": [float(v) for v in origin],
        "bbox": {"min": [b + o for b, o in zip(box[0], origin)],
                 "max": [b + o for b, o in zip(box[1], origin)]},
        "surface_classes": {SURFACE_CLASSES[i]: int(c)
                            for i, c in enumerate(index["surface_classes"]) if c},
        "materials": len(tiled.materials), "textures": [t["uri"] for t in tiled.textures],
        "kdtree": None,
        "tiled": {"folder": str(tiled.path), "tile_m": index["tile_m"],
                  "tiles": len(index["tiles"]),
                  "bytes": sum(t["size"] for t in index["tiles"]),
                  "kdtree_nodes": sum(t["kdtree"]["nodes"] or 0 for t in index["tiles"]),
                  "per_tile": [{k: t[k] for k in ("key", "file", "size", "triangles",
                                                  "objects", "box_m")}
                               for t in index["tiles"]]},
    })
    return out


def describe_report(rep: dict, header: dict, counts: dict) -> dict:
    """The parts of ``info --json`` that come from the build report."""
    return {
        "file": str(header.get("source", {}).get("path", "")) or None,
        "format_version": header.get("format_version"),
        "triangles": counts["triangles"], "vertices": counts["vertices"],
        "objects": {"total": counts["objects"], "by_type": rep["objects_by_type"]},
        "polygons": rep["polygons"], "skipped": rep["skipped"],
        "left_out": rep.get("left_out", {}), "closure_surfaces": rep.get("closure_surfaces"),
        "implicit": {k: rep.get("counters", {}).get("implicit_" + k, 0)
                     for k in ("prototypes", "instances", "references_unresolved")},
        "skipped_ids": rep.get("skipped_ids", {}), "repairs": rep["repairs"],
        "lods": rep["lods"], "lods_drawn": rep.get("lods_drawn", {}),
        "lod_requested": rep.get("lod_requested"),
        "time_range": rep["time_range"], "time_source": rep["time_source"],
        "time_sources_used": rep["time_sources_used"],
        "time_attribute": rep.get("time_attribute"),
        "creation_dates_unused": rep.get("creation_dates_unused", 0),
        "axis_order": rep.get("axis_order"), "source_crs": rep.get("source_crs"),
        "theme": rep.get("theme"), "themes": rep.get("themes", []),
        "input_format": rep.get("format", "CityGML"),
        "citygml_versions": rep.get("versions", []), "counters": rep.get("counters", {}),
        "warnings": rep.get("warnings", []), "timings": rep.get("timings", {}),
        "tiles": rep.get("tiles"),
    }


def _text(d: dict) -> str:
    from cityshade.util import plural

    lines = []
    add = lines.append
    if d["file"]:
        add(f"source        {d['file']}")
    tiles = d.get("tiles")
    if tiles:
        add(f"tiles         {tiles['files']} files; {tiles['duplicate_objects']:,} objects met "
            f"again in a later file (same gml:id) kept once")
    # Versions of the input format (the key keeps its old name: CityJSON's are listed too).
    add(f"{d['input_format']:<14}{', '.join(d['citygml_versions']) or '?'}")
    objs = ", ".join(f"{n} {t}" for t, n in d["objects"]["by_type"].items())
    add(f"objects       {d['objects']['total']:,} ({objs})")
    p = d["polygons"]
    add(f"polygons      {p['read']:,} read, {p['drawn']:,} drawn, {p['skipped']:,} skipped, "
        f"{p['not_selected_lod']:,} of other LoDs"
        + (f", {p['left_out']:,} left out" if p.get("left_out") else ""))
    if d["skipped"]:
        add("  skipped     " + ", ".join(f"{k} {v}" for k, v in d["skipped"].items()))
    if d["repairs"]:
        add("  repaired    " + ", ".join(f"{k} {v}" for k, v in d["repairs"].items()))
    left = d.get("left_out") or {}
    if left.get("closure_polygons"):
        add(f"  left out    {left['closure_polygons']:,} ClosureSurface polygons "
            f"({left['closure_triangles']:,} triangles): virtual surfaces, neither cast nor "
            f"receive (build --closure-surfaces keep draws them)")
    imp = d.get("implicit") or {}
    if imp.get("prototypes") or imp.get("instances"):
        unresolved = imp.get("references_unresolved")
        add(f"implicit      {imp['prototypes']:,} prototypes, {imp['instances']:,} instances "
            f"placed" + (f", {unresolved:,} references unresolved" if unresolved else ""))
    veg = d.get("vegetation")
    if veg:
        add(f"vegetation    {veg['crowns']:,} crowns, {veg['evergreen']:,} evergreen; "
            f"{veg['with_codes']:,} with class/function/usage/species codes")
    add(f"triangles     {d['triangles']:,} ({d['vertices']:,} vertices)")
    add("surfaces      " + ", ".join(f"{k} {v:,}" for k, v in d["surface_classes"].items()))
    lods = ", ".join(f"LoD{k}: {v}" for k, v in d["lods"].items()) or "none"
    add(f"LoDs          objects with {lods}; drawn "
        + (", ".join(f"LoD{k}: {v}" for k, v in d["lods_drawn"].items()) or "none"))
    tr = d["time_range"]
    used = ", ".join(f"{k} {v}" for k, v in d["time_sources_used"].items())
    attribute = f", attribute {d['time_attribute']}" if d.get("time_attribute") else ""
    add(f"time          {tr[0] + ' … ' + tr[1] if tr else 'no dates'} "
        f"(source {d['time_source']}{attribute}; objects by source: {used})")
    if d.get("creation_dates_unused"):
        add(f"              creationDate/terminationDate of "
            f"{plural(d['creation_dates_unused'], 'object')} unused (database times; --time-source creation uses them)")
    crs = d["crs"]
    src = d["source_crs"]
    crs_text = crs["name"] + (f" (EPSG:{crs['horizontal_epsg']})" if crs["horizontal_epsg"] else "")
    if src and src.get("is_geographic"):
        crs_text += f", projected from {src['name']}"
        if d.get("axis_order"):
            crs_text += f" read {'latitude' if d['axis_order'] == 'latlon' else 'longitude'} first"
    add(f"CRS           {crs_text}")
    add(f"origin        {d['origin'][0]:.3f} {d['origin'][1]:.3f} {d['origin'][2]:.3f}")
    if d["bbox"]["min"]:
        lo, hi = d["bbox"]["min"], d["bbox"]["max"]
        add(f"bbox          {lo[0]:.3f} {lo[1]:.3f} {lo[2]:.3f} … {hi[0]:.3f} {hi[1]:.3f} "
            f"{hi[2]:.3f} ({hi[0] - lo[0]:.1f} × {hi[1] - lo[1]:.1f} × {hi[2] - lo[2]:.1f} m)")
    add(f"appearance    theme {d['theme']!r} of {d['themes']}; {d['materials']} materials, "
        f"{len(d['textures'])} textures" if d["themes"] else "appearance    none")
    tiled = d.get("tiled")
    if tiled:
        add(f"tiled cache   {tiled['tiles']} tiles of {tiled['tile_m']:g} m, "
            f"{tiled['bytes'] / 1e6:,.1f} MB, {tiled['kdtree_nodes']:,} kd-tree nodes in all "
            f"(one kd-tree per tile)")
    kd = d["kdtree"]
    if kd:
        add(f"kd-tree       {kd.get('nodes', 0):,} nodes, {kd.get('leaves', 0):,} leaves "
            f"({kd.get('empty_leaves', 0):,} empty), depth ≤ {kd.get('max_depth')}, "
            f"{kd.get('mean_leaf_triangles', 0):.2f} triangles/leaf, duplication "
            f"{kd.get('duplication', 0):.2f}, {kd.get('time_splits', 0)} time splits, "
            f"SAH {kd.get('sah_cost', 0):.1f}, built in {kd.get('build_s', 0):.2f} s")
    if d.get("verified"):
        v = d["verified"]
        add(f"verified      all {v['arrays']} arrays match their checksums "
            f"({v['bytes'] / 1e6:,.1f} MB in {v['seconds']:.2f} s)")
    for w in d["warnings"]:
        add(f"warning       {w}")
    return "\n".join(lines)


@click.command("info", cls=GroupedCommand)
@click.argument("file", type=click.Path(path_type=Path))
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object.")
@click.option("--verify", is_flag=True,
              help="Check every array of a .cityshade file against its checksum (one pass over "
                   "the file); loads otherwise trust a verified stamp (docs/SCALE.md).")
@crs_option
def info(file: Path, as_json: bool, crs: str | None, verify: bool) -> None:
    """Describe FILE: objects by type, triangles, skipped polygons by reason, LoDs, time range
    and its source, CRS, origin, bounding box, materials, textures and the kd-tree.

    FILE is a .cityshade file; a CityGML, CityJSON or CityJSONSeq file is read and described
    without writing anything.
    """
    from cityshade.store.cache import is_cache_file
    from cityshade.cli.options import settings_for_source
    from cityshade.errors import InputError
    if file.is_dir():  # a tiled cache (or a folder that is not one: said in one line)
        import time

        from cityshade.store.tiled import open_tiled

        tiled = open_tiled(file)
        d = describe_tiled(tiled)
        if verify:
            t0 = time.perf_counter()
            tiled.verify()
            d["verified"] = {"arrays": sum(len(tiled.tile(i).header["arrays"])
                                           for i in range(len(tiled.tiles))),
                             "bytes": d["tiled"]["bytes"],
                             "seconds": round(time.perf_counter() - t0, 3)}
        click.echo(json.dumps(d, indent=2, sort_keys=False) if as_json else _text(d))
        return
    if not file.is_file():
        raise InputError("no such file", path=str(file))
    settings = settings_for_source(file, crs)
    checked = None
    if is_cache_file(file):
        import time

        from cityshade.store.scenefile import load_scene

        t0 = time.perf_counter()
        scene = load_scene(file, verify=True if verify else "auto")
        if verify:
            arrays = scene.header.get("arrays", {})
            checked = {"arrays": len(arrays), "bytes": sum(a["nbytes"] for a in arrays.values()),
                       "seconds": round(time.perf_counter() - t0, 3)}
    else:
        if verify:
            from cityshade.errors import UsageError

            raise UsageError(f"--verify checks a .cityshade file; {file} is a city model")
        from cityshade.build import build_scene_from_file

        scene = build_scene_from_file(file, settings)
    d = describe(scene, settings.vegetation if settings is not None else None)
    if checked:
        d["verified"] = checked
    if as_json:
        click.echo(json.dumps(d, indent=2, sort_keys=False))
    else:
        click.echo(_text(d))
