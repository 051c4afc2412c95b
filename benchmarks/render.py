"""Camera-pass benchmark: the culled G-buffer rasterizer on the 1M-triangle city vs Mesa llvmpipe.

Input: the synthetic benchmark city of ``cityshade.samplegen`` (``--triangles``, default
1 000 000, seed 7), generated into ``--workdir`` (default ``bench_out/``) when missing and
built once with ``cityshade build`` to ``city_1M.cityshade`` (or ``city_<N>.cityshade``).

Measured, at 1 and 2 Numba threads, at ``--size`` (default 1920x1080) and the city time
``--date-days`` (default 2000-01-01), for the overview camera (the whole city from the
south-west, 35° down: the figure compared with llvmpipe in DESIGN §12) and a "street" camera
inside the city (where frustum and occlusion culling have work to do):

* ``rasterize`` with occlusion culling on, and off (frustum + time culling only), and without
  the kd-tree walk at all (every triangle present at the date); the first (cold) run is
  reported apart, then the median of ``--repeat`` runs, with the per-step timings and the
  culling statistics (nodes/triangle references removed by each step);
* agreement of ``prim_id`` with one closest-hit ray per pixel (``gbuffer_by_raycasting``).

Anchor (when ``moderngl`` creates an EGL context, i.e. Mesa llvmpipe on this machine): the same
triangles (those present at the date), the same clip matrix, drawn into a 1080p RGBA8 + 24-bit
depth framebuffer (clear + draw + finish), in a child process per thread count
(``LP_NUM_THREADS``). DESIGN §12 measured 264 ms / 165 ms at 1 / 2 threads. Prints one JSON
object and then a table.

Usage: python benchmarks/render.py [--repeat 5] [--size 1920x1080] [--views overview,street]
       [--no-llvmpipe]
       [--triangles 1000000] [--workdir bench_out] [--json out.json]
       python benchmarks/render.py --shadow-map [--size 4096] [--repeat 5] [--sun 135,30]
       (the light-space depth pass against llvmpipe depth-only; see shadow_map_main)
       python benchmarks/render.py --techniques [--size 1920x1080] [--map-side 2048]
       [--repeat 3] [--sun 135,30] (every technique: shadow-stage time and error against
       raytrace, and the full raytrace frame; see techniques_main)
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)

import numpy as np

REPO = Path(__file__).resolve().parents[1]
DAY_2000 = 10957.0          # 2000-01-01 in days since 1970-01-01
ANCHOR_DESIGN_MS = {1: 264.0, 2: 165.0}   # DESIGN §12, llvmpipe 1080p depth+colour


def _machine() -> dict:
    return {"cpu_count": os.cpu_count(), "platform": platform.platform(),
            "python": platform.python_version()}


def ensure_scene(workdir: Path, triangles: int, seed: int) -> Path:
    """Generate (when missing) and build (once) the benchmark city; returns the scene path."""
    workdir.mkdir(parents=True, exist_ok=True)
    gml = workdir / f"city_{triangles}_s{seed}.gml"
    tag = "1M" if triangles == 1_000_000 else str(triangles)
    scene = workdir / f"city_{tag}.cityshade"
    if not gml.exists():
        subprocess.run([sys.executable, "-m", "cityshade.samplegen", str(gml), "--triangles",
                        str(triangles), "--seed", str(seed)], check=True)
    if not scene.exists():
        subprocess.run([sys.executable, "-m", "cityshade", "build", str(gml), "-o", str(scene)],
                       check=True)
    return scene


def time_runs(fn, repeat: int) -> tuple[float, list[float], object]:
    """(first run s, later runs s, last result)."""
    t = time.perf_counter()
    result = fn()
    first = time.perf_counter() - t
    runs = []
    for _ in range(repeat):
        t = time.perf_counter()
        result = fn()
        runs.append(time.perf_counter() - t)
    return first, runs, result


# --- llvmpipe anchor (child process: LP_NUM_THREADS is read when the context is created) -------
_LLVMPIPE_CHILD = r"""
import json, sys, time, statistics
import numpy as np
import moderngl
data = np.load(sys.argv[1])
width, height, repeat = int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
ctx = moderngl.create_standalone_context(backend="egl")
prog = ctx.program(
    vertex_shader='''#version 330
        uniform mat4 clip_from_world;
        in vec3 pos;
        flat out int tri;
        void main() { gl_Position = clip_from_world * vec4(pos, 1.0); }''',
    fragment_shader='''#version 330
        out vec4 colour;
        void main() { colour = vec4(float(gl_PrimitiveID & 255) / 255.0, 0.5, 0.5, 1.0); }''')
