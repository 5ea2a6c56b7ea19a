"""The ACES 2.0 chroma compression and gamut compression, in JMh.

Academy of Motion Picture Arts and Sciences, aces-core v2.0 (2025),
``lib/Lib.Academy.OutputTransform.ctl``. Chroma compression (``chroma_compress_fwd``,
``chroma_compress_inv``) rescales M with the tone-mapped J, expands it near the neutral
axis and compresses it towards a hue-dependent limit. Gamut compression
(``gamut_compress_fwd``, ``gamut_compress_inv``, ``compress_gamut``) moves each colour along
a line of its hue plane through a focus on the J axis (between the cusp's J and mid grey's)
and compresses M on that line from 0.75 of the limiting gamut's boundary onward, so that the
reach gamut's (AP1's) boundary lands on it. The boundary is approximated from the cusp by a
lower hull of power ``1 / lower_hull_gamma_inv`` and an upper hull whose power is tabulated
by hue, joined by a smooth minimum.

Every function acts elementwise on float64 arrays of the same shape.
"""

from __future__ import annotations

import numpy as np

from generator.rendering.aces2_params import ACES2Tables
from generator.rendering.jmh import MODEL_GAMMA

#: Margin of the chroma expansion's limit (aces-core v2.0 ``chroma_compress_fwd``: 0.001).
TOE_LIMIT_MARGIN = 0.001
#: Smallest second constant of the toe function.
TOE_K2_MIN = 0.001
#: Fourier coefficients of the chroma compression's hue normaliser: cos h, cos 2h, cos 3h,
#: sin h, sin 2h, sin 3h and the constant (aces-core v2.0 ``chroma_compress_norm``).
NORM_COEFFICIENTS = (11.34072, 16.46899, 7.88380, 14.66441, -6.37224, 9.19364, 77.12896)
#: Cusp smoothing and the focus's blend towards mid grey and the threshold of the focus gain.
SMOOTH_CUSPS = 0.12
CUSP_MID_BLEND = 1.3
FOCUS_GAIN_BLEND = 0.3
#: Smallest distance to limit_J_max in the focus gain.
FOCUS_GAIN_FLOOR = 0.0001
#: Share of the gamut boundary's M below which M is kept.
COMPRESSION_THRESHOLD = 0.75


def toe_forward(x, limit, k1_in, k2_in):
    """The CTL's toe: x in [0, limit] remapped with a rounded toe near 0; beyond limit, x."""
    k2 = np.maximum(k2_in, TOE_K2_MIN)
    k1 = np.sqrt(k1_in * k1_in + k2 * k2)
    k3 = (limit + k1) / (limit + k2)
    minus_b = k3 * x - k1
    toed = 0.5 * (minus_b + np.sqrt(minus_b * minus_b + 4.0 * k2 * k3 * x))
    return np.where(x > limit, x, toed)


def toe_inverse(x, limit, k1_in, k2_in):
    """Inverse of :func:`toe_forward`."""
    k2 = np.maximum(k2_in, TOE_K2_MIN)
    k1 = np.sqrt(k1_in * k1_in + k2 * k2)
    k3 = (limit + k1) / (limit + k2)
    return np.where(x > limit, x, (x * x + k1 * x) / (k3 * (x + k2)))


def chroma_compress_norm(cos_h, sin_h, scale: float):
    """M of the rendering space's cusp by hue, a Fourier fit in (cos h, sin h), times ``scale``."""
    c1, s1 = cos_h, sin_h
    c2, s2 = c1 * c1 - s1 * s1, 2.0 * c1 * s1
    c3, s3 = (4.0 * c1 * c1 - 3.0) * c1, (3.0 - 4.0 * s1 * s1) * s1
    w = NORM_COEFFICIENTS
    return (w[0] * c1 + w[1] * c2 + w[2] * c3 + w[3] * s1 + w[4] * s2 + w[5] * s3 + w[6]) * scale


def reach_m_at(h, t: ACES2Tables):
    """Reach M at limit_J_max for hue ``h`` in [0, 360): the table is at whole degrees
    (aces-core v2.0 ``reach_M_from_table``)."""
    base = np.floor(h).astype(np.intp)
    w = h - base
    return t.reach_m[base + 1] * (1.0 - w) + t.reach_m[base + 2] * w


