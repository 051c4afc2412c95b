"""Coordinate reference systems of CityGML files: parsing ``srsName``, choosing a file's CRS,
projecting geographic coordinates and the meridian convergence for sun azimuths.

Conventions (docs/DESIGN.md §1)
-------------------------------
* Projected coordinates are always read **easting first** (x east, y north), whatever axis
  order the EPSG registry declares: Gauss-Krüger codes such as EPSG:31468 are northing-first in
  the registry, but every CityGML file writes easting first. All pyproj calls therefore use
  ``always_xy=True``.
* Geographic coordinates are reprojected to WGS 84 / UTM (:class:`GeographicProjector`); their
  axis order is decided from the value ranges, the right angles of the footprints and the
  srsName spelling (``EPSG:4326`` short form and CRS84 longitude first, URNs and http URIs
  latitude first), with a warning, or forced by ``--axis-order``.
* A CRS that cannot be used (an unknown spelling, a code that does not exist) makes the model
  build with its CRS recorded as unknown (:func:`unknown_crs`); an unknown height system of a
  compound CRS is dropped with a note (heights are kept as written anyway).
* Heights are never transformed: a city model's z is kept as written (vertical datums differ by
  centimetres to a few metres, which does not move a shadow).
* A compound code (``EPSG:5555``, ``EPSG:6697``) is split into its horizontal and vertical parts,
  so :attr:`CrsInfo.horizontal_epsg` is always a 2-D projected or geographic CRS (or a 3-D
  geographic one such as EPSG:4979).

pyproj is imported inside the functions that need it, so importing this module is cheap.
"""
from __future__ import annotations

import functools
import math
import re
from collections import Counter
from dataclasses import dataclass, fields
from typing import Any, Iterable, Mapping, NamedTuple
from urllib.parse import parse_qsl

import numpy as np

from cityshade.errors import CRSError

__all__ = [
    "AXIS_ORDERS", "CrsInfo", "CrsResolution", "GeographicProjector", "MAX_CONVERGENCE_DEG",
    "area_of_use_warning", "grid_convergence_deg", "parse_srs_name", "reproject_horizontal",
    "resolve_model_crs",
    "resolve_model_crs_detailed", "right_angle_share", "srs_name_notes", "to_wgs84",
    "unknown_crs",
]

#: Hint appended to every "cannot use this CRS" message. It names no example code: a code from
#: another country, followed literally, builds London in UTM 32N with the sun in the north.
_CRS_HINT = "give the CRS of the coordinates with --crs EPSG:nnnn"
#: What a model with an unknown CRS cannot do, for the warning and the later errors.
_REBUILD_HINT = "rebuild the scene with --crs EPSG:nnnn"


@dataclass(frozen=True)
class CrsInfo:
    """What cityshade knows about the CRS of a model.

    Attributes
    ----------
    srs_name : str or None
        The spelling found in the file (or given by the user); None when the file has none.
    horizontal_epsg : int or None
        EPSG code of the horizontal part, e.g. 25832; None for a local/engineering CRS or none.
    vertical_epsg : int or None
        EPSG code of the height system, e.g. 5783 (DHHN92 height), 7837 (DHHN2016 height);
        None when the spelling names none.
    is_geographic : bool
        True when the horizontal coordinates are degrees (EPSG:4326, 4979, 6697, 4258, ...).
    local : bool
        True for ``#local-CRS-1``-style references, engineering CRSs and files with no CRS: the
        coordinates are metres, but their place on Earth (and so the sun) is unknown.
    name : str
        Human-readable name, e.g. ``"ETRS89 / UTM zone 32N + DHHN92 height"``.
    """

    srs_name: str | None
    horizontal_epsg: int | None
    vertical_epsg: int | None
    is_geographic: bool
    local: bool
    name: str

    def to_json(self) -> dict:
        """Return a JSON-serialisable dict of all fields (for the cache and output metadata)."""
        return {f.name: getattr(self, f.name) for f in fields(self)}

    @classmethod
    def from_json(cls, d: Mapping[str, Any]) -> CrsInfo:
        """Rebuild a :class:`CrsInfo` from :meth:`to_json` output.

        Raises
        ------
        CRSError
            If keys are missing or unknown, or a value has the wrong type.
        """
        if not isinstance(d, Mapping):
            raise CRSError(f"CRS record must be a JSON object, not {type(d).__name__}")
        expected = {
            "srs_name": (str, type(None)), "horizontal_epsg": (int, type(None)),
            "vertical_epsg": (int, type(None)), "is_geographic": (bool,), "local": (bool,),
            "name": (str,),
        }
        if set(d) != set(expected):
            raise CRSError(f"CRS record has keys {sorted(d)}, expected {sorted(expected)}")
        for key, types in expected.items():
            value = d[key]
            # bool is an int subclass: an EPSG code of True is a type error, not EPSG:1.
            if not isinstance(value, types) or (types[0] is int and isinstance(value, bool)):
                raise CRSError(f"CRS record field {key!r} has the wrong type "
                               f"({type(value).__name__})")
        return cls(**{key: d[key] for key in expected})


#: What a file without any srsName gets (docs/DESIGN.md §1: renders with an explicit sun only).
NO_CRS = CrsInfo(srs_name=None, horizontal_epsg=None, vertical_epsg=None, is_geographic=False,
                 local=True, name="none")

# --- srsName spellings ----------------------------------------------------------------------

