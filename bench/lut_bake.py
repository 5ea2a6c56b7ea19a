"""Bake speed: `ocioforge bake` against `ociobakelut`, whole-process wall time.

Both bake ACEScg -> "sRGB - Display" (clip, the transform the config's display
colour space expresses) as a 65³ Resolve .cube; ociobakelut reads a config built
by ocioforge (OCIO 2.1). Each is run REPEATS times as a fresh process, start-up
included; the best times and their ratio are printed, with ocioforge's own
report of the time spent baking and writing (after its imports). ocioforge is
timed twice: in the environment as it is, and with its bytecode cached (in a
temporary folder, compiled by one untimed run) as an installed package runs;
the two differ when the environment turns bytecode writing off
(PYTHONDONTWRITEBYTECODE), which makes Python compile every module at start-up.

Run: .venv/bin/python bench/lut_bake.py
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPEATS = 5
SIZE = 65
#: `ocioforge` as a fresh process of this Python (the environment's entry point, without
#: relying on PATH).
OCIOFORGE = "import sys, generator.cli as c; c.main(sys.argv[1:])"


def best_time(args, env=None) -> tuple[float, str]:
    best, output = float("inf"), ""
    for _ in range(REPEATS):
        started = time.perf_counter()
        done = subprocess.run(args, capture_output=True, text=True, check=True, env=env)
        elapsed = time.perf_counter() - started
        if elapsed < best:
            best, output = elapsed, done.stdout.strip()
    return best, output


def main() -> None:
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    if shutil.which("ociobakelut") is None:
        sys.exit("ociobakelut is not installed")
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        config = folder / "ocioforge-bench"
        build(for_folder(load.load(), config, (2, 1)), config)
        theirs, _ = best_time(
            [
                "ociobakelut",
                "--iconfig",
                str(config / "config.ocio"),
                "--inputspace",
                "ACEScg",
                "--outputspace",
                "sRGB - Display",
                "--format",
                "resolve_cube",
                "--cubesize",
                str(SIZE),
                str(folder / "theirs.cube"),
            ]
        )
        bake = [
            sys.executable,
            "-c",
            OCIOFORGE,
            "bake",
            "--from",
            "ACEScg",
            "--to",
            "sRGB - Display",
            "--gamut-map",
            "clip",
            "--size",
            str(SIZE),
            "-o",
            str(folder / "ours.cube"),
            "--force",
        ]
        ours, report = best_time(bake)
        cached = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}
        cached["PYTHONPYCACHEPREFIX"] = str(folder / "bytecode")
        subprocess.run(bake, capture_output=True, check=True, env=cached)
        ours_cached, report_cached = best_time(bake, cached)
    print(f"65^3 Resolve cube, ACEScg -> sRGB - Display, best of {REPEATS} fresh processes:")
    print(f"  ociobakelut      {theirs:6.3f} s")
    print(f"  ocioforge bake   {ours:6.3f} s   ({report})")
    print(f"  bytecode cached  {ours_cached:6.3f} s   ({report_cached.rsplit('(', 1)[1]}")
    inside = float(report.rsplit("(", 1)[1].split(" s)")[0])
    print(
        f"  of which start-up {ours - inside:5.3f} s (Python, numpy, click, the spec: the bake's own report subtracted)"
    )
    print(
        f"  ratio ocioforge / ociobakelut: {ours / theirs:.2f}x ({ours_cached / theirs:.2f}x bytecode cached); "
        f"baking and writing alone: {inside / theirs:.2f}x"
    )


if __name__ == "__main__":
    main()
