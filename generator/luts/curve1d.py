"""Baking a decoding curve into a uniformly sampled 1D LUT, as dense as the bound needs.

Used where the target OCIO version cannot express a curve analytically. The
size doubles until linear interpolation between nodes stays within
``tolerances.BAKED_CURVE_RELATIVE`` of the curve everywhere it is probed
(between every pair of nodes); the measured figure is kept with the LUT.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator import tolerances
from generator.colorimetry.transfer import Tabulated, TransferFunction
from generator.luts.names import slug
from generator.luts.spi1d import format_spi1d
from generator.metrics import relative_error

MIN_SIZE = 1024
MAX_SIZE = 1 << 17

#: How evenly a table's rows must be spaced, relative to their step, to be baked on its rows
#: (codes written to nine decimals, as a 10-bit table's i/1023 are, vary by 1e-9).
ROW_SPACING_RELATIVE = 1e-5


#: Shaper exponents tried in turn: the LUT is indexed by u = t ** (1 / k), t the code
#: normalised to [0, 1] over the domain. k = 2 unfolds a square-root singularity at the
#: domain's start (Apple Log's and Mi-Log's quadratic toes decode as a square root);
#: k = 1/3 makes a cubic toe linear in u, so the LUT's inverse stays exact where the
#: curve is flat (N-Log's cube-root encoding).
SHAPER_EXPONENTS = (1.0, 2.0, 1.0 / 3.0)


@dataclass(frozen=True)
class BakedCurve:
    """A baked decoding curve: LUT ``values`` at u = 0..1, code = lo + (hi - lo) * u ** shaper."""

    filename: str
    domain: tuple[float, float]
    shaper: float
    values: tuple[float, ...]
    max_relative_error: float


@dataclass(frozen=True)
class _Shaped:
    curve: TransferFunction
    domain: tuple[float, float]
    shaper: float

    def code(self, u):
        """Code values of the table positions ``u`` (0 to 1) through the shaper."""
        lo, hi = self.domain
        return lo + (hi - lo) * np.asarray(u, dtype=np.float64) ** self.shaper

    def decode(self, u):
        """Linear values of the table positions ``u``."""
        return self.curve.decode(self.code(u))


def curve_file(baked: BakedCurve) -> bytes:
    """The .spi1d file of ``baked``, as the config references it."""
    return format_spi1d(baked.values).encode("ascii")


def _lut_errors(curve, domain, size: int, jumps=()) -> tuple[float, float]:
    """(decode, encode) worst relative errors of a LUT of ``size`` nodes over ``domain``.

    Decoding interpolates between nodes; encoding inverts that interpolation, so a
    value interpolated at a fraction t of an interval maps back exactly to the
    input at t: its error is that input against the curve's own encoding (in
    code values when ``curve`` is a shaped curve). Intervals holding one of ``jumps``
    (the curve's own published discontinuities, where no interpolation can do better
    than half the jump) are left out.
    """
    nodes = np.linspace(domain[0], domain[1], size)
    values = curve.decode(nodes)
    keep = np.ones(size - 1, dtype=bool)
    for jump in jumps:
        keep &= ~((nodes[:-1] <= jump) & (jump <= nodes[1:]))
    worst = [0.0, 0.0]
    for t in (0.25, 0.5, 0.75):
        x = nodes[:-1] + t * np.diff(nodes)
        interpolated = values[:-1] + t * np.diff(values)
        worst[0] = max(worst[0], float(np.max(relative_error(interpolated, curve.decode(x))[keep])))
        if isinstance(curve, _Shaped):
            inverse = relative_error(curve.code(x), curve.curve.encode(interpolated))
            worst[1] = max(worst[1], float(np.max(inverse[keep])))
    return worst[0], worst[1]


def _smallest(curve, jumps, limit: int = MAX_SIZE) -> tuple[int, float]:
    """The smallest size from MIN_SIZE doubling to ``limit`` meeting the bound, with its error
    (``limit`` and its error when none does)."""
    size = MIN_SIZE
    while (error := max(_lut_errors(curve, (0.0, 1.0), size + 1, jumps))) > tolerances.BAKED_CURVE_RELATIVE / 2:
        if size >= limit:
            break
        size *= 2
    return size, error


def _row_intervals(curve, domain: tuple[float, float]) -> int:
    """For a tabulated curve whose rows are evenly spaced in code over ``domain``, the number
    of LUT intervals putting an entry on every row (a multiple of the table's, at least
    MIN_SIZE, at most MAX_SIZE); 0 otherwise. Linear interpolation between such entries is
    the table's own, so a steep row (a clip flag on the top code) costs nothing."""
    if not isinstance(curve, Tabulated) or (curve.code[0], curve.code[-1]) != tuple(domain):
        return 0
    code = np.asarray(curve.code)
    intervals = code.size - 1
    step = (code[-1] - code[0]) / intervals
    if not np.allclose(np.diff(code), step, rtol=0.0, atol=ROW_SPACING_RELATIVE * step):
        return 0
    multiple = max(1, int(2 ** np.ceil(np.log2(MIN_SIZE / intervals)))) if intervals < MIN_SIZE else 1
    return intervals * multiple if intervals * multiple <= MAX_SIZE else 0


def bake_curve(name: str, curve, domain) -> BakedCurve:
    """Bake ``curve.decode`` over ``domain`` (code values) into the smallest LUT whose
    decoding and inverse both stay within bound, over the shapers of SHAPER_EXPONENTS."""
    lo, hi = (float(v) for v in domain)
    jumps = tuple((j - lo) / (hi - lo) for j in getattr(curve, "discontinuities", ()))
    candidates = []
    rows = _row_intervals(curve, (lo, hi))
    if rows:  # a table with evenly spaced rows: entries on every row reproduce it exactly, and
        # are taken whenever they are within bound, even where a smaller LUT would be too
        shaped = _Shaped(curve, (lo, hi), 1.0)
        error = max(_lut_errors(shaped, (0.0, 1.0), rows + 1, jumps))
        candidates.append((error > tolerances.BAKED_CURVE_RELATIVE / 2, False, rows, error, -1, shaped))
    for k in SHAPER_EXPONENTS:
        # rows within bound win over any shaper, and a shaper only wins at a size no larger than
        # the best within bound so far: search no further than that
        passing = [c[2] for c in candidates if not c[0]]
        if any(not c[0] and not c[1] for c in candidates):
            break
        shaped = _Shaped(curve, (lo, hi), k)
        size, error = _smallest(shaped, tuple(j ** (1.0 / k) for j in jumps), min(passing, default=MAX_SIZE))
        candidates.append(
            (error > tolerances.BAKED_CURVE_RELATIVE / 2, True, size, error, SHAPER_EXPONENTS.index(k), shaped)
        )
    *_, size, error, _, shaped = min(candidates, key=lambda c: c[:5])
    values = shaped.decode(np.linspace(0.0, 1.0, size + 1)).astype(np.float32).astype(np.float64)
    return BakedCurve(f"{slug(name)}_to_linear.spi1d", (lo, hi), shaped.shaper, tuple(values), error)