def chroma_compress(j, j_ts, m, h, norm, t: ACES2Tables, invert: bool = False):
    """M of (J, M, h) after (or, ``invert``, before) chroma compression, where the tone scale
    takes J to ``j_ts`` and ``norm`` is :func:`chroma_compress_norm` at h (aces-core v2.0
    ``chroma_compress_fwd`` / ``chroma_compress_inv``)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        nj = j_ts / t.limit_j_max
        snj = np.maximum(0.0, 1.0 - nj)
        limit = nj ** (1.0 / MODEL_GAMMA) * reach_m_at(h, t) / norm
        expand = (limit - TOE_LIMIT_MARGIN, snj * t.sat, np.sqrt(nj * nj + t.sat_thr))
        compress = (limit, nj * t.compr, snj)
        if invert:
            out = toe_inverse(m / norm, *compress)
            out = limit - toe_inverse(limit - out, *expand)
            out = out * norm * (j_ts / j) ** (-1.0 / MODEL_GAMMA)
        else:
            out = m * (j_ts / j) ** (1.0 / MODEL_GAMMA) / norm
            out = limit - toe_forward(limit - out, *expand)
            out = toe_forward(out, *compress) * norm
    return np.where(m != 0.0, out, m)


def focus_j(cusp_j, mid_j: float, j_max: float):
    """J of the focus: from the cusp's J towards mid grey's (aces-core v2.0 ``compute_focus_J``)."""
    return cusp_j + (mid_j - cusp_j) * np.minimum(1.0, CUSP_MID_BLEND - cusp_j / j_max)


def focus_gain(j, threshold, j_max: float, focus_dist: float):
    """The slope gain of the compression lines, steeper towards limit_J_max above ``threshold``
    (aces-core v2.0 ``get_focus_gain``)."""
    gain = j_max * focus_dist
    with np.errstate(divide="ignore", invalid="ignore"):
        adjust = np.log10((j_max - threshold) / np.maximum(FOCUS_GAIN_FLOOR, j_max - j))
    return np.where(j > threshold, gain * (adjust * adjust + 1.0), gain)


def solve_j_intersect(j, m, focus: np.ndarray, j_max: float, slope_gain):
    """J where the compression line through (J, M) meets the J axis (aces-core v2.0
    ``solve_J_intersect``): the root of a quadratic, in its numerically stable form."""
    m_scaled = m / slope_gain
    a = m_scaled / focus
    below = j < focus
    b = np.where(below, 1.0 - m_scaled, -(1.0 + m_scaled + j_max * a))
    c = np.where(below, -j, j_max * m_scaled + j)
    root = np.sqrt(b * b - 4.0 * a * c)
    return -2.0 * c / np.where(below, b + root, b - root)


def compression_slope(j_intersect, focus: np.ndarray, j_max: float, slope_gain):
    """dJ/dM of the compression line from its J-axis intersection (aces-core v2.0
    ``compute_compression_vector_slope``)."""
    direction = np.where(j_intersect < focus, j_intersect, j_max - j_intersect)
    return direction * (j_intersect - focus) / (focus * slope_gain)


def boundary_m(j_axis, slope, inv_gamma, j_max, m_max, j_reference):
    """M where a line of ``slope`` from ``j_axis`` meets the hull J = j_max (M / m_max)^gamma,
    approximated (aces-core v2.0 ``estimate_line_and_boundary_intersection_M``)."""
    shifted = j_reference * (j_axis / j_reference) ** inv_gamma
    return shifted * m_max / (j_max - slope * m_max)


def smooth_min(a, b, reference):
    """Cubic smooth minimum of width SMOOTH_CUSPS x ``reference`` (aces-core v2.0 ``smin_scaled``)."""
    s = SMOOTH_CUSPS * reference
    h = np.maximum(s - np.abs(a - b), 0.0) / s
    return np.minimum(a, b) - h * h * h * s / 6.0


def gamut_boundary_m(cusp_j, cusp_m, j_max, gamma_top_inv, gamma_bottom_inv, j_is, slope, j_ic):
    """M of the limiting gamut's approximate boundary on a compression line (aces-core v2.0
    ``find_gamut_boundary_intersection``): the smooth minimum of the lower and upper hulls'."""
    lower = boundary_m(j_is, slope, gamma_bottom_inv, cusp_j, cusp_m, j_ic)
    upper = boundary_m(j_max - j_is, -slope, gamma_top_inv, j_max - cusp_j, cusp_m, j_max - j_ic)
    return smooth_min(lower, upper, cusp_m)


def remap_m(m, gamut_m, reach_m, invert: bool = False):
    """M compressed (or expanded) from the threshold on so that ``reach_m`` lands on ``gamut_m``
    (aces-core v2.0 ``remap_M`` and ``reinhard_remap``)."""
    proportion = np.maximum(gamut_m / reach_m, COMPRESSION_THRESHOLD)
    threshold = proportion * gamut_m
    gamut_offset = gamut_m - threshold
    reach_offset = reach_m - threshold
    with np.errstate(divide="ignore", invalid="ignore"):
        scale = reach_offset / (reach_offset / gamut_offset - 1.0)
        nd = (m - threshold) / scale
        if invert:
            moved = threshold + np.where(nd >= 1.0, scale, scale * -(nd / (nd - 1.0)))
        else:
            moved = threshold + scale * nd / (1.0 + nd)
    return np.where((m <= threshold) | (proportion >= 1.0), m, moved)