prog["clip_from_world"].write(data["clip"].astype("f4").T.tobytes())
vbo = ctx.buffer(data["vertices"].astype("f4").tobytes())
ibo = ctx.buffer(data["triangles"].astype("i4").tobytes())
vao = ctx.vertex_array(prog, [(vbo, "3f", "pos")], ibo)
fbo = ctx.framebuffer(color_attachments=[ctx.renderbuffer((width, height), 4)],
                      depth_attachment=ctx.depth_renderbuffer((width, height)))
fbo.use()
ctx.enable(moderngl.DEPTH_TEST)
def frame():
    fbo.clear(0.0, 0.0, 0.0, 1.0, depth=1.0)
    vao.render(moderngl.TRIANGLES)
    ctx.finish()
t = time.perf_counter(); frame(); first = time.perf_counter() - t
runs = []
for _ in range(repeat):
    t = time.perf_counter(); frame(); runs.append(time.perf_counter() - t)
depth = np.frombuffer(fbo.read(attachment=-1, components=1, dtype="f4"), "f4").reshape(height, width)[::-1]
print(json.dumps({"renderer": ctx.info["GL_RENDERER"], "first_s": first, "runs_s": runs,
                  "covered": float((depth < 1.0).mean())}))
"""


def llvmpipe(scene, camera, t_days, repeat, threads, tmp: Path) -> dict:
    """Mesa llvmpipe drawing the triangles present at ``t_days`` (child process per count)."""
    try:
        import moderngl  # noqa: F401
    except ImportError as exc:
        return {"unavailable": f"moderngl not importable ({exc})"}
    present = ((np.asarray(scene.tri_t_begin_days) <= t_days)
               & (t_days < np.asarray(scene.tri_t_end_days)))
    npz = tmp / "llvmpipe_input.npz"
    np.savez(npz, vertices=np.asarray(scene.vertices), triangles=np.asarray(scene.triangles)[present],
             clip=camera.clip_from_world())
    out = {}
    for n in threads:
        env = dict(os.environ, LP_NUM_THREADS=str(n))
        proc = subprocess.run([sys.executable, "-c", _LLVMPIPE_CHILD, str(npz),
                               str(camera.width_px), str(camera.height_px), str(repeat)],
                              env=env, capture_output=True, text=True, timeout=1800)
        if proc.returncode != 0:
            lines = proc.stderr.strip().splitlines()
            return {"unavailable": lines[-1] if lines else "llvmpipe child failed"}
        res = json.loads(proc.stdout.strip().splitlines()[-1])
        res["median_ms"] = 1000.0 * statistics.median(res["runs_s"])
        res["first_ms"] = 1000.0 * res["first_s"]
        out[n] = res
    npz.unlink(missing_ok=True)
    return out


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--triangles", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--workdir", type=Path, default=REPO / "bench_out")
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--date-days", type=float, default=DAY_2000,
                    help="city time in days since 1970-01-01 (default 2000-01-01)")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--views", default="overview,street",
                    help="comma-separated: overview (the figure of DESIGN §12), street")
    ap.add_argument("--no-llvmpipe", action="store_true")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)

    import numba

    from cityshade.raster import camera as cams
    from cityshade.raster.gbuffer import gbuffer_by_raycasting
    from cityshade.raster.rasterize import rasterize
    from cityshade.store.scenefile import load_scene

    width, height = (int(v) for v in args.size.lower().split("x"))
    path = ensure_scene(args.workdir, args.triangles, args.seed)
    scene = load_scene(path)
    t_days = args.date_days
    box = cams.scene_box(scene)
    centre = box.mean(axis=0)
    size = box[1] - box[0]
    cameras = {
        "overview": cams.overview(scene, width, height),
        # Inside the city near its south-west corner, looking north-east along the streets:
        # the frustum and occlusion culling have something to remove here.
        "street": cams.perspective(centre + [-0.3 * size[0], -0.3 * size[1], 20.0],
                                   centre + [0.2 * size[0], 0.1 * size[1], 0.0], vfov_deg=60.0,
                                   width_px=width, height_px=height, scene=scene),
    }
    present = int(((np.asarray(scene.tri_t_begin_days) <= t_days)
                   & (t_days < np.asarray(scene.tri_t_end_days))).sum())
    report: dict = {"commit": commit(), "machine": _machine(), "scene": str(path),
                    "triangles": scene.n_triangles, "present_at_date": present,
                    "kdtree_references": int(scene.kdtree.prim_indices.shape[0]),
                    "size": [width, height], "t_days": t_days, "views": {}}
    threads = [1, 2] if numba.config.NUMBA_NUM_THREADS >= 2 else [1]
    variants = {"auto": dict(occlusion_culling="auto"),
                "occlusion": dict(occlusion_culling=True),
                "frustum_time": dict(occlusion_culling=False),
                "no_walk": dict(culling=False)}
    for view in [v for v in args.views.split(",") if v]:
        if view not in cameras:
            raise SystemExit(f"unknown view {view!r}; valid: {', '.join(cameras)}")
        camera = cameras[view]
        out: dict = {"ours": {}}
        reference = None
        for n in threads:
            numba.set_num_threads(n)
            for name, kwargs in variants.items():
                first, runs, g = time_runs(lambda: rasterize(scene, camera, t_days, **kwargs),
                                           args.repeat)
                if reference is None:
                    reference = g.prim_id
                steps = g.stats["timings_s"]
                out["ours"][f"{name}_{n}t"] = {
                    "first_ms": 1000 * first, "median_ms": 1000 * statistics.median(runs),
                    "runs_ms": [1000 * r for r in runs],
                    "identical_to_first_variant": bool(np.array_equal(g.prim_id, reference)),
                    "last_run_steps_ms": {k[:-2]: 1000 * v for k, v in steps.items()},
                    "stats": {k: v for k, v in g.stats.items() if k != "timings_s"}}
        numba.set_num_threads(threads[-1])
        t = time.perf_counter()
        rays = gbuffer_by_raycasting(scene, camera, t_days)
        out["raycast_twin"] = {"ms": 1000 * (time.perf_counter() - t),
                               "prim_id_agreement": float((rays.prim_id == reference).mean()),
                               "covered": float((reference >= 0).mean())}
        if not args.no_llvmpipe:
            out["llvmpipe"] = llvmpipe(scene, camera, t_days, args.repeat, threads, args.workdir)
        report["views"][view] = out
    print(json.dumps(report, indent=1, default=str))
    if args.json:
        args.json.write_text(json.dumps(report, indent=1, default=str))
    for view, out in report["views"].items():
        _table(report, view, out, threads)
    return report


def _table(report: dict, view: str, out: dict, threads) -> None:
    lp = out.get("llvmpipe", {})
    print(f"\nG-buffer pass, {report['triangles']} triangles ({report['present_at_date']} present "
          f"at the date), {report['size'][0]}x{report['size'][1]}, {view} camera "
          f"({out['raycast_twin']['covered']:.1%} of pixels covered); agreement with ray "
          f"casting {out['raycast_twin']['prim_id_agreement']:.4%}")
    print(f"{'variant':<16}{'threads':>8}{'first ms':>10}{'median ms':>11}{'drawn':>10}"
          f"{'frustum':>10}{'occluded':>10}{'time':>10}{'vs llvmpipe':>13}")
    for key, res in out["ours"].items():
        name, n = key.rsplit("_", 1)
        n = int(n[:-1])
        st = res["stats"]
        anchor = lp.get(n, {}).get("median_ms") if isinstance(lp, dict) else None
        ratio = f"{anchor / res['median_ms']:.2f}x" if anchor else "-"
        print(f"{name:<16}{n:>8}{res['first_ms']:>10.1f}{res['median_ms']:>11.1f}"
              f"{st.get('triangles_drawn', 0):>10}{st.get('frustum_refs_removed', 0):>10}"
              f"{st.get('occlusion_refs_removed', 0):>10}{st.get('time_refs_removed', 0):>10}"
              f"{ratio:>13}")
    if "unavailable" in lp:
        print(f"llvmpipe: unavailable ({lp['unavailable']})")
    else:
        for n in threads:
            if n in lp:
                print(f"{'llvmpipe':<16}{n:>8}{lp[n]['first_ms']:>10.1f}{lp[n]['median_ms']:>11.1f}"
                      f"   (DESIGN §12: {ANCHOR_DESIGN_MS[n]:.0f} ms; {lp[n]['renderer']})")
    print("(drawn/frustum/occluded/time: triangles drawn; triangle references removed by each "
          "step; 'vs llvmpipe' = llvmpipe median / ours, >1 means we are faster)")


# --- shadow-map depth pass (issue 5): python benchmarks/render.py --shadow-map ------------------
_LLVMPIPE_DEPTH_CHILD = r"""
import json, sys, time
import numpy as np
import moderngl
data = np.load(sys.argv[1])
width, height, repeat = int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
ctx = moderngl.create_standalone_context(backend="egl")
prog = ctx.program(
    vertex_shader='''#version 330
        uniform mat4 clip_from_world;
        in vec3 pos;
        void main() { gl_Position = clip_from_world * vec4(pos, 1.0); }''',
    fragment_shader='''#version 330
        void main() { }''')
