"""The segmented quadratic B-spline of the ACES 1.x tone scales, forward and inverse.

Academy of Motion Picture Arts and Sciences, aces-dev v1.3 (2021),
``transforms/ctl/lib/ACESlib.Tonescales.ctl`` (``segmented_spline_c5_fwd`` /
``_rev``, ``segmented_spline_c9_fwd`` / ``_rev``) and ``ACESlib.SSTS.ctl`` (``ssts`` /
``inv_ssts``, the same curve with six coefficients a side). In log10-log10 space the
curve is a uniform quadratic B-spline from its minimum point to its middle point and
another from the middle to the maximum, with straight extensions of given slopes
beyond the ends. A curve of ``n + 2`` coefficients a side has ``n`` knots a side
(C5: 4, the RRT and the SSTS; C9: 8, the ODTs).

The inverse is the CTL's: it solves each segment's quadratic, and it clamps output
beyond the end points to the end points' inputs, whatever the forward extension's
slope (the 48-nit ODT's high extension rises at 0.04 and is not inverted).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Smallest positive half float (OpenEXR's HALF_MIN, 2**-24, which CTL provides): the CTL takes
#: the log of max(x, HALF_MIN).
HALF_MIN = 2.0**-24

#: Largest half float: the CTL's clamps of rendering-space values.
HALF_MAX = 65504.0

#: Floor of the inverse's log10 (``segmented_spline_c5_rev``: ``max(y, 1e-10)``).
INVERSE_FLOOR = 1e-10


@dataclass(frozen=True)
class SegmentedSpline:
    """One ACES 1.x segmented spline (the CTL's ``SegmentedSplineParams_c5/_c9``, ``TsParams``).

    ``min_point``, ``mid_point`` and ``max_point`` are (input, output) pairs in linear
    units (scene exposure in, cd/m² or OCES out); ``coefs_low`` and ``coefs_high`` are
    the B-spline coefficients in log10 output units; ``slope_low`` and ``slope_high``
    the log-log slopes of the extensions below the minimum and above the maximum.
    """

    coefs_low: tuple[float, ...]
    coefs_high: tuple[float, ...]
    min_point: tuple[float, float]
    mid_point: tuple[float, float]
    max_point: tuple[float, float]
    slope_low: float = 0.0
    slope_high: float = 0.0

    def __post_init__(self):
        if len(self.coefs_low) != len(self.coefs_high) or len(self.coefs_low) < 4:
            raise ValueError("coefs_low and coefs_high need the same length, at least 4")

    @property
    def knots(self) -> int:
        """Knots a side: two fewer than the coefficients."""
        return len(self.coefs_low) - 2

    def log_points(self) -> np.ndarray:
        """log10 of the three points, shape (3, 2): rows min, mid, max; columns input, output."""
        return np.log10(np.array([self.min_point, self.mid_point, self.max_point], dtype=np.float64))


#: Monomial to B-spline basis of one quadratic segment: [t², t, 1] · (coefficients · M).
BASIS = np.array([[0.5, -1.0, 0.5], [-1.0, 1.0, 0.5], [0.5, 0.0, 0.0]])

#: ln 10: 10**v is computed as exp(v ln 10), which numpy does faster (17 ms against 20 for 65³ colours).
LN10 = np.log(10.0)


def _quadratics(spline: SegmentedSpline) -> np.ndarray:
    """(a, b, c) of a t² + b t + c for every segment, low half then high, shape (2 (n - 1), 3)."""
    rows, n = [], spline.knots
    for coefs in (spline.coefs_low, spline.coefs_high):
        c = np.asarray(coefs, dtype=np.float64)
        rows.append(np.stack([c[: n - 1], c[1:n], c[2 : n + 1]], axis=-1) @ BASIS)
    return np.concatenate(rows)


def spline_forward(x, spline: SegmentedSpline) -> np.ndarray:
    """The tone scale at linear input ``x`` (any shape), elementwise.

    ``segmented_spline_c5_fwd`` / ``segmented_spline_c9_fwd`` / ``ssts``
    (aces-dev v1.3, ACESlib.Tonescales.ctl and ACESlib.SSTS.ctl): inputs at or below
    HALF_MIN count as HALF_MIN.

    >>> from generator.rendering.aces13_rrt import RRT_SPLINE
    >>> round(float(spline_forward(0.18, RRT_SPLINE)), 6)
    4.8
    """
    x = np.asarray(x, dtype=np.float64)
    logx = np.log10(np.maximum(np.atleast_1d(x), HALF_MIN))
    (lmin, ymin), (lmid, _), (lmax, ymax) = spline.log_points()
    n = spline.knots
    # Knot coordinate: 0 at the minimum, n - 1 at the middle, 2 (n - 1) at the maximum.
    knot = np.interp(logx, (lmin, lmid, lmax), (0.0, n - 1.0, 2.0 * (n - 1)))
    j = np.minimum(np.nan_to_num(knot).astype(np.intp), 2 * n - 3)
    t = knot - j
    a, b, c = (np.take(column, j) for column in _quadratics(spline).T)
    logy = (a * t + b) * t + c
    for mask, slope, (lx, ly) in (
        (logx <= lmin, spline.slope_low, (lmin, ymin)),
        (logx >= lmax, spline.slope_high, (lmax, ymax)),
    ):
        # A flat extension is its end's output even at an infinite input.
        logy[mask] = slope * (logx[mask] - lx) + ly if slope else ly
    return np.exp(logy * LN10).reshape(x.shape)


def spline_inverse(y, spline: SegmentedSpline) -> np.ndarray:
    """The input whose tone-scale output is ``y``, elementwise.

    ``segmented_spline_c5_rev`` / ``segmented_spline_c9_rev`` / ``inv_ssts`` (aces-dev
    v1.3): each segment's quadratic solved for t; outputs at or below the minimum point's
    give its input, at or above the maximum point's give its input (the extensions are
    not inverted).
    """
    y = np.asarray(y, dtype=np.float64)
    logy = np.log10(np.maximum(np.atleast_1d(y), INVERSE_FLOOR))
    (lmin, ymin), (lmid, ymid), (lmax, ymax) = spline.log_points()
    n = spline.knots
    # A segment is chosen by the knot outputs around it; the middle's output splits the halves.
    low, high = (np.asarray(c, dtype=np.float64) for c in (spline.coefs_low, spline.coefs_high))
    edges = np.concatenate([(low[1 : n - 1] + low[2:n]) / 2.0, [ymid], (high[1 : n - 1] + high[2:n]) / 2.0])
    j = np.searchsorted(edges, logy, side="left")
    a, b, c = (np.take(column, j, mode="clip") for column in _quadratics(spline).T)
    c = c - logy
    with np.errstate(invalid="ignore", divide="ignore"):
        d = np.sqrt(np.maximum(b * b - 4.0 * a * c, 0.0))
        t = np.where(b + d != 0.0, 2.0 * c / (-d - b), 0.0)
    logx = np.interp(t + j, (0.0, n - 1.0, 2.0 * (n - 1)), (lmin, lmid, lmax))
    logx[logy <= ymin] = lmin
    logx[logy >= ymax] = lmax
    return np.exp(logx * LN10).reshape(y.shape)
