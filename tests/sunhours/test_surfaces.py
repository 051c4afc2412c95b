"""Per-surface sampling: stratified points on every standing polygon, facing rule, CSV."""
from __future__ import annotations

import csv

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, city, ground

from cityshade.errors import UsageError
from cityshade.geo.sun import sun_from_angles
from cityshade.sunhours.surfaces import (SampleSettings, polygon_means, sample_surfaces, samples_lit,
                                write_surface_csv)


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    """A plane, a 10 × 10 × 20 m box, and a shed demolished in 1950 (absent in 2000)."""
    from cityshade.build import build_file
    from cityshade.store.scenefile import load_scene

    tmp = tmp_path_factory.mktemp("surfaces")
    src = tmp / "s.gml"
    shed = "<bldg:yearOfConstruction>1900</bldg:yearOfConstruction>" \
           "<bldg:yearOfDemolition>1950</bldg:yearOfDemolition>"
    src.write_text(city(ground(-50, -50, 50, 50), building("box", box_polygons(-5, -5, 0, 10, 10, 20, "b")),
                        building("shed", box_polygons(20, 20, 0, 4, 4, 3, "s"), extra=shed)))
    out, _, _ = build_file(src, tmp / "s.cityshade")
    return load_scene(out)


def _days(year):
    from cityshade.geo.temporal import parse_xsd_datetime_days

    return parse_xsd_datetime_days(str(year))


def _barycentric_inside(scene, samples):
    """Every sample lies inside a triangle of its polygon (checked by barycentrics)."""
    verts = np.asarray(scene.vertices, np.float64)
    for i in range(samples.n):
        tris = np.flatnonzero(scene.tri_polygon == samples.polygon[i])
        p = samples.points_m[i]
        ok = False
        for t in tris:
            a, b, c = verts[scene.triangles[t]]
            m = np.column_stack([b - a, c - a])
            uv, *_ = np.linalg.lstsq(m, p - a, rcond=None)
            if uv.min() >= -1e-9 and uv.sum() <= 1 + 1e-9 and np.allclose(m @ uv, p - a, atol=1e-6):
                ok = True
                break
        assert ok, f"sample {i} is not on polygon {samples.polygon[i]}"


def test_stratified_samples_cover_every_polygon(scene):
    s = sample_surfaces(scene, samples_per_m2=0.5, t_days=_days(2000))
    ids = [scene.poly_ids[p] for p in np.flatnonzero(s.sampled)]
    assert "ground_poly" in ids and "br" in ids and not any(i.startswith("s") for i in ids)
    # Weights add up to each polygon's area; density close to the target.
    area = np.bincount(s.polygon, weights=s.weight_m2, minlength=len(scene.poly_ids))
    np.testing.assert_allclose(area[s.sampled], scene.poly_area_m2[s.sampled], rtol=1e-9)
    counts = np.bincount(s.polygon, minlength=len(scene.poly_ids))
    big = s.sampled & (scene.poly_area_m2 > 50)
    np.testing.assert_allclose(counts[big] / scene.poly_area_m2[big], 0.5, rtol=0.25)
    np.testing.assert_allclose(np.linalg.norm(s.normals, axis=1), 1.0)
    roof = s.polygon == scene.poly_ids.index("br")
    assert (s.normals[roof] == [0, 0, 1]).all()
    # The mean of a constant is the constant; the mean of z over a wall is its mid-height.
    np.testing.assert_allclose(polygon_means(s, np.full(s.n, 3.0))[s.sampled], 3.0)
    wall = scene.poly_ids.index("bs")
    z = s.points_m[:, 2] - (np.asarray(scene.vertices)[:, 2].min())
    assert polygon_means(s, z)[wall] == pytest.approx(10.0, abs=1e-4)


def test_samples_lie_on_their_polygons_and_low_density_gives_one_per_triangle(scene):
    s = sample_surfaces(scene, samples_per_m2=1e-6, t_days=_days(1920))
    standing = (np.asarray(scene.tri_t_begin_days) <= _days(1920)) & \
        (_days(1920) < np.asarray(scene.tri_t_end_days))
    assert s.n == int(standing.sum())  # one centroid per triangle
    assert s.sampled.sum() == len(scene.poly_ids)  # the shed stands in 1920
    _barycentric_inside(scene, s)
    dense = sample_surfaces(scene, samples_per_m2=0.3, t_days=_days(2000))
    _barycentric_inside(scene, dense)


def test_facing_rule_and_shadow(scene):
    s = sample_surfaces(scene, samples_per_m2=0.2, t_days=_days(2000))
    lit = samples_lit(scene, s, sun_from_angles(180.0, 30.0), _days(2000))
    poly = np.array(scene.poly_ids, dtype=object)[s.polygon]
    assert lit[poly == "br"].all() and lit[poly == "bs"].all()  # roof and south wall
    assert not lit[poly == "bn"].any() and not lit[poly == "bg"].any()  # facing away
    ground_pts = (poly == "ground_poly")
    behind = ground_pts & (np.abs(s.points_m[:, 0] - s.points_m[:, 0].mean()) < 3) & \
        (s.points_m[:, 1] > 6) & (s.points_m[:, 1] < 20)
    assert behind.any() and not lit[behind].any()  # in the box's shadow, north of it
    night = samples_lit(scene, s, sun_from_angles(180.0, -1.0), _days(2000))
    assert not night.any()


def test_csv_round_trip(scene, tmp_path):
    s = sample_surfaces(scene, samples_per_m2=0.1, t_days=_days(2000))
    hours = polygon_means(s, np.arange(s.n, dtype=np.float64) % 3)
    path = write_surface_csv(tmp_path / "s.csv", scene, s, hours)
    with path.open() as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == int(s.sampled.sum())
    roof = next(r for r in rows if r["polygon_id"] == "br")
    assert roof["object_id"] == "box" and roof["surface_class"] == "roof"
    assert float(roof["area_m2"]) == pytest.approx(100.0)
    assert float(roof["mean_sun_hours"]) == pytest.approx(hours[scene.poly_ids.index("br")],
                                                          abs=1e-4)
    assert not list(tmp_path.glob(".*tmp"))


def test_validation(scene):
    with pytest.raises(UsageError, match="samples per m²"):
        sample_surfaces(scene, samples_per_m2=-1.0)
    with pytest.raises(UsageError, match="exceed the limit"):
        sample_surfaces(scene, samples_per_m2=1.0, settings=SampleSettings(max_samples=100))
    with pytest.raises(UsageError, match="NaN"):
        sample_surfaces(scene, t_days=float("nan"))
    s = sample_surfaces(scene, samples_per_m2=0.01)
    with pytest.raises(UsageError, match="shape"):
        polygon_means(s, np.zeros(3))
