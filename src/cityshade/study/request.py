"""What a shadow study asks: the days, the times of day, the two states, the view, where to write.

:class:`StudyTimes` holds the days and the local clock times of the panels (in an IANA zone or
in solar time at the model's longitude); :class:`StudyRequest` the rest. ``cityshade study``
parses its options into these (:func:`parse_days`, :func:`parse_times`, :func:`clock_range`)
and calls :func:`cityshade.study.run.run_study`.
"""
from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from datetime import UTC, date, datetime, timedelta
from typing import Any

from cityshade.errors import UsageError

__all__ = [
    "DEFAULT_MAP_SIDE_PX",
    "MAX_PANELS",
    "StudyRequest",
    "StudyTimes",
    "clock_range",
    "default_days",
    "parse_days",
    "parse_times",
]

#: The days of a study without ``--days``: the March equinox and both solstices (the days
#: planning authorities ask for; the 21st stands for the astronomical date, ±1 day).
DEFAULT_MONTH_DAYS = ((3, 21), (6, 21), (12, 21))
#: Panels on one sheet at most (a sheet of more is unreadable on A3).
MAX_PANELS = 24
#: A study's default map: its longer side in pixels (a panel on an A3 sheet is ~75 mm wide,
#: 440 px at 150 dpi: 1024 keeps the PDF sharp when zoomed and the run well under a minute).
DEFAULT_MAP_SIDE_PX = 1024


def default_days(year: int) -> tuple[date, ...]:
    """21 March, 21 June and 21 December of ``year``."""
    if not 1000 <= int(year) <= 3000:
        raise UsageError(f"--year must lie in 1000 to 3000, not {year}")
    return tuple(date(int(year), m, d) for m, d in DEFAULT_MONTH_DAYS)


def parse_days(text: str) -> tuple[date, ...]:
    """``2025-03-21,2025-06-21`` → the days, in the order given (no repeats).

    Raises
    ------
    UsageError
        A text that is not a comma-separated list of YYYY-MM-DD days, or a day given twice.
    """
    days = []
    for part in text.split(","):
        try:
            day = date.fromisoformat(part.strip())
        except ValueError:
            raise UsageError(f"--days must be days YYYY-MM-DD separated by commas, not "
                             f"{part.strip()!r}") from None
        if day in days:
            raise UsageError(f"--days gives {day} twice")
        days.append(day)
    return tuple(days)


def parse_times(text: str) -> tuple[int, ...]:
    """``09:00,12:00,15:00`` → seconds after local midnight, sorted (no repeats)."""
    from cityshade.sunhours.plan import parse_clock_s

    clocks = sorted({parse_clock_s(part) for part in text.split(",")})
    return _checked(tuple(clocks))


def clock_range(from_s: int, to_s: int, every_s: float) -> tuple[int, ...]:
    """The local times ``from_s``, ``from_s + every_s``, … up to ``to_s`` inclusive (seconds
    after midnight): a study shows 08:00 to 18:00 hourly as eleven panels."""
    if not to_s >= from_s:
        raise UsageError("--to must not be earlier than --from")
    if not every_s >= 60:
        raise UsageError(f"--every must be at least 1 minute, not {every_s:g} s")
    n = int((to_s - from_s) // every_s) + 1
    return _checked(tuple(round(from_s + k * every_s) for k in range(n)))


def _checked(clocks: tuple[int, ...]) -> tuple[int, ...]:
    if len(clocks) > MAX_PANELS:
        raise UsageError(f"{len(clocks)} times a day make {len(clocks)} panels on a sheet; "
                         f"at most {MAX_PANELS}: choose a longer --every or fewer --times")
    if any(c >= 86_400 for c in clocks):
        raise UsageError("a time of day must be before 24:00")
    return clocks


@dataclass(frozen=True)
class StudyTimes:
    """The panels' instants: every clock time on every day.

    Attributes
    ----------
    days : tuple of datetime.date
        One sheet per day.
    clocks_s : tuple of int
        Local times of day (seconds after midnight), one panel each.
    tz : str
        IANA zone of the clock times, or ``local-apparent``/``local-mean`` (solar time at the
        model's longitude).
    """

    days: tuple[date, ...]
    clocks_s: tuple[int, ...]
    tz: str

    def __post_init__(self) -> None:
        if not self.days:
            raise UsageError("a study needs at least one day")
        if not self.clocks_s:
            raise UsageError("a study needs at least one time of day")
        for day in self.days:
            if not 1000 <= day.year <= 3000:
                raise UsageError(f"dates must lie in the years 1000 to 3000, not {day}")

    def zone(self, scene):
        """The tzinfo of the clock times (solar time needs the model's longitude)."""
        from cityshade.geo.sun import solar_time_zone
        from cityshade.geo.temporal import SOLAR_TIME_ZONES, zone_info

        if self.tz in SOLAR_TIME_ZONES:
            return solar_time_zone(self.tz, scene.crs, scene.origin_m)
        return zone_info(self.tz)

    def instants(self, scene, day: date) -> list[datetime]:
        """The aware local instants of ``day``'s panels (a wall time skipped by a
        daylight-saving change is read with the offset before it, as batch does)."""
        zone = self.zone(scene)
        midnight = datetime(day.year, day.month, day.day)
        return [(midnight + timedelta(seconds=c)).replace(tzinfo=zone) for c in self.clocks_s]

    def utc(self, scene, day: date) -> list[datetime]:
        """:meth:`instants` in UTC."""
        return [t.astimezone(UTC) for t in self.instants(scene, day)]


@dataclass(frozen=True)
class StudyRequest:
    """A shadow study: what :func:`cityshade.study.run.run_study` computes and writes.

    Attributes
    ----------
    scene : path or Scene
        A ``.cityshade`` file, a tiled cache folder, a CityGML/CityJSON file (built in
        memory) or a loaded scene.
    times : StudyTimes
    states : cityshade.planning.run.CompareStates
        Before and after: two dates of one model, or the model with a proposal added.
    technique : str
        An exact technique (``exact``, ``izb`` or ``raytrace``).
    settings : cityshade.config.Settings, optional
    pixel_size_m : float, optional
        Metres per map pixel (default: the map's longer side in
        :data:`DEFAULT_MAP_SIDE_PX` pixels).
    area : (x0, y0, x1, y1), optional
        Site boundary in model CRS metres, drawn on every panel.
    extent : (x0, y0, x1, y1), optional
        What the map shows, in model CRS metres (default: the whole model).
    ground : str or None
        Ground plane, as ``render --ground``.
    outdir : path, optional
        Output folder (checked and created before any work); None: nothing is written.
    provenance : mapping, optional
        What was asked, recorded in ``study.json``.
    """

    scene: Any
    times: StudyTimes
    states: Any
    technique: str = "exact"
    settings: Any = None
    pixel_size_m: float | None = None
    area: Sequence[float] | None = None
    extent: Sequence[float] | None = None
    ground: str | None = "auto"
    outdir: str | os.PathLike | None = None
    provenance: Any = None

    def __post_init__(self) -> None:
        from cityshade.config import Settings
        from cityshade.planning.run import require_exact

        require_exact(self.technique, "a study")
        if self.settings is None:
            object.__setattr__(self, "settings", Settings())
        if self.pixel_size_m is not None and not self.pixel_size_m > 0:
            raise UsageError(f"--pixel-size must be > 0, not {self.pixel_size_m}")
