"""``cityshade export SCENE SURFACES``: the scene coloured by a per-surface result, as .glb/.ply."""
from __future__ import annotations

from pathlib import Path

import click

from cityshade.cli.helpfmt import GroupedCommand


@click.command("export", cls=GroupedCommand)
@click.argument("scene_file", metavar="SCENE", type=click.Path(path_type=Path))
@click.argument("surfaces", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--column", help="The column of SURFACES to show [default: mean_sun_hours, else "
              "hours_after]: any numeric column (loss_h, hours_before, …).")
@click.option("--range", "range_text", metavar="LO,HI",
              help="Ends of the colour scale [default: 0 (or the smallest value) to the "
                   "largest].")
@click.option("--unit", help="Unit of the values in the legend [default: from the column's "
              "name: h for hours, % for _pct].")
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False, path_type=Path),
              help="The binary glTF file (.glb).")
@click.option("--ply", type=click.Path(dir_okay=False, path_type=Path),
              help="Also a PLY file (model-CRS coordinates, colours and _VALUE per vertex).")
def export(scene_file, surfaces, column, range_text, unit, output, ply):
    """Write SCENE (a .cityshade file) coloured by one column of SURFACES (a surfaces.csv of
    batch --surfaces or compare) as binary glTF: viridis vertex colours, the value as the
    vertex attribute _VALUE, the legend, origin and CRS in the asset extras; polygons without
    a value grey. Opens in Blender, three.js or Cesium viewers; trimesh reads it back."""
    from cityshade.meshes.export import ExportRequest, run_export

    request = ExportRequest(scene_file, surfaces, output, column=column,
                            value_range=_range(range_text), unit=unit, ply=ply)
    result = run_export(request)
    click.echo(f"{output}: {result['polygons']:,} polygons coloured by {result['column']} "
               f"({result['range'][0]:g} to {result['range'][1]:g}"
               f"{' ' + result['unit'] if result['unit'] else ''}), "
               f"{result['context_polygons']:,} without a value in grey"
               f"{f'; {ply}' if ply else ''}")


def _range(text):
    from cityshade.errors import UsageError

    if text is None:
        return None
    try:
        lo, hi = (float(v) for v in text.split(","))
    except ValueError:
        raise UsageError(f"--range must be LO,HI, not {text!r}") from None
    return lo, hi
