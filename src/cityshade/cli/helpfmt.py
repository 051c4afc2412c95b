"""``--help`` a person can read: every command's options under the same headings, in the same
order, and a few examples at the end.

Plain click (no extension): :class:`GroupedCommand` formats the options by :data:`SECTIONS`,
keyed by the parameter's name, so an option shared by several commands sits under the same
heading in each; an option no section names lands under "Other options" (a test keeps that
list empty); ``--help`` comes last. :data:`EXAMPLES` holds each command's examples (a test parses every one).
"""
from __future__ import annotations

import click

#: Heading → parameter names (click's ``param.name``), in help order.
SECTIONS: dict[str, tuple[str, ...]] = {
    "City state": ("city_date", "before_text", "after_text", "proposal",
                   "mesh_units", "up_axis", "place_text", "trees", "trees_crs",
                   "lod", "theme", "time_source", "time_attribute", "closure_surfaces"),
    "Sun and time": ("date_text", "instant_date", "time_text", "tz", "sun_azimuth",
                     "sun_elevation", "from_text",
                     "to_text", "every_text", "days", "to_date_text", "from_date", "to_date", "year", "days_text",
                     "times_text", "every_day", "times", "sun_text",
                     "no_refraction"),
    "Weather and sky": ("weather_file", "weather", "svf", "vsc", "season", "irradiance", "sky_name", "sky_model",
                        "albedo"),
    "Place": ("crs", "axis_order"),
    "Camera and extent": ("camera", "eye", "target", "fov", "size", "pixel_size", "cameras_file",
                          "views", "bbox", "margin_m", "extent_text", "ground", "no_sky"),
    "Shadows": ("technique", "no_vegetation", "tree_transmissivity", "smooth", "map_px", "bias", "slope_bias", "max_bias",
                "pcf_kernel", "vsm_blur", "cascades", "sizes"),
    "Receivers and rules": ("surfaces", "no_surfaces", "samples_per_m2", "min_stretch_text",
                            "rule_files", "area_text"),
    "Outputs": ("column", "range_text", "unit", "ply", "output", "exr_precision", "outdir", "png", "mask", "geotiff", "decorate", "no_decorate", "no_gis",
                "frames", "monthly", "as_json", "overwrite", "tile_m", "no_map"),
    "Execution": ("tile_px", "scheduler", "strip_rows", "repeat", "stress", "quick", "verify",
                  "config_path", "verbose", "quiet"),
}

#: Command → example lines for the end of its help.
EXAMPLES: dict[str, tuple[str, ...]] = {
    "build": (
        "cityshade build city.gml                        # writes city.cityshade",
        "cityshade build tiles/ -o city.cityshade --crs EPSG:25832",
        "cityshade build city.gml -o city.cityshade --tile-m 500   # a tiled cache",
    ),
    "info": (
        "cityshade info city.gml",
        "cityshade info city.cityshade --json --verify",
    ),
    "render": (
        "cityshade render city.cityshade --date 1850 --sun-azimuth 135 --sun-elevation 30 "
        "-o a.exr --png a.png",
        "cityshade render city.cityshade --date 2025-06-21 --time 15:00 --tz Europe/Berlin "
        "--camera map --pixel-size 0.5 -o m.exr --mask m.png --geotiff m.tif --decorate",
        "cityshade render city.cityshade --city-date 1990 --date 2025-06-21 --time 15:00 "
        "--tz Europe/Berlin --png then.png    # the city of 1990 in a 2025 sun; no EXR",
    ),
    "batch": (
        "cityshade batch city.cityshade --date 2025-06-21 --from 05:00 --to 21:00 "
        "--every 10min --tz Europe/Berlin --surfaces -o sunhours",
        "cityshade batch city.cityshade --date 2025-01-01 --to-date 2025-12-31 --every-day 7 "
        "--every 1h --tz Europe/Berlin --tile-px 512 --monthly -o year",
    ),
    "compare": (
        "cityshade compare city.cityshade --with proposal.gml --date 2025-03-21 "
        "--tz Europe/London --rules bre209 -o planning",
        "cityshade compare city.cityshade --before 1850 --after 1990 --date 2025-03-21 "
        "--tz Europe/Berlin -o since1850",
        "cityshade compare house.cityshade --with block.gml --date 2025-03-21 --tz Europe/Berlin "
        "--rules bre209 --weather london.epw -o planning    # VSC and APSH of every window",
        "cityshade compare city.cityshade --with massing.obj --up-axis y --place 690120,5336110,,20 "
        "--date 2025-03-21 --tz Europe/Berlin -o planning",
    ),
    "sky": (
        "cityshade sky city.cityshade --pixel-size 1 -o svf          # sky view factor map",
        "cityshade sky city.cityshade --pixel-size 1 --vsc --surfaces -o vsc  # VSC map, walls",
        "cityshade sky city.cityshade --surfaces --no-map -o svf      # per roof, wall, building",
        "cityshade sky city.cityshade --surfaces --weather london.epw --irradiance -o solar",
        "cityshade sky trees.cityshade --pixel-size 1 --season leaf-off -o winter  # crowns leafless",
        "cityshade sky city.cityshade --weather london.epw --date 2025-06-21 --times 09:00,12:00 "
        "--tz Europe/London -o noon      # W/m² at instants",
        "cityshade sky city.cityshade --pixel-size 1 --tile-px 512 --scheduler local:2 -o svf  "
        "# tiled, on Dask; again after Ctrl-C: resumes",
    ),
    "export": (
        "cityshade export city.cityshade sunhours/surfaces.csv -o sunhours.glb",
        "cityshade export city.cityshade planning/surfaces.csv --column loss_h -o loss.glb "
        "--ply loss.ply",
    ),
    "study": (
        "cityshade study city.cityshade --with proposal.gml --area 690110,5336122,690140,5336131 "
        "--year 2025 --tz Europe/Berlin -o study",
        "cityshade study city.cityshade --before 1750 --after 1990 --times 09:00,12:00,15:00 "
        "--tz local-apparent -o study1750",
        "cityshade study city.cityshade --with proposal.gml --city-date 2024 --year 2025 "
        "--tz Europe/Berlin -o study2024",
    ),
    "evaluate": (
        "cityshade evaluate city.cityshade --views overview,map --sun \"135,45;240,15\" "
        "--shadows all -o report",
        "cityshade evaluate city.cityshade --stress --quick",
    ),
}

_SECTION_OF = {name: heading for heading, names in SECTIONS.items() for name in names}


class GroupedCommand(click.Command):
    """A click command whose help lists its options by :data:`SECTIONS` and ends with its
    :data:`EXAMPLES`."""

    def format_options(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        groups: dict[str, list[tuple[str, str]]] = {heading: [] for heading in SECTIONS}
        groups["Other options"] = []
        help_rows = []
        for param in self.get_params(ctx):
            record = param.get_help_record(ctx) if isinstance(param, click.Option) else None
            if record is None:
                continue
            if param is self.get_help_option(ctx):
                help_rows.append(record)
            else:
                groups[_SECTION_OF.get(param.name, "Other options")].append(record)
        groups["Help"] = help_rows
        for heading, rows in groups.items():
            if rows:
                with formatter.section(heading):
                    formatter.write_dl(rows)

    def format_epilog(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        super().format_epilog(ctx, formatter)
        lines = EXAMPLES.get(self.name or "", ())
        if lines:
            with formatter.section("Examples"):
                for line in lines:      # unwrapped: a command is copied whole
                    formatter.write(f"{' ' * formatter.current_indent}{line}\n")
