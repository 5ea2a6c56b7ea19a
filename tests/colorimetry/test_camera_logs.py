"""The LogCamera curves against colour-science's implementations of the vendors' formulas
and the constants their papers print."""

from __future__ import annotations

from functools import partial

import colour.models as cm
import numpy as np
import pytest

from generator import tolerances
from generator.colorimetry.curves import CURVES

# --- LogCamera records against colour-science's implementation of the vendor formula -------

COLOUR = {
    "ACEScct": (cm.log_encoding_ACEScct, cm.log_decoding_ACEScct),
    "ARRI LogC3 (EI800)": (partial(cm.log_encoding_ARRILogC3, EI=800), partial(cm.log_decoding_ARRILogC3, EI=800)),
    "ARRI LogC4": (cm.log_encoding_ARRILogC4, cm.log_decoding_ARRILogC4),
    "S-Log3": (cm.log_encoding_SLog3, cm.log_decoding_SLog3),
    "Log3G10": (partial(cm.log_encoding_Log3G10, method="v3"), partial(cm.log_decoding_Log3G10, method="v3")),
    "V-Log": (cm.log_encoding_VLog, cm.log_decoding_VLog),
    "BMDFilm Gen5": (cm.oetf_BlackmagicFilmGeneration5, cm.oetf_inverse_BlackmagicFilmGeneration5),
    "DaVinci Intermediate": (cm.oetf_DaVinciIntermediate, cm.oetf_inverse_DaVinciIntermediate),
    "D-Log": (cm.log_encoding_DJIDLog, cm.log_decoding_DJIDLog),
    "F-Log": (cm.log_encoding_FLog, cm.log_decoding_FLog),
    "F-Log2": (cm.log_encoding_FLog2, cm.log_decoding_FLog2),
    "L-Log": (cm.log_encoding_LLog, cm.log_decoding_LLog),
    "T-Log": (cm.log_encoding_FilmLightTLog, cm.log_decoding_FilmLightTLog),
    "T-LogE": (partial(cm.log_encoding_FilmLightTLog, w=512.0), partial(cm.log_decoding_FilmLightTLog, w=512.0)),
}

#: The vendor's printed toe minus the log segment at the break, in code value, as
#: documented in each curve's docstring (0 where they meet to better than 1e-9).
TOE_STEP = {
    "ARRI LogC3 (EI800)": 2.5e-7,
    "V-Log": 3.1e-7,
    "DaVinci Intermediate": 3.4e-10,
    "D-Log": -2.0e-6,
    "F-Log": 1.0e-4,
    "F-Log2": 3.5e-8,
    "L-Log": 9.0e-4,
}


@pytest.mark.parametrize("name", sorted(COLOUR))
def test_log_camera_against_colour(name):
    curve = CURVES[name]
    encode, decode = COLOUR[name]
    brk = curve.lin_side_break
    above = brk + np.geomspace(1e-7, 1e4, 3000)
    with np.errstate(all="ignore"):
        assert np.abs(curve.encode(above) - encode(above)).max() <= tolerances.FORMULA_ABSOLUTE
        below = brk - np.geomspace(1e-9, 0.1, 500)
        step = encode(below) - curve.encode(below)
    documented = TOE_STEP.get(name, 0.0)
    assert np.ptp(step) <= tolerances.FORMULA_ABSOLUTE, "the printed toe must be parallel to ours"
    assert abs(step.mean() - documented) <= max(tolerances.FORMULA_ABSOLUTE, 0.05 * abs(documented))
    # The vendor's printed decoding, re-encoded by us, above the step.
    codes = np.linspace(curve.break_code + abs(documented) + 1e-6, 1.0, 1000)
    with np.errstate(all="ignore"):
        assert np.abs(curve.encode(decode(codes)) - codes).max() <= tolerances.PUBLISHED_CURVE_ABSOLUTE


def test_jplog2_constants():
    curve = CURVES["JPLog2"]
    assert curve.encode(1.0) == pytest.approx(525.0 / 1023.0, abs=tolerances.FORMULA_ABSOLUTE)
    assert curve.lin_side_break == pytest.approx(2.0**-7.2, rel=1e-15)
    assert curve.break_code == pytest.approx(165.0 / 1023.0, abs=tolerances.FORMULA_ABSOLUTE)
    # The published toe, slope 10.36773919972907 and offset 0.09077750069969258.
    toe = np.linspace(-0.05, curve.lin_side_break, 100)
    expected = 10.36773919972907 * toe + 0.09077750069969258
    assert np.abs(curve.encode(toe) - expected).max() <= tolerances.FORMULA_ABSOLUTE


@pytest.mark.parametrize("name, w", [("T-Log", 128.0), ("T-LogE", 512.0)])
def test_filmlight_defining_values(name, w):
    """FilmLight's construction: linear w encodes to 1.0 and linear 0 to o = 0.075."""
    curve = CURVES[name]
    assert curve.encode(w) == pytest.approx(1.0, abs=tolerances.FORMULA_ABSOLUTE)
    assert curve.encode(0.0) == pytest.approx(0.075, abs=tolerances.FORMULA_ABSOLUTE)
