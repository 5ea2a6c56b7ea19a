"""Build benchmark: what the default spec produces and how long building and start-up take.

Prints colour spaces, displays, views, files, whole-process build seconds per target
OCIO version, and `ocioforge --help` seconds (median of several runs, start-up included).
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def wall(argv: list[str], repeat: int = 1) -> float:
    times = []
    for _ in range(repeat):
        started = time.perf_counter()
        subprocess.run(argv, check=True, capture_output=True)
        times.append(time.perf_counter() - started)
    return statistics.median(times)


def main() -> None:
    import PyOpenColorIO as ocio

    from generator.spec.allowed import newest_ocio_version

    ocioforge = [sys.executable, "-m", "generator"]
    newest = newest_ocio_version()
    print(f"{'target':>8} {'spaces':>7} {'displays':>9} {'views':>6} {'files':>6} {'LUT MB':>7} {'build s':>8}")
    with tempfile.TemporaryDirectory() as tmp:
        for version in [(2, 1), newest]:
            folder = Path(tmp) / f"bench-{version[1]}"
            seconds = wall([*ocioforge, "build", "-o", str(folder), "--ocio-version", f"{version[0]}.{version[1]}"])
            cfg = ocio.Config.CreateFromFile(str(folder / "config.ocio"))
            files = [p for p in folder.rglob("*") if p.is_file()]
            lut_mb = sum(p.stat().st_size for p in files if p.parent.name == "luts") / 1e6
            views = sum(len(cfg.getViews(d)) for d in cfg.getDisplays())
            target = f"{version[0]}.{version[1]}"
            print(
                f"{target:>8} {len(cfg.getColorSpaceNames()):>7} {len(cfg.getDisplays()):>9} "
                f"{views:>6} {len(files):>6} {lut_mb:>7.2f} {seconds:>8.2f}"
            )
    help_seconds = wall([*ocioforge, "--help"], repeat=5)
    python_seconds = wall([sys.executable, "-c", "pass"], repeat=5)
    print(
        f"ocioforge --help: {help_seconds:.3f} s (bare python start-up {python_seconds:.3f} s, "
        f"ratio {help_seconds / python_seconds:.1f}x)"
    )


if __name__ == "__main__":
    main()
