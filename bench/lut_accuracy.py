"""LUT accuracy: ocioforge's bakes against ociobakelut's, on the same probes.

For each transform (source colour space to display, gamut mapping clip, the
only one a config's display colour space expresses for ociobakelut) this bakes
ocioforge's CLF and Resolve .cube, and ociobakelut's Resolve .cube from a config
built by ocioforge (OCIO 2.1) with every shaper it accepts, then reads all of
them back through PyOpenColorIO and measures them against the reference
evaluation on the probe sets of generator.luts.probes (ten-bit codes for SDR,
ΔE ITP for HDR). It prints max and p99 per set, and the ratio of ociobakelut's
best p99 to ours. The other gamut mappings are measured for ocioforge alone.

Run: .venv/bin/python bench/lut_accuracy.py [--size 33]
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

PAIRS = (("ACEScg", "sRGB - Display"), ("ACEScct", "sRGB - Display"), ("ARRI LogC4", "Rec.1886 Rec.709 - Display"),
         ("Linear Rec.2020", "Gamma 2.6 P3-D65 - Display"), ("ACEScg", "Rec.2100-PQ - Display"))
#: Shaper spaces tried for ociobakelut (None: no shaper); those it refuses are skipped.
OCIO_SHAPERS = (None, "ACEScct", "ACEScc", "sRGB Encoded AP1", "Gamma 2.2 Encoded AP1")
METHODS = ("clip", "scale", "desaturate", "rgc", "perceptual")


def _fmt(figures: dict) -> str:
    return "  ".join(f"{name} {f.maximum:8.3f}/{f.p99:7.3f}" for name, f in figures.items())


def _worst_p99(figures: dict) -> float:
    return max(f.p99 for f in figures.values())


def ocio_bakes(config: Path, source: str, display: str, size: int, folder: Path):
    """ociobakelut's Resolve cubes of source -> display, one per accepted shaper."""
    for number, shaper in enumerate(OCIO_SHAPERS):
        out = folder / f"ociobakelut_{number}.cube"
        args = ["ociobakelut", "--iconfig", str(config), "--inputspace", source, "--outputspace", display,
                "--format", "resolve_cube", "--cubesize", str(size), str(out)]
        if shaper:
            args[-1:-1] = ["--shaperspace", shaper]
        done = subprocess.run(args, capture_output=True, text=True)
        if done.returncode == 0:
            yield shaper or "none", out


def main(argv=None) -> None:
    import PyOpenColorIO as ocio

    from generator.luts import bake, probes
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=33)
    args = parser.parse_args(argv)
    if shutil.which("ociobakelut") is None:
        sys.exit("ociobakelut is not installed")
    spec = load.load()
    tetra = ocio.INTERP_TETRAHEDRAL
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        config = folder / "ocioforge-bench"
        build(for_folder(spec, config, (2, 1)), config)
        for source, display in PAIRS:
            print(f"\n== {source} -> {display}, {args.size}^3, max/p99 per probe set")
            ours = {}
            for fmt in ("clf", "resolve_cube"):
                req = bake.request(spec, source, display, "clip", fmt, args.size)
                path = folder / f"ours{bake.FORMATS[fmt].suffix}"
                path.write_bytes(bake.bake(req)[""])
                for interp, label in ((tetra, "tetrahedral"), (ocio.INTERP_LINEAR, "trilinear")):
                    figures = probes.measure(spec, req.source, req.display, "clip",
                                             probes.ocio_apply(ocio.FileTransform(str(path), interpolation=interp)))
                    ours[(fmt, label)] = figures
                    print(f"  ocioforge {fmt:12s} {label:11s} {_fmt(figures)}")
            best = {}
            for shaper, path in ocio_bakes(config / "config.ocio", source, display, args.size, folder):
                for interp, label in ((tetra, "tetrahedral"), (ocio.INTERP_LINEAR, "trilinear")):
                    figures = probes.measure(spec, req.source, req.display, "clip",
                                             probes.ocio_apply(ocio.FileTransform(str(path), interpolation=interp)))
                    print(f"  ociobakelut shaper {shaper:22s} {label:11s} {_fmt(figures)}")
                    if label not in best or _worst_p99(figures) < _worst_p99(best[label][1]):
                        best[label] = (shaper, figures)
            for label, (shaper, figures) in best.items():
                for fmt in ("resolve_cube", "clf"):
                    ratio = _worst_p99(figures) / max(_worst_p99(ours[(fmt, label)]), 1e-12)
                    print(f"  ratio ({label}) ociobakelut best p99 (shaper {shaper}) / ocioforge {fmt} p99: {ratio:.1f}x")
            for method in METHODS[1:]:
                req = bake.request(spec, source, display, method, "clf", args.size)
                path = folder / "method.clf"
                path.write_bytes(bake.bake(req)[""])
                figures = probes.measure(spec, req.source, req.display, method,
                                         probes.ocio_apply(ocio.FileTransform(str(path), interpolation=tetra)))
                print(f"  ocioforge clf {method:11s} {_fmt(figures)}")


if __name__ == "__main__":
    main()