prog["clip_from_world"].write(data["clip"].astype("f4").T.tobytes())
vbo = ctx.buffer(data["vertices"].astype("f4").tobytes())
ibo = ctx.buffer(data["triangles"].astype("i4").tobytes())
vao = ctx.vertex_array(prog, [(vbo, "3f", "pos")], ibo)
fbo = ctx.framebuffer(depth_attachment=ctx.depth_texture((width, height)))
fbo.use()
ctx.enable(moderngl.DEPTH_TEST)
def frame():
    fbo.clear(depth=1.0)
    vao.render(moderngl.TRIANGLES)
    ctx.finish()
t = time.perf_counter(); frame(); first = time.perf_counter() - t
runs = []
for _ in range(repeat):
    t = time.perf_counter(); frame(); runs.append(time.perf_counter() - t)
depth = np.frombuffer(fbo.read(attachment=-1, components=1, dtype="f4"), "f4")
print(json.dumps({"renderer": ctx.info["GL_RENDERER"], "first_s": first, "runs_s": runs,
                  "covered": float((depth < 1.0).mean())}))
"""
#: DESIGN §12: Mesa llvmpipe, depth-only 4096² shadow map of the 1M-triangle city.
SHADOW_ANCHOR_DESIGN_MS = {1: 303.0, 2: 195.0}


def shadow_map_main(argv=None) -> dict:
    """The light-space depth pass (:func:`cityshade.shadows.shadowmap.render_depth_map`) of the
    whole benchmark city in a ``--size``² orthographic sun view, at 1 and 2 Numba threads
    (first run apart, median of ``--repeat``), against llvmpipe drawing the same triangles with
    the same matrix into a depth-only framebuffer (child process per thread count)."""
    import numba

    from cityshade.store.scenefile import load_scene
    from cityshade.shadows import shadowmap as sm
    from cityshade.geo.sun import sun_from_angles

    global _LLVMPIPE_CHILD
    ap = argparse.ArgumentParser(description="shadow-map depth pass benchmark")
    ap.add_argument("--size", type=int, default=4096)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--sun", default="135,30", help="azimuth,elevation in degrees")
    ap.add_argument("--triangles", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--workdir", type=Path, default=REPO / "bench_out")
    ap.add_argument("--date-days", type=float, default=DAY_2000)
    ap.add_argument("--no-llvmpipe", action="store_true")
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)
    threads = [int(v) for v in args.threads.split(",")]
    az, el = (float(v) for v in args.sun.split(","))
    scene = load_scene(ensure_scene(args.workdir, args.triangles, args.seed))
    sun = sun_from_angles(az, el)
    # The whole city: its box seen along the sun's rays.
    box = sm.scene_bounds(scene)
    corners = np.array([[box[i, 0], box[j, 1], box[k, 2]]
                        for i in (0, 1) for j in (0, 1) for k in (0, 1)])
    light = corners @ np.stack(sm.light_basis(sun.direction), axis=1)
    lo, hi = light.min(axis=0), light.max(axis=0)
    view = sm.ortho_view(sun.direction, (lo[0], hi[0]), (lo[1], hi[1]), (lo[2] - 1, hi[2] + 1),
                         args.size, args.size)
    report = {"benchmark": "shadow-map depth pass", "commit": commit(), "machine": _machine(),
              "size": args.size, "sun_deg": [az, el], "triangles": int(scene.triangles.shape[0]),
              "ours": {}, "llvmpipe": {}}
    for n in threads:
        numba.set_num_threads(n)
        first, runs, dm = time_runs(lambda: sm.render_depth_map(scene, view, args.date_days),
                                    args.repeat)
        report["ours"][n] = {"first_ms": 1000 * first,
                             "median_ms": 1000 * statistics.median(runs),
                             "runs_ms": [1000 * r for r in runs],
                             "stages_ms": {k: 1000 * v for k, v in
                                           dm.stats["timings_s"].items()},
                             "casters_drawn": dm.stats["casters_drawn"],
                             "texels_covered": int((dm.prim_id >= 0).sum())}
    if not args.no_llvmpipe:
        import tempfile

        class _LightCamera:
            width_px = height_px = args.size

            def clip_from_world(self):
                return view.clip_from_world

        saved = _LLVMPIPE_CHILD
        _LLVMPIPE_CHILD = _LLVMPIPE_DEPTH_CHILD
        try:
            with tempfile.TemporaryDirectory() as tmp:
                report["llvmpipe"] = llvmpipe(scene, _LightCamera(), args.date_days,
                                              args.repeat, threads, Path(tmp))
        finally:
            _LLVMPIPE_CHILD = saved
    print(json.dumps(report, default=float))
    if args.json:
        args.json.write_text(json.dumps(report, indent=1, default=float))
    lp = report["llvmpipe"]
    print(f"\n{'':<12}{'threads':>8}{'first ms':>10}{'median ms':>11}{'vs llvmpipe':>13}")
    for n, res in report["ours"].items():
        ratio = f"{lp[n]['median_ms'] / res['median_ms']:.2f}x" if n in lp else ""
        print(f"{'cityshade':<12}{n:>8}{res['first_ms']:>10.1f}{res['median_ms']:>11.1f}"
              f"{ratio:>13}")
    for n in threads:
        if n in lp:
            print(f"{'llvmpipe':<12}{n:>8}{lp[n]['first_ms']:>10.1f}{lp[n]['median_ms']:>11.1f}"
                  f"   (DESIGN §12: {SHADOW_ANCHOR_DESIGN_MS.get(n, float('nan')):.0f} ms; "
                  f"texels covered {lp[n]['covered']:.4f}, ours "
                  f"{report['ours'][n]['texels_covered'] / args.size ** 2:.4f})")
    if "unavailable" in lp:
        print(f"llvmpipe unavailable: {lp['unavailable']}")
    return report


# --- every technique: full frame, shadow stage and error against raytrace ---------------------

TECHNIQUES = ["raytrace", "izb", "shadowmap", "pcf", "vsm", "psm", "lispsm", "xpsm", "csm",
              "csm:lispsm", "vsm+smooth", "hybrid:shadowmap", "hybrid:vsm", "hybrid:lispsm",
              "hybrid:csm"]


def _stages(d) -> dict:
    """Stage seconds of one shadow pass: the technique's ``timings_s`` (a hybrid's base stages
    prefixed ``base.``), and the depth pass's own steps (``depth.setup`` …) of a single map."""
    out = {k.removesuffix("_s"): v for k, v in (d.get("timings_s") or {}).items()
           if isinstance(v, (int, float))}
    base = d.get("base")
    if base is not None:
        out.update({f"base.{k}": v for k, v in _stages(base).items()})
    depth = (d.get("depth_map") or {}).get("timings_s") or {}
    out.update({f"depth.{k.removesuffix('_s')}": v for k, v in depth.items()
                if k != "total_s" and isinstance(v, (int, float))})
    return out


