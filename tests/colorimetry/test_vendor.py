"""Vendor data colour-science lacks: Samsung Log and the missing camera gamuts."""

from __future__ import annotations

import dataclasses

import colour
import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.colorimetry import vendor
from generator.colorimetry.vendor import VENDOR_GAMUTS, GamutData, samsung_log_decode, samsung_log_encode

#: Samsung Log White Paper (2025), Table 1: scene reflectance -> normalised code value.
SAMSUNG_TABLE_1 = [(0.0, 0.125124), (0.01, 0.206562), (0.18, 0.527859), (0.90, 0.708700), (12.0, 1.0)]


@pytest.mark.parametrize("linear, code", SAMSUNG_TABLE_1)
def test_samsung_log_printed_values(linear, code):
    assert float(samsung_log_encode(linear)) == pytest.approx(code, abs=tolerances.PUBLISHED_CURVE_ABSOLUTE)
    decoded = float(samsung_log_decode(code))
    assert abs(decoded - linear) / max(linear, tolerances.RELATIVE_FLOOR) <= tolerances.PUBLISHED_CURVE_ABSOLUTE


def test_samsung_log_round_trip():
    codes = np.linspace(0.0, 1.0, 4097)
    linear = samsung_log_decode(codes)
    assert np.all(np.diff(linear) > 0)
    assert np.abs(samsung_log_encode(linear) - codes).max() <= tolerances.FORMULA_ABSOLUTE
    x = np.concatenate([np.linspace(-0.0499, 0.02, 2001), np.geomspace(0.02, 12.0, 2001)])
    error = np.abs(samsung_log_decode(samsung_log_encode(x)) - x) / np.maximum(np.abs(x), tolerances.RELATIVE_FLOOR)
    assert error.max() <= tolerances.ROUND_TRIP_RELATIVE


def test_samsung_log_clamps_and_segments():
    k = vendor.SAMSUNG_LOG
    assert float(samsung_log_encode(-0.2)) == 0.0
    assert float(samsung_log_decode(-0.2)) == k["x0"]
    assert float(samsung_log_decode(k["yt"])) == pytest.approx(k["xt"], abs=1e-9)
    # The printed constants' rounding, as documented: a 3.6e-6 step down at xt, 3.8e-6 at x0.
    step = float(samsung_log_encode(np.nextafter(k["xt"], 0.0)) - samsung_log_encode(k["xt"]))
    assert step == pytest.approx(3.6e-6, abs=1e-7)
    assert float(samsung_log_encode(k["x0"])) == pytest.approx(3.8e-6, abs=1e-7)
    with pytest.raises(TypeError):
        k["xt"] = 0.02


def test_samsung_log_arrays_keep_shape():
    codes = np.linspace(0.0, 1.0, 12).reshape(3, 4)
    assert samsung_log_decode(codes).shape == (3, 4)
    assert samsung_log_encode(samsung_log_decode(codes)).shape == (3, 4)


def test_vendor_gamuts_are_missing_from_colour_and_well_formed():
    assert set(VENDOR_GAMUTS) == {"Apple Wide Gamut", "Leica L-Gamut", "Samsung Log Gamut", "Xiaomi Mi-Log Gamut"}
    for name, gamut in VENDOR_GAMUTS.items():
        assert gamut.name == name and name not in colour.RGB_COLOURSPACES
        assert np.shape(gamut.primaries) == (3, 2) and np.shape(gamut.whitepoint) == (2,)
        assert gamut.citation
        npm = colour.normalised_primary_matrix(np.array(gamut.primaries), np.array(gamut.whitepoint))
        assert npm[1].sum() == pytest.approx(1.0, abs=1e-12)  # white has Y = 1
        assert np.linalg.det(npm) > 0.1  # three distinct, correctly ordered primaries
    with pytest.raises(dataclasses.FrozenInstanceError):
        VENDOR_GAMUTS["Apple Wide Gamut"].name = "x"
    with pytest.raises(TypeError):
        VENDOR_GAMUTS["x"] = GamutData("x", ((1, 0), (0, 1), (0, 0)), (0.3, 0.3), "")


@pytest.mark.parametrize("name", ["Leica L-Gamut", "Samsung Log Gamut", "Xiaomi Mi-Log Gamut"])
def test_bt2020_based_gamuts_match_colour_bt2020(name):
    bt2020 = colour.RGB_COLOURSPACES["ITU-R BT.2020"]
    gamut = VENDOR_GAMUTS[name]
    np.testing.assert_allclose(gamut.primaries, bt2020.primaries, atol=1e-12)
    np.testing.assert_allclose(gamut.whitepoint, bt2020.whitepoint, atol=1e-12)


def test_apple_wide_gamut_against_ocio_builtin():
    """OCIO's "APPLE_LOG-APPLEWG_to_ACES2065-1" ends with Apple Wide Gamut to ACES2065-1
    (Bradford); our primaries must reproduce that matrix."""
    group = ocio.Config.CreateRaw().getProcessor(ocio.BuiltinTransform("APPLE_LOG-APPLEWG_to_ACES2065-1"))
    matrix = [t for t in group.createGroupTransform() if isinstance(t, ocio.MatrixTransform)]
    assert len(matrix) == 1
    ocio_matrix = np.array(matrix[0].getMatrix()).reshape(4, 4)[:3, :3]
    gamut = VENDOR_GAMUTS["Apple Wide Gamut"]
    awg = colour.RGB_Colourspace("Apple Wide Gamut", np.array(gamut.primaries), np.array(gamut.whitepoint))
    ap0 = colour.RGB_COLOURSPACES["ACES2065-1"]
    ours = colour.matrix_RGB_to_RGB(awg, ap0, chromatic_adaptation_transform="Bradford")
    np.testing.assert_allclose(ours, ocio_matrix, atol=tolerances.PUBLISHED_MATRIX_ABSOLUTE / 1000)
