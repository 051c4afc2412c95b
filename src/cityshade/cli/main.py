"""The ``cityshade`` command: a click group whose subcommands are imported only when run.

``cityshade --help`` therefore imports nothing heavy (no numba, lxml, pyproj, OpenImageIO).
Library errors (:class:`~cityshade.errors.CityshadeError`) become one line on stderr and a
non-zero exit status here, and only here.
"""
from __future__ import annotations

import importlib
import sys

import click

from cityshade import __version__

#: Subcommand name → "module:function"; the module is imported when the command runs.
COMMANDS = {
    "build": ("cityshade.cli.build:build", "Build the .cityshade scene file of a CityGML or CityJSON model."),
    "info": ("cityshade.cli.info:info", "Describe a .cityshade file (or a CityGML file)."),
    "render": ("cityshade.cli.render:render", "Render a picture and shadow mask at a date and sun."),
    "batch": ("cityshade.cli.batch:batch", "Sun-hour maps and per-surface sun-hours over times."),
    "compare": ("cityshade.cli.compare:compare", "Sun-hours before and after a change; rules."),
    "sky": ("cityshade.cli.sky:sky", "Sky view factor and irradiation (kWh/m²) from weather."),
    "study": ("cityshade.cli.study:study", "Shadow-study sheets: existing and new shadow by hour."),
    "evaluate": ("cityshade.cli.evaluate:evaluate", "Shadow error against run time; the stress set."),
    "export": ("cityshade.cli.export:export", "A scene coloured by a surfaces.csv column as .glb/.ply."),
}


def first_compile_line(command: str, processes: int, stream=None) -> None:
    """On a terminal, say why the first use of a command waits (its kernels compiling)."""
    stream = stream or sys.stderr
    if processes and stream.isatty():
        # From the line's start, cleared: a progress line may be on it (the wait begins at
        # the command's first compile, mid-work); the progress repaints below.
        stream.write(f"\r\033[Kcityshade: first use of {command}: compiling its kernels once "
                     f"({processes} processes)\n")
        stream.flush()


class LazyGroup(click.Group):
    def parse_args(self, ctx, args):
        # -v of any subcommand also shows the traceback of an internal error.
        ctx.meta["cityshade.verbose"] = any(a in ("-v", "--verbose") for a in args)
        return super().parse_args(ctx, args)

    def invoke(self, ctx):
        from cityshade.cli.options import translate_errors
        from cityshade.runtime import prewarm
        from cityshade.util import folders_made, remove_folders_made

        # A command that fails (or is interrupted) leaves none of the folders it created for
        # its outputs, e.g. the -o folder check_outputs makes before the work.
        mark = folders_made()
        try:
            with translate_errors(verbose=ctx.meta.get("cityshade.verbose", False)):
                return super().invoke(ctx)
        except click.exceptions.Exit as exc:
            if exc.exit_code:
                remove_folders_made(mark)
            raise
        except BaseException:
            remove_folders_made(mark)
            raise
        finally:
            prewarm.stop()  # children still compiling when the command ended early

    def resolve_command(self, ctx, args):
        # A misspelled command: "did you mean" the nearest name (click says only "No such
        # command").
        name = click.utils.make_str(args[0]) if args else ""
        if args and name not in COMMANDS and not name.startswith("-"):
            import difflib

            close = difflib.get_close_matches(name, list(COMMANDS), n=1, cutoff=0.6)
            hint = (f"did you mean '{close[0]}'?" if close
                    else f"the commands are {', '.join(COMMANDS)}")
            raise click.UsageError(f"no command '{name}'; {hint}", ctx)
        if name in COMMANDS and not {"-h", "--help"} & set(args):
            # On a command's first use its kernels compile in parallel while it reads its
            # input (the first compile waits for them, and only then is the terminal told):
            # see cityshade.runtime.prewarm.
            from cityshade.cli.options import interrupt_seen
            from cityshade.runtime import prewarm

            prewarm.start(name, should_stop=interrupt_seen,
                          on_wait=lambda processes: first_compile_line(name, processes))
        return super().resolve_command(ctx, args)

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
    """cityshade: exact, fast shadow pictures and shadow data from CityGML and CityJSON city
    models.

    \b
    Typical use (every command; COMMAND --help for its options):
      cityshade build city.gml            # writes city.cityshade
      cityshade info city.cityshade       # what is in it
      cityshade render city.cityshade --date 1850 --sun-azimuth 135 --sun-elevation 30 -o a.exr
      cityshade batch city.cityshade --date 2024-06-21 --from 05:00 --to 21:00 --every 10min \\
          --tz Europe/Berlin --camera map -o sunhours/
      cityshade compare city.cityshade --with proposal.gml --date 2025-03-21 \\
          --tz Europe/London --rules bre209 -o planning/
      cityshade study city.cityshade --with proposal.gml --tz Europe/London -o study/
      cityshade sky city.cityshade --surfaces --weather london.epw --irradiance -o solar/
      cityshade export city.cityshade solar/surfaces.csv -o solar.glb
      cityshade evaluate city.cityshade --shadows all -o report/
    """


