"""``cityshade build CITY``: write the .cityshade scene file (CityGML or CityJSON input)."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand
from cityshade.cli.options import (
    AXIS_ORDER_HELP,
    CRS_HELP,
    TIME_ATTRIBUTE_HELP,
    TREES_CRS_HELP,
    TREES_HELP,
)
from cityshade.config import AXIS_ORDERS, CLOSURE_SURFACES, TIME_SOURCES


def _lod_option(ctx, param, value: str | None) -> int | float | None:
    """``--lod 2`` → 2; ``--lod 2.2`` → 2.2 (CityJSON's refined LoDs)."""
    if value is None:
        return None
    text = value.strip()
    whole, dot, tenth = text.partition(".")
    if not (len(whole) == 1 and whole in "01234" and (not dot or (len(tenth) == 1
                                                                   and tenth.isdigit()))):
        raise click.BadParameter(f"{value} is not in the range 0 to 4 (whole LoDs; CityJSON "
                                 f"also has refined ones such as 2.2)")
    return float(text) if dot else int(whole)


@click.command("build", cls=GroupedCommand)
@click.argument("city", nargs=-1, required=True, type=click.Path(path_type=Path))
@click.option("-o", "--output", type=click.Path(path_type=Path),
              help="Output file (default for one CITY file: CITY with suffix .cityshade; "
                   "needed for several files or a folder); with --tile-m a folder.")
@click.option("--tile-m", type=float, metavar="SIDE",
              help="Write a tiled cache: a folder of tile caches of SIDE × SIDE CRS metres "
                   "(each object in the tile of its building's box centre, each tile with its "
                   "own kd-tree) and an index.json; render, batch and info read it like a "
                   "file, mapping only the tiles they reach.")
@click.option("--lod", callback=_lod_option, metavar="LOD",
              help="LoD to take from every object: 0-4, or a CityJSON LoD such as 2.2 "
                   "(default: the highest each object has).")
@click.option("--theme", help="Appearance theme (default: the one with the most surfaces).")
@click.option("--crs", help=CRS_HELP + " With several files: the projected CRS every file is "
                                      "projected to (a file without a known CRS is taken to be "
                                      "in it); without it the files must share one CRS.")
@click.option("--axis-order", type=click.Choice(AXIS_ORDERS), help=AXIS_ORDER_HELP)
@click.option("--time-source", type=click.Choice(TIME_SOURCES), default="auto", show_default=True,
              help="Where object validity intervals come from: auto = validFrom/validTo, else "
                   "construction/demolition, else --time-attribute; creation = the database "
                   "dates creationDate/terminationDate (only when asked for).")
@click.option("--time-attribute", help=TIME_ATTRIBUTE_HELP)
@click.option("--closure-surfaces", type=click.Choice(CLOSURE_SURFACES),
              help="ClosureSurfaces are virtual (they close a solid between building parts or "
                   "across a passage): omit (the default, [build] closure_surfaces) leaves them "
                   "out, so they neither cast nor receive; keep draws them like walls.")
@click.option("--trees", type=click.Path(dir_okay=False, path_type=Path), metavar="REGISTER",
              help=TREES_HELP)
@click.option("--trees-crs", metavar="CRS", help=TREES_CRS_HELP)
@click.option("--config", "config_path", type=click.Path(dir_okay=False, path_type=Path),
              help="TOML settings file ([build], [kdtree], [trees] tables).")
@click.option("-q", "--quiet", is_flag=True, help="No progress display and no summary.")
def build(city: tuple[Path, ...], output: Path | None, lod: int | float | None, theme: str | None,
          crs: str | None, axis_order: str | None, time_source: str, time_attribute: str | None,
          config_path: Path | None, quiet: bool, tile_m: float | None,
          closure_surfaces: str | None, trees: Path | None, trees_crs: str | None) -> None:
    """Read CITY (CityGML 1.0/2.0/3.0, CityJSON 1.0/1.1/2.0 or CityJSONSeq, told apart by
    the content), triangulate it, build its kd-tree, and write one versioned,
    memory-mappable .cityshade file.

    Several files or folders (tiles, CityGML and CityJSON mixed) become one city: one origin
    and CRS, an object whose gml:id an earlier file had is kept once and counted, and the
    files are read one at a time."""
    import dataclasses

    from cityshade.build import build_file, default_output
    from cityshade.cli.options import Progress
    from cityshade.config import Settings, load_settings
    from cityshade.errors import UsageError

    settings = load_settings(config_path) if config_path else Settings()
    overrides = {k: v for k, v in (("lod", lod), ("theme", theme), ("crs", crs),
                                   ("axis_order", axis_order), ("time_attribute", time_attribute),
                                   ("closure_surfaces", closure_surfaces))
                 if v is not None}
    if time_source != "auto":
        overrides["time_source"] = time_source
    settings = dataclasses.replace(settings, build=dataclasses.replace(settings.build, **overrides))
    from cityshade.build import expand_sources

    sources = expand_sources(city)
    several = len(sources) > 1 or any(c.is_dir() for c in city)
    if output is None:
        if several:
            raise UsageError("several input files (or a folder) need -o OUT.cityshade")
        output = default_output(sources[0])
    if any(output.resolve() == s.resolve() for s in sources):
        raise UsageError("the output would overwrite the input file; choose another -o")
    if tile_m is not None and not (tile_m > 0 and tile_m < float("inf")):
        raise UsageError(f"--tile-m must be a positive number of metres, not {tile_m:g}")
    extend = _trees_extension(trees, trees_crs, settings, tile_m)
    if tile_m is None and output.is_dir():
        raise UsageError(f"{output} is a folder: give a file name with -o, or --tile-m SIDE "
                         f"for a tiled cache")
    from cityshade.util import check_outputs, plural

    # Before the work: a folder where no file can be made fails now, not after the build.
    check_outputs(("-o", output, None if tile_m is not None else (output.suffix.lower(),)))
    progress = Progress(enabled=None if not quiet else False, files=several and not quiet)
    try:
        out, scene, size = build_file(list(city) if several else sources[0], output, settings,
                                      progress, tile_m=tile_m, extend=extend)
    finally:
        progress.close()
    for warning in scene.report.get("warnings", []):
        click.echo(f"cityshade: warning: {warning}", err=True)
    if not quiet:
        rep = scene.report
        skipped = sum(rep["skipped"].values())
        click.echo(f"{out}: {plural(scene.n_triangles, 'triangle')} from "
                   f"{plural(rep['polygons']['drawn'], 'polygon')} of "
                   f"{plural(len(scene.obj_ids), 'object')}"
                   f"{', ' + plural(skipped, 'polygon') + ' skipped' if skipped else ''}; "
                   f"{size / 1e6:.1f} MB in {sum(rep.get('timings', {}).values()):.2f} s"
                   f"{_tiles_note(out, scene) if tile_m else ''}")
        if "trees" in rep:
            t = rep["trees"]
            left = ", ".join(f"{v} {k.replace('_', ' ')}" for k, v in t["skipped"].items())
            click.echo(f"{t['trees']:,} trees from {trees.name} ({t['crs']}; standing on the "
                       f"{t['ground']}){f'; left out: {left}' if left else ''}")
        tiles = rep.get("tiles")
        if tiles:
            click.echo(f"{plural(tiles['files'], 'file')}; "
                       f"{plural(tiles['duplicate_objects'], 'object')} met "
                       f"again in a later file (the same gml:id) kept once")


def _trees_extension(trees: Path | None, trees_crs: str | None, settings, tile_m):
    """The build's ``extend`` step adding a register's trees (None without ``--trees``)."""
    from cityshade.errors import UsageError

    if trees is None:
        if trees_crs is not None:
            raise UsageError("--trees-crs needs --trees REGISTER")
        return None
    if tile_m is not None:
        raise UsageError("--trees cannot go with --tile-m (a tiled cache): build the trees "
                         "into one file")
    if not trees.is_file():
        raise UsageError(f"--trees {trees}: no such file")
    import functools

    from cityshade.meshes.trees import add_trees

    return functools.partial(add_trees, path=trees, settings=settings.trees, crs_text=trees_crs)


def _tiles_note(folder: Path, scene) -> str:
    from cityshade.build.tiled import TiledBuild
    from cityshade.store.tiled import open_tiled

    n = len(open_tiled(folder).tiles)
    if isinstance(scene, TiledBuild):  # several files: the timings cover the tiles too
        return f" (read, spilled to tiles, {n} tiles built)"
    return f" (read and assembly; then {n} tiles)"
