"""Options shared by several commands, progress display, and the error translation."""
from __future__ import annotations

import contextlib
import signal
import sys
import time
from pathlib import Path

import click

from cityshade.errors import CityshadeError, ContractError


class LibraryFailure(click.ClickException):
    """A library error shown as one line, ``cityshade: error: ...``, with its exit status."""

    def __init__(self, message: str, exit_code: int = 1):
        super().__init__(message)
        self.exit_code = exit_code

    def show(self, file=None) -> None:
        click.echo(f"cityshade: error: {self.message}", err=True)


class Interrupted(LibraryFailure):
    """Ctrl-C: ``cityshade: interrupted`` and exit status 130 (128 + SIGINT); a SIGTERM (a job
    scheduler's, ``kill``'s) ends the same way as ``cityshade: terminated`` and 143."""

    def __init__(self):
        terminated = _interrupt["terminated"]
        super().__init__("terminated" if terminated else "interrupted", 143 if terminated else 130)

    def show(self, file=None) -> None:
        click.echo(f"cityshade: {self.message}", err=True)


#: Set by :func:`on_sigint`: every failure after a Ctrl-C is the interrupt's consequence.
#: ``held``: a Ctrl-C that came while Numba compiled, raised when the compile is over.
#: ``raised``: the KeyboardInterrupt is on its way; ``again``: the thread that delivers a
#: Ctrl-C held outside a compile once more (:func:`_deliver_again`) is running.
_interrupt = {"seen": False, "held": False, "listening": False, "raised": False,
              "again": False, "terminated": False, "sigterm_ours": False, "done": False}
#: Seconds between deliveries of a held Ctrl-C: short against a user's patience, long
#: against the few microseconds Numba's wrappers spend in Python code.
REDELIVER_S = 0.005


def on_sigint(signum, frame) -> None:
    """SIGINT handler of the command: raise KeyboardInterrupt once, ignore further Ctrl-Cs so
    the clean-up (temporary files removed, nothing half-written) runs to its end.

    The exception is raised only where Python can unwind it: never inside Numba. Python
    signal handlers run between any two bytecodes, also in Python code that compiled code
    calls (boxing a kernel's typed-list result, typing its arguments), and Numba's wrappers
    do not expect an exception there: they go on with it set and free a half-made result
    (SIGSEGV in ``NRT_MemInfo_release``, or ``SystemError: CPUDispatcher(...) returned a
    result with an exception set``). With Numba on the stack the Ctrl-C is held: during a
    compile until the compiler's current pass ends (:func:`_raise_after_compile`; llvmlite's
    objects are whole then), otherwise it is delivered again every :data:`REDELIVER_S`
    until it lands in code that is not Numba's (:func:`_deliver_again`); so it is while a
    module is being imported (:func:`import_on_stack`)."""
    if _interrupt["raised"] or _interrupt["done"]:
        return  # one KeyboardInterrupt; none once the command has ended (:func:`command_done`)
    _interrupt["seen"] = True
    if _numba_compiling():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        _raise_after_compile()
        return
    if numba_on_stack(frame) or import_on_stack(frame):
        _deliver_again()
        return
    _interrupt["raised"] = True
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    raise KeyboardInterrupt


def on_sigterm(signum, frame) -> None:
    """SIGTERM handler of the command: the clean-up of a Ctrl-C (temporary files and folders
    removed), by way of :func:`on_sigint`; ends with status 143."""
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
    if not _interrupt["seen"] and not _interrupt["done"]:
        _interrupt["terminated"] = True
    on_sigint(signal.SIGINT, frame)


def command_done() -> None:
    """The command has ended and its status is known: a signal from here on is ignored (it
    would raise where nothing catches it, in ``main``'s last lines)."""
    _interrupt["done"] = True


def terminate_is_ours() -> bool:
    """Whether :func:`install_sigint_handler` installed :func:`on_sigterm`."""
    return _interrupt["sigterm_ours"]


def numba_on_stack(frame) -> bool:
    """Whether ``frame`` or a frame it was called from is Numba's or llvmlite's Python code
    (without importing them: not imported, not on the stack)."""
    import os

    roots = tuple(os.path.dirname(module.__file__) + os.sep for name in ("numba", "llvmlite")
                  if (module := sys.modules.get(name)) is not None
                  and getattr(module, "__file__", None))
    return _on_stack(frame, roots)


def _on_stack(frame, prefixes: tuple[str, ...]) -> bool:
    """Whether ``frame`` or a frame it was called from runs code of a file named with one of
    ``prefixes``."""
    while prefixes and frame is not None:
        if frame.f_code.co_filename.startswith(prefixes):
            return True
        frame = frame.f_back
    return False