def main(argv: list[str] | None = None, *, own_process: bool = False) -> None:
    """Console-script entry point (``cityshade`` and ``python -m cityshade``, which pass
    ``own_process``: the process ends with the command).

    Ctrl-C at any moment ends with one line, ``cityshade: interrupted``, and exit status 130:
    inside a command :func:`~cityshade.cli.options.translate_errors` says so; while click
    parses the arguments its own "Aborted!" is replaced here. A signal after the command has
    ended is ignored: the status is the command's.
    """
    import signal
    import sys

    from cityshade.cli.options import (Interrupted, command_done, install_sigint_handler,
                                       terminate_is_ours)

    install_sigint_handler()
    try:
        status = _command(argv)
        command_done()
    except KeyboardInterrupt:
        # The signal came in the last moments of the command, in its own error report.
        command_done()
        stop = Interrupted()
        stop.show()
        status = stop.exit_code
    finally:
        command_done()
        # The interpreter's shutdown resets handlers to the default, which would kill the
        # process on a late Ctrl-C (status -2 instead of ours); an ignored SIGINT stays ignored.
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        if terminate_is_ours():
            # The same for a late SIGTERM (status -15) when the process ends here. Called
            # in-process, it is given back instead: an ignored SIGTERM would be inherited by
            # every process the caller starts later (a test run's Dask workers would not stop).
            signal.signal(signal.SIGTERM, signal.SIG_IGN if own_process else signal.SIG_DFL)
    if status in (130, 143):
        # After a KeyboardInterrupt inside code that a C library ran through PyRun_* the
        # interpreter's epilogue kills itself with SIGINT (status -2, not 130) whatever
        # sys.exit says; everything is written and closed here, so leave without it.
        _leave_now(status)
    if own_process:
        _leave_now(status)
    sys.exit(status)


def _leave_now(status: int) -> None:
    """End the process with ``status`` once the exit handlers have run and the standard
    streams are flushed, without the interpreter's teardown: every output is written and
    closed by then, and tearing down ~860 modules and the LLVM code of every loaded kernel took
    0.15-0.3 s of each warm render (about a tenth of a map render of the 1M city). A live
    non-daemon thread keeps the ordinary exit, which waits for it, and so does a profiler or
    tracer (``python -m cProfile``, pyinstrument: they report after the command returns)."""
    import atexit
    import os
    import sys
    import threading

    from cityshade.runtime.threadpool import shutdown

    shutdown()
    if sys.getprofile() is not None or sys.gettrace() is not None or any(
            t is not threading.main_thread() and t.is_alive() and not t.daemon
            for t in threading.enumerate()):
        sys.exit(status)
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed pipe or stream: nothing left to say there
            pass
    os._exit(status)


def _command(argv: list[str] | None) -> int:
    """Run the command; its exit status, every failure reported in one line."""
    from cityshade.cli.options import Interrupted, interrupt_seen

    try:
        status = cli.main(args=argv, prog_name="cityshade", standalone_mode=False)
        # Without standalone mode click returns the status of --help, --version, ctx.exit().
        status = status if isinstance(status, int) else 0
        if interrupt_seen():
            # A Ctrl-C swallowed by a library (a bare except around an import) still stops.
            raise Interrupted()
    except (KeyboardInterrupt, click.exceptions.Abort):
        stop = Interrupted()
        stop.show()
        status = stop.exit_code
    except click.exceptions.NoArgsIsHelpError as exc:
        exc.show()  # ``cityshade`` alone: the help
        status = exc.exit_code
    except click.UsageError as exc:
        # click's own form is four lines (usage, hint, blank, message): one line, as for
        # every other bad input.
        hint = f" (see '{exc.ctx.command_path} --help')" if exc.ctx is not None else ""
        click.echo(f"cityshade: error: {exc.format_message()}{hint}", err=True)
        status = exc.exit_code
    except click.ClickException as exc:
        exc.show()
        status = exc.exit_code
    except click.exceptions.Exit as exc:
        status = exc.exit_code
    return status
