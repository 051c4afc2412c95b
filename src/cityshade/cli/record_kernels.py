"""Record the kernels each command compiles, for the parallel first compile
(:mod:`cityshade.runtime.prewarm`): a maintainer's step after kernels or their argument types
change, ``python -m cityshade.cli.record_kernels`` in a source checkout (it runs the commands
on ``sample_data`` and a generated city, each in an empty Numba cache, and rewrites
``runtime/kernels.json``; a few minutes)."""
from __future__ import annotations

import base64
import json
import os
import pickle
import subprocess
import sys
import time
from pathlib import Path

from cityshade.runtime.prewarm import ENV_SWITCH, MANIFEST, entry_types, usable_cores

#: The commands recorded on the bundled sample city after ``build`` (the scene first; ``{out}``
#: a temporary folder, ``{sample}`` sample_data); one command may have several runs, whose
#: kernels are merged.
RECORD_RUNS = (
    ("render", ["--city-date", "1990", "--sun-azimuth", "135", "--sun-elevation", "30",
                "-o", "{out}/city.exr", "--png", "{out}/city.png"]),
    ("render", ["--city-date", "1990", "--sun-azimuth", "135", "--sun-elevation", "30",
                "--camera", "map", "--pixel-size", "0.5", "-o", "{out}/map.exr", "--mask",
                "{out}/mask.png", "--geotiff", "{out}/mask.tif", "--decorate"]),
    ("batch", ["--date", "2025-03-21", "--from", "06:00", "--to", "19:00", "--every", "15min",
               "--tz", "Europe/Berlin", "--camera", "map", "--pixel-size", "1", "--surfaces",
               "-o", "{out}/march"]),
    ("compare", ["--with", "{sample}/proposal_block.gml", "--date", "2025-03-21", "--tz",
                 "Europe/Berlin", "--pixel-size", "0.5", "--rules", "bre209", "--rules",
                 "en17037", "--area", "690110,5336122,690140,5336131", "-o", "{out}/planning"]),
    ("study", ["--with", "{sample}/proposal_block.gml", "--area",
               "690110,5336122,690140,5336131", "--year", "2025", "--tz", "Europe/Berlin",
               "-o", "{out}/study"]),
    ("sky", ["--pixel-size", "1", "--surfaces", "-o", "{out}/svf"]),
)


#: Triangles of the generated city whose build is recorded besides the sample's.
LARGE_CITY_TRIANGLES = 60_000


def _record_one(out: str, argv: list[str]) -> None:
    """Run one command in this process and write the kernels it compiled at the top level
    (the ones it called; their callees compile with them) as manifest entries to ``out``."""
    from numba.core import event

    depth = [0]
    roots: list[list] = []

    class Roots(event.Listener):
        def on_start(self, ev):
            if depth[0] == 0:
                roots.append([ev.data["dispatcher"], ev.data["args"], time.thread_time()])
            depth[0] += 1

        def on_end(self, ev):
            depth[0] -= 1
            if depth[0] == 0:
                roots[-1][2] = time.thread_time() - roots[-1][2]

    event.register("numba:compile", Roots())
    from cityshade.cli.main import cli

    cli.main(args=argv, prog_name="cityshade", standalone_mode=False)
    entries = []
    for dispatcher, args, seconds in roots:
        f = dispatcher.py_func
        entries.append({"kernel": f"{f.__module__}:{f.__qualname__}",
                        "signature": base64.b64encode(pickle.dumps(tuple(args))).decode(),
                        "compile_s": round(seconds, 2)})
    Path(out).write_text(json.dumps(entries))


def record(manifest: Path = MANIFEST) -> dict:
    """Record ``build`` and every command of :data:`RECORD_RUNS` on the bundled sample city,
    each in an empty Numba cache (the runs after ``build`` one per core at a time), and write
    the manifest."""
    import tempfile
    from concurrent.futures import ThreadPoolExecutor

    import numba

    from cityshade.samplegen import generate_city

    samples = Path(__file__).resolve().parents[3] / "sample_data"
    commands: dict[str, list[dict]] = {}
    with tempfile.TemporaryDirectory(prefix="cityshade-record-") as tmp:
        scene = f"{tmp}/city.cityshade"

        def one(k: int, name: str, args: list[str]) -> tuple[str, list[dict]]:
            found = f"{tmp}/found{k}.json"
            env = dict(os.environ, NUMBA_CACHE_DIR=f"{tmp}/numba{k}", **{ENV_SWITCH: "0"})
            subprocess.run([sys.executable, "-m", "cityshade.cli.record_kernels", "--record-one",
                            found, name, *args], env=env, check=True, stdout=subprocess.DEVNULL)
            return name, json.loads(Path(found).read_text())

        found = [one(0, "build", [str(samples / "sample_city.gml"), "-o", scene])]
        # A city past the interpreter's budgets (runtime.interpret): the kernels a large
        # model's build compiles (the sample's parse and triangulation run interpreted).
        generate_city(f"{tmp}/large.gml", target_triangles=LARGE_CITY_TRIANGLES)
        runs = [("build", [f"{tmp}/large.gml", "-o", f"{tmp}/large.cityshade"])] + [
            (name, [scene] + [a.format(out=f"{tmp}/out{k}", sample=samples) for a in args])
            for k, (name, args) in enumerate(RECORD_RUNS, 2)]
        with ThreadPoolExecutor(usable_cores()) as pool:
            found += pool.map(lambda k: one(k + 1, *runs[k]), range(len(runs)))
    for name, entries in found:
        # The same types may pickle to other bytes in another process: compare the types.
        have = commands.setdefault(name, [])
        known = {(e["kernel"], entry_types(e)) for e in have}
        have += [e for e in entries if (e["kernel"], entry_types(e)) not in known]
    data = {"numba": numba.__version__, "commands": commands}
    manifest.write_text(json.dumps(data, indent=1) + "\n")
    return data


def _main(argv: list[str]) -> None:
    if argv[:1] == ["--record-one"]:
        _record_one(argv[1], argv[2:])
        return
    data = record()
    for name, entries in data["commands"].items():
        print(f"{name}: {len(entries)} kernels, "
              f"{sum(e['compile_s'] for e in entries):.1f} s recorded")


if __name__ == "__main__":
    _main(sys.argv[1:])