#: One EPSG code in any of its single-code spellings (matched case-insensitively, whole text):
#: ``EPSG:25832``, ``EPSG::25832``, ``urn:ogc:def:crs:EPSG::25832``, versioned
#: ``urn:ogc:def:crs:EPSG:6.12:25833``, the compound part ``crs:EPSG:5783``, the old
#: ``urn:x-ogc:…`` form, OGC http URIs ``http://www.opengis.net/def/crs/EPSG/0/6697`` (any
#: version segment, as CityJSON writes ``…/EPSG/6.12/3068``) and GML 2's
#: ``http://www.opengis.net/gml/srs/epsg.xml#4326``.
_SINGLE_CODE_RES = (
    re.compile(r"epsg::?(\d+)"),
    re.compile(r"(?:urn:(?:x-)?ogc:def:)?crs:epsg:(?:[\w.]*:)?(\d+)"),
    re.compile(r"https?://www\.opengis\.net/def/crs/epsg/[^/]*/(\d+)/?"),
    re.compile(r"https?://www\.opengis\.net/gml/srs/epsg\.xml#(\d+)"),
)
#: Head of the OGC compound URN ``urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783``.
_COMPOUND_URN_HEADS = ("urn:ogc:def:crs", "urn:x-ogc:def:crs")
#: Head of the OGC compound http URI ``…/def/crs-compound?1=<uri>&2=<uri>``.
_COMPOUND_URI_RE = re.compile(r"https?://www\.opengis\.net/def/crs-compound\?(.*)")

#: Horizontal parts of AdV URNs (``urn:adv:crs:<horizontal>[*<vertical>]``), the German
#: surveying authorities' names; codes checked against the EPSG names in PROJ 9.5.
_ADV_HORIZONTAL = {
    "ETRS89_LAT-LON": 4258,
    "DE_RD/83_3GK4": 3398, "DE_RD/83_3GK5": 3399,
    "DE_PD/83_3GK3": 3396, "DE_PD/83_3GK4": 3397,
    # DHDN / 3-degree Gauss-Kruger zones 2..5 are EPSG:31466..31469.
    **{f"DE_DHDN_3GK{zone}": 31464 + zone for zone in range(2, 6)},
    # ETRS89 / UTM zones 28N..38N are EPSG:25828..25838.
    **{f"ETRS89_UTM{zone}": 25800 + zone for zone in range(28, 39)},
}
_ADV_VERTICAL = {
    "DE_DHHN92_NH": 5783,
    "DE_DHN92_NH": 5783,  # misspelling found in the LDBV Munich CityGML 3 tile (12,128 times)
    "DE_DHHN2016_NH": 7837,
    "DE_DHHN12_NH": 7699,
    "DE_DHHN85_NN": 5784,
    "DE_SNN76_NH": 5785,
}
_ADV_HEAD = "urn:adv:crs:"
#: OGC's longitude-first WGS 84 (CRS84, 2-D; CRS84h, 3-D), as EPSG codes of the same datum.
_CRS84_RE = re.compile(r"(?:ogc:|urn:ogc:def:crs:ogc:[\w.]*:|"
                       r"https?://www\.opengis\.net/def/crs/ogc/[^/]*/)?(crs84h?)/?")
_CRS84_EPSG = {"crs84": 4326, "crs84h": 4979}


def _single_code(part: str) -> int | None:
    """EPSG code of one single-code spelling, or None when ``part`` is not one."""
    match = _CRS84_RE.fullmatch(part)
    if match:
        return _CRS84_EPSG[match.group(1)]
    for pattern in _SINGLE_CODE_RES:
        match = pattern.fullmatch(part)
        if match:
            return int(match.group(1))
    return None


def _codes_from_spelling(text: str) -> list[int] | None:
    """EPSG codes named by ``text`` (horizontal first), or None for an unknown spelling."""
    lowered = text.lower()
    # Take AdV URNs apart with their own tables.
    if lowered.startswith(_ADV_HEAD):
        horizontal, _, vertical = text[len(_ADV_HEAD):].partition("*")
        h_code = _ADV_HORIZONTAL.get(horizontal.strip().upper())
        v_code = _ADV_VERTICAL.get(vertical.strip().upper()) if vertical else None
        if h_code is None or (vertical and v_code is None):
            return None
        return [h_code] if v_code is None else [h_code, v_code]
    # Split the OGC compound http URI into its component URIs.
    match = _COMPOUND_URI_RE.fullmatch(lowered)
    if match:
        parts = [value for _, value in sorted(parse_qsl(match.group(1)))]
    elif "," in lowered:
        # Compound URN, or the comma-and-space form 'urn:ogc:def:crs:EPSG:25832, crs:EPSG:5783'.
        parts = [p.strip() for p in lowered.split(",")]
        if parts[0] in _COMPOUND_URN_HEADS:
            parts = parts[1:]
    elif "+" in lowered and lowered.startswith("epsg:"):
        # pyproj's own compound shorthand 'EPSG:25832+5783', handy for --crs.
        head, *rest = lowered.split("+")
        parts = [head] + [f"epsg:{p.strip()}" for p in rest]
    else:
        parts = [lowered]
    codes = [_single_code(p) for p in parts]
    if not parts or any(c is None for c in codes):
        return None
    return codes


@functools.lru_cache(maxsize=None)
def _pyproj_crs(epsg: int):
    """pyproj CRS of an EPSG code (cached: building one costs a database query)."""
    from pyproj import CRS
    from pyproj.exceptions import CRSError as PyprojCRSError

    try:
        return CRS.from_epsg(epsg)
    except PyprojCRSError:
        return None


def _sub_code(sub) -> int | None:
    """EPSG code of a component of a compound pyproj CRS."""
    code = sub.to_epsg(min_confidence=100)
    return int(code) if code is not None else None


def _unknown_code_message(code: int, srs_name: str) -> str:
    from pyproj import proj_version_str
    return (f"EPSG:{code} does not exist (no such code in the EPSG registry of PROJ "
            f"{proj_version_str}; given as {srs_name!r})")


