"""The ``cityshade`` command: a click group whose subcommands are imported only when run.

``cityshade --help`` therefore imports nothing heavy (no numba, lxml, pyproj, OpenImageIO).
Library errors (:class:`~cityshade.errors.CityshadeError`) become one line on stderr and a
non-zero exit status here, and only here.
"""
from __future__ import annotations

import importlib

import click

from cityshade import __version__

#: Subcommand name → "module:function"; the module is imported when the command runs.
COMMANDS = {
    "build": ("cityshade.cli.build:build", "Build the .cityshade scene file of a CityGML model."),
    "info": ("cityshade.cli.info:info", "Describe a .cityshade file (or a CityGML file)."),
    "render": ("cityshade.cli.render:render", "Render a picture and shadow mask at a date and sun."),
    "batch": ("cityshade.cli.batch:batch", "Sun-hour maps and per-surface sun-hours over times."),
    "evaluate": ("cityshade.cli.evaluate:evaluate", "Shadow error against run time; the stress set."),
}


class LazyGroup(click.Group):
    def parse_args(self, ctx, args):
        # -v of any subcommand also shows the traceback of an internal error.
        ctx.meta["cityshade.verbose"] = any(a in ("-v", "--verbose") for a in args)
        return super().parse_args(ctx, args)

    def invoke(self, ctx):
        from cityshade.cli.options import translate_errors

        with translate_errors(verbose=ctx.meta.get("cityshade.verbose", False)):
            return super().invoke(ctx)

    def list_commands(self, ctx):
        return list(COMMANDS)

    def get_command(self, ctx, name):
        entry = COMMANDS.get(name)
        if entry is None:
            return None
        module, func = entry[0].split(":")
        return getattr(importlib.import_module(module), func)

    def format_commands(self, ctx, formatter):
        # Short help without importing every command module.
        rows = [(name, help_text) for name, (_, help_text) in COMMANDS.items()]
        with formatter.section("Commands"):
            formatter.write_dl(rows)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="cityshade")
def cli() -> None:
    """cityshade: exact, fast shadow pictures and shadow data from CityGML city models.

    \b
    Typical use:
      cityshade build city.gml            # writes city.cityshade
      cityshade info city.cityshade       # what is in it
    """


def main(argv: list[str] | None = None) -> None:
    """Console-script entry point (``cityshade`` and ``python -m cityshade``)."""
    cli.main(args=argv, prog_name="cityshade")
