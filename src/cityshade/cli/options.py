"""Options shared by several commands, progress display, and the error translation."""
from __future__ import annotations

import contextlib
import sys
import time

import click

from cityshade.errors import CityshadeError, ContractError


class LibraryFailure(click.ClickException):
    """A library error shown as one line, ``cityshade: error: ...``, with its exit status."""

    def __init__(self, message: str, exit_code: int = 1):
        super().__init__(message)
        self.exit_code = exit_code

    def show(self, file=None) -> None:
        click.echo(f"cityshade: error: {self.message}", err=True)


@contextlib.contextmanager
def translate_errors(verbose: bool = False):
    """Turn every failure into one line and an exit status, never a traceback.

    A :class:`~cityshade.errors.ContractError` is a bug, not a user error: "internal error"
    and exit status 70, with the traceback on stderr only when ``verbose`` (``-v``).
    """
    try:
        yield
    except CityshadeError as exc:
        raise LibraryFailure(str(exc), exc.exit_code) from None
    except ContractError as exc:
        if verbose:
            import traceback

            traceback.print_exc(file=sys.stderr)
        raise LibraryFailure(f"internal error: {exc}", ContractError.exit_code) from None
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


# --- settings and shadow options shared by render, batch and evaluate --------------------------

#: The shadow flags of every command: click parameter name → ShadowSettings.override name.
_SHADOW_FLAGS = ("map_px", "bias", "slope_bias", "max_bias", "pcf_kernel", "vsm_blur",
                 "cascades")


def config_option(func):
    """``--config FILE``: the TOML settings tree (:mod:`cityshade.config`)."""
    return click.option("--config", "config_path", type=click.Path(dir_okay=False),
                        help="TOML settings file ([shadows], [sun], [batch], [evaluate], "
                             "...; configs/default.toml lists them). Flags override it.")(func)


def load_config(config_path):
    """The settings tree of ``--config`` (defaults without one)."""
    from cityshade.config import Settings, load_settings

    return load_settings(config_path) if config_path else Settings()


def shadow_options(default_technique: str, *, technique_help: str | None = None,
                   map_px: bool = True):
    """Decorator adding ``--config``, ``--shadows``, ``--smooth`` and the shadow tunables
    (``--map-px``, ``--bias``, ...). The command receives one ``settings`` argument: the
    :class:`~cityshade.config.Settings` of ``--config`` with the flags applied, its
    ``shadows.technique`` resolved (flag, else the file's ``[shadows] technique``, else
    ``default_technique``; ``--smooth`` appends ``+smooth``)."""
    import functools

    from cityshade.shadows import names_help

    def decorate(func):
        @functools.wraps(func)
        def wrapper(*args, **kwargs):
            import dataclasses

            settings = load_config(kwargs.pop("config_path"))
            technique = kwargs.pop("technique") or settings.shadows.technique \
                or default_technique
            if kwargs.pop("smooth") and not technique.endswith("+smooth"):
                technique += "+smooth"
            flags = {k: kwargs.pop(k, None) for k in _SHADOW_FLAGS}
            shadows = dataclasses.replace(settings.shadows.override(**flags),
                                          technique=technique)
            kwargs["settings"] = dataclasses.replace(settings, shadows=shadows)
            return func(*args, **kwargs)

        options = [
            click.option("--shadows", "technique",
                         help=technique_help or f"Shadow technique (default "
                         f"{default_technique}): {names_help()}."),
            click.option("--smooth", is_flag=True, help="Depth-aware screen-space smoothing of "
                         "the shadow (same as --shadows NAME+smooth)."),
            *([click.option("--map-px", type=click.IntRange(16, 16384),
                            help="Shadow-map side in texels (map techniques; default 2048).")]
              if map_px else []),
            click.option("--bias", type=click.FloatRange(min=0),
                         help="Constant depth bias in metres."),
            click.option("--slope-bias", type=click.FloatRange(min=0),
                         help="Slope-scaled bias (texels)."),
            click.option("--max-bias", type=click.FloatRange(min=0),
                         help="Largest slope bias in metres."),
            click.option("--pcf-kernel", type=click.IntRange(1, 63), help="PCF kernel side (odd)."),
            click.option("--vsm-blur", type=click.IntRange(0, 64),
                         help="VSM filter radius in texels."),
            click.option("--cascades", type=click.IntRange(1, 16),
                         help="CSM cascade count (default 4)."),
        ]
        for option in reversed(options):
            wrapper = option(wrapper)
        return config_option(wrapper)
    return decorate


# --- camera options shared by render, batch and evaluate ---------------------------------------

def camera_options(default_camera: str):
    """Decorator adding --camera, --eye, --target, --fov, --size, --pixel-size and
    --cameras."""
    def decorate(func):
        for option in reversed([
            click.option("--camera", default=default_camera, show_default=True,
                         help="overview, map, or a preset of configs/cameras.toml or of "
                              "--cameras."),
            click.option("--eye", help="Camera position X,Y,Z in the model CRS (metres); "
                         "with --target."),
            click.option("--target", help="Point looked at, X,Y,Z in the model CRS (metres)."),
            click.option("--fov", type=click.FloatRange(1, 170), default=45.0, show_default=True,
                         help="Vertical field of view in degrees (perspective)."),
            click.option("--size", default="1280x720", show_default=True,
                         help="WIDTHxHEIGHT (perspective)."),
            click.option("--pixel-size", type=click.FloatRange(min=1e-3),
                         help="Metres per pixel of the map view (default: fits 2048 px)."),
            click.option("--cameras", "cameras_file", type=click.Path(dir_okay=False),
                         help="TOML file of more camera presets (same tables as "
                              "configs/cameras.toml), added to the built-in ones."),
        ]):
            func = option(func)
        return func
    return decorate


def parse_triple(text: str | None, what: str):
    """'X,Y,Z' → [x, y, z] (None stays None)."""
    if text is None:
        return None
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != 3:
        raise click.BadParameter(f"{what} must be X,Y,Z in metres, e.g. 690100,5336000,600")
    return values


def parse_size(text: str) -> tuple[int, int]:
    """'WIDTHxHEIGHT' → (width, height) in pixels."""
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise click.BadParameter(f"--size must be WIDTHxHEIGHT, e.g. 1280x720, not {text!r}")
    if not (1 <= w <= 16384 and 1 <= h <= 16384):
        raise click.BadParameter("--size must be between 1x1 and 16384x16384 pixels")
    return w, h


def make_camera(scene, name, eye, target, fov, size, pixel_size, cameras_file=None):
    """The camera the shared options describe (eye/target in model CRS coordinates)."""
    import numpy as np

    from cityshade.errors import UsageError
    from cityshade.raster import camera as cams

    eye_v, target_v = parse_triple(eye, "--eye"), parse_triple(target, "--target")
    if (eye_v is None) != (target_v is None):
        raise UsageError("give both --eye and --target, or neither")
    width, height = parse_size(size)
    if eye_v is not None:
        return cams.perspective(np.asarray(eye_v) - scene.origin_m,
                                np.asarray(target_v) - scene.origin_m, vfov_deg=fov,
                                width_px=width, height_px=height, scene=scene)
    if name == "overview":
        return cams.overview(scene, width, height)
    if name == "map":
        return cams.map_view(scene, pixel_size)
    return cams.preset(name, scene, width, height, extra=cameras_file)