@functools.lru_cache(maxsize=1024)  # a file repeats the same srsName thousands of times
def _parse_cached(srs_name: str) -> tuple[CrsInfo, tuple[str, ...]]:
    """(CrsInfo, notes) of a spelling; notes say what was left out (an unknown height system)."""
    text = srs_name.strip()
    if not text:
        raise CRSError(f"empty srsName; {_CRS_HINT}")
    # Refer to a CRS defined inside the file (gml:EngineeringCRS) or elsewhere: local metres.
    if text.startswith("#"):
        return CrsInfo(srs_name=srs_name, horizontal_epsg=None, vertical_epsg=None,
                       is_geographic=False, local=True, name=f"local CRS {text}"), ()
    codes = _codes_from_spelling(text)
    if codes is None:
        raise CRSError(f"unknown CRS spelling {srs_name!r} (not an EPSG code, OGC URN/URI or "
                       f"AdV URN that cityshade understands); {_CRS_HINT}")
    if len(codes) > 2:
        raise CRSError(f"CRS {srs_name!r} names {len(codes)} components; expected a horizontal "
                       f"CRS and at most one height system; {_CRS_HINT}")
    notes: list[str] = []
    crss = []
    for k, code in enumerate(codes):
        crs = _pyproj_crs(code)
        if crs is None:
            if k == 0:
                raise CRSError(f"{_unknown_code_message(code, srs_name)}; {_CRS_HINT}")
            # Heights are kept as written anyway (module docstring): an unknown height system
            # (UK producers write EPSG:5101, Newlyn, which PROJ lacks) loses nothing.
            notes.append(f"height system EPSG:{code} of {srs_name!r} is unknown to PROJ; "
                         f"using the horizontal part EPSG:{codes[0]}, heights as written")
            continue
        crss.append((code, crs))
    h_code, h_crs = crss[0]
    v_code = None
    v_name = None
    # Split a compound code into its horizontal and vertical parts.
    if h_crs.is_compound:
        subs = h_crs.sub_crs_list
        h_crs = subs[0]
        h_code = _sub_code(h_crs)
        if len(subs) > 1 and subs[1].is_vertical:
            v_code, v_name = _sub_code(subs[1]), subs[1].name
    if len(crss) == 2:
        if v_code is not None:
            raise CRSError(f"CRS {srs_name!r} names two height systems; {_CRS_HINT}")
        v_code, v_crs = crss[1]
        if not v_crs.is_vertical or v_crs.is_compound:
            raise CRSError(f"second component EPSG:{v_code} of {srs_name!r} is a "
                           f"{v_crs.type_name}, not a height system; {_CRS_HINT}")
        v_name = v_crs.name
    # Refuse what cannot place a city: heights alone, geocentric XYZ, engineering, feet.
    if h_crs.is_vertical:
        raise CRSError(f"CRS {srs_name!r} names only a height system ({h_crs.name}), no "
                       f"horizontal CRS; {_CRS_HINT}")
    if h_crs.is_engineering:
        return CrsInfo(srs_name=srs_name, horizontal_epsg=None, vertical_epsg=v_code,
                       is_geographic=False, local=True, name=h_crs.name), tuple(notes)
    if not (h_crs.is_projected or h_crs.is_geographic):
        raise CRSError(f"CRS {srs_name!r} is a {h_crs.type_name} ({h_crs.name}); cityshade "
                       f"needs a projected or geographic CRS; {_CRS_HINT}")
    if h_crs.is_projected:
        units = {axis.unit_name for axis in h_crs.axis_info}
        if units != {"metre"}:
            # The scene is in metres (docs/DESIGN.md §1); silently scaling feet would be worse.
            raise CRSError(f"CRS {srs_name!r} ({h_crs.name}) has axis unit(s) "
                           f"{', '.join(sorted(units))}; cityshade supports metre-based "
                           f"projected CRSs and geographic CRSs only")
    name = h_crs.name if v_name is None else f"{h_crs.name} + {v_name}"
    return CrsInfo(srs_name=srs_name, horizontal_epsg=h_code, vertical_epsg=v_code,
                   is_geographic=bool(h_crs.is_geographic), local=False, name=name), tuple(notes)


def srs_name_notes(srs_name: str) -> tuple[str, ...]:
    """What :func:`parse_srs_name` left out of a spelling (e.g. an unknown height system)."""
    return _parse_cached(srs_name)[1] if isinstance(srs_name, str) else ()


def unknown_crs(srs_name: str) -> CrsInfo:
    """The record of a CRS cityshade cannot use: local metres, no place on Earth."""
    return CrsInfo(srs_name=srs_name, horizontal_epsg=None, vertical_epsg=None,
                   is_geographic=False, local=True, name=f"unknown ({srs_name})")


def parse_srs_name(srs_name: str) -> CrsInfo:
    """Parse a CityGML ``srsName`` (or a user's ``--crs``) into a :class:`CrsInfo`.

    Understood spellings (case-insensitive): ``EPSG:25832``; ``urn:ogc:def:crs:EPSG::25832``
    and versioned ``urn:ogc:def:crs:EPSG:6.12:25833``; compound URNs
    ``urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::5783`` (also versioned) and the comma-and-space
    form ``urn:ogc:def:crs:EPSG:25832, crs:EPSG:5783``; OGC URIs
    ``http://www.opengis.net/def/crs/EPSG/0/6697`` and ``…/def/crs-compound?1=…&2=…``;
    ``EPSG:25832+5783``; AdV URNs ``urn:adv:crs:ETRS89_UTM32[*DE_DHHN92_NH]``,
    ``urn:adv:crs:DE_DHDN_3GK4*DE_DHHN92_NH`` (GK zones 2..5, UTM zones 28..38, DHHN92,
    DHHN2016, DHHN12, and the misspelt ``DE_DHN92_NH`` of a real file). A reference starting
    with ``#`` (``#local-CRS-1``) is a local CRS.

    Parameters
    ----------
    srs_name : str
        The text of the ``srsName`` attribute.

    Returns
    -------
    CrsInfo
        Cached per spelling: the same object is returned for the same text.

    Raises
    ------
    CRSError
        Unknown spelling, an EPSG code PROJ does not know, a CRS that is neither projected nor
        geographic (geocentric, vertical only), or a projected CRS not in metres.
    """
    if not isinstance(srs_name, str):
        raise CRSError(f"srsName must be text, not {type(srs_name).__name__}")
    return _parse_cached(srs_name)[0]


