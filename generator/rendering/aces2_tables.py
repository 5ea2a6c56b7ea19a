"""The ACES 2.0 Output Transform's hue tables, computed as the Academy's CTL computes them.

Academy of Motion Picture Arts and Sciences, aces-core v2.0 (2025),
``lib/Lib.Academy.OutputTransform.ctl``, the table functions of ``init_ODTParams``: the same
sizes (360 hues, padded to 362 for the wrap), the same searches (stepped then bisected, to
the same tolerances), each run for every hue at once rather than hue by hue:

* ``make_reach_m_table``: the reach gamut's (AP1's) M at limit_J_max, at whole degrees;
* ``make_uniform_hue_gamut_table``: a nearly uniform hue table holding the hues of the six
  cube corners of the limiting gamut (at peak) and of the reach gamut (at limit_J_max), and
  the limiting gamut's cusp (J, M) at each hue, found by bisection along the cube edge;
* ``make_upper_hull_gamma_table``: the smallest upper-hull gamma (to 1e-5) putting the
  approximate boundary outside the limiting cube at five J between cusp and limit_J_max.

Where the CTL and OpenColorIO differ, this follows the CTL except where the CTL has a slip
OpenColorIO mends: the limiting corners are rotated to start at the lowest hue (the CTL sets
its index to 1 instead of ``i``; the two agree when red has the lowest hue, as in every
Academy preset). OpenColorIO starts each cusp bisection from the previous hue's result (the
cusps then move by less than the 1e-7 tolerance) and uses float32.
"""

from __future__ import annotations

import math

import numpy as np

from generator.rendering.aces2_compress import (
    FOCUS_GAIN_BLEND,
    compression_slope,
    focus_gain,
    focus_j,
    gamut_boundary_m,
    solve_j_intersect,
)
from generator.rendering.aces2_params import CUBE_CORNERS
from generator.rendering.jmh import JMhParams, j_to_achromatic, jmh_to_rgb, rgb_to_aab, rgb_to_jmh

#: Nominal entries of every hue table and the padded size (one entry each side).
TABLE_SIZE = 360
PADDED_SIZE = TABLE_SIZE + 2
#: The reach table's search: steps of M, the largest M, the bisection's tolerance.
REACH_STEP = 50.0
REACH_M_MAX = 1300.0
REACH_TOLERANCE = 1e-2
#: Tolerances of the reach corners' scale and of the cusp's position along a cube edge.
REACH_CORNER_TOLERANCE = 1e-3
CUSP_TOLERANCE = 1e-7
#: Enlargement of the cusp's M by the cusp smoothing: 1 + smooth_m x smooth_cusps.
CUSP_M_SCALE = 1.0 + 0.27 * 0.12
#: The upper hull's gamma search: step, largest step, tolerance, and the test points'
#: positions from the cusp's J (0) to limit_J_max (1).
GAMMA_STEP = 0.4
GAMMA_MAX = 5.0
GAMMA_TOLERANCE = 1e-5
GAMMA_TEST_POSITIONS = (0.01, 0.1, 0.5, 0.8, 0.99)


def _pad(nominal: np.ndarray, wrap: float = 0.0) -> np.ndarray:
    """Entries 1..360 from ``nominal``; entry 0 repeats the last less ``wrap``, 361 the first plus it."""
    return np.concatenate([nominal[-1:] - wrap, nominal, nominal[:1] + wrap])


def _bisect(predicate, low: np.ndarray, high: np.ndarray, tolerance: float) -> np.ndarray:
    """The CTL's bisection, for every entry at once: while high - low > tolerance, the
    midpoint replaces ``high`` where ``predicate`` holds and ``low`` elsewhere; returns ``high``."""
    while True:
        open_ = high - low > tolerance
        if not open_.any():
            return high
        mid = (high + low) / 2.0
        hit = predicate(mid)
        high = np.where(open_ & hit, mid, high)
        low = np.where(open_ & ~hit, mid, low)


def reach_m_table(reach: JMhParams, j_max: float) -> np.ndarray:
    """The reach gamut's M at J = ``j_max`` for hues 0..359 degrees, padded (``make_reach_m_table``):
    M stepped by 50 until a channel goes negative (at most 1300), then bisected to 0.01."""
    hues = np.arange(TABLE_SIZE, dtype=np.float64)

    def outside(m: np.ndarray) -> np.ndarray:
        hue = hues.reshape((-1,) + (1,) * (m.ndim - 1))
        jmh = np.stack(np.broadcast_arrays(np.float64(j_max), m, hue), axis=-1)
        return np.any(jmh_to_rgb(jmh, reach) < 0.0, axis=-1)

    steps = np.arange(REACH_STEP, REACH_M_MAX, REACH_STEP)
    hit = outside(np.broadcast_to(steps, (TABLE_SIZE, steps.size)))
    first = np.where(hit.any(axis=1), hit.argmax(axis=1), steps.size)
    high = (first + 1) * REACH_STEP
    return _pad(_bisect(outside, high - REACH_STEP, high, REACH_TOLERANCE))


def _cycle(jmh: np.ndarray, rgb: np.ndarray | None = None):
    """Corners rotated to start at the lowest hue, padded with the last (hue - 360) before and
    the first (hue + 360) after."""
    start = int(np.argmin(jmh[:, 2]))
    order = np.roll(np.arange(jmh.shape[0]), -start)
    cycled = _pad(jmh[order], 0.0)
    cycled[0, 2] -= 360.0
    cycled[-1, 2] += 360.0
    return cycled, None if rgb is None else _pad(rgb[order])


