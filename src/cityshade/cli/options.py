"""Options shared by several commands, progress display, and the error translation."""
from __future__ import annotations

import sys
import time

import click

from cityshade.errors import CityshadeError


def run_cli(group: click.Group, argv: list[str] | None) -> int:
    """Run ``group``; every failure is one line on stderr and an exit status, never a traceback."""
    try:
        group.main(args=argv, prog_name="cityshade", standalone_mode=False)
    except click.exceptions.Abort:
        click.echo("cityshade: interrupted", err=True)
        return 130
    except click.ClickException as exc:
        exc.show()
        return exc.exit_code
    except click.exceptions.Exit as exc:
        return exc.exit_code
    except CityshadeError as exc:
        click.echo(f"cityshade: error: {exc}", err=True)
        return exc.exit_code
    except KeyboardInterrupt:
        click.echo("cityshade: interrupted", err=True)
        return 130
    except OSError as exc:
        where = f"{exc.filename}: " if getattr(exc, "filename", None) else ""
        click.echo(f"cityshade: error: {where}{exc.strerror or exc}", err=True)
        return 1
    except MemoryError:
        click.echo("cityshade: error: out of memory", err=True)
        return 1
    return 0


def fail_on_library_error(func):
    """For CliRunner and API use of a command object: same translation as :func:`run_cli`."""
    return func


class Progress:
    """A one-line progress display on a terminal's stderr (silent otherwise or with --quiet)."""

    def __init__(self, enabled: bool | None = None):
        self.enabled = sys.stderr.isatty() if enabled is None else enabled
        self.t0 = time.perf_counter()
        self.last = 0.0
        self.stage = None

    def __call__(self, stage: str, done: int, total: int) -> None:
        if not self.enabled:
            return
        now = time.perf_counter()
        if stage == self.stage and now - self.last < 0.1 and done < total:
            return
        self.stage, self.last = stage, now
        if stage == "read" and total:
            rate = done / max(now - self.t0, 1e-9) / 1e6
            text = f"reading {100 * done / total:5.1f}%  {rate:6.1f} MB/s"
        else:
            text = f"{stage}..."
        sys.stderr.write("\r\033[K" + text)
        sys.stderr.flush()

    def close(self) -> None:
        if self.enabled and self.stage is not None:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()
