"""Verify speed and figures: the default config (OCIO 2.1) through each engine, timed.

Builds the embedded default spec into a temporary folder, verifies it with each
engine family on its own (full probe density), and prints per engine the time
taken and, per check type, the worst error and the largest p99 against the
tolerance. The requirement: the PyOpenColorIO engines (default and lossless
flags, together) take at most 30 s on the 2-core machine. For scale, it times
``ociocheck``, what a user would run instead: it loads the config and resolves
every transform but compares no number.

Run: .venv/bin/python bench/verify.py [--engines ocio,oiiotool,ocioconvert,blender,gpu] [--quick]
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

#: The issue's budget for verifying the default config with the PyOpenColorIO engine.
OCIO_BUDGET_SECONDS = 30.0


def build(folder: Path) -> Path:
    from generator.ocio.write import build as write
    from generator.ocio.write import for_folder
    from generator.spec import load

    target = folder / "ocioforge-bench"
    write(for_folder(load.load(), target.absolute(), (2, 1)), target)
    return target / "config.ocio"


def ociocheck_seconds(config: Path) -> float | None:
    exe = shutil.which("ociocheck")
    if exe is None:
        return None
    started = time.perf_counter()
    subprocess.run([exe, "--iconfig", str(config)], capture_output=True, check=False)
    return time.perf_counter() - started


def main() -> int:
    from generator.verify import report
    from generator.verify.run import verify

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--engines", default="ocio,oiiotool,ocioconvert,blender,gpu")
    parser.add_argument("--quick", action="store_true", help="small probe sets")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    with tempfile.TemporaryDirectory() as tmp:
        config = build(Path(tmp))
        print(f"{'engine':<24} {'seconds':>8}  check type: max / p99 (tolerance)")
        ocio_total = None
        for family in args.engines.split(","):
            started = time.perf_counter()
            result = verify(config, (family,), density="quick" if args.quick else "full")
            wall = time.perf_counter() - started
            for run in result.engines:
                if run.skipped:
                    print(f"{run.name:<24} {'-':>8}  not run: {run.skipped}")
                    continue
                figures = [
                    f"{kind} {g['max']:.2g}/{g['p99']:.2g} ({g['tolerance']:g} {metric})"
                    for (engine, kind, metric), g in report.groups(result).items()
                    if engine.startswith(run.name)
                ]
                print(f"{run.name:<24} {run.seconds:>8.2f}  " + "; ".join(figures))
            print(
                f"{'  ' + family + ' wall time':<24} {wall:>8.2f}  (checks built, in-process engines run beside, in {result.timings['checks']:.2f} s; "
                f"{len(result.failures)} failing)"
            )
            if family == "ocio":
                ocio_total = wall
        seconds = ociocheck_seconds(config)
        if seconds is not None and ocio_total is not None:
            print(
                f"ociocheck (no numbers compared): {seconds:.2f} s; ocio verify / ociocheck = {ocio_total / seconds:.1f}"
            )
    if ocio_total is not None:
        verdict = "within" if ocio_total <= OCIO_BUDGET_SECONDS else "OVER"
        print(
            f"PyOpenColorIO verify of the default config: {ocio_total:.1f} s, {verdict} the {OCIO_BUDGET_SECONDS:g} s budget "
            f"({os.cpu_count()} cores)"
        )
        return 0 if ocio_total <= OCIO_BUDGET_SECONDS else 1
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
    sys.exit(main())
