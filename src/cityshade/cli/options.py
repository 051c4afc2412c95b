"""Options shared by several commands, progress display, and the error translation."""
from __future__ import annotations

import contextlib
import sys
import time

import click

from cityshade.errors import CityshadeError


class LibraryFailure(click.ClickException):
    """A library error shown as one line, ``cityshade: error: ...``, with its exit status."""

    def __init__(self, message: str, exit_code: int = 1):
        super().__init__(message)
        self.exit_code = exit_code

    def show(self, file=None) -> None:
        click.echo(f"cityshade: error: {self.message}", err=True)


@contextlib.contextmanager
def translate_errors():
    """Turn every failure into one line and an exit status, never a traceback."""
    try:
        yield
    except CityshadeError as exc:
        raise LibraryFailure(str(exc), exc.exit_code) from None
    except KeyboardInterrupt:
        raise click.Abort() from None
    except OSError as exc:
        where = f"{exc.filename}: " if getattr(exc, "filename", None) else ""
        raise LibraryFailure(f"{where}{exc.strerror or exc}") from None
    except MemoryError:
        raise LibraryFailure("out of memory") from None


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