def import_on_stack(frame) -> bool:
    """Whether ``frame`` or a frame it was called from is importing a module: an exception
    raised there leaves the module half made, and an extension module's own start-up may not
    survive it (OpenImageIO's, imported when the first texture is read: "Critical nanobind
    error", the process aborted with a traceback)."""
    return _on_stack(frame, ("<frozen importlib._bootstrap",))


def _deliver_again() -> None:
    """Send SIGINT to the main thread every :data:`REDELIVER_S` until :func:`on_sigint` has
    raised it (a daemon thread: it ends with the process)."""
    import threading

    if _interrupt["again"]:
        return
    _interrupt["again"] = True
    main = threading.main_thread().ident

    def again() -> None:
        while not _interrupt["raised"]:
            time.sleep(REDELIVER_S)
            if not _interrupt["raised"]:
                signal.pthread_kill(main, signal.SIGINT)
        _interrupt["again"] = False

    threading.Thread(target=again, name="cityshade-ctrl-c", daemon=True).start()


def _numba_compiling() -> bool:
    """Whether this thread holds Numba's compiler lock (not importing Numba to find out)."""
    lock = sys.modules.get("numba.core.compiler_lock")
    return lock is not None and lock.global_compiler_lock.is_locked()


def _raise_after_compile() -> None:
    """Raise KeyboardInterrupt in the main thread at the end of Numba's current compiler pass
    (its ``numba:run_pass`` event) or when its compiler lock is released: between passes the
    compiler is plain Python and no llvmlite object is half made."""
    import threading

    from numba.core import event

    class AfterPass(event.Listener):
        def on_start(self, ev) -> None:
            pass

        def on_end(self, ev) -> None:
            if _interrupt["held"] and threading.current_thread() is threading.main_thread():
                _interrupt["held"] = False
                _interrupt["raised"] = True
                raise KeyboardInterrupt

    _interrupt["held"] = True
    if not _interrupt["listening"]:
        listener = AfterPass()
        event.register("numba:run_pass", listener)
        event.register("numba:compiler_lock", listener)
        _interrupt["listening"] = True


def interrupt_seen() -> bool:
    """Whether a Ctrl-C arrived since :func:`install_sigint_handler`."""
    return _interrupt["seen"]


def install_sigint_handler() -> None:
    """Route Ctrl-C through :func:`on_sigint` and SIGTERM through :func:`on_sigterm` (only in
    the main thread, e.g. not in tests), and keep an interrupt that lands in a destructor
    (``Exception ignored in ...``) quiet: the command ends with its one line anyway."""
    import threading

    if threading.current_thread() is threading.main_thread():
        _interrupt["done"] = False
        signal.signal(signal.SIGINT, on_sigint)
        from cityshade.runtime.startup import terminated_while_starting

        if signal.getsignal(signal.SIGTERM) in (signal.SIG_DFL, terminated_while_starting):
            signal.signal(signal.SIGTERM, on_sigterm)
            _interrupt["sigterm_ours"] = True
        previous = sys.unraisablehook

        def unraisable(info) -> None:
            if not (_interrupt["seen"] and isinstance(info.exc_value, KeyboardInterrupt)):
                previous(info)

        sys.unraisablehook = unraisable


def _caused_by_interrupt(exc: BaseException) -> bool:
    """A KeyboardInterrupt inside a Numba kernel surfaces as ``SystemError: CPUDispatcher(...)
    returned a result with an exception set`` (docs/DESIGN.md §14): look through the chain."""
    seen = set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, KeyboardInterrupt):
            return True
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return _interrupt["seen"]


@contextlib.contextmanager
def translate_errors(verbose: bool = False):
    """Turn every failure into one line and an exit status, never a traceback.

    A :class:`~cityshade.errors.ContractError` is a bug, not a user error: "internal error"
    and exit status 70, with the traceback on stderr only when ``verbose`` (``-v``).
    """
    try:
        yield
    except KeyboardInterrupt:
        raise Interrupted() from None
    except click.ClickException:
        raise
    except Exception as exc:
        if _caused_by_interrupt(exc):
            raise Interrupted() from None
        if isinstance(exc, ContractError):
            if verbose:
                import traceback

                traceback.print_exc(file=sys.stderr)
            raise LibraryFailure(f"internal error: {exc}", ContractError.exit_code) from None
        if isinstance(exc, CityshadeError):
            raise LibraryFailure(str(exc), exc.exit_code) from None
        if isinstance(exc, OSError):
            where = f"{exc.filename}: " if getattr(exc, "filename", None) else ""
            raise LibraryFailure(f"{where}{exc.strerror or exc}") from None
        if isinstance(exc, MemoryError):
            raise LibraryFailure("out of memory") from None
        raise


