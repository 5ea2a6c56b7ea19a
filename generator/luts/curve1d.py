"""Baking a decoding curve into a uniformly sampled 1D LUT, as dense as the bound needs.

Used where the target OCIO version cannot express a curve analytically. The
size doubles until linear interpolation between nodes stays within
``tolerances.BAKED_CURVE_RELATIVE`` of the curve everywhere it is probed
(between every pair of nodes); the measured figure is kept with the LUT.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from generator import tolerances

MIN_SIZE = 1024
MAX_SIZE = 1 << 17


#: Shaper exponents tried in turn: the LUT is indexed by u = t ** (1 / k), t the code
#: normalised to [0, 1] over the domain, which unfolds a square-root singularity at
#: the domain's start (Apple Log's and Mi-Log's quadratic toe decode as a square root).
SHAPER_EXPONENTS = (1, 2)


@dataclass(frozen=True)
class BakedCurve:
    """A baked decoding curve: LUT ``values`` at u = 0..1, code = lo + (hi - lo) * u ** shaper."""

    filename: str
    domain: tuple[float, float]
    shaper: int
    values: tuple[float, ...]
    max_relative_error: float


@dataclass(frozen=True)
class _Shaped:
    curve: object
    domain: tuple[float, float]
    shaper: int

    def decode(self, u):
        lo, hi = self.domain
        return self.curve.decode(lo + (hi - lo) * np.asarray(u, dtype=np.float64) ** self.shaper)


def slug(name: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", name.lower()).strip("_")


def relative_error(actual, expected) -> np.ndarray:
    expected = np.asarray(expected, dtype=np.float64)
    return np.abs(np.asarray(actual, dtype=np.float64) - expected) / np.maximum(np.abs(expected), tolerances.RELATIVE_FLOOR)


def interpolation_error(curve, domain, size: int, jumps=()) -> float:
    """Worst relative error of linear interpolation between ``size`` nodes, probed at 1/4, 1/2, 3/4.

    Intervals holding one of ``jumps`` (the curve's own published discontinuities,
    where no interpolation can do better than half the jump) are left out.
    """
    nodes = np.linspace(domain[0], domain[1], size)
    values = curve.decode(nodes)
    keep = np.ones(size - 1, dtype=bool)
    for jump in jumps:
        keep &= ~((nodes[:-1] <= jump) & (jump <= nodes[1:]))
    worst = 0.0
    for t in (0.25, 0.5, 0.75):
        x = nodes[:-1] + t * np.diff(nodes)
        interpolated = values[:-1] + t * np.diff(values)
        worst = max(worst, float(np.max(relative_error(interpolated, curve.decode(x))[keep])))
    return worst


def _smallest(curve, jumps) -> tuple[int, float]:
    size = MIN_SIZE
    while (error := interpolation_error(curve, (0.0, 1.0), size + 1, jumps)) > tolerances.BAKED_CURVE_RELATIVE / 2:
        if size >= MAX_SIZE:
            break
        size *= 2
    return size, error


def bake_curve(name: str, curve, domain) -> BakedCurve:
    """Bake ``curve.decode`` over ``domain`` (code values) into the smallest LUT within bound,
    trying each shaper in turn."""
    lo, hi = (float(v) for v in domain)
    jumps = tuple((j - lo) / (hi - lo) for j in getattr(curve, "discontinuities", ()))
    best = None
    for k in SHAPER_EXPONENTS:
        shaped = _Shaped(curve, (lo, hi), k)
        size, error = _smallest(shaped, tuple(j ** (1.0 / k) for j in jumps))
        if best is None or (error, size) < (best[2], best[1]):
            best = (k, size, error, shaped)
        if error <= tolerances.BAKED_CURVE_RELATIVE / 2:
            break
    k, size, error, shaped = best
    values = shaped.decode(np.linspace(0.0, 1.0, size + 1)).astype(np.float32).astype(np.float64)
    return BakedCurve(f"{slug(name)}_to_linear.spi1d", (lo, hi), k, tuple(values), error)
