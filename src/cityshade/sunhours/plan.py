"""The time plan of a sun-hours run: steps of local time, their weights, and the work units
(distinct sun positions above the horizon).

Each step stands for an interval of time and is weighted by its length in hours; the sun of a
step is taken at the interval's centre (midpoint rule: the weights add up to the covered time
exactly, and the error in sun-hours is second order in the step). Steps with the sun at or
below the horizon contribute nothing and are skipped; steps with an identical sun direction
are computed once, with their weights summed (:func:`plan_units`).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from datetime import date, datetime, timedelta, timezone
from typing import Any, Sequence

import numpy as np

from cityshade.errors import UsageError
from cityshade.util import plural

__all__ = ["Step", "Unit", "parse_duration_s", "parse_clock_s", "plan_steps", "plan_units",
           "step_months", "step_weights", "plan_run", "unit_month_weights", "MAX_STEPS"]

#: Largest number of steps of one run: 1 year every minute is 525 600; more is a typo.
MAX_STEPS = 1_000_000
_DURATION_RE = re.compile(r"\s*(\d+(?:\.\d*)?)\s*(h|min|s)\s*")
_CLOCK_RE = re.compile(r"(\d{1,2}):(\d{2})(?::(\d{2}))?")


# --- time steps -------------------------------------------------------------------------------

def parse_duration_s(text: str) -> float:
    """Seconds of a duration such as ``10min``, ``1h``, ``30s`` or ``1h30min``.

    Raises
    ------
    UsageError
        No unit, an unknown unit, or a duration that is not positive.
    """
    pos, total = 0, 0.0
    text_s = str(text)
    for match in _DURATION_RE.finditer(text_s):
        if match.start() != pos:
            break
        total += float(match.group(1)) * {"h": 3600.0, "min": 60.0, "s": 1.0}[match.group(2)]
        pos = match.end()
    if pos != len(text_s) or pos == 0:
        raise UsageError(f"cannot read duration {text!r}; use e.g. 10min, 1h, 30s or 1h30min")
    if not total > 0.0:
        raise UsageError(f"a duration must be longer than 0 s, not {text!r}")
    return total


def parse_clock_s(text: str) -> int:
    """Seconds after midnight of a time of day ``HH:MM[:SS]``; ``24:00`` is the next midnight."""
    match = _CLOCK_RE.fullmatch(str(text).strip())
    if match is None:
        raise UsageError(f"cannot read time of day {text!r}; use HH:MM, e.g. 05:30")
    h, m, s = int(match.group(1)), int(match.group(2)), int(match.group(3) or 0)
    seconds = (h * 60 + m) * 60 + s
    if m >= 60 or s >= 60 or seconds > 86_400:
        raise UsageError(f"time of day {text!r} does not exist; use 00:00 to 24:00")
    return seconds


@dataclass(frozen=True)
class Step:
    """One time step: the interval ``[start_utc, end_utc)`` it stands for."""

    index: int
    start_utc: datetime
    end_utc: datetime

    @property
    def weight_h(self) -> float:
        return (self.end_utc - self.start_utc).total_seconds() / 3600.0

    @property
    def centre_utc(self) -> datetime:
        """Where the sun of the step is evaluated (midpoint rule)."""
        return self.start_utc + (self.end_utc - self.start_utc) / 2


def _local(day: date, seconds: int, zone) -> datetime:
    """Aware datetime of a wall-clock time on ``day`` in ``zone`` (24:00 = next midnight).

    A wall time skipped by a daylight-saving change is read with the offset before the change
    (zoneinfo's ``fold=0``), i.e. one hour later in real time.
    """
    extra_day, rest = divmod(seconds, 86_400)
    d = day + timedelta(days=extra_day)
    h, rem = divmod(rest, 3600)
    return datetime(d.year, d.month, d.day, h, rem // 60, rem % 60, tzinfo=zone)


def plan_steps(first_day: date, from_s: int, to_s: int, every_s: float, tz: str,
               days: int | None = None, to_date: date | None = None,
               every_day: int = 1) -> list[Step]:
    """Time steps of a batch: on each day, ``[from, to)`` local time cut into steps of
    ``every_s`` (the last one shorter when it does not divide).

    Parameters
    ----------
    first_day : datetime.date
    from_s, to_s : int
        Local times of day in seconds after midnight (:func:`parse_clock_s`), ``from < to``.
    every_s : float
        Step length in seconds, elapsed time (a daylight-saving change inside the window
        adds or removes steps, as it adds or removes real time).
    tz : str
        IANA time zone of the local times ("UTC" for UTC).
    days : int, optional
        Number of days (default 1), ``every_day`` apart.
    to_date : datetime.date, optional
        Last day (inclusive) instead of ``days``.
    every_day : int
        Days between the days taken.

    Returns
    -------
    list of Step

    Raises
    ------
    UsageError
        Unknown zone, empty window, both ``days`` and ``to_date``, non-positive counts, years
        outside 1000–3000, or more than :data:`MAX_STEPS` steps.
    """
    from cityshade.geo.temporal import zone_info

    if days is not None and to_date is not None:
        raise UsageError("give --days or --to-date, not both")
    if every_day < 1:
        raise UsageError(f"--every-day must be >= 1, not {every_day}")
    if not to_s > from_s:
        raise UsageError("--to must be later than --from on the same day (24:00 is midnight "
                         "at the end of the day)")
    if not (math.isfinite(every_s) and every_s > 0):
        raise UsageError(f"the step must be longer than 0 s, not {every_s}")
    zone = zone_info(tz)
    if to_date is not None:
        if to_date < first_day:
            raise UsageError(f"--to-date {to_date} is before --date {first_day}")
        n_days = (to_date - first_day).days // every_day + 1
    else:
        n_days = 1 if days is None else int(days)
        if n_days < 1:
            raise UsageError(f"--days must be >= 1, not {days}")
    per_day = math.ceil((to_s - from_s) / every_s)
    if n_days * per_day > MAX_STEPS:
        raise UsageError(f"{n_days * per_day} steps exceed the limit of {MAX_STEPS}; "
                         f"choose a longer step or fewer days")
    steps: list[Step] = []
    step = timedelta(seconds=every_s)
    for k in range(n_days):
        day = first_day + timedelta(days=k * every_day)
        if not 1000 <= day.year <= 3000:
            raise UsageError(f"dates must lie in the years 1000 to 3000, not {day}")
        start = _local(day, from_s, zone).astimezone(timezone.utc)
        end = _local(day, to_s, zone).astimezone(timezone.utc)
        s = start
        while s < end:
            e = min(s + step, end)
            steps.append(Step(len(steps), s, e))
            s = e
    return steps


# --- work units: distinct sun positions above the horizon -------------------------------------

@dataclass(frozen=True)
class Unit:
    """A distinct sun position above the horizon and the steps that share it."""

    sun: Any
    steps: tuple[int, ...]
    weight_h: float


def plan_units(suns: Sequence, weights_h: Sequence[float]) -> tuple[list[Unit], list[int], int]:
    """Group steps by identical sun direction, skipping those at or below the horizon.

    Returns
    -------
    units : list of Unit
        In the order of each position's first step; weights summed in step order.
    below : list of int
        Indices of the steps with the sun at or below the horizon.
    duplicates : int
        Steps that reuse an earlier step's identical sun position.
    """
    by_key: dict[tuple, int] = {}
    steps: list[list[int]] = []
    weights: list[float] = []
    order: list[Any] = []
    below: list[int] = []
    duplicates = 0
    for i, (sun, w) in enumerate(zip(suns, weights_h)):
        if not sun.above_horizon:
            below.append(i)
            continue
        key = tuple(float(v) for v in sun.direction)
        u = by_key.get(key)
        if u is None:
            by_key[key] = len(order)
            order.append(sun)
            steps.append([i])
            weights.append(float(w))
        else:
            duplicates += 1
            steps[u].append(i)
            weights[u] += float(w)
    units = [Unit(sun, tuple(s), w) for sun, s, w in zip(order, steps, weights)]
    return units, below, duplicates



def step_months(steps: Sequence[Step], tz: str) -> list[str]:
    """The month (YYYY-MM, local time in ``tz``) of each step's start: the ``--monthly`` labels."""
    from cityshade.geo.temporal import zone_info

    local = zone_info(tz)
    return [s.start_utc.astimezone(local).strftime("%Y-%m") for s in steps]


def step_weights(instants: list, weights_h) -> np.ndarray:
    """Hours each instant stands for: ``weights_h`` checked, or the even spacing."""
    if weights_h is not None:
        w = np.asarray(weights_h, dtype=np.float64)
        if w.shape != (len(instants),):
            raise UsageError(f"weights_h must have one value per instant ({len(instants)}), "
                             f"not shape {w.shape}")
        if not (np.isfinite(w).all() and (w >= 0).all()):
            raise UsageError("weights_h must be finite hours >= 0")
        return w
    if len(instants) < 2:
        raise UsageError("give weights_h (hours per instant) for a single instant")
    gaps = np.array([(b - a).total_seconds() for a, b in zip(instants, instants[1:])])
    if not np.all(gaps == gaps[0]) or gaps[0] <= 0:
        raise UsageError("instants are not evenly spaced; give weights_h (hours per instant)")
    return np.full(len(instants), gaps[0] / 3600.0)


def _city_changes(scene, instants, t_days) -> str | None:
    """A warning when objects appear or disappear between the first and last instant."""
    if not scene.has_time or not instants:
        return None
    from cityshade.geo.temporal import datetime_to_days

    lo = min(datetime_to_days(t) for t in instants)
    hi = max(datetime_to_days(t) for t in instants)
    ends = np.concatenate([scene.obj_t_begin_days, scene.obj_t_end_days])
    n = int(((ends > lo) & (ends <= hi)).sum())
    if n:
        from cityshade.geo.temporal import days_to_iso

        return (f"{plural(n, 'object date')} fall{'s' if n == 1 else ''} inside the run; the "
                f"city is shown as it stood at {days_to_iso(t_days) if math.isfinite(t_days) else 'any time'} throughout")
    return None


def plan_run(scene, instants, t_days: float, suns, weights, warnings: list[str]):
    """:func:`plan_units` of a run, with its warnings (sun never up, the city changing)."""
    units, below, duplicates = plan_units(suns, weights)
    if not units:
        every = "the" if len(suns) == 1 else "all"
        warnings.append(f"the sun stays at or below the horizon in {every} "
                        f"{plural(len(suns), 'step')}: nothing is lit, sun-hours are 0 "
                        f"everywhere")
    change = _city_changes(scene, instants, float(t_days))
    if change:
        warnings.append(change)
    return units, below, duplicates


def unit_month_weights(units, weights_h: np.ndarray, step_month: Sequence[str] | None
                       ) -> tuple[list[str], np.ndarray]:
    """(month labels, (U, 1 + M) weights): column 0 the unit's total weight (its own), then
    its weight in each month (its steps' weights there, added in step order)."""
    months = sorted(set(step_month)) if step_month is not None else []
    col = {m: i + 1 for i, m in enumerate(months)}
    w = np.zeros((len(units), 1 + len(months)), np.float64)
    for u, unit in enumerate(units):
        w[u, 0] = unit.weight_h
        if step_month is not None:
            per: dict[int, float] = {}
            for i in unit.steps:
                c = col[step_month[i]]
                per[c] = per[c] + float(weights_h[i]) if c in per else float(weights_h[i])
            for c, v in per.items():
                w[u, c] = v
    return months, w