class Progress:
    """A one-line progress display on a terminal's stderr (silent otherwise or with --quiet)."""

    def __init__(self, enabled: bool | None = None, files: bool = False):
        self.enabled = sys.stderr.isatty() if enabled is None else enabled
        # A build of several files says which file it reads: a line per file when stderr is
        # not a terminal (logs), in the bar otherwise.
        self.file_lines = files and not self.enabled
        self.t0 = time.perf_counter()
        self.last = 0.0
        self.stage = None

    def __call__(self, stage: str, done: int, total: int) -> None:
        if self.file_lines and stage.startswith("file ") and stage != self.stage:
            self.stage = stage
            name, _, count = stage[5:].rpartition(" ")
            sys.stderr.write(f"cityshade: reading {count} {name}\n")
            sys.stderr.flush()
        if not self.enabled:
            return
        now = time.perf_counter()
        if stage == self.stage and now - self.last < 0.1 and done < total:
            return
        self.stage, self.last = stage, now
        if stage == "read" and total:
            rate = done / max(now - self.t0, 1e-9) / 1e6
            text = f"reading {100 * done / total:5.1f}%  {rate:6.1f} MB/s"
        elif stage.startswith("file ") and total:
            name, _, count = stage[5:].rpartition(" ")
            i, n = (int(v) for v in count.split("/"))
            share = (i - 1 + done / total) / n
            bar = "#" * int(30 * share)
            text = f"[{bar:<30}] file {count} {name} {100 * done / total:5.1f}%"
        else:
            text = f"{stage}..."
        sys.stderr.write("\r\033[K" + text)
        sys.stderr.flush()

    def close(self) -> None:
        if self.enabled and self.stage is not None:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()


# --- options of reading a CityGML file (build, and info/evaluate on a .gml) ----------------------

CRS_HELP = ("CRS of the coordinates (overrides srsName), e.g. EPSG:25832, "
            "urn:ogc:def:crs:EPSG::4326, OGC:CRS84.")
AXIS_ORDER_HELP = ("Order of geographic coordinates (default: decided from the values, the "
                   "footprints' right angles and the srsName spelling, with a warning).")
TREES_HELP = ("A tree register (GeoJSON points or CSV rows with a position, height, crown "
              "diameter and trunk height; column names and units in [trees] of --config): each "
              "tree becomes an ellipsoid crown on a cylinder trunk, a vegetation object "
              "standing on the model's terrain under it, else on the ground plane.")
TREES_CRS_HELP = ("CRS of the register's points when the file names none (default: its GeoJSON "
                  "crs member, else the model's CRS), e.g. EPSG:4326 (longitude first).")
TIME_ATTRIBUTE_HELP = ("Generic attribute(s) with construction/demolition years or dates, "
                       "begin=NAME[,end=NAME], e.g. begin=baujahr.")


def crs_option(func):
    """``--crs`` for commands that accept a CityGML file as well as a scene file."""
    return click.option("--crs", help=CRS_HELP + " Only for a CityGML FILE.")(func)


def settings_for_source(path, crs: str | None, settings=None):
    """``settings`` (default: the defaults) for building FILE in memory with the user's
    ``--crs``; ``settings`` as given (None included) without ``--crs``."""
    import dataclasses

    from cityshade.store.cache import is_cache_file
    from cityshade.config import Settings
    from cityshade.errors import UsageError

    if crs is None:
        return settings
    folder = Path(path).is_dir()        # a tiled cache
    if folder or is_cache_file(path):
        kind = "tiled scene folder" if folder else "scene file"
        raise UsageError(f"--crs applies to a CityGML file; {path} is a {kind} built with "
                         f"its CRS: rebuild it with cityshade build --crs")
    settings = settings or Settings()
    return dataclasses.replace(settings, build=dataclasses.replace(settings.build, crs=crs))


# --- --tz local-mean / local-apparent (solar time needs the model's longitude) -------------------

def solar_placeholder(tz):
    """``--tz`` for checking a date's text before the model is loaded: solar time is checked
    as UTC (the date is parsed again with :func:`reparse_solar_date` once the model is there)."""
    from cityshade.geo.temporal import SOLAR_TIME_ZONES

    return "UTC" if tz in SOLAR_TIME_ZONES else tz


def solar_zone_of_scene(tz, scene):
    """``--tz`` as given, or the solar-time tzinfo at the model's longitude."""
    from cityshade.geo.temporal import SOLAR_TIME_ZONES

    if tz not in SOLAR_TIME_ZONES:
        return tz
    from cityshade.geo.sun import solar_time_zone

    return solar_time_zone(tz, scene.crs, scene.origin_m)


def solar_zone_of_file(tz, path):
    """:func:`solar_zone_of_scene` for a scene file not loaded yet (loaded only for solar time)."""
    from cityshade.geo.temporal import SOLAR_TIME_ZONES

    if tz not in SOLAR_TIME_ZONES:
        return tz
    from cityshade.store.scenefile import load_scene

    return solar_zone_of_scene(tz, load_scene(path))