def reach_corners(reach: JMhParams, j_max: float, forward_limit: float) -> np.ndarray:
    """JMh of the reach cube's corners scaled to J = ``j_max`` (``find_reach_corners_table``),
    the scale bisected in [0, forward_limit] to 1e-3 on the achromatic response."""
    corners = np.asarray(CUBE_CORNERS)
    target = j_to_achromatic(j_max)
    scale = _bisect(
        lambda s: rgb_to_aab(s[:, None] * corners, reach)[:, 0] >= target,
        np.zeros(len(corners)),
        np.full(len(corners), forward_limit),
        REACH_CORNER_TOLERANCE,
    )
    return _cycle(rgb_to_jmh(scale[:, None] * corners, reach))[0]


def hue_table(sorted_hues: np.ndarray) -> np.ndarray:
    """The padded hue table (``build_hue_table``): each corner hue at the entry nearest its
    degree (nudged so no two share one), the hues between spread evenly."""
    counts: list[int] = []
    last, least = None, 0 if sorted_hues[0] == 0.0 else 1
    for k, hue in enumerate(sorted_hues):
        nominal = min(max(math.floor(hue + 0.5), least), TABLE_SIZE - 1)
        if nominal == last:
            if k > 1 and counts[k - 2] != counts[k - 1] - 1:
                counts[k - 1] -= 1
            else:
                nominal += 1
        counts.append(min(nominal, TABLE_SIZE - 1))
        last = least = nominal
    bounds = [0.0, *sorted_hues, 360.0]
    sizes = np.diff([0, *counts, TABLE_SIZE])
    table = np.concatenate([lo + np.arange(n) * ((hi - lo) / n) for lo, hi, n in zip(bounds, bounds[1:], sizes) if n])
    return _pad(table, 360.0)


def cusp_table(hues: np.ndarray, limit: JMhParams, peak: float) -> tuple[np.ndarray, np.ndarray]:
    """Cusp J and smoothed M of the limiting gamut at each hue of ``hues`` (``build_cusp_table``):
    on the cube edge between the corners around the hue, bisected to 1e-7 along the edge."""
    rgb = np.asarray(CUBE_CORNERS) * (peak / 100.0)
    corners, corner_rgb = _cycle(rgb_to_jmh(rgb, limit), rgb)
    nominal = hues[1:-1]
    upper = np.searchsorted(corners[1:, 2], nominal, side="right") + 1
    lower = upper - 1
    rgb_lo, rgb_hi = corner_rgb[lower], corner_rgb[upper]
    h_lo, h_hi = corners[lower, 2], corners[upper, 2]

    def sample(t: np.ndarray) -> np.ndarray:
        return rgb_to_jmh(rgb_lo + t[:, None] * (rgb_hi - rgb_lo), limit)

    def beyond(t: np.ndarray) -> np.ndarray:
        h = sample(t)[:, 2]
        return (h < h_lo) | ((h < h_hi) & (h > nominal))

    low, high = np.zeros(nominal.size), np.ones(nominal.size)
    while high[0] - low[0] > CUSP_TOLERANCE:
        mid = (low + high) / 2.0
        hit = beyond(mid)
        high, low = np.where(hit, mid, high), np.where(hit, low, mid)
    found = sample((low + high) / 2.0)
    exact = h_lo == nominal
    j = np.where(exact, corners[lower, 0], found[:, 0])
    m = np.where(exact, corners[lower, 1], found[:, 1]) * CUSP_M_SCALE
    return _pad(j), _pad(m)


def upper_hull_gamma_table(
    hues,
    cusp_j,
    cusp_m,
    limit: JMhParams,
    peak: float,
    j_max: float,
    mid_j: float,
    focus_dist: float,
    lower_hull_gamma_inv: float,
) -> np.ndarray:
    """The upper hull's inverse gamma at each hue, padded (``make_upper_hull_gamma_table``):
    the least gamma (stepped by 0.4 below 5, then bisected to 1e-5) whose approximate boundary
    lies outside the limiting cube (a channel above peak / 100) at all five test points."""
    h, cj, cm = (np.asarray(v)[1:-1, None] for v in (hues, cusp_j, cusp_m))
    test_j = cj + (j_max - cj) * np.asarray(GAMMA_TEST_POSITIONS)
    focus = focus_j(cj, mid_j, j_max)
    gain = focus_gain(test_j, cj + (j_max - cj) * FOCUS_GAIN_BLEND, j_max, focus_dist)
    j_is = solve_j_intersect(test_j, cm, focus, j_max, gain)
    slope = compression_slope(j_is, focus, j_max, gain)
    j_ic = solve_j_intersect(cj, cm, focus, j_max, gain)

    def fits(gamma: np.ndarray) -> np.ndarray:
        g = np.reshape(gamma, (h.shape[0], -1))[:, :, None]
        m = gamut_boundary_m(
            cj[:, None], cm[:, None], j_max, 1.0 / g, lower_hull_gamma_inv, j_is[:, None], slope[:, None], j_ic[:, None]
        )
        jmh = np.stack(np.broadcast_arrays(j_is[:, None] + slope[:, None] * m, m, h[:, None]), axis=-1)
        return np.all(np.any(jmh_to_rgb(jmh, limit) > peak / 100.0, axis=-1), axis=-1).reshape(np.shape(gamma))

    steps = [GAMMA_STEP]
    while steps[-1] < GAMMA_MAX:
        steps.append(steps[-1] + GAMMA_STEP)
    tried = np.asarray(steps[:-1])
    hit = fits(np.broadcast_to(tried, (h.shape[0], tried.size)))
    first = np.where(hit.any(axis=1), hit.argmax(axis=1), tried.size)
    low = np.concatenate([[0.0], steps])[first]
    high = np.asarray(steps)[first]
    return _pad(1.0 / _bisect(fits, low, high, GAMMA_TOLERANCE))