class CrsResolution(NamedTuple):
    """The CRS chosen for a whole file, with the warnings the reader should report."""

    crs: CrsInfo
    warnings: tuple[str, ...]


def resolve_model_crs_detailed(srs_names: Iterable[str],
                               override: str | None = None) -> CrsResolution:
    """Choose the CRS of a whole file and say what was odd about its ``srsName`` values.

    The rules of :func:`resolve_model_crs`; besides, the warnings name the other horizontal
    CRSs found (with their counts), the unknown spellings that were ignored, a height system
    PROJ does not know, and an unknown CRS the file was built without.
    """
    if override is not None:
        return CrsResolution(parse_srs_name(override), srs_name_notes(override))
    counts = Counter(srs_names)
    # Group the spellings by the CRS they name, so 'EPSG:25832' and its URN count together.
    by_crs: dict[int, Counter] = {}
    unknown: Counter = Counter()
    unknown_errors: dict[str, CRSError] = {}
    first_local: CrsInfo | None = None
    for name, count in counts.items():
        try:
            info = parse_srs_name(name)
        except CRSError as exc:
            unknown[name] += count
            unknown_errors[name] = exc
            continue
        if info.local:
            first_local = first_local or info
            continue
        by_crs.setdefault(info.horizontal_epsg, Counter())[name] += count
    if not by_crs:
        if unknown:
            # Build anyway (docs/DESIGN.md §1): what needs no geodesy works; the rest names --crs.
            name = unknown.most_common(1)[0][0]
            why = str(unknown_errors[name]).removesuffix(f"; {_CRS_HINT}")
            warnings = [f"the CRS of the file is unknown: {why}; building in its coordinates "
                        f"without a place on Earth (for a sun from a date, true north or a "
                        f"GeoTIFF's CRS, {_REBUILD_HINT})"]
            warnings += [f"ignored {c}× unknown srsName {n!r}: {unknown_errors[n]}"
                         for n, c in unknown.items() if n != name]
            return CrsResolution(unknown_crs(name), tuple(warnings))
        return CrsResolution(first_local or NO_CRS, ())
    # Take the most frequent horizontal CRS (ties: first seen); within it the most frequent
    # spelling, preferring one that also names the height system. A known CRS wins over
    # unknown spellings, whatever their counts: a model placed on Earth is worth a warning.
    ranked = sorted(by_crs.items(), key=lambda item: -sum(item[1].values()))
    _, spellings = ranked[0]
    total = sum(spellings.values())
    best = max(spellings.items(),
               key=lambda item: (item[1], parse_srs_name(item[0]).vertical_epsg is not None))[0]
    crs = parse_srs_name(best)
    warnings = list(srs_name_notes(best))
    if len(ranked) > 1:
        others = ", ".join(f"{parse_srs_name(next(iter(s))).name} ({sum(s.values())}×)"
                           for _, s in ranked[1:])
        warnings.append(f"several horizontal CRSs in one file: using {crs.name} ({total}×), "
                        f"ignoring {others}")
    for name, count in unknown.items():
        warnings.append(f"ignored {count}× unknown srsName {name!r}: {unknown_errors[name]}")
    return CrsResolution(crs, tuple(warnings))


def resolve_model_crs(srs_names: Iterable[str], override: str | None = None) -> CrsInfo:
    """The CRS of a whole file.

    Parameters
    ----------
    srs_names : iterable of str
        Every ``srsName`` value met in the file, repeats included (their counts decide).
    override : str, optional
        A user's ``--crs`` in any spelling :func:`parse_srs_name` understands; it wins.

    Returns
    -------
    CrsInfo
        The override; else the most frequent known non-local CRS (spellings of the same
        horizontal EPSG code count together; with several horizontal CRSs the most frequent
        wins, see :func:`resolve_model_crs_detailed` for the warnings); else, when the file
        only has unknown spellings or codes, :func:`unknown_crs` of the most frequent (local,
        no place on Earth); else the first local CRS; else
        ``CrsInfo(local=True, name="none")`` for a file without any srsName.

    Raises
    ------
    CRSError
        The override cannot be parsed or names a code that does not exist.
    """
    return resolve_model_crs_detailed(srs_names, override).crs


# --- geographic coordinates -----------------------------------------------------------------

#: Largest |latitude| accepted as a city's when both axis orders fit: city models are not in
#: Antarctica nor on the Arctic ice (the northernmost towns lie near 78°N, but there an order
#: mistake cannot happen: a longitude-first reading would need |longitude| > 75°).
_MAX_CITY_LATITUDE_DEG = 75.0


def _require_projectable(crs: CrsInfo, purpose: str) -> None:
    """Raise unless ``crs`` places the model on Earth; ``purpose`` says what needs it."""
    if not isinstance(crs, CrsInfo):
        raise CRSError(f"expected a CrsInfo, not {type(crs).__name__}")
    if crs.local or crs.horizontal_epsg is None:
        raise CRSError(f"the model has no CRS ({crs.name}: local coordinates), so {purpose} "
                       f"is unknown; {_REBUILD_HINT} (or give --crs EPSG:nnnn)")


@functools.lru_cache(maxsize=64)
def _transformer(from_epsg: int, to_epsg: int):
    """Cached easting/longitude-first transformer between two EPSG codes."""
    from pyproj import Transformer
    return Transformer.from_crs(_pyproj_crs(from_epsg), _pyproj_crs(to_epsg), always_xy=True)


@functools.lru_cache(maxsize=64)
def _proj(epsg: int):
    """Cached pyproj Proj of a projected CRS (longitude/latitude in its own datum)."""
    from pyproj import Proj
    return Proj(_pyproj_crs(epsg))