def reparse_solar_date(user_date, tz, scene):
    """The date again in solar time at the model's longitude (unchanged for other zones)."""
    from cityshade.geo.temporal import SOLAR_TIME_ZONES, parse_user_date

    if tz not in SOLAR_TIME_ZONES or user_date.instant_utc is None:
        return user_date
    return parse_user_date(user_date.text, solar_zone_of_scene(tz, scene))


def warn_lmt(instants_utc, tz) -> None:
    """Warn when ``--tz`` gives the tz database's local mean time at these instants."""
    from cityshade.geo.temporal import SOLAR_TIME_ZONES, lmt_warning, zone_info

    if not isinstance(tz, str) or tz in SOLAR_TIME_ZONES:
        return
    zone = zone_info(tz)
    for instant in instants_utc:
        warning = lmt_warning(zone, instant.astimezone(zone), tz)
        if warning:
            click.echo(f"cityshade: warning: {warning}", err=True)
            return


def warn_geotiff_without_crs(scene, path) -> None:
    """A GeoTIFF of a model without a (known) CRS has no .prj: GIS software cannot place it."""
    if scene.crs.local or scene.crs.horizontal_epsg is None:
        click.echo(f"cityshade: warning: {path} has no .prj and no CRS in its tags: the model's "
                   f"CRS is {scene.crs.name}, so GIS software cannot place it; rebuild the "
                   f"scene with --crs EPSG:nnnn", err=True)


# --- settings and shadow options shared by render, batch and evaluate --------------------------

#: The shadow flags of every command: click parameter name → ShadowSettings.override name.
_SHADOW_FLAGS = ("map_px", "bias", "slope_bias", "max_bias", "pcf_kernel", "vsm_blur",
                 "cascades")


def config_option(func):
    """``--config FILE``: the TOML settings tree (:mod:`cityshade.config`)."""
    return click.option("--config", "config_path", type=click.Path(dir_okay=False),
                        help="TOML settings file ([shadows], [sun], [batch], [evaluate], "
                             "...; cityshade/configs/default.toml lists them). Flags override it.")(func)


def load_config(config_path):
    """The settings tree of ``--config`` (defaults without one)."""
    from cityshade.config import Settings, load_settings

    return load_settings(config_path) if config_path else Settings()


