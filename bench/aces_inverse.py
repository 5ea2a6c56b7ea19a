"""ACES views read back: display codes through a view's inverse, then forward again, in OCIO.

Builds the default spec for OCIO 2.1 (untimed), where the ACES 2.0 views are baked tables and
ACES 1.3's are OCIO's builtins. For each view below, its "<view> - <display>" colour space is
run to ACES2065-1 and back, with OCIO's lossless flags and its default ones (which invert a
table through a coarser 48³ table), tetrahedral interpolation as the config names it. Two sets,
ten-bit codes of the display, p99 and max of each colour's largest channel error: "shown",
the codes the view makes from random ACES2065-1 colours in [0, 2]; "codes", random codes in
[0, 1], which a view need not make (left out on HDR displays, whose codes reach 10000 cd/m²
and the whole Rec.2020 gamut, far beyond the view's). The issue's goal: shown colours within
1 code p99.

Run: .venv/bin/python bench/aces_inverse.py
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import generator  # noqa: F401  (numpy's settings first)

# isort: split
import numpy as np

#: (view, display) read back, as docs/aces-views.md lists them.
PAIRS = (
    ("ACES 2.0 - SDR 100 nits (Rec.709)", "sRGB - Display"),
    ("ACES 2.0 - SDR 100 nits (P3 D65)", "Display P3 - Display"),
    ("ACES 2.0 - HDR 1000 nits (P3 D65)", "Rec.2100-PQ - Display"),
    ("ACES 1.0 - SDR Video", "sRGB - Display"),
)

#: Colours per set, and the seed drawing them.
COUNT, SEED = 20000, 5


def round_trip(config, space: str, optimization: str):
    """Codes (n, 3) to their round trip through ``space``'s inverse and forward, in float32."""
    import PyOpenColorIO as ocio

    flags = getattr(ocio, optimization)
    forward = config.getProcessor("ACES2065-1", space).getOptimizedCPUProcessor(flags)
    inverse = config.getProcessor(space, "ACES2065-1").getOptimizedCPUProcessor(flags)

    def apply(processor, values):
        out = np.ascontiguousarray(values, dtype=np.float32).copy()
        processor.applyRGB(out)
        return out

    return lambda codes: apply(forward, apply(inverse, codes)).astype(np.float64), lambda aces: apply(forward, aces)


def main() -> None:
    import PyOpenColorIO as ocio

    from generator.ocio.write import build, for_folder
    from generator.spec import load

    rng = np.random.default_rng(SEED)
    aces, codes = rng.random((COUNT, 3)) * 2.0, rng.random((COUNT, 3))
    spec = load.load()
    hdr = {d.name for d in spec.displays if d.is_hdr}
    with tempfile.TemporaryDirectory() as tmp:
        target = Path(tmp) / "aces-inverse"
        build(for_folder(spec, target.absolute(), (2, 1)), target)
        config = ocio.Config.CreateFromFile(str(target / "config.ocio"))
        print(f"{'view':<36} {'display':<22} {'flags':<9} {'shown p99':>9} {'max':>6} {'codes p99':>9} {'max':>6}")
        for view, display in PAIRS:
            for flags in ("OPTIMIZATION_LOSSLESS", "OPTIMIZATION_DEFAULT"):
                trip, forward = round_trip(config, f"{view} - {display}", flags)
                shown = forward(aces).astype(np.float64)
                cells = []
                for start in (shown,) if display in hdr else (shown, codes):
                    error = np.abs(trip(start) - start).max(axis=1) * 1023.0
                    cells.append(f"{np.percentile(error, 99):9.3f} {error.max():6.1f}")
                print(f"{view:<36} {display:<22} {flags[13:].lower():<9} {' '.join(cells)}")


if __name__ == "__main__":
    main()