def _utm_epsg(lon_deg: float, lat_deg: float) -> int:
    """EPSG code of the WGS 84 / UTM zone containing (lon, lat): 326zz north, 327zz south.

    The plain 6° zone is used, also where UTM has exceptions (Norway, Svalbard): the projection
    is only needed to be metric and nearly conformal near the data.
    """
    zone = int(math.floor((lon_deg + 180.0) / 6.0)) + 1
    zone = min(max(zone, 1), 60)  # lon = 180° exactly belongs to zone 60
    return (32600 if lat_deg >= 0.0 else 32700) + zone


def _as_xyz(xyz: np.ndarray, what: str) -> np.ndarray:
    arr = np.asarray(xyz, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise CRSError(f"{what} must have shape (N, 3), not {arr.shape}")
    return arr


#: Axis orders a user can force (``--axis-order``).
AXIS_ORDERS = ("lonlat", "latlon")
#: A corner counts as right-angled within this many degrees; footprints drawn by surveyors
#: are right to well under a degree, a 1.5× stretch of the wrong order bends them by ~20°.
_RIGHT_ANGLE_TOL_DEG = 2.0
#: Corners nearer than this to straight or to a spike say nothing about right angles.
_CORNER_MIN_SIN = math.sin(math.radians(60.0))
#: Edges shorter than this (metres, horizontal) are ignored: walls seen from above.
_CORNER_MIN_EDGE_M = 0.5
#: The geometric test decides when one order has this many more right-angled corners (as a
#: share of the corners counted) and at least this many corners were counted.
_RIGHT_ANGLE_MIN_MARGIN = 0.2
_RIGHT_ANGLE_MIN_CORNERS = 4
#: Mean Earth radius for the local equirectangular projection of the corner test (angles
#: only; the radius cancels).
_EARTH_RADIUS_M = 6_371_000.0


def _spelling_order(srs_name: str | None) -> tuple[bool | None, str]:
    """(latitude first?, why) from the srsName spelling; None when it says nothing.

    GML 3.1 practice writes the short forms ``EPSG:4326`` and GML 2's
    ``…/gml/srs/epsg.xml#4326`` longitude first, like CRS84; the URN and the OGC http URI
    forms mean the EPSG definition's own order.
    """
    if not srs_name:
        return None, "no srsName"
    text = srs_name.strip().lower()
    if _CRS84_RE.fullmatch(text):
        return False, f"{srs_name!r} is longitude first by definition"
    if re.fullmatch(r"epsg::?\d+", text) or text.startswith("http://www.opengis.net/gml/srs/"):
        return False, f"the short spelling {srs_name!r} means longitude first in GML 3.1 practice"
    if text.startswith(("urn:", "http://", "https://")):
        return True, f"the spelling {srs_name!r} means the EPSG order, latitude first"
    return None, f"the spelling {srs_name!r} implies no order"


def right_angle_share(lon_deg: np.ndarray, lat_deg: np.ndarray,
                      ring_offsets: np.ndarray) -> tuple[float, int]:
    """Share of the horizontal ring corners that are right angles, and how many were counted.

    The rings are projected to a local equirectangular plane (conformal at the centre, so
    angles within a city are true to ~1e-4 rad). A corner is counted when both its horizontal
    edges are longer than 0.5 m (walls seen from above have none) and it is not near straight
    or a spike (60°–120°); it is right when within 2° of 90°.

    Parameters
    ----------
    lon_deg, lat_deg : (N,) float64
        Ring points, degrees, in ring order.
    ring_offsets : (R + 1,) int
        Ring ``r`` is points ``ring_offsets[r]:ring_offsets[r + 1]``.
    """
    lat0 = math.radians(0.5 * (float(lat_deg.min()) + float(lat_deg.max())))
    if abs(lat0) >= math.pi / 2:
        return 0.0, 0
    x = np.radians(lon_deg) * math.cos(lat0) * _EARTH_RADIUS_M
    y = np.radians(lat_deg) * _EARTH_RADIUS_M
    offsets = np.asarray(ring_offsets, np.int64)
    # Edge i joins point i to i + 1 inside a ring; corner i joins edges i and i + 1.
    n = x.shape[0]
    ring_of = np.repeat(np.arange(len(offsets) - 1), np.diff(offsets))
    same = ring_of[:-1] == ring_of[1:]
    ex, ey = np.diff(x), np.diff(y)
    length = np.hypot(ex, ey)
    valid_edge = same & (length > _CORNER_MIN_EDGE_M)
    if n < 3:
        return 0.0, 0
    a, b = slice(0, n - 2), slice(1, n - 1)
    corner = valid_edge[a] & valid_edge[b] & same[a] & same[b]
    with np.errstate(invalid="ignore", divide="ignore"):
        cross = (ex[a] * ey[b] - ey[a] * ex[b]) / (length[a] * length[b])
    counted = corner & (np.abs(cross) >= _CORNER_MIN_SIN)
    k = int(counted.sum())
    if k == 0:
        return 0.0, 0
    right = np.abs(cross[counted]) >= math.cos(math.radians(_RIGHT_ANGLE_TOL_DEG))
    return float(right.mean()), k


class GeographicProjector:
    """Project geographic coordinates (degrees) to a WGS 84 / UTM zone chosen from the data.

    The zone (EPSG:326zz north, 327zz south) is the one of the centre of the sample's bounding
    box. Heights are kept as written.

    The axis order is decided, in this order (docs/DESIGN.md §1):

    1. ``axis_order`` (the user's ``--axis-order lonlat|latlon``), when given;
    2. the value ranges, where they decide: |value| > 90 can only be a longitude; a reading
       whose latitudes would be polar (> 75°) loses to one that is not (city models are not
       on the ice);
    3. geometry, where the values fit both orders (a German city at 8.4° E, 49.0° N does):
       building footprints are mostly right-angled, and the wrong order stretches the model
       by cos(lat)/cos(lon) across the diagonal, bending every corner not parallel to the axes.
       Both readings are projected (:func:`right_angle_share`) and the clearly more
       right-angled one wins;
    4. the srsName spelling: ``EPSG:4326`` (short form), GML 2 URLs and CRS84 are longitude
       first in practice; URNs and OGC http URIs latitude first as EPSG defines;
    5. the CRS definition's order.

    :attr:`warning` always says what was chosen and why.

    Parameters
    ----------
    crs : CrsInfo
        A geographic CRS (``crs.is_geographic``).
    sample_xyz : numpy.ndarray
        (N, 3) float64 coordinates as written in the file (first two columns in file order);
        non-finite rows are ignored.
    axis_order : {"lonlat", "latlon"}, optional
        Forced order; an order under which the values are no degrees is an error.
    ring_offsets : (R + 1,) int array, optional
        The rings of ``sample_xyz`` for the geometric test (without it, no geometric test).
    target : CrsInfo, optional
        A projected CRS to project to (a multi-file build's ``--crs``); default the UTM zone.

    Attributes
    ----------
    axis_lat_first : bool
        True when the file's first coordinate is the latitude.
    reason : str
        Why this order.
    warning : str
        What was chosen and why, for the build report.
    target : CrsInfo
        The metric CRS the scene will be in.
    source : CrsInfo
        The geographic CRS given.

    Raises
    ------
    CRSError
        ``crs`` is not geographic, the sample is empty, no axis order makes every point a
        valid longitude/latitude (projected coordinates under a geographic srsName), or the
        forced order does not.
    """

    def __init__(self, crs: CrsInfo, sample_xyz: np.ndarray, axis_order: str | None = None,
                 ring_offsets: np.ndarray | None = None, target: CrsInfo | None = None):
        _require_projectable(crs, "the place on Earth")
        if not crs.is_geographic:
            raise CRSError(f"{crs.name} is not a geographic CRS; nothing to project")
        if axis_order is not None and axis_order not in AXIS_ORDERS:
            raise CRSError(f"axis order must be one of {', '.join(AXIS_ORDERS)}, "
                           f"not {axis_order!r}")
        sample = _as_xyz(sample_xyz, "sample_xyz")
        finite = np.isfinite(sample[:, 0]) & np.isfinite(sample[:, 1])
        if not finite.any():
            raise CRSError(f"no finite coordinates to decide the axis order of {crs.name}")
        self.source = crs
        axes = _pyproj_crs(crs.horizontal_epsg).axis_info
        official_lat_first = axes[0].direction.lower() == "north"
        fin = sample[finite]
        abs0 = np.abs(fin[:, 0]).max()
        abs1 = np.abs(fin[:, 1]).max()
        # Decide which orders fit every point at all.
        lat_first_fits = abs0 <= 90.0 and abs1 <= 180.0
        lon_first_fits = abs0 <= 180.0 and abs1 <= 90.0
        ranges = f"first axis up to |{abs0:.6g}|, second up to |{abs1:.6g}|"
        if not (lat_first_fits or lon_first_fits):
            raise CRSError(f"coordinates up to |{abs0:.6g}|, |{abs1:.6g}| are not degrees, "
                           f"but the srsName says {crs.name} (EPSG:{crs.horizontal_epsg}); "
                           f"{_CRS_HINT}")
        lat_first: bool | None = None
        if axis_order is not None:
            lat_first = axis_order == "latlon"
            if not (lat_first_fits if lat_first else lon_first_fits):
                raise CRSError(f"--axis-order {axis_order} does not fit the coordinates "
                               f"({ranges}): latitudes would exceed 90°")
            reason = f"--axis-order {axis_order}"
        elif not (lat_first_fits and lon_first_fits):
            lat_first = lat_first_fits
            reason = f"only this order gives valid degrees ({ranges})"
        elif (abs0 <= _MAX_CITY_LATITUDE_DEG) != (abs1 <= _MAX_CITY_LATITUDE_DEG):
            lat_first = abs0 <= _MAX_CITY_LATITUDE_DEG
            reason = (f"the other order puts the model beyond {_MAX_CITY_LATITUDE_DEG:g}° of "
                      f"latitude ({ranges})")
        spelled, spelled_why = _spelling_order(crs.srs_name)
        if lat_first is None and ring_offsets is not None:
            offsets = np.asarray(ring_offsets, np.int64)
            share_lonlat, n_lonlat = right_angle_share(sample[:, 0], sample[:, 1], offsets)
            share_latlon, n_latlon = right_angle_share(sample[:, 1], sample[:, 0], offsets)
            if (min(n_lonlat, n_latlon) >= _RIGHT_ANGLE_MIN_CORNERS
                    and abs(share_lonlat - share_latlon) >= _RIGHT_ANGLE_MIN_MARGIN):
                lat_first = share_latlon > share_lonlat
                reason = (f"building corners are right-angled in this order "
                          f"({100 * max(share_lonlat, share_latlon):.0f} % of "
                          f"{n_latlon if lat_first else n_lonlat} corners, against "
                          f"{100 * min(share_lonlat, share_latlon):.0f} % in the other)")
                if spelled is not None and spelled != lat_first:
                    reason += f", although {spelled_why}"
        if lat_first is None:
            if spelled is not None:
                lat_first, reason = spelled, spelled_why
            else:
                lat_first = official_lat_first
                reason = f"{spelled_why}: the EPSG definition's order"
        self.axis_lat_first = bool(lat_first)
        self.reason = reason
        written = "latitude" if self.axis_lat_first else "longitude"
        other = "lonlat" if self.axis_lat_first else "latlon"
        self.warning = (f"{crs.name} coordinates read {written} first: {reason}; "
                        f"override with --axis-order {other}")
        lon, lat = self._lon_lat(fin)
        # Centre of the bounding box (not the mean: a few far-off objects must not drag it).
        centre_lon = 0.5 * (lon.min() + lon.max())
        centre_lat = 0.5 * (lat.min() + lat.max())
        self.target = target or parse_srs_name(f"EPSG:{_utm_epsg(centre_lon, centre_lat)}")

    def _lon_lat(self, xyz: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        if self.axis_lat_first:
            return xyz[:, 1], xyz[:, 0]
        return xyz[:, 0], xyz[:, 1]

    def project(self, xyz: np.ndarray) -> np.ndarray:
        """Project file coordinates to :attr:`target`.

        Parameters
        ----------
        xyz : numpy.ndarray
            (N, 3) float64 in file order (degrees, degrees, height).

        Returns
        -------
        numpy.ndarray
            (N, 3) float64: easting_m, northing_m, height as written.

        Raises
        ------
        CRSError
            A finite input point has no finite projection (outside the projection's domain).
        """
        src = _as_xyz(xyz, "xyz")
        lon, lat = self._lon_lat(src)
        transformer = _transformer(self.source.horizontal_epsg, self.target.horizontal_epsg)
        east_m, north_m = transformer.transform(np.ascontiguousarray(lon),
                                                np.ascontiguousarray(lat))
        out = np.empty_like(src)
        out[:, 0] = east_m
        out[:, 1] = north_m
        out[:, 2] = src[:, 2]
        finite_in = np.isfinite(src[:, 0]) & np.isfinite(src[:, 1])
        finite_out = np.isfinite(out[:, 0]) & np.isfinite(out[:, 1])
        bad = finite_in & ~finite_out
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise CRSError(f"{int(bad.sum())} point(s) cannot be projected to "
                           f"{self.target.name}, first ({lon[i]:.9g}, {lat[i]:.9g}) lon/lat")
        return out


def reproject_horizontal(xyz: np.ndarray, source: CrsInfo, target: CrsInfo, *,
                         lonlat_source: bool = False) -> np.ndarray:
    """Coordinates of projected CRS ``source`` → projected CRS ``target`` (easting, northing;
    heights kept as written: the tiles of one city share their height system).
    ``lonlat_source`` also accepts a geographic ``source`` whose points are longitude first
    (GeoJSON's order, RFC 7946 §3.1.1, whatever the CRS declares).

    Raises
    ------
    CRSError
        Either CRS is not a projected one with an EPSG code, or a point has no projection.
    """
    for crs in (source, target):
        _require_projectable(crs, "the projection between tiles")
        if crs.is_geographic and not (lonlat_source and crs is source):
            raise CRSError(f"{crs.name} is geographic; expected a projected CRS")
    src = _as_xyz(xyz, "xyz")
    out = src.copy()
    if source.horizontal_epsg == target.horizontal_epsg:
        return out
    transformer = _transformer(source.horizontal_epsg, target.horizontal_epsg)
    out[:, 0], out[:, 1] = transformer.transform(np.ascontiguousarray(src[:, 0]),
                                                 np.ascontiguousarray(src[:, 1]))
    bad = np.isfinite(src[:, :2]).all(axis=1) & ~np.isfinite(out[:, :2]).all(axis=1)
    if bad.any():
        raise CRSError(f"{int(bad.sum())} point(s) of {source.name} cannot be projected to "
                       f"{target.name}")
    return out


#: A scene's place as its file stores it (:func:`place_record`, :func:`remember_place`): the
#: grid convergence and WGS 84 position of its origin, by CRS and point, so a command turns its
#: sun without importing pyproj (30-40 ms of a one-frame render).
_PLACES: dict[tuple[CrsInfo, float, float], dict] = {}


def place_record(crs: CrsInfo, x: float, y: float) -> dict | None:
    """``{"point", "convergence_deg", "wgs84"}`` of a point (a scene's origin, stored in its
    file when it is built), or None where :func:`grid_convergence_deg` or :func:`to_wgs84`
    refuses it (the command that needs it then says why)."""
    try:
        lon, lat, _ = to_wgs84(crs, x, y)
        return {"point": [float(x), float(y)], "convergence_deg": grid_convergence_deg(crs, x, y),
                "wgs84": [lon, lat]}
    except CRSError:
        return None


def remember_place(crs: CrsInfo, record: Any) -> None:
    """Answer :func:`grid_convergence_deg` and :func:`to_wgs84` at ``record``'s point from
    it (a loaded scene's stored :func:`place_record`) instead of asking pyproj. Anything but
    such a record (None, an older file's nothing, a malformed one) is left out: pyproj
    answers then, as without it."""
    try:
        x, y = (float(v) for v in record["point"])
        convergence = float(record["convergence_deg"])
        lon, lat = (float(v) for v in record["wgs84"])
    except (TypeError, KeyError, ValueError):
        return
    if all(math.isfinite(v) for v in (x, y, convergence, lon, lat)) and abs(lat) <= 90.0:
        _PLACES[(crs, x, y)] = {"convergence_deg": convergence, "wgs84": (lon, lat)}


def to_wgs84(crs: CrsInfo, x: float, y: float, z: float = 0.0) -> tuple[float, float, float]:
    """Longitude, latitude (WGS 84, degrees) and height of a point of the model.

    Parameters
    ----------
    crs : CrsInfo
        The model's CRS (projected, or geographic with ``x`` = longitude, ``y`` = latitude).
    x, y : float
        Easting and northing in metres (projected), or longitude and latitude (geographic).
    z : float
        Height; returned unchanged (no vertical datum shift).

    Returns
    -------
    tuple of float
        ``(lon_deg, lat_deg, h)``.

    Raises
    ------
    CRSError
        Local CRS or no CRS, or the point has no WGS 84 position.
    """
    known = _PLACES.get((crs, float(x), float(y)))
    if known is not None:
        return known["wgs84"][0], known["wgs84"][1], float(z)
    _require_projectable(crs, "the place on Earth")
    if crs.horizontal_epsg == 4326:
        lon_deg, lat_deg = float(x), float(y)
    else:
        lon_deg, lat_deg = _transformer(crs.horizontal_epsg, 4326).transform(float(x), float(y))
    if not (math.isfinite(lon_deg) and math.isfinite(lat_deg)):
        raise CRSError(f"point ({x}, {y}) of {crs.name} has no WGS 84 position")
    return float(lon_deg), float(lat_deg), float(z)


#: Degrees by which a model may reach beyond its CRS's area of use before it is warned about:
#: producers use UTM and Gauss-Krüger zones a little beyond their bands (the Netherlands in
#: EPSG:25832); a wrong CRS or a 10^7 m offset misses by far more.
_AREA_OF_USE_MARGIN_DEG = 3.0
#: Largest meridian convergence accepted for true → grid north outside polar projections:
#: transverse Mercator zones stay within ~3.5° and national conic grids within ~7° inside
#: their areas of use; +139.8° (the sample shifted by 10^7 m) only comes from wrong places.
MAX_CONVERGENCE_DEG = 15.0


def _area_of_use(epsg: int):
    crs = _pyproj_crs(epsg)
    return None if crs is None else crs.area_of_use


def area_of_use_warning(crs: CrsInfo, lo_m, hi_m) -> str | None:
    """A warning when the model's bounding box lies outside its CRS's area of use.

    Parameters
    ----------
    crs : CrsInfo
        The model's (projected or geographic) CRS; local and unknown CRSs get None.
    lo_m, hi_m : sequence of float
        Lower and upper corners of the bounding box in CRS coordinates (x, y first).

    Returns
    -------
    str or None
        The warning (the box in degrees, the area of use, what goes wrong), or None when the
        box lies within the area of use widened by 3°.
    """
    if crs.local or crs.horizontal_epsg is None:
        return None
    area = _area_of_use(crs.horizontal_epsg)
    if area is None:
        return None
    xs = [float(lo_m[0]), float(hi_m[0])]
    ys = [float(lo_m[1]), float(hi_m[1])]
    if crs.is_geographic:
        lons, lats = xs, ys
    else:
        with np.errstate(all="ignore"):
            lons, lats = _transformer(crs.horizontal_epsg, 4326).transform(
                np.array([xs[0], xs[1], xs[0], xs[1]]), np.array([ys[0], ys[0], ys[1], ys[1]]))
        lons, lats = list(np.asarray(lons)), list(np.asarray(lats))
    m = _AREA_OF_USE_MARGIN_DEG
    west, south, east, north = area.west, area.south, area.east, area.north
    finite = all(math.isfinite(v) for v in (*lons, *lats))
    if finite and all(abs(v) <= 90.0 for v in lats):
        if west > east:  # the area crosses the antimeridian
            inside_lon = all(v >= west - m or v <= east + m for v in lons)
        else:
            inside_lon = all(west - m <= v <= east + m for v in lons)
        if inside_lon and all(south - m <= v <= north + m for v in lats):
            return None
        where = (f"{min(lons):.3f}…{max(lons):.3f}° E, {min(lats):.3f}…{max(lats):.3f}° N")
    else:
        where = "no place on Earth"
    return (f"the model's bounding box ({xs[0]:.0f}…{xs[1]:.0f}, {ys[0]:.0f}…{ys[1]:.0f}) "
            f"lies outside the area of use of {crs.name} (EPSG:{crs.horizontal_epsg}: "
            f"{west:.1f}…{east:.1f}° E, {south:.1f}…{north:.1f}° N, {area.name.split(':')[0]}): "
            f"it maps to "
            f"{where}, so the CRS (or the coordinates) are wrong and the sun would be wrong; "
            f"{_REBUILD_HINT} naming the right CRS")


def _is_polar_projection(epsg: int) -> bool:
    operation = _pyproj_crs(epsg).coordinate_operation
    method = (operation.method_name if operation is not None else "").lower()
    return "polar" in method or "azimuthal" in method


def grid_convergence_deg(crs: CrsInfo, x: float, y: float) -> float:
    """Meridian (grid) convergence at a point: the angle from true north to grid north.

    Convention: degrees, positive when grid north lies clockwise (east) of true north, so
    ``azimuth_grid_deg = azimuth_true_deg - convergence_deg`` for any direction. This is the
    sign of PROJ's ``meridian_convergence`` factor; it is negative west of a Transverse
    Mercator central meridian in the northern hemisphere (γ ≈ Δλ·sin φ).

    Parameters
    ----------
    crs : CrsInfo
        The model's CRS. For a geographic CRS grid north is true north and 0.0 is returned.
    x, y : float
        Easting and northing in metres.

    Returns
    -------
    float
        Convergence in degrees.

    Raises
    ------
    CRSError
        Local CRS or no CRS ("the model has no CRS; give --crs"), a point outside the
        projection's domain, or an absurd convergence (beyond :data:`MAX_CONVERGENCE_DEG` in a
        projection that is not polar): the point is far outside the CRS's area of use, and
        turning a true azimuth by that angle would make shadows fall the wrong way.
    """
    known = _PLACES.get((crs, float(x), float(y)))
    if known is not None:
        return known["convergence_deg"]
    _require_projectable(crs, "true north")
    if crs.is_geographic:
        return 0.0
    proj = _proj(crs.horizontal_epsg)
    lon_deg, lat_deg = proj(float(x), float(y), inverse=True)
    factors = proj.get_factors(lon_deg, lat_deg)
    convergence_deg = float(factors.meridian_convergence)
    if not math.isfinite(convergence_deg):
        raise CRSError(f"point ({x}, {y}) is outside the domain of {crs.name}; "
                       f"{_REBUILD_HINT} naming the right CRS")
    if abs(convergence_deg) > MAX_CONVERGENCE_DEG and not _is_polar_projection(
            crs.horizontal_epsg):
        raise CRSError(f"the meridian convergence of {crs.name} at the model's origin "
                       f"({x:.0f}, {y:.0f}) is {convergence_deg:+.1f}°, which its projection "
                       f"never gives in its area of use (at most ±{MAX_CONVERGENCE_DEG:g}° is "
                       f"believable): the coordinates are not in {crs.name}, so true north "
                       f"cannot be turned to grid north; {_REBUILD_HINT} naming the right CRS")
    return convergence_deg