def hue_dependent(h, t: ACES2Tables) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cusp J, cusp M and the upper hull's inverse gamma at hue ``h`` in [0, 360) (aces-core
    v2.0 ``init_HueDependentGamutParams``): the interval of the hue table holding ``h`` and
    linear interpolation in it, by the hue's share of the interval.

    The CTL finds the cusp's interval by bisecting the whole table (``cusp_from_table``), as
    here, but the gamma's by a search narrowed to a window around the hue's entry
    (``lookup_hue_interval``), which misses the interval for a fifth to a half of hues (its window
    is set one entry too high), and weighs the gamma by the hue's distance from the interval's
    start in degrees (``interpolation_weight`` ignores the width it is given, a remnant of the
    earlier uniform tables; v2.0's intervals are 0.09 to 1.27 degrees wide): the hull's gamma
    then jumps at every entry, and the rendering with it (up to 9e-4 of peak, measured).
    OpenColorIO weighs both by the share, as here, and narrows its search correctly but in
    slivers of the Rec.2020 presets' hue circle.
    """
    i = np.clip(np.searchsorted(t.hues, h, side="left"), 1, t.hues.size - 1)
    lo, hi = t.hues[i - 1], t.hues[i]
    w = (h - lo) / (hi - lo)

    def lerp(table: np.ndarray) -> np.ndarray:
        return table[i - 1] + w * (table[i] - table[i - 1])

    return lerp(t.cusp_j), lerp(t.cusp_m), lerp(t.gamma_top_inv)


def compress_gamut(j, m, h, jx, t: ACES2Tables, invert: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """(J, M) moved along its compression line, whose slope gain ``jx`` sets (aces-core v2.0
    ``compress_gamut``); colours with J > 0, M > 0 and J <= limit_J_max only.

    A boundary M that is not a number (a near-grey at limit_J_max, whose line meets the axis
    1e-14 above it, so the upper hull's power takes a negative base) leaves M = 0, as a boundary
    at or below 0 does; the CTL's test ``<= 0`` lets the NaN through.
    """
    j_max = t.limit_j_max
    cusp_j, cusp_m, gamma_top_inv = hue_dependent(h, t)
    focus = focus_j(cusp_j, t.mid_j, j_max)
    gain = focus_gain(jx, cusp_j + (j_max - cusp_j) * FOCUS_GAIN_BLEND, j_max, t.focus_dist)
    j_is = solve_j_intersect(j, m, focus, j_max, gain)
    slope = compression_slope(j_is, focus, j_max, gain)
    j_ic = solve_j_intersect(cusp_j, cusp_m, focus, j_max, gain)
    with np.errstate(invalid="ignore"):
        gamut_m = gamut_boundary_m(cusp_j, cusp_m, j_max, gamma_top_inv, t.lower_hull_gamma_inv, j_is, slope, j_ic)
        reach = boundary_m(j_is, slope, 1.0 / MODEL_GAMMA, j_max, reach_m_at(h, t), j_max)
        out_m = remap_m(m, gamut_m, reach, invert)
    inside = gamut_m > 0.0
    return np.where(inside, j_is + out_m * slope, j), np.where(inside, out_m, 0.0)


def gamut_compress(jmh, t: ACES2Tables, invert: bool = False) -> np.ndarray:
    """JMh after (or, ``invert``, before) gamut compression (aces-core v2.0
    ``gamut_compress_fwd`` / ``gamut_compress_inv``). J <= 0 gives black; M <= 0 or J above
    limit_J_max gives M = 0. Inverting, the slope gain above the analytic threshold depends on
    the unknown source J, which one forward pass estimates, as in the CTL."""
    j, m, h = jmh[..., 0], jmh[..., 1], jmh[..., 2]
    active = (j > 0.0) & (m > 0.0) & (j <= t.limit_j_max)
    every = bool(active.all())
    ja, ma, ha = (j, m, h) if every else (j[active], m[active], h[active])
    jx = ja
    if invert:
        cusp_j = hue_dependent(ha, t)[0]
        above = ja > cusp_j + (t.limit_j_max - cusp_j) * FOCUS_GAIN_BLEND
        jx = np.where(above, compress_gamut(ja, ma, ha, ja, t, invert)[0], ja)
    j_in, m_in = compress_gamut(ja, ma, ha, jx, t, invert)
    if every:
        return np.stack([j_in, m_in, h], axis=-1)
    j_out, m_out = np.maximum(j, 0.0), np.zeros_like(m)
    j_out[active], m_out[active] = j_in, m_in
    return np.stack([j_out, m_out, h], axis=-1)
