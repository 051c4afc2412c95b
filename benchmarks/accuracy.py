"""The published accuracy report: ``docs/ACCURACY.md`` from a real run.

Runs ``cityshade evaluate`` (library calls, same code) on three models and the full stress set
on the sample city, then writes ``docs/ACCURACY.md`` with the commit and the machine, and the
plots and worst-case difference images under ``docs/accuracy/``:

- the sample city (``sample_data/sample_city.gml``): every technique (``--shadows all``),
  maps 1024², 2048², 4096²;
- the TUM campus LoD2 (``../shared/data/citygml/munich-tum-campus-lod2/TUM Munich.gml``): every
  technique, maps 2048² and 4096²;
- the 1-million-triangle city (``bench_out/city_1M.cityshade``, built from
  ``bench_out/city_1000000_s7.gml`` when missing): a modest subset, one timed run.

Usage, from the repository root (about 15–25 minutes on 2 cores)::

    python benchmarks/accuracy.py [--skip-1m] [--city-1m PATH] [--skip-stress] [--out docs]

``--city-1m`` takes the 1M city from elsewhere: a ``.cityshade`` cache is opened as it is, a
CityGML file is built into ``bench_out/city_1M.cityshade`` first.
"""
from __future__ import annotations

import argparse
import datetime as dt
import os
import platform
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from provenance import commit  # noqa: E402  (the benchmarks' shared provenance)

REPO = Path(__file__).resolve().parents[1]
TUM = REPO.parent / "shared" / "data" / "citygml" / "munich-tum-campus-lod2" / "TUM Munich.gml"
CITY_1M_GML = REPO / "bench_out" / "city_1000000_s7.gml"
CITY_1M = REPO / "bench_out" / "city_1M.cityshade"
#: Sun positions of every model: south-east 45° (short shadows) and south-west 15° (long).
SUNS = "135,45;240,15"


def _machine() -> str:
    cpu = platform.processor() or "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    import numba

    return (f"{cpu}, {os.cpu_count()} logical cores, Numba {numba.__version__} with "
            f"{numba.get_num_threads()} threads, Python {platform.python_version()}, "
            f"{platform.system()} {platform.release()}")


def _progress(done: int, total: int, label: str) -> None:
    if sys.stderr.isatty():
        sys.stderr.write(f"\r\033[K{done}/{total} {label[:70]}")
        sys.stderr.flush()


