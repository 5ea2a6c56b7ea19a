"""The ACES 1.x segmented spline held to the CTL's coefficient tables and points."""

from __future__ import annotations

import numpy as np
import pytest

from generator import tolerances
from generator.rendering.aces13_odt import ODT_48NITS_SPLINE
from generator.rendering.aces13_rrt import RRT_SPLINE
from generator.rendering.aces13_spline import SegmentedSpline, spline_forward, spline_inverse
from generator.rendering.aces13_ssts import hdr_spline

#: The CTL's tables are printed to 10 decimals (ACESlib.Tonescales.ctl).
TABLE = tolerances.published_rounding(10)

SPLINES = {
    "RRT (C5)": RRT_SPLINE,
    "ODT 48 nits (C9)": ODT_48NITS_SPLINE,
    "SSTS 1000 nits": hdr_spline(0.0001, 15.0, 1000.0),
    "SSTS 108 nits": hdr_spline(0.0001, 7.2, 108.0),
}


def knot_inputs(spline: SegmentedSpline) -> np.ndarray:
    """log10 inputs of the knots, both halves (the middle point once)."""
    (lmin, _), (lmid, _), (lmax, _) = spline.log_points()
    n = spline.knots
    return np.concatenate([np.linspace(lmin, lmid, n), np.linspace(lmid, lmax, n)[1:]])


@pytest.mark.parametrize("name", list(SPLINES))
def test_knots_output_the_coefficient_averages(name):
    """The CTL's inverse reads each knot's log output as the mean of two neighbouring
    coefficients (KNOT_Y_LOW / KNOT_Y_HIGH): the forward curve passes through them."""
    spline = SPLINES[name]
    n = spline.knots
    low, high = np.asarray(spline.coefs_low), np.asarray(spline.coefs_high)
    # At the middle point the high half's first knot holds (the CTL's ``logx >= midPoint``).
    expected = np.concatenate([((low[:n] + low[1 : n + 1]) / 2.0)[:-1], (high[:n] + high[1 : n + 1]) / 2.0])
    inputs = knot_inputs(spline)
    # The end knots are the end points, where the extensions take over from the spline.
    got = np.log10(spline_forward(10.0 ** inputs[1:-1], spline))
    assert np.abs(got - expected[1:-1]).max() <= 1e-12


@pytest.mark.parametrize(
    "spline, points",
    [
        (RRT_SPLINE, ((0.18 * 2.0**-15, 0.0001), (0.18, 4.8), (0.18 * 2.0**18, 10000.0))),
        (
            ODT_48NITS_SPLINE,
            (
                (ODT_48NITS_SPLINE.min_point[0], 0.02),
                (ODT_48NITS_SPLINE.mid_point[0], 4.8),
                (ODT_48NITS_SPLINE.max_point[0], 48.0),
            ),
        ),
    ],
)
def test_published_tables_meet_their_points(spline, points):
    """RRT_PARAMS: 1e-4, 4.8 and 1e4 cd/m² at 0.18·2^-15, 0.18, 0.18·2^18; ODT_48nits: 0.02,
    4.8 and 48 cd/m² at the RRT's outputs for 0.18·2^-6.5, 0.18, 0.18·2^6.5 (the tables'
    10 decimals, in log10)."""
    x, y = np.array(points).T
    got = spline_forward(x * (1.0 - 1e-15), spline)
    assert np.abs(np.log10(got) - np.log10(y)).max() <= TABLE


def test_odt_points_are_the_rrt_at_the_cinema_stops():
    expected = spline_forward(0.18 * 2.0 ** np.array([-6.5, 0.0, 6.5]), RRT_SPLINE)
    got = [ODT_48NITS_SPLINE.min_point[0], ODT_48NITS_SPLINE.mid_point[0], ODT_48NITS_SPLINE.max_point[0]]
    assert np.array_equal(got, expected)


@pytest.mark.parametrize("name", list(SPLINES))
def test_inverse_undoes_forward_between_the_ends(name):
    spline = SPLINES[name]
    (lmin, _), _, (lmax, _) = spline.log_points()
    x = 10.0 ** np.linspace(lmin, lmax, 20001)[1:-1]
    y = spline_forward(x, spline)
    assert np.all(np.diff(y) > 0.0)
    assert np.abs(spline_inverse(y, spline) / x - 1.0).max() <= tolerances.ACES13_ROUND_TRIP_RELATIVE


@pytest.mark.parametrize("name", list(SPLINES))
def test_ends_extend_and_the_inverse_clamps(name):
    """Below the minimum and above the maximum the curve follows its end slopes (0, but
    0.04 above the 48-nit ODT's maximum); the inverse gives the end points' inputs."""
    spline = SPLINES[name]
    (lmin, ymin), _, (lmax, ymax) = spline.log_points()
    below = 10.0 ** (lmin - np.array([0.5, 3.0]))
    above = 10.0 ** (lmax + np.array([0.5, 3.0]))
    assert np.allclose(np.log10(spline_forward(below, spline)), ymin - spline.slope_low * np.array([0.5, 3.0]))
    assert np.allclose(np.log10(spline_forward(above, spline)), ymax + spline.slope_high * np.array([0.5, 3.0]))
    ends = spline_inverse(np.array([0.0, 10.0**ymin / 2.0, 10.0**ymax * 2.0, 1e30]), spline)
    assert np.allclose(np.log10(ends), [lmin, lmin, lmax, lmax], rtol=0.0, atol=1e-12)


def test_shapes_and_non_positive_inputs():
    x = np.full((2, 4, 3), 0.18)
    assert spline_forward(x, RRT_SPLINE).shape == (2, 4, 3)
    assert np.ndim(spline_forward(0.18, RRT_SPLINE)) == 0
    flat = spline_forward(np.array([-1.0, 0.0]), RRT_SPLINE)
    assert np.allclose(flat, RRT_SPLINE.min_point[1])