def shadow_options(default_technique: str, *, technique_help: str | None = None,
                   map_px: bool = True, tunables: bool = True):
    """Decorator adding ``--config``, ``--shadows``, ``--smooth`` and the shadow tunables
    (``--map-px``, ``--bias``, ...); ``tunables=False`` (a command of the exact engines only,
    ``sky``) leaves out ``--smooth`` and the map techniques' tunables, which could not apply
    (issue 40: no option silently ignored). The command receives one ``settings`` argument: the
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
            if kwargs.pop("smooth", False):
                # Every name of a list (evaluate's "shadowmap,pcf", "all") gets the filter.
                technique = ",".join(n if n.strip().endswith("+smooth") else f"{n.strip()}+smooth"
                                     for n in technique.split(",") if n.strip())
            flags = {k: kwargs.pop(k, None) for k in _SHADOW_FLAGS}
            for flag in inapplicable_flags(technique, flags):
                click.echo(f"cityshade: warning: --{flag.replace('_', '-')} does not apply to "
                           f"--shadows {technique}; ignored", err=True)
            shadows = dataclasses.replace(settings.shadows.override(**flags),
                                          technique=technique)
            kwargs["settings"] = dataclasses.replace(
                settings, shadows=shadows,
                vegetation=vegetation_flags(settings.vegetation, kwargs.pop("no_vegetation"),
                                            kwargs.pop("tree_transmissivity")))
            return func(*args, **kwargs)

        options = [
            click.option("--shadows", "technique",
                         help=technique_help or f"Shadow technique (default "
                         f"{default_technique}): {names_help()}."),
            *_tunable_options(map_px and tunables, tunables),
            click.option("--no-vegetation", is_flag=True, help="Leave the vegetation "
                         "(SolitaryVegetationObject, PlantCover) out: trees neither cast nor "
                         "receive ([vegetation] enabled = false)."),
            click.option("--tree-transmissivity", type=click.FloatRange(0.0, 1.0),
                         help="Fraction of the sun one crown lets through in leaf, every "
                         "vegetation class (default 0.03, UMEP/SOLWEIG; [vegetation])."),
        ]
        for option in reversed(options):
            wrapper = option(wrapper)
        return config_option(wrapper)
    return decorate


def _tunable_options(map_px: bool, tunables: bool) -> list:
    """``--smooth`` and the map techniques' tunables (none for ``tunables=False``)."""
    if not tunables:
        return []
    return [
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


def vegetation_flags(vegetation, no_vegetation: bool, tree_transmissivity):
    """``[vegetation]`` with ``--no-vegetation`` and ``--tree-transmissivity`` applied."""
    import dataclasses

    if no_vegetation:
        vegetation = dataclasses.replace(vegetation, enabled=False)
    if tree_transmissivity is not None:
        vegetation = vegetation.with_transmissivity(tree_transmissivity)
    return vegetation


def _flag_applies(flag: str, name: str) -> bool:
    """Whether a tunable of ``[shadows]`` changes technique ``name``."""
    from cityshade.errors import UsageError
    from cityshade.shadows import describe

    if name in ("all", "all+smooth", ""):
        return True
    try:
        spec = describe(name)
    except UsageError:
        return True  # the command refuses the name itself, with the registry's message
    if flag == "cascades":
        return spec.planner == "csm"
    if flag == "pcf_kernel":
        return spec.lookup == "pcf"
    if flag == "vsm_blur":
        return spec.lookup == "vsm"  # also hybrid's default base
    return spec.family != "exact"  # the map's size and biases: every map technique


def inapplicable_flags(technique: str, flags: dict) -> list[str]:
    """The shadow flags given (not None) that apply to none of the comma-separated techniques."""
    names = [n.strip() for n in str(technique).split(",")]
    return [flag for flag, value in flags.items() if value is not None
            and not any(_flag_applies(flag, n) for n in names)]


def check_scheduler_scene(scheduler, settings, file) -> None:
    """Refuse ``--scheduler`` where Dask workers would not see the scene the command sees:
    non-default ``[vegetation]`` settings, a tiled cache (``batch`` and ``sky``)."""
    from cityshade.config import VegetationSettings
    from cityshade.errors import UsageError
    from cityshade.store.tiled import is_tiled_cache

    if scheduler is None:
        return
    if settings.vegetation != VegetationSettings():
        raise UsageError("--scheduler: Dask workers open the scene with the default "
                         "[vegetation] settings; run without --scheduler to change them")
    if is_tiled_cache(file):
        raise UsageError("--scheduler needs one cache file: a tiled cache is not read by "
                         "Dask workers yet")


class ProgressLines:
    """Progress for a stderr that is not a terminal (a log, CI): one plain line every
    ``every_s`` seconds or every tenth of the work, whichever comes first."""

    def __init__(self, label: str, every_s: float = 10.0, clock=None):
        import time

        self.label = label
        self.every_s = float(every_s)
        self.clock = clock or time.monotonic
        self.last_t = self.start_t = self.clock()
        self.last_tenth = 0
        self.first_done: int | None = None

    def __call__(self, done: int, total: int, what: str = "") -> None:
        now = self.clock()
        if self.first_done is None:
            # Work taken from a saved state does not count for the rate.
            self.first_done, self.start_t = done, now
        tenth = 10 * done // max(total, 1)
        if tenth > self.last_tenth or now - self.last_t >= self.every_s:
            self.last_t, self.last_tenth = now, tenth
            eta = ""
            if done > self.first_done and done < total:
                left_s = (now - self.start_t) / (done - self.first_done) * (total - done)
                eta = f", ETA {int(left_s) // 3600}:{int(left_s) % 3600 // 60:02d}:" \
                      f"{int(left_s) % 60:02d}"
            click.echo(f"cityshade: {self.label} {done}/{total} ({100 * done // max(total, 1)} %"
                       f"{eta})" + (f" {what}" if what else ""), err=True)


# --- the city's state and the sun's day: one meaning in every command --------------------------
# --city-date is the state of the city, --date the sun's day (docs/DESIGN.md §17). Where the
# sun can be given as angles (render, evaluate --sun), a --date without a time of day has no
# sun to date, so it keeps its old meaning as the short form of --city-date.

def city_date_option(default: str):
    """``--city-date``: the city's state, the same words in every command."""
    return click.option("--city-date", help=f"State of the city: a year or date, e.g. 1850 or "
                        f"1850-06-21 (default: {default}).")


def city_of_short_date(date_text: str | None, city_date: str | None, tz,
                       time_option: str) -> str | None:
    """The city's state when ``--date`` carries no time of day and the sun is given as angles:
    ``--date`` is then the short form of ``--city-date``; both given with different states is
    a contradiction. ``time_option`` names what makes ``--date`` the sun's day (``--time``).

    Raises
    ------
    UsageError
        ``--date`` and ``--city-date`` name different states of the city.
    """
    from cityshade.errors import UsageError
    from cityshade.geo.temporal import parse_user_date

    if date_text is None or city_date is None:
        return city_date if date_text is None else date_text
    zone = solar_placeholder(tz)
    if parse_user_date(date_text, zone).city_days != parse_user_date(city_date, zone).city_days:
        raise UsageError(f"--date {date_text} without a time of day is the city's state (short "
                         f"for --city-date), and --city-date says {city_date}: give one of "
                         f"them, or {time_option} to make --date the sun's day")
    return city_date


def _with_city_date(kwargs) -> None:
    """``--city-date`` of compare and study: the one state a ``--with`` proposal is added to,
    that is ``--before`` (refused for two dates of one model, or beside another --before)."""
    from cityshade.errors import UsageError
    from cityshade.geo.temporal import parse_user_date

    city_date = kwargs.pop("city_date")
    if city_date is None:
        return
    if kwargs.get("proposal") is None:
        raise UsageError("--city-date is the state of the city that --with adds a proposal "
                         "to; two states of one model are --before and --after")
    before = kwargs.get("before_text")
    if before is not None and parse_user_date(before).city_days != \
            parse_user_date(city_date).city_days:
        raise UsageError(f"--city-date {city_date} and --before {before} both give the state "
                         f"the proposal is added to, and they differ: give one of them")
    kwargs["before_text"] = city_date


# --- the time plan of batch and compare -------------------------------------------------------

def time_plan_options(func):
    """``--date --from --to --every --tz --days --to-date --every-day`` (see
    :func:`cityshade.sunhours.plan.plan_steps`)."""
    options = [
        click.option("--date", "date_text", required=True, help="First day of the sun "
                     "positions, YYYY-MM-DD; the city's state too unless --city-date (or "
                     "--before) says otherwise."),
        click.option("--from", "from_text", default="00:00", show_default=True,
                     help="Local start time of each day, HH:MM."),
        click.option("--to", "to_text", default="24:00", show_default=True,
                     help="Local end time of each day, HH:MM (24:00 = midnight at the end)."),
        click.option("--every", "every_text", default="10min", show_default=True,
                     help="Step length: 10min, 1h, 30s, 1h30min."),
        click.option("--tz", required=True, help="IANA time zone of --from/--to, e.g. "
                     "Europe/Berlin (UTC for UTC); local-mean or local-apparent: mean or true "
                     "solar time at the model's longitude (for historical dates)."),
        click.option("--days", type=int, help="Number of days (default 1), --every-day apart."),
        click.option("--to-date", "to_date_text", help="Last day (inclusive), YYYY-MM-DD."),
        click.option("--every-day", type=int, default=1, show_default=True,
                     help="Days between days."),
    ]
    for option in reversed(options):
        func = option(func)
    return func


def states_options(before_default: str, meshes: bool = False):
    """``--before --after --with --city-date``: the two states of compare and study
    (:class:`cityshade.planning.run.CompareStates`); ``before_default`` says what a missing
    ``--before`` means; ``meshes``: the command has the mesh placement options. The command
    does not receive ``--city-date``: it arrives as ``before_text`` (:func:`_with_city_date`)."""
    import functools

    def decorate(command):
        @functools.wraps(command)
        def func(*args, **kwargs):
            _with_city_date(kwargs)
            return command(*args, **kwargs)

        for option in reversed([
            click.option("--city-date", help=f"State of the city that --with adds the "
                         f"proposal to (the same as --before there; default: "
                         f"{before_default}); two dates of one model are --before and "
                         f"--after."),
            click.option("--before", "before_text", help=f"State of the city before (date or "
                         f"year); default: {before_default}."),
            click.option("--after", "after_text", help="State of the city after (date or "
                         "year), on the same model: a proposed building carries a later "
                         "validFrom."),
            click.option("--with", "proposal", type=click.Path(dir_okay=False, path_type=Path),
                         help="Proposal added to FILE for the state after: a model "
                              "(.cityshade, CityGML or CityJSON, same CRS) or a mesh (.obj, "
                              ".glb, .gltf, .ply, .stl" + (
                                  "; placed by --place, --up-axis, --mesh-units)." if meshes else
                                  ", in model CRS coordinates, Z up; glTF Y up).")),
        ]):
            func = option(func)
        return func
    return decorate


def mesh_options(command):
    """``--mesh-units --up-axis --place``: how a mesh proposal given by ``--with`` is read and
    placed (compare, study); the command receives ``mesh_units``, ``up_axis`` and
    ``place_text`` (:func:`mesh_placement` makes them one object)."""
    from cityshade.config import LENGTH_UNITS_M

    for option in reversed([
        click.option("--mesh-units", type=click.Choice(tuple(LENGTH_UNITS_M)),
                     help="Unit of a mesh proposal's numbers [default: m]."),
        click.option("--up-axis", type=click.Choice(("z", "y")),
                     help="Up axis of a mesh proposal [default: y for glTF/GLB (Y-up by the "
                          "glTF specification), z for OBJ, PLY, STL]."),
        click.option("--place", "place_text", metavar="X,Y[,Z][,ROTATION_DEG]",
                     help="Put a mesh proposal's origin at X,Y (model CRS) and height Z "
                          "(default: the terrain, else the ground plane, under X,Y), turned "
                          "ROTATION_DEG counter-clockwise seen from above; without it the "
                          "mesh's coordinates are model CRS coordinates."),
    ]):
        command = option(command)
    return command


def mesh_placement(units, up_axis, place_text):
    """The mesh options as a :class:`~cityshade.meshes.proposal.MeshPlacement` (None when
    none is given)."""
    if units is None and up_axis is None and place_text is None:
        return None
    from cityshade.meshes.proposal import MeshPlacement

    return MeshPlacement(units or "m", up_axis, MeshPlacement.parse_place(place_text))


def check_every_day(days, to_date_text) -> None:
    """--every-day spaces the days of --days or --to-date: alone it would change nothing."""
    from cityshade.errors import UsageError

    if given("every_day") and days is None and to_date_text is None:
        raise UsageError("--every-day spaces several days: give --days N or --to-date too")


# --- the ground plane option of render, batch and evaluate -------------------------------------

GROUND_HELP = ("Ground plane where the model shows no surface, so cast shadows fall on "
               "something: auto (the typical ground level, the median of the objects' lowest "
               "points), min (the lowest point), a height in metres, or none.")


def _ground_value(ctx, param, value):
    """'none' switches the plane off (None for the library); other values are checked there."""
    return None if value is None or value.strip().lower() == "none" else value.strip()


def ground_option(func):
    """--ground, default auto (docs/DESIGN.md §10: most real files carry no terrain)."""
    return click.option("--ground", default="auto", show_default=True, callback=_ground_value,
                        help=GROUND_HELP)(func)


def presentation_options(func):
    """--no-decorate and --no-gis of batch and compare (docs/DESIGN.md §19)."""
    func = click.option("--no-gis", is_flag=True, help="Do not write results.gpkg (surfaces, "
                        "openings, buildings, rules as GIS layers in the model's CRS) and the "
                        "results_*.geojson files (EPSG:4326).")(func)
    return click.option("--no-decorate", is_flag=True, help="Plain PNG maps: no title, scale "
                        "bar, north arrow, CRS or colour bar around a map view (GeoTIFF and "
                        "EXR values are never decorated).")(func)


# --- camera options shared by render, batch and evaluate ---------------------------------------

def _preset_names() -> list[str]:
    from cityshade.raster.presets import load_presets

    return [n for n in load_presets() if n != "overview"]


_PRESET_NAMES = _preset_names()


MAP_EXTENT_META = "cityshade.map_extent"


def map_extent_options(func):
    """Decorator adding --bbox and --margin-m (the map view's extent). The command does not
    receive them as arguments: they go to the click context's meta, where
    :func:`map_extent_of_command` (:func:`make_camera`) finds them."""
    import functools

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        ctx = click.get_current_context()
        ctx.meta[MAP_EXTENT_META] = (_parse_bbox(kwargs.pop("bbox")), kwargs.pop("margin_m"))
        return func(*args, **kwargs)

    wrapper = click.option("--margin-m", type=float, help="Map view: metres added around the "
                           "mapped box on every side (default: none around --bbox, twice the "
                           "model's height around the whole model, up to where the ground "
                           "plane ends, so shadows falling past its edge are kept).")(wrapper)
    return click.option("--bbox", help="Map view: only the box X0,Y0,X1,Y1 (model CRS "
                        "metres); the casters still come from the whole model, so shadows "
                        "cast into the box from outside it are computed.")(wrapper)


def _parse_bbox(text: str | None):
    """'X0,Y0,X1,Y1' → four floats (None stays None)."""
    return parse_box(text, "--bbox must be X0,Y0,X1,Y1 in the model CRS (metres)")


def parse_box(text: str | None, must: str, ordered: bool = False):
    """Four comma-separated numbers (x0 < x1 and y0 < y1 when ``ordered``) → a tuple; None
    stays None; otherwise a UsageError ``"{must}, not 'TEXT'"``."""
    from cityshade.errors import UsageError

    if text is None:
        return None
    try:
        values = tuple(float(v) for v in text.split(","))
    except ValueError:
        values = ()
    if len(values) != 4 or ordered and not (values[0] < values[2] and values[1] < values[3]):
        raise UsageError(f"{must}, not {text!r}")
    return values


def map_extent_of_command(scene, name: str, eye: bool):
    """The render-space extent of the map view from the command's --bbox and --margin-m
    (:func:`~cityshade.raster.camera.map_extent`), None for the default (the whole model, no
    margin) when the command has no such options; refused for a perspective camera."""
    from cityshade.errors import UsageError
    from cityshade.raster import camera as cams

    ctx = click.get_current_context(silent=True)
    bbox, margin_m = (ctx.meta.get(MAP_EXTENT_META, (None, None)) if ctx is not None
                      else (None, None))
    if eye or name != "map":
        if bbox is not None or margin_m is not None:
            raise UsageError("--bbox and --margin-m apply to the map view (--camera map)")
        return None
    if margin_m is None:
        margin_m = 0.0 if bbox is not None else cams.default_map_margin_m(scene)
    return cams.map_extent(scene, bbox, margin_m)


def camera_options(default_camera: str):
    """Decorator adding --camera, --eye, --target, --fov, --size, --pixel-size, --cameras,
    and --bbox and --margin-m (:func:`map_extent_options`)."""
    def decorate(func):
        func = map_extent_options(func)
        for option in reversed([
            click.option("--camera", default=default_camera, show_default=True,
                         help=f"overview, map, or a preset: {', '.join(_PRESET_NAMES)} "
                              f"(shipped in cityshade/configs/cameras.toml) or one of "
                              f"--cameras."),
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
                              "cityshade/configs/cameras.toml), added to the built-in ones."),
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


def parse_size(text: str, technique: str | None = None, *, batch: bool = False
               ) -> tuple[int, int]:
    """'WIDTHxHEIGHT' → (width, height) in pixels. A size over :data:`MAX_SIZE_PX` a side
    is refused with the memory it would need (for ``technique``, or a batch's receivers)."""
    from cityshade.raster.camera import DEFAULT_MAX_MAP_PX as MAX_SIZE_PX  # the map's limit

    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise click.BadParameter(f"--size must be WIDTHxHEIGHT, e.g. 1280x720, not {text!r}")
    if w < 1 or h < 1:
        raise click.BadParameter("--size must be at least 1x1 pixels")
    if max(w, h) > MAX_SIZE_PX:
        import types

        from cityshade.errors import UsageError
        from cityshade.frame.pipeline import frame_bytes
        from cityshade.shadows import describe

        view = types.SimpleNamespace(width_px=w, height_px=h, kind="perspective")
        need, per_px = frame_bytes(view, technique, batch=batch)
        per = (f"{per_px} bytes per receiver pixel" if batch else
               f"{per_px} bytes per pixel for {describe(technique or 'raytrace').name}")
        raise UsageError(f"--size {w}x{h} exceeds the limit of {MAX_SIZE_PX} pixels a side "
                         f"(the {'sun-hour map' if batch else 'picture'} would need about "
                         f"{need / 1e9:,.0f} GB: {per})")
    return w, h


def parse_area(text: str | None, option: str = "--area"):
    """``--area x0,y0,x1,y1`` (model CRS metres) → the box, or None without the option
    (``option`` names it in the message)."""
    return parse_box(text, f"{option} must be x0,y0,x1,y1 with x0 < x1 and y0 < y1",
                     ordered=True)


def given(name: str) -> bool:
    """Whether the running command's option ``name`` (its parameter name) was given by the
    user, not left at its default."""
    from click.core import ParameterSource

    ctx = click.get_current_context(silent=True)
    source = ctx.get_parameter_source(name) if ctx is not None else None
    return source in (ParameterSource.COMMANDLINE, ParameterSource.ENVIRONMENT)


def check_camera_options(name: str, eye: bool) -> None:
    """Refuse a camera option that the chosen camera would ignore (--size of the map view,
    --pixel-size of a perspective one, --fov of a preset, --camera beside --eye).

    Raises
    ------
    UsageError
    """
    from cityshade.errors import UsageError

    if eye and given("camera"):
        raise UsageError(f"--eye/--target place a perspective camera of their own: give them "
                         f"or --camera {name}, not both")
    kind = "perspective" if eye else ("map" if name == "map" else "preset")
    if kind == "map":
        for option in ("size", "fov"):
            if given(option):
                raise UsageError(f"--{option} does not apply to the map view (--camera map): "
                                 f"its size follows from --pixel-size (metres per pixel) and "
                                 f"the model's extent")
    elif given("pixel_size"):
        raise UsageError("--pixel-size applies to the map view (--camera map); a perspective "
                         "picture's size is --size WIDTHxHEIGHT")
    elif kind == "preset" and given("fov"):
        raise UsageError(f"--fov applies to a camera placed with --eye/--target; --camera "
                         f"{name} has its own field of view")


def make_camera(scene, name, eye, target, fov, size, pixel_size, cameras_file=None):
    """The camera the shared options describe (eye/target in model CRS coordinates)."""
    import numpy as np

    from cityshade.errors import UsageError
    from cityshade.raster import camera as cams

    eye_v, target_v = parse_triple(eye, "--eye"), parse_triple(target, "--target")
    if (eye_v is None) != (target_v is None):
        raise UsageError("give both --eye and --target, or neither")
    check_camera_options(name, eye_v is not None)
    width, height = parse_size(size)
    extent = map_extent_of_command(scene, name, eye_v is not None)
    if eye_v is not None:
        return cams.perspective(np.asarray(eye_v) - scene.origin_m,
                                np.asarray(target_v) - scene.origin_m, vfov_deg=fov,
                                width_px=width, height_px=height, scene=scene)
    if name == "overview":
        return cams.overview(scene, width, height)
    if name == "map":
        return cams.map_view(scene, pixel_size, bbox=extent)
    return cams.preset(name, scene, width, height, extra=cameras_file)
