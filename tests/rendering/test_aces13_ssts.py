"""The single-stage tone scale held to ACESlib.SSTS.ctl's points, to the RRT's table it
generalises, and to the control points OpenColorIO's HDR builtins carry."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.rendering.aces13 import PRESETS13
from generator.rendering.aces13_rrt import RRT_SPLINE
from generator.rendering.aces13_spline import spline_forward
from generator.rendering.aces13_ssts import aces_max, aces_min, hdr_spline, ssts_spline

TABLE = tolerances.published_rounding(10)
FLOAT64 = 1e-12


def test_exposure_ends_follow_the_stop_tables():
    """lookup_ACESmin/max: 1e-4 cd/m² at 0.18·2^-15 and 0.02 at 0.18·2^-6.5; 48 at 0.18·2^6.5
    and 1e4 at 0.18·2^18, log-linear between (1000 nits: 6.5 + 11.5 log(1000/48) / log(1e4/48) stops)."""
    assert aces_min(0.0001) == pytest.approx(0.18 * 2.0**-15, rel=FLOAT64)
    assert aces_min(0.02) == pytest.approx(0.18 * 2.0**-6.5, rel=FLOAT64)
    assert aces_max(48.0) == pytest.approx(0.18 * 2.0**6.5, rel=FLOAT64)
    assert aces_max(10000.0) == pytest.approx(0.18 * 2.0**18, rel=FLOAT64)
    stops = 6.5 + 11.5 * np.log10(1000.0 / 48.0) / np.log10(10000.0 / 48.0)
    assert aces_max(1000.0) == pytest.approx(0.18 * 2.0**stops, rel=FLOAT64)


@pytest.mark.parametrize("peak", [1000.0, 2000.0, 4000.0, 108.0])
def test_unshifted_curve_meets_its_three_points(peak):
    """0.0001 cd/m² at the minimum exposure, 4.8 at 0.18, the peak at the maximum exposure."""
    spline = ssts_spline(0.0001, peak)
    x = np.array([aces_min(0.0001), 0.18, aces_max(peak)]) * (1.0 - 1e-15)
    assert spline_forward(x, spline) == pytest.approx([0.0001, 4.8, peak], rel=1e-12)


def test_at_the_rrts_limits_it_is_the_rrts_table():
    """Between 1e-4 and 1e4 cd/m², init_TsParams gives ACESlib.Tonescales.ctl's RRT_PARAMS
    (the table is printed to 10 decimals)."""
    spline = ssts_spline(0.0001, 10000.0)
    assert np.abs(np.subtract(spline.coefs_low, RRT_SPLINE.coefs_low)).max() <= TABLE
    assert np.abs(np.subtract(spline.coefs_high, RRT_SPLINE.coefs_high)).max() <= TABLE
    assert np.allclose(spline.log_points(), RRT_SPLINE.log_points(), rtol=0.0, atol=FLOAT64)


@pytest.mark.parametrize("mid, peak", [(15.0, 1000.0), (15.0, 2000.0), (15.0, 4000.0), (7.2, 108.0)])
def test_exposure_shift_puts_mid_grey_at_the_mid_luminance(mid, peak):
    """RRTODT.Academy.*_15nits / _7.2nits: ACES 0.18 gives Y_MID, and the points keep their
    luminances at shifted exposures."""
    spline = hdr_spline(0.0001, mid, peak)
    assert spline_forward(0.18, spline) == pytest.approx(mid, rel=1e-12)
    shift = np.log2(spline.mid_point[0] / 0.18)
    assert shift == pytest.approx(np.log2(spline.min_point[0] / aces_min(0.0001)), abs=FLOAT64)
    assert spline.min_point[1] == 0.0001 and spline.max_point[1] == peak


def ocio_curve(style: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Control points (x, y) and slopes of the HDR builtin's tone curve (log10 units)."""
    group = ocio.Config.CreateRaw().getProcessor(ocio.BuiltinTransform(style)).createGroupTransform()
    master = next(t for t in group if isinstance(t, ocio.GradingRGBCurveTransform)).getValue().master
    points = np.array([(p.x, p.y) for p in master.getControlPoints()], dtype=np.float32)
    return points[:, 0], points[:, 1], np.array(master.getSlopes(), dtype=np.float32)


@pytest.mark.parametrize("view", [v for v, p in PRESETS13.items() if p.kind == "hdr"])
def test_knots_are_the_ocio_builtins_control_points(view):
    """OpenColorIO's HDR builtins hold the SSTS as control points with slopes, computed from
    the same CTL: ours round to theirs in float32 (one unit in the last place)."""
    spline = PRESETS13[view].odt.spline
    (lmin, _), (lmid, _), (lmax, _) = spline.log_points()
    halves = []
    for coefs, lo, hi in ((spline.coefs_low, lmin, lmid), (spline.coefs_high, lmid, lmax)):
        c, step = np.asarray(coefs), (hi - lo) / 3.0
        halves.append(np.stack([lo + step * np.arange(4), (c[:4] + c[1:5]) / 2.0, (c[1:5] - c[:4]) / step]))
    knots, values, slopes = np.concatenate([halves[0], halves[1][:, 1:]], axis=1)
    for ours, theirs in zip((knots, values, slopes), ocio_curve(PRESETS13[view].style)):
        ours32 = ours.astype(np.float32)
        assert np.all(np.abs(ours32 - theirs) <= np.spacing(np.abs(theirs)) + 1e-30)
