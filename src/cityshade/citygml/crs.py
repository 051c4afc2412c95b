"""Coordinate reference systems of CityGML files: parsing ``srsName``, choosing a file's CRS,
projecting geographic coordinates and the meridian convergence for sun azimuths.

Conventions (DESIGN §3)
-----------------------
* Projected coordinates are always read **easting first** (x east, y north), whatever axis
  order the EPSG registry declares: Gauss-Krüger codes such as EPSG:31468 are northing-first in
  the registry, but every CityGML file writes easting first. All pyproj calls therefore use
  ``always_xy=True``.
* Geographic coordinates are reprojected to WGS 84 / UTM (:class:`GeographicProjector`); their
  axis order is decided from the CRS definition *and* the coordinate ranges.
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
    "CrsInfo", "CrsResolution", "GeographicProjector", "grid_convergence_deg", "parse_srs_name",
    "resolve_model_crs", "resolve_model_crs_detailed", "to_wgs84",
]

#: Hint appended to every "cannot use this CRS" message.
_CRS_HINT = "give the CRS explicitly, e.g. --crs EPSG:25832"


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


#: What a file without any srsName gets (DESIGN §3: renders with an explicit sun only).
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


def _single_code(part: str) -> int | None:
    """EPSG code of one single-code spelling, or None when ``part`` is not one."""
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


@functools.lru_cache(maxsize=1024)  # a file repeats the same srsName thousands of times
def _parse_cached(srs_name: str) -> CrsInfo:
    text = srs_name.strip()
    if not text:
        raise CRSError(f"empty srsName; {_CRS_HINT}")
    # Refer to a CRS defined inside the file (gml:EngineeringCRS) or elsewhere: local metres.
    if text.startswith("#"):
        return CrsInfo(srs_name=srs_name, horizontal_epsg=None, vertical_epsg=None,
                       is_geographic=False, local=True, name=f"local CRS {text}")
    codes = _codes_from_spelling(text)
    if codes is None:
        raise CRSError(f"unknown CRS spelling {srs_name!r} (not an EPSG code, OGC URN/URI or "
                       f"AdV URN that cityshade understands); {_CRS_HINT}")
    if len(codes) > 2:
        raise CRSError(f"CRS {srs_name!r} names {len(codes)} components; expected a horizontal "
                       f"CRS and at most one height system; {_CRS_HINT}")
    crss = []
    for code in codes:
        crs = _pyproj_crs(code)
        if crs is None:
            from pyproj import proj_version_str
            raise CRSError(f"EPSG:{code} (from srsName {srs_name!r}) is not in the EPSG "
                           f"registry of PROJ {proj_version_str}; {_CRS_HINT}")
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
                       is_geographic=False, local=True, name=h_crs.name)
    if not (h_crs.is_projected or h_crs.is_geographic):
        raise CRSError(f"CRS {srs_name!r} is a {h_crs.type_name} ({h_crs.name}); cityshade "
                       f"needs a projected or geographic CRS; {_CRS_HINT}")
    if h_crs.is_projected:
        units = {axis.unit_name for axis in h_crs.axis_info}
        if units != {"metre"}:
            # The scene is in metres (DESIGN §3); silently scaling feet would be worse.
            raise CRSError(f"CRS {srs_name!r} ({h_crs.name}) has axis unit(s) "
                           f"{', '.join(sorted(units))}; cityshade supports metre-based "
                           f"projected CRSs and geographic CRSs only")
    name = h_crs.name if v_name is None else f"{h_crs.name} + {v_name}"
    return CrsInfo(srs_name=srs_name, horizontal_epsg=h_code, vertical_epsg=v_code,
                   is_geographic=bool(h_crs.is_geographic), local=False, name=name)


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
    return _parse_cached(srs_name)


class CrsResolution(NamedTuple):
    """The CRS chosen for a whole file, with the warnings the reader should report."""

    crs: CrsInfo
    warnings: tuple[str, ...]


def resolve_model_crs_detailed(srs_names: Iterable[str],
                               override: str | None = None) -> CrsResolution:
    """Choose the CRS of a whole file and say what was odd about its ``srsName`` values.

    The rules of :func:`resolve_model_crs`; besides, the warnings name the other horizontal
    CRSs found (with their counts) and the unknown spellings that were ignored because a known
    CRS was more frequent.
    """
    if override is not None:
        return CrsResolution(parse_srs_name(override), ())
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
            raise unknown_errors[unknown.most_common(1)[0][0]]
        return CrsResolution(first_local or NO_CRS, ())
    # Take the most frequent horizontal CRS (ties: first seen); within it the most frequent
    # spelling, preferring one that also names the height system.
    ranked = sorted(by_crs.items(), key=lambda item: -sum(item[1].values()))
    _, spellings = ranked[0]
    total = sum(spellings.values())
    best_unknown = unknown.most_common(1)
    if best_unknown and best_unknown[0][1] > total:
        raise unknown_errors[best_unknown[0][0]]
    best = max(spellings.items(),
               key=lambda item: (item[1], parse_srs_name(item[0]).vertical_epsg is not None))[0]
    crs = parse_srs_name(best)
    warnings = []
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
        The override; else the most frequent non-local CRS (spellings of the same horizontal
        EPSG code count together; with several horizontal CRSs the most frequent wins, see
        :func:`resolve_model_crs_detailed` for the warnings); else the first local CRS; else
        ``CrsInfo(local=True, name="none")`` for a file without any srsName.

    Raises
    ------
    CRSError
        The override cannot be parsed, or the most frequent srsName is unknown.
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
                       f"is unknown; give --crs EPSG:nnnn")


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


class GeographicProjector:
    """Project geographic coordinates (degrees) to a WGS 84 / UTM zone chosen from the data.

    The zone (EPSG:326zz north, 327zz south) is the one of the centre of the sample's bounding
    box. Heights are kept as written.

    Axis order heuristic: a coordinate whose magnitude exceeds 90 can only be a longitude, so
    an order under which any latitude would exceed 90 (or a longitude 180) is impossible. When
    both orders fit every point, the order whose latitudes are not polar (all
    |lat| <= 75°) wins, since city models are not near the poles; when that does not decide,
    the CRS's official order (latitude first for EPSG:4326, 4979, 6697, 4258, ...) wins. When
    the chosen order contradicts the official one, :attr:`warning` says so (the Jefferson
    building example writes longitude first under EPSG:4979: x ≈ -77.005, y ≈ 38.888).
    A file written longitude first at small longitudes and latitudes below 75° (e.g. lon 10,
    lat 50) cannot be told apart from the official order and is read in the official order.

    Parameters
    ----------
    crs : CrsInfo
        A geographic CRS (``crs.is_geographic``).
    sample_xyz : numpy.ndarray
        (N, 3) float64 coordinates as written in the file (first two columns in file order);
        non-finite rows are ignored.

    Attributes
    ----------
    axis_lat_first : bool
        True when the file's first coordinate is the latitude.
    warning : str or None
        Set when the file's order contradicts the CRS definition.
    target : CrsInfo
        The metric CRS the scene will be in.
    source : CrsInfo
        The geographic CRS given.

    Raises
    ------
    CRSError
        ``crs`` is not geographic, the sample is empty, or no axis order makes every point a
        valid longitude/latitude (projected coordinates under a geographic srsName).
    """

    def __init__(self, crs: CrsInfo, sample_xyz: np.ndarray):
        _require_projectable(crs, "the place on Earth")
        if not crs.is_geographic:
            raise CRSError(f"{crs.name} is not a geographic CRS; nothing to project")
        sample = _as_xyz(sample_xyz, "sample_xyz")
        sample = sample[np.isfinite(sample[:, 0]) & np.isfinite(sample[:, 1])]
        if sample.shape[0] == 0:
            raise CRSError(f"no finite coordinates to decide the axis order of {crs.name}")
        self.source = crs
        axes = _pyproj_crs(crs.horizontal_epsg).axis_info
        official_lat_first = axes[0].direction.lower() == "north"
        abs0 = np.abs(sample[:, 0]).max()
        abs1 = np.abs(sample[:, 1]).max()
        # Decide which orders fit every point at all.
        lat_first_fits = abs0 <= 90.0 and abs1 <= 180.0
        lon_first_fits = abs0 <= 180.0 and abs1 <= 90.0
        if not (lat_first_fits or lon_first_fits):
            raise CRSError(f"coordinates up to |{abs0:.6g}|, |{abs1:.6g}| are not degrees, "
                           f"but the srsName says {crs.name} (EPSG:{crs.horizontal_epsg}); "
                           f"{_CRS_HINT}")
        if lat_first_fits and lon_first_fits:
            lat_first_city = abs0 <= _MAX_CITY_LATITUDE_DEG
            lon_first_city = abs1 <= _MAX_CITY_LATITUDE_DEG
            lat_first = official_lat_first if lat_first_city == lon_first_city else lat_first_city
        else:
            lat_first = lat_first_fits
        self.axis_lat_first = bool(lat_first)
        self.warning: str | None = None
        if self.axis_lat_first != official_lat_first:
            written = "latitude" if self.axis_lat_first else "longitude"
            official = "latitude" if official_lat_first else "longitude"
            self.warning = (
                f"coordinates are written {written} first (first axis up to |{abs0:.6g}|, "
                f"second up to |{abs1:.6g}|) although EPSG:{crs.horizontal_epsg} defines "
                f"{official} first; reading them {written} first")
        lon, lat = self._lon_lat(sample)
        # Centre of the bounding box (not the mean: a few far-off objects must not drag it).
        centre_lon = 0.5 * (lon.min() + lon.max())
        centre_lat = 0.5 * (lat.min() + lat.max())
        self.target = parse_srs_name(f"EPSG:{_utm_epsg(centre_lon, centre_lat)}")

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
    _require_projectable(crs, "the place on Earth")
    if crs.horizontal_epsg == 4326:
        lon_deg, lat_deg = float(x), float(y)
    else:
        lon_deg, lat_deg = _transformer(crs.horizontal_epsg, 4326).transform(float(x), float(y))
    if not (math.isfinite(lon_deg) and math.isfinite(lat_deg)):
        raise CRSError(f"point ({x}, {y}) of {crs.name} has no WGS 84 position")
    return float(lon_deg), float(lat_deg), float(z)


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
        Local CRS or no CRS ("the model has no CRS; give --crs"), or a point outside the
        projection's domain.
    """
    _require_projectable(crs, "true north")
    if crs.is_geographic:
        return 0.0
    proj = _proj(crs.horizontal_epsg)
    lon_deg, lat_deg = proj(float(x), float(y), inverse=True)
    factors = proj.get_factors(lon_deg, lat_deg)
    convergence_deg = float(factors.meridian_convergence)
    if not math.isfinite(convergence_deg):
        raise CRSError(f"point ({x}, {y}) is outside the domain of {crs.name}")
    return convergence_deg
