"""Boxes of a scene's vertices: the one-pass kernels against numpy, and the scene's memo."""
import numpy as np

from cityshade.geometry import bounds
from cityshade.runtime.interpret import python_twin
from reference import reference_all_vertex_box


def test_all_vertex_box_is_numpys_min_and_max():
    """The kernel and its interpreted twin against numpy's per-column min and max, also with
    a NaN (it sticks, as numpy's) and on a read-only array."""
    rng = np.random.default_rng(3)
    v = (rng.normal(size=(5000, 3)) * [100.0, 50.0, 7.0]).astype(np.float32)
    for vertices in (v, v[:1]):
        want = reference_all_vertex_box(vertices)
        assert bounds.all_vertices_box(vertices).tobytes() == want.tobytes()
        out = np.empty((2, 3))
        bounds.all_vertex_box(vertices, out)
        assert out.tobytes() == want.tobytes()
        python_twin(bounds.all_vertex_box)(vertices, out)
        assert out.tobytes() == want.tobytes()
    w = v.copy()
    w[1234, 2] = np.nan
    w.flags.writeable = False
    out = np.empty((2, 3))
    bounds.all_vertex_box(w, out)
    assert np.isnan(out[:, 2]).all()
    assert out.tobytes() == reference_all_vertex_box(w).tobytes()


def test_scene_derives_its_boxes_once_while_its_arrays_cannot_change(sample_city_scene):
    """A loaded scene (read-only memory maps) computes a derived array once and hands out
    copies; a scene whose arrays can change, or that was given other arrays, computes again.
    The city's box is numpy's min and max of every vertex."""
    import dataclasses

    scene = dataclasses.replace(sample_city_scene)     # its own memo, the same arrays
    lo, hi = scene.city_box_m()
    want = reference_all_vertex_box(scene.vertices)
    assert lo.tobytes() == want[0].tobytes() and hi.tobytes() == want[1].tobytes()
    from cityshade.raster.camera import scene_box
    from reference import reference_used_vertex_box

    box = scene_box(scene)
    box[:] = 0.0
    assert scene_box(scene).tobytes() == reference_used_vertex_box(
        scene.vertices, scene.triangles).tobytes()
    calls = []

    def compute():
        calls.append(1)
        return np.arange(6.0).reshape(2, 3)

    first = scene.derived("test", compute)
    first[0, 0] = 99.0                                  # a copy: the kept value is intact
    assert scene.derived("test", compute)[0, 0] == 0.0 and len(calls) == 1
    scene.vertices = np.array(scene.vertices)           # writable: no longer kept
    scene.derived("test", compute)
    scene.derived("test", compute)
    assert len(calls) == 3
    frozen = np.array(scene.vertices)
    frozen.flags.writeable = False
    scene.vertices = frozen                             # other read-only arrays: once more
    scene.derived("test", compute)
    scene.derived("test", compute)
    assert len(calls) == 4