def evaluate_model(name: str, path: Path, out: Path, shadows: str, sizes: tuple[int, ...],
                   repeat: int, size=(1280, 720), views=("overview", "map")):
    from cityshade.geo.temporal import days_to_iso, parse_user_date
    from cityshade.evaluate import (EvaluateSettings, expand_techniques, load_or_build_scene,
                                    parse_suns, run_evaluation, view_camera, write_report)

    t0 = time.perf_counter()
    scene = load_or_build_scene(path)
    load_s = time.perf_counter() - t0
    city_days = parse_user_date("2024-06-21").city_days
    cams = [(v, view_camera(scene, v, size, None, city_days)) for v in views]
    settings = EvaluateSettings(repeat=repeat, sizes=sizes, worst_cases=1)
    evaluation = run_evaluation(scene, cams, parse_suns(SUNS, scene), city_days,
                                expand_techniques(shadows), settings, progress=_progress,
                                model=name)
    evaluation.meta["city_time"] = days_to_iso(city_days)
    folder = out / "accuracy" / name
    write_report(evaluation, folder, title=name)
    print(f"\n{name}: {scene.n_triangles} triangles, load/build {load_s:.1f} s, "
          f"{len(evaluation.rows)} rows, {time.perf_counter() - t0:.0f} s", file=sys.stderr)
    return scene, evaluation, folder


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", type=Path, default=REPO / "docs")
    parser.add_argument("--skip-1m", action="store_true")
    parser.add_argument("--city-1m", type=Path, default=None,
                        help="the 1M city's cache or GML (default: bench_out/city_1M.cityshade, "
                             "built from bench_out/city_1000000_s7.gml when missing)")
    parser.add_argument("--skip-stress", action="store_true")
    args = parser.parse_args(argv)
    from cityshade.evaluate import report_markdown, summary

    started = time.perf_counter()
    header = [
        "# Accuracy: shadow error against run time",
        "",
        "Produced by `python benchmarks/accuracy.py` (from the repository root; it calls the "
        "same code as `cityshade evaluate FILE --sun '135,45;240,15' --shadows … --sizes … "
        "-o DIR` and `cityshade evaluate sample_data/sample_city.gml --stress`). Do not edit by "
        "hand: run it again.",
        "",
        f"- commit: `{commit()}`; run {dt.datetime.now().strftime('%Y-%m-%d %H:%M')}",
        f"- machine: {_machine()} (shared with other jobs while it ran: times are indicative)",
        "- error = share of surface pixels whose sun/shadow class differs from `raytrace` on "
        "the same pixels; edge = distance from a wrong pixel's surface point to the nearest "
        "pixel that truly has its class; times are the shadow stage as `render` runs it "
        "(the camera pass is shared by all techniques and listed in `results.csv`).",
        "",
    ]
    sections, closing = [], []
    models = [("sample_city", REPO / "sample_data" / "sample_city.gml", "all", (1024, 2048, 4096),
               1, (960, 540))]
    if TUM.exists():
        models.append(("tum_campus_lod2", TUM, "all", (2048, 4096), 1, (960, 540)))
    else:
        closing.append(f"- TUM campus model not found at `{TUM}`: skipped.")
    if not args.skip_1m:
        from cityshade.build import build_file

        city_1m, gml = CITY_1M, None
        if args.city_1m is not None and not args.city_1m.exists():
            parser.error(f"--city-1m: {args.city_1m} does not exist")
        if args.city_1m is not None and args.city_1m.suffix == ".cityshade":
            city_1m = args.city_1m
        elif args.city_1m is not None:
            gml = args.city_1m                  # built anew into bench_out/
        elif not CITY_1M.exists() and CITY_1M_GML.exists():
            gml = CITY_1M_GML
        if gml is not None:
            CITY_1M.parent.mkdir(parents=True, exist_ok=True)
            build_file(gml, CITY_1M)
        if city_1m.exists():
            models.append(("city_1M", city_1m, "izb,shadowmap,pcf,vsm,lispsm,csm,pcf+smooth,"
                           "hybrid:shadowmap,hybrid:vsm", (2048, 4096), 1, (1280, 720)))
        else:
            closing.append("- 1M-triangle city not found: skipped.")
    for name, path, shadows, sizes, repeat, size in models:
        scene, evaluation, folder = evaluate_model(name, path, args.out, shadows, sizes, repeat,
                                                   size)
        rel = folder.relative_to(args.out)
        images = {}
        for png in sorted(folder.glob("*.png")):
            view = next((v for v in ("overview", "map") if f"_{v}" in png.stem), None)
            if view:
                images.setdefault(view, []).append(f"{rel}/{png.name}")
        sections.append(report_markdown(evaluation, images, title=f"{name} "
                                        f"({scene.n_triangles} triangles)", heading_level=2))
        sections.append(f"Full table: [`{rel}/results.csv`]({rel}/results.csv).\n")
        for view, entries in summary(evaluation.rows).items():
            front = [e["key"] for e in entries if e["pareto"]]
            closing.append(f"- {name} / {view}: Pareto front {' → '.join(front)}.")
        for r in evaluation.rows:
            if r.get("error"):
                closing.append(f"- {name}: `{r['technique']}` map {r['map_px']} {r['view']} "
                               f"{r['sun']} failed: {r['error']}")
    if not args.skip_stress:
        from cityshade.config import StressSettings
        from cityshade.evaluate.stress import run_stress, stress_markdown

        report = run_stress(REPO / "sample_data" / "sample_city.gml", StressSettings(),
                            progress=_progress, echo=lambda line: print(line, file=sys.stderr))
        sections.append("## Stress set (full, sample city)\n\n" + stress_markdown(report) + "\n")
        for c in report.cases:
            if not c.passed:
                closing.append(f"- stress FAIL, {c.name}: {'; '.join(c.failures)}")
    text = "\n".join(header + sections + ["## Closing note", "",
                                          "Pareto fronts (fastest first) and failures:", ""]
                     + closing + ["", f"Total run time {time.perf_counter() - started:.0f} s."])
    (args.out / "ACCURACY.md").write_text(text + "\n", encoding="utf-8")
    print(f"wrote {args.out / 'ACCURACY.md'}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
