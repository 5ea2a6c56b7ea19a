"""One check's record and how each output kind is judged: metric, tolerance and target by kind,
the samples left out beside a baked curve's jumps, the largest code a display is sent."""

from __future__ import annotations

import numpy as np
import pytest

from generator import tolerances
from generator.colorimetry.curves import NLOG_BREAK
from generator.luts.curve1d import curve_file
from generator.verify import paths
from generator.verify.check import (
    CODES,
    COLOUR,
    FROM_REFERENCE,
    ITP,
    LUT,
    RELATIVE,
    TO_REFERENCE,
    VIEW,
    Check,
    baked_lut,
    discontinuity_band,
    display_code_limit,
    judging,
)
from tests.verify.conftest import dim_output_table, newly_failing


def _display(spec, name):
    return next(d for d in spec.displays if d.name == name)


def test_a_scale_file_dimmed_by_half_a_code_is_named(config_copy):
    """The exact lattices (Scale, Desaturate) are held to the in-gamut target on every set, as
    Perceptual is to its lattice: the sRGB Scale file's output table scaled by 0.9995 (half a
    ten-bit code at white) fails its view and file; under the issue's every-set bound of a
    code, a file scaled by 0.9991 had passed."""

    def dim(path):
        dim_output_table(path.parent / "luts" / "view_srgb_display_scale_17.clf", 0.9995)

    failing = newly_failing(config_copy, dim, (VIEW, LUT))
    assert failing == {"luts/view_srgb_display_scale_17.clf", "sRGB - Display / Scale"}


def test_a_check_is_titled_as_its_kind_names_it():
    assert Check(TO_REFERENCE, "ACEScct", "ACEScct", "ACES2065-1").title == "ACEScct -> ACES2065-1"
    assert Check(FROM_REFERENCE, "ACEScct", "ACES2065-1", "ACEScct").title == "ACES2065-1 -> ACEScct"
    view = Check(VIEW, "sRGB - Display / Scale", "ACEScg", display="sRGB - Display", view="Scale")
    assert view.title == "sRGB - Display / Scale from ACEScg"
    assert Check(LUT, "luts/a.clf", "Scale", lut="luts/a.clf").title == "luts/a.clf"


def test_each_output_is_judged_in_its_metric_against_its_tolerance(spec):
    """SDR codes relative, HDR codes in ΔE ITP, linear light by colour; a baked curve's error grows
    by its matrix's largest row sum; a baked view's file is held to the LUT target in codes (ΔE
    ITP on HDR), an ACES 1.3 view to what OCIO's builtins were measured at."""
    ends = paths.LazyEndpoints(spec)
    srgb, pq = _display(spec, "sRGB - Display"), _display(spec, "Rec.2100-PQ - Display")
    acescct, aces = ends["ACEScct"], ends["ACES2065-1"]
    assert judging(acescct, None, None) == dict(metric=RELATIVE, tolerance=tolerances.ANALYTIC_RELATIVE, target=None)
    assert judging(aces, None, None) == dict(metric=COLOUR)
    assert judging(ends[srgb.name], srgb, None)["metric"] == RELATIVE
    assert judging(ends[pq.name], pq, None) == dict(metric=ITP, tolerance=tolerances.ANALYTIC_DELTA_E_ITP, target=pq)
    nlog = ends["N-Log N-Gamut"]
    baked = judging(aces, None, nlog)
    assert baked["metric"] == COLOUR and baked["tolerance"] == tolerances.BAKED_CURVE_RELATIVE
    assert baked["scale"] == pytest.approx(np.abs(nlog.matrix).sum(axis=1).max()) and baked["scale"] > 1.0
    assert judging(None, srgb, None, "Scale") == dict(
        metric=CODES, tolerance=tolerances.LUT_CLF_IN_GAMUT_CODES, target=srgb
    )
    assert judging(None, pq, None, "Scale") == dict(
        metric=ITP, tolerance=tolerances.LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP, target=pq
    )
    assert judging(None, srgb, None, "ACES 1.0 - SDR Video") == dict(
        metric=CODES, tolerance=tolerances.ACES13_OCIO_CODES, target=srgb
    )
    assert judging(None, srgb, None, "Colorimetric")["metric"] == RELATIVE
    with pytest.raises(ValueError, match="'Scale' is judged on a display, and none was given"):
        judging(None, None, None, "Scale")


def test_samples_beside_a_baked_curves_jump_are_left_out(spec):
    """N-Log jumps at its published break (its two pieces do not meet): samples with a channel
    within two ten-bit codes of it are not compared; a curve without a jump keeps everything."""
    nlog = paths.LazyEndpoints(spec)["N-Log N-Gamut"]
    below, above = nlog.curve.decode(np.array([NLOG_BREAK - 1e-9, NLOG_BREAK + 1e-9]))
    assert abs(above - below) > 1e-4  # a jump no interpolation between nodes can follow
    codes = np.zeros((4, 3))
    codes[:, 1] = [NLOG_BREAK - 3.0 / 1023, NLOG_BREAK - 1.0 / 1023, NLOG_BREAK + 1.5 / 1023, NLOG_BREAK + 3.0 / 1023]
    assert discontinuity_band(nlog, codes).tolist() == [True, False, False, True]
    assert discontinuity_band(paths.LazyEndpoints(spec)["ACEScct"], codes) is None


@pytest.mark.parametrize("name", ["N-Log N-Gamut", "CanonLog2 CinemaGamut D55"])
def test_a_baked_lut_is_the_file_the_build_wrote(build_config, spec, name):
    """verify re-runs the bake from the spec: its table is the config's file, byte for byte."""
    end = paths.LazyEndpoints(spec)[name]
    baked = baked_lut(end.baked, end.curve)
    assert baked is baked_lut(end.baked, end.curve)
    assert curve_file(baked) == (build_config((2, 1)).parent / "luts" / baked.filename).read_bytes()


def test_the_largest_code_a_display_is_sent_is_its_peaks(spec):
    """1 for an SDR display; ST 2084's code of 1000 cd/m², 0.7518, for a 1000 cd/m² PQ display;
    extended sRGB's code of its peak over 1, for Display P3 HDR."""
    assert display_code_limit(_display(spec, "sRGB - Display")) == pytest.approx(1.0)
    assert display_code_limit(_display(spec, "Rec.2100-PQ - Display")) == pytest.approx(0.75183, abs=1e-5)
    hdr = _display(spec, "Display P3 HDR - Display")
    srgb_peak = 1.055 * hdr.clip_high ** (1 / 2.4) - 0.055
    assert display_code_limit(hdr) == pytest.approx(srgb_peak)
