"""The technique registry's one parser: :func:`cityshade.shadows.describe`."""
from __future__ import annotations

import re

import pytest

from cityshade.config import ShadowSettings
from cityshade.errors import UsageError
from cityshade.shadows import (LOOKUPS, PLANNERS, TechniqueSpec, describe, get_technique,
                               hybrid_base, map_technique_names, names_help, technique_names)


def _all_names() -> list[str]:
    base = [*technique_names(), *(f"{p}/{lk}" for p in PLANNERS for lk in LOOKUPS),
            "csm:lispsm/pcf"]
    maps = [n for n in base if describe(n).family == "map"]
    plain = [*base, "hybrid", *(f"hybrid:{n}" for n in maps)]
    return [*plain, *(f"{n}+smooth" for n in plain)]


@pytest.mark.parametrize("name", ["raytrace", "izb", "exact"])
def test_exact_family(name):
    spec = describe(name)
    assert (spec.family, spec.engine, spec.planner, spec.lookup) == ("exact", name, None, None)
    assert spec.exact and spec.tileable and not spec.smooth
    assert spec.maps_per_frame() == 0


def test_map_family_and_aliases():
    spec = describe("shadowmap")
    assert (spec.family, spec.planner, spec.lookup, spec.warp) == ("map", "shadowmap", "hard",
                                                                   None)
    assert not spec.exact and not spec.tileable and spec.maps_per_frame() == 1
    for alias, lookup in (("pcf", "pcf"), ("vsm", "vsm")):
        spec = describe(alias)
        assert (spec.name, spec.family, spec.planner, spec.lookup) == (alias, "map",
                                                                       "shadowmap", lookup)
    assert describe("lispsm/vsm").planner == "lispsm"
    assert describe("lispsm/vsm").lookup == "vsm"


def test_csm_warp_and_cascades():
    spec = describe("csm:lispsm")
    assert (spec.family, spec.planner, spec.warp, spec.lookup) == ("map", "csm", "lispsm", "hard")
    assert describe("csm").warp is None
    assert spec.maps_per_frame() == ShadowSettings().cascades.count
    assert spec.maps_per_frame(ShadowSettings().override(cascades=3)) == 3


def test_hybrid_default_base_and_given_base():
    spec = describe("hybrid")
    assert (spec.family, spec.base, spec.planner, spec.lookup) == ("hybrid", "vsm", "shadowmap",
                                                                   "vsm")
    assert not spec.exact and not spec.tileable and spec.maps_per_frame() == 1
    spec = describe("hybrid:csm:psm/pcf")
    assert (spec.family, spec.base, spec.planner, spec.warp, spec.lookup) == (
        "hybrid", "csm:psm/pcf", "csm", "psm", "pcf")


def test_smooth_keeps_the_family_but_is_not_exact():
    spec = describe("raytrace+smooth")
    assert (spec.family, spec.base, spec.smooth) == ("exact", "raytrace", True)
    assert not spec.exact and not spec.tileable
    spec = describe("hybrid:pcf+smooth")
    assert (spec.family, spec.base, spec.lookup, spec.smooth) == ("hybrid", "hybrid:pcf", "pcf",
                                                                  True)


def test_a_spec_describes_itself():
    spec = describe("csm:xpsm/vsm")
    assert describe(spec) is spec
    assert isinstance(spec, TechniqueSpec)


@pytest.mark.parametrize("name, why", [
    ("magic", ""),
    ("psm:lispsm", ""),
    ("shadowmap/foo", " (unknown lookup 'foo')"),
    ("csm:foo", " (unknown warp 'foo'; valid: psm, lispsm, xpsm)"),
    ("izb+blur", " (unknown suffix +blur)"),
    ("hybrid:magic", None),
])
def test_unknown_names_raise_the_registry_message(name, why):
    shown = "magic" if why is None else name
    expected = f"unknown shadow technique {shown!r}{why or ''}; valid: {names_help()}"
    with pytest.raises(UsageError, match=f"^{re.escape(expected)}$"):
        describe(name)
    with pytest.raises(UsageError, match=f"^{re.escape(expected)}$"):
        get_technique(name)


@pytest.mark.parametrize("base", ["izb", "raytrace", "hybrid:vsm", "vsm+smooth"])
def test_hybrid_refuses_a_base_that_is_not_a_map(base):
    from cityshade.shadows.hybrid import Hybrid

    expected = (f"hybrid needs a shadow-map base technique, not {base!r}; valid: "
                + ", ".join(map_technique_names()) + " (or PLANNER/LOOKUP)")
    if "+" not in base:  # hybrid:vsm+smooth is the smoothed hybrid:vsm
        with pytest.raises(UsageError, match=f"^{re.escape(expected)}$"):
            describe(f"hybrid:{base}")
    with pytest.raises(UsageError, match=f"^{re.escape(expected)}$"):
        hybrid_base(base)
    with pytest.raises(UsageError, match=f"^{re.escape(expected)}$"):
        Hybrid(base)


def test_get_technique_of_a_spec_equals_that_of_its_name():
    for name in _all_names():
        a, b = get_technique(name), get_technique(describe(name))
        assert (type(a), a.name) == (type(b), b.name), name
