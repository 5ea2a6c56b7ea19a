"""Convert benchmark: 6 frames of 3840x2160 half-float EXR (zip) from ARRI LogC4 to ACEScg through the
default config, `ocioforge convert` against one `oiiotool --frames` command doing the same conversion
with the same config, whole wall time of each command.

Prints: oiiotool's time; ours with the default --jobs, its ratio (target <= 1.0); with --verify (target
<= 1.5); from 1 to N jobs; on a Dask LocalCluster of N worker processes on 127.0.0.1; and, for one
frame in this process, PyOpenColorIO's lossless CPU processor against ImageBufAlgo.colorconvert.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import generator  # noqa: F401  (numpy's and OpenBLAS's fixed kernels: before numpy loads)

# isort: split
import numpy as np

from generator.avx_state import clear_upper

FRAMES, WIDTH, HEIGHT = 6, 3840, 2160
SRC, DST = "ARRI LogC4", "ACEScg"


def frames(folder: Path) -> None:
    """LogC4 codes: ramps across the frame, a little noise (so zip compresses as a plate does)."""
    import OpenImageIO as oiio

    folder.mkdir()
    rng = np.random.default_rng(1)
    y, x = np.mgrid[0:HEIGHT, 0:WIDTH].astype(np.float32)
    base = np.stack([x / WIDTH, y / HEIGHT, (x + y) / (WIDTH + HEIGHT)], -1) * 0.7 + 0.1
    for f in range(1, FRAMES + 1):
        spec = oiio.ImageSpec(WIDTH, HEIGHT, 3, oiio.HALF)
        spec.attribute("compression", "zip")
        out = oiio.ImageOutput.create("exr")
        out.open(str(folder / f"plate.{f:04d}.exr"), spec)
        out.write_image(base + rng.normal(0.0, 0.01, base.shape).astype(np.float32))
        out.close()


#: Runs of each command; the fastest is kept (the machine may be shared: the others' load only adds).
REPEAT = 2


def wall(argv: list[str], output: Path | None = None) -> float:
    """The fastest of REPEAT runs of ``argv``, whole wall time; ``output`` (a folder) emptied before each."""
    best = float("inf")
    for _ in range(REPEAT if output is not None else 1):
        if output is not None:
            shutil.rmtree(output, ignore_errors=True)
            output.mkdir()
        started = time.perf_counter()
        result = subprocess.run(argv, capture_output=True, text=True)
        best = min(best, time.perf_counter() - started)
        if result.returncode != 0:
            raise SystemExit(f"{' '.join(argv)} failed: {result.stdout}{result.stderr}")
    return best


def engines(config: Path, frame: Path) -> tuple[float, float]:
    """Seconds for one frame's pixels: PyOpenColorIO lossless applyRGB, ImageBufAlgo.colorconvert."""
    import OpenImageIO as oiio
    import PyOpenColorIO as ocio

    buf = oiio.ImageBuf(str(frame))
    pixels = buf.get_pixels(oiio.FLOAT).reshape(-1, 3).copy()
    cpu = (
        ocio.Config.CreateFromFile(str(config))
        .getProcessor(SRC, DST)
        .getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS)
    )
    clear_upper()  # as convert does: the EXR reader leaves AVX state that slows OCIO's SSE code
    started = time.perf_counter()
    cpu.applyRGB(pixels)
    ours = time.perf_counter() - started
    started = time.perf_counter()
    oiio.ImageBufAlgo.colorconvert(buf, SRC, DST, colorconfig=str(config))
    return ours, time.perf_counter() - started


def main() -> None:
    oiiotool = shutil.which("oiiotool")
    if oiiotool is None:
        raise SystemExit("oiiotool is not installed (Debian: apt-get install openimageio-tools)")
    cores = os.cpu_count() or 1
    ocioforge = [sys.executable, "-m", "generator"]
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        config = tmp / "studio" / "config.ocio"
        wall([*ocioforge, "build", "-o", str(config.parent)])
        frames(tmp / "in")
        pattern = str(tmp / "in" / "plate.####.exr")
        theirs = wall(
            [
                oiiotool,
                "--frames",
                f"1-{FRAMES}",
                str(tmp / "in" / "plate.#.exr"),
                "--colorconfig",
                str(config),
                "--colorconvert",
                SRC,
                DST,
                "-d",
                "half",
                "--compression",
                "zip",
                "-o",
                str(tmp / "oiiotool" / "plate.#.exr"),
            ],
            tmp / "oiiotool",
        )
        args = [*ocioforge, "convert", pattern, "--config", str(config), "--from", SRC, "--to", DST]
        ours = wall([*args, "-o", str(tmp / "ours")], tmp / "ours")
        verified = wall([*args, "-o", str(tmp / "verified"), "--verify"], tmp / "verified")
        print(f"{FRAMES} frames {WIDTH}x{HEIGHT} half EXR (zip), {SRC} -> {DST}, {cores} cores")
        print(f"oiiotool --frames (one command):  {theirs:7.2f} s")
        print(f"ocioforge convert (--jobs {cores}):    {ours:7.2f} s  ratio {ours / theirs:.2f} (target <= 1.0)")
        print(f"ocioforge convert --verify:       {verified:7.2f} s  ratio {verified / theirs:.2f} (target <= 1.5)")
        for jobs in range(1, cores + 1):
            seconds = wall([*args, "-o", str(tmp / f"jobs{jobs}"), "--jobs", str(jobs)], tmp / f"jobs{jobs}")
            print(f"ocioforge convert --jobs {jobs}:       {seconds:7.2f} s  {FRAMES / seconds:.2f} frames/s")
        cluster(args, tmp, cores, theirs)
        same = all(
            (tmp / "ours" / n).read_bytes() == (tmp / "cluster" / n).read_bytes() for n in os.listdir(tmp / "ours")
        )
        print(f"cluster output the same bytes as local: {same}")
        ocio_s, iba_s = engines(config, tmp / "in" / "plate.0001.exr")
        print(f"one frame's pixels: PyOpenColorIO lossless {ocio_s:.2f} s, ImageBufAlgo.colorconvert {iba_s:.2f} s")


def cluster(args: list[str], tmp: Path, cores: int, theirs: float) -> None:
    from distributed import LocalCluster

    with LocalCluster(
        n_workers=cores, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None
    ) as local:
        seconds = wall([*args, "-o", str(tmp / "cluster"), "--scheduler", local.scheduler_address], tmp / "cluster")
    print(
        f"ocioforge convert --scheduler (LocalCluster, {cores} workers): {seconds:7.2f} s  ratio {seconds / theirs:.2f}"
    )


if __name__ == "__main__":
    main()