def techniques_main(argv=None) -> dict:
    """The overview at --size and the top-down map at --map-side² of the 1M-triangle city:
    the full exact frames of ``raytrace`` and ``izb`` (G-buffer + resolve + shadows + shading,
    ms; for izb also with the EXR written, as ``cityshade render -o`` does), and for
    every technique its shadow-stage time (median of --repeat runs after a warm-up), the
    whole frame's CPU time of all threads (user and kernel apart) and its misclassified
    pixels against ``raytrace`` on the same pixels (false-lit, false-shadow)."""
    ap = argparse.ArgumentParser(description=techniques_main.__doc__.split("\n")[0])
    ap.add_argument("--size", default="1920x1080")
    ap.add_argument("--map-side", type=int, default=2048)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sun", default="135,30", help="azimuth,elevation in degrees")
    ap.add_argument("--techniques", default=",".join(TECHNIQUES))
    ap.add_argument("--frame-technique", default="exact",
                    help="the full frame timed with its EXR (default: render's default)")
    ap.add_argument("--triangles", type=int, default=1_000_000)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--workdir", type=Path, default=REPO / "bench_out")
    ap.add_argument("--date-days", type=float, default=DAY_2000)
    ap.add_argument("--json", type=Path)
    args = ap.parse_args(argv)
    from cityshade.raster.camera import map_view, overview
    from cityshade.frame.render import render_frame, write_frame
    from cityshade.store.scenefile import load_scene
    from cityshade.geo.sun import sun_from_angles

    scene = load_scene(ensure_scene(args.workdir, args.triangles, args.seed), verify=False)
    w, h = (int(v) for v in args.size.split("x"))
    az, el = (float(v) for v in args.sun.split(","))
    sun = sun_from_angles(az, el, scene.crs, scene.origin_m)
    # A map of --map-side² pixels centred on the model.
    lo = scene.vertices.min(axis=0).astype(float)
    hi = scene.vertices.max(axis=0).astype(float)
    side_m = float(max(hi[0] - lo[0], hi[1] - lo[1]))
    px = side_m / args.map_side
    cx, cy = 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])
    views = {"overview": overview(scene, w, h),
             "map": map_view(scene, px, bbox=(cx - side_m / 2, cy - side_m / 2,
                                              cx + side_m / 2, cy + side_m / 2))}
    report = {"benchmark": "render-techniques", "commit": commit(), "machine": _machine(),
              "triangles": scene.n_triangles, "sun": [az, el], "views": {}}
    for view_name, cam in views.items():
        t_frame = []
        ref = None
        for _ in range(args.repeat + 1):
            t0 = time.perf_counter()
            ref = render_frame(scene, cam, args.date_days, sun, "raytrace")
            t_frame.append(time.perf_counter() - t0)
        # The full frame with the default technique (render's --shadows), with and without
        # its default EXR: what `cityshade render -o x.exr` does after its set-up.
        t_izb, t_izb_exr, cpu_izb, cpu_exr = [], [], [], []
        with tempfile.TemporaryDirectory() as tmp:
            for _ in range(args.repeat + 1):
                t0, c0 = time.perf_counter(), time.process_time()
                fr = render_frame(scene, cam, args.date_days, sun, args.frame_technique)
                t1, c1 = time.perf_counter(), time.process_time()
                write_frame(fr, scene, "2000-01-01", exr=Path(tmp) / "frame.exr")
                t_izb.append(t1 - t0)
                t_izb_exr.append(time.perf_counter() - t0)
                # CPU seconds of all threads: steadier than wall time on a shared machine.
                cpu_izb.append(c1 - c0)
                cpu_exr.append(time.process_time() - c1)
            exr_mb = (Path(tmp) / "frame.exr").stat().st_size / 1e6
        izb_same = bool((fr.lit == ref.lit).all())
        valid = ref.surfaces.valid
        truth = ref.lit >= 0.5
        rows = {}
        for name in args.techniques.split(","):
            times, stages, frame, user, system = [], {}, None, [], []
            for k in range(args.repeat + 1):
                c0 = os.times()
                frame = render_frame(scene, cam, args.date_days, sun, name)
                c1 = os.times()
                times.append(frame.timings_s["shadow_s"])
                if k:
                    # CPU of all threads over the whole frame, user and kernel apart: kernel
                    # time is mostly the zeroing of freshly faulted pages.
                    user.append(c1.user - c0.user)
                    system.append(c1.system - c0.system)
                    for stage, s in _stages(frame.diagnostics.shadow).items():
                        stages.setdefault(stage, []).append(s)
            got = frame.lit >= 0.5
            d = frame.diagnostics.shadow
            rows[name] = {
                "shadow_ms_median": 1000 * statistics.median(times[1:]),
                "first_run_ms": 1000 * times[0],
                "wrong_pct": 100 * float(((got != truth) & valid).sum() / valid.sum()),
                "false_lit_pct": 100 * float((got & ~truth & valid).sum() / valid.sum()),
                "false_shadow_pct": 100 * float((~got & truth & valid).sum() / valid.sum()),
                "stages_ms": {k: 1000 * statistics.median(v) for k, v in stages.items()},
                "frame_user_cpu_ms": 1000 * statistics.median(user),
                "frame_system_cpu_ms": 1000 * statistics.median(system),
                "traced_share": d.get("traced_share"),
                "aliasing_m": d.get("aliasing_m"), "texel_m": d.get("texel_m"),
                "map_px": d.get("map_px")}
        report["views"][view_name] = {
            "pixels": [cam.width_px, cam.height_px], "surface_px": int(valid.sum()),
            "raytrace_frame_ms_median": 1000 * statistics.median(t_frame[1:]),
            "raytrace_frame_stages_ms": {k: 1000 * v for k, v in ref.timings_s.items()},
            "frame_technique": args.frame_technique,
            "frame_ms_median": 1000 * statistics.median(t_izb[1:]),
            "frame_with_exr_ms_median": 1000 * statistics.median(t_izb_exr[1:]),
            "frame_runs_with_exr_ms": [round(1000 * t, 1) for t in t_izb_exr[1:]],
            "frame_cpu_ms_median": 1000 * statistics.median(cpu_izb[1:]),
            "exr_cpu_ms_median": 1000 * statistics.median(cpu_exr[1:]),
            "exr_mb": exr_mb,
            "frame_stages_ms": {k: 1000 * v for k, v in fr.timings_s.items()},
            "frame_lit_identical_to_raytrace": izb_same,
            "techniques": rows}
    print(json.dumps(report, indent=2, default=float))
    for view_name, v in report["views"].items():
        print(f"\n{view_name} {v['pixels'][0]}x{v['pixels'][1]}, {v['surface_px']:,} surface px; "
              f"full raytrace frame {v['raytrace_frame_ms_median']:.0f} ms; full "
              f"{v['frame_technique']} frame {v['frame_ms_median']:.0f} ms, with its EXR "
              f"{v['frame_with_exr_ms_median']:.0f} ms {v['frame_runs_with_exr_ms']} (lit "
              f"identical to raytrace: {v['frame_lit_identical_to_raytrace']}); CPU of all "
              f"threads: frame {v['frame_cpu_ms_median']:.0f} ms, EXR "
              f"{v['exr_cpu_ms_median']:.0f} ms ({v['exr_mb']:.1f} MB)")
        print(f"{'technique':<18} {'shadow ms':>10} {'wrong %':>9} {'false-lit %':>12} "
              f"{'false-shadow %':>15} {'traced %':>9} {'cpu user/sys ms':>16}  "
              f"stages ms (median)")
        for name, r in v["techniques"].items():
            traced = "" if r["traced_share"] is None else f"{100 * r['traced_share']:.1f}"
            stages = " ".join(f"{k}={ms:.0f}" for k, ms in r["stages_ms"].items())
            cpu = f"{r['frame_user_cpu_ms']:.0f}/{r['frame_system_cpu_ms']:.0f}"
            print(f"{name:<18} {r['shadow_ms_median']:>10.0f} {r['wrong_pct']:>9.4f} "
                  f"{r['false_lit_pct']:>12.4f} {r['false_shadow_pct']:>15.4f} {traced:>9} "
                  f"{cpu:>16}  {stages}")
    if args.json:
        args.json.write_text(json.dumps(report, indent=2, default=float))
    return report


if __name__ == "__main__":
    if "--shadow-map" in sys.argv[1:]:
        shadow_map_main([a for a in sys.argv[1:] if a != "--shadow-map"])
    elif "--techniques" in sys.argv[1:] and sys.argv[1] == "--techniques":
        techniques_main(sys.argv[2:])
    else:
        main()
