"""Judging an engine's output for a check: a wrong value fails and its input is named; what is
taken off first (a file's quantisation, the float32 allowance) and no more; samples left out
(undefined, not kept, the non-finite family) and the non-finite policy; an engine's error."""

from __future__ import annotations

import numpy as np
import pytest

from generator import tolerances
from generator.verify import paths, probes
from generator.verify.check import CODES, COLOUR, ITP, LUT, TO_REFERENCE, VIEW, Check
from generator.verify.judge import FAIL, PASS, Output, judge, policy_violations

RAMP = probes.Family("ramp", np.repeat(np.linspace(0.0, 1.0, 11)[:, None], 3, axis=1))
PATCHES = probes.Family("patches", [[0.2, 0.4, 0.6], [0.5, 0.25, 0.125]], ("one", "two"))
INPUTS = probes.Probes((RAMP, PATCHES))


def _identity(**fields) -> Check:
    """A check whose expected output is its input (relative error unless ``fields`` say otherwise)."""
    return Check(TO_REFERENCE, "Identity", "A", "B", probes=INPUTS, expected=INPUTS.values.copy(), **fields)


def test_the_right_values_pass():
    outcome = judge(_identity(), "engine", Output(INPUTS.values.copy()))
    assert outcome.verdict == PASS and outcome.worst == 0.0 and outcome.compared == 13 and outcome.undefined == 0


def test_a_wrong_value_fails_naming_its_input():
    """Patch "two"'s green off by 1e-3: relative to 0.25 that is 4e-3, over the 1e-4 tolerance;
    the worst input is that patch, with its family, position, note and value."""
    actual = INPUTS.values.copy()
    actual[12, 1] += 1e-3
    outcome = judge(_identity(), "oiiotool", Output(actual, "EXR float"))
    assert outcome.verdict == FAIL and outcome.engine == "oiiotool (EXR float)"
    assert outcome.worst == pytest.approx(4e-3)
    assert outcome.worst_input == "patches[1] two (0.5, 0.25, 0.125)"
    np.testing.assert_array_equal(outcome.values, actual)  # kept to draw the failure


def test_an_error_under_the_tolerance_passes_and_one_over_it_fails():
    """Relative errors below 0.1 are taken over the floor of 0.1 (a ramp's 0.1 off by 9e-6 is
    9e-5; its 0 off by 1.1e-5 is 1.1e-4)."""
    under, over = INPUTS.values.copy(), INPUTS.values.copy()
    under[1] += 9e-6
    over[0] += 1.1e-5
    assert judge(_identity(), "e", Output(under)).verdict == PASS
    failed = judge(_identity(), "e", Output(over))
    assert (
        failed.verdict == FAIL and failed.worst == pytest.approx(1.1e-4) and failed.worst_input.startswith("ramp[0] ")
    )


def test_a_16_bit_files_half_step_is_taken_off_and_no_more():
    """Read back from a 16-bit file, a value half a step off is the file's rounding; one and a
    half steps off leaves a step, judged in 10-bit codes: 1023 / 65535."""
    step = tolerances.UINT16_STEP
    check = _identity(metric=CODES, tolerance=0.005)  # under half a step: 0.0078 codes
    rounded, wrong = INPUTS.values.copy(), INPUTS.values.copy()
    rounded[3] += step / 2
    wrong[3] += 1.5 * step
    assert judge(check, "e", Output(rounded, step=step)).worst == pytest.approx(0.0, abs=1e-12)
    assert judge(check, "e", Output(rounded)).verdict == FAIL  # the same values from a float file
    assert judge(check, "e", Output(wrong, step=step)).worst == pytest.approx(1023 * step)


def test_the_float32_allowance_is_taken_off_each_sample_and_channel():
    departure = np.zeros_like(INPUTS.values)
    departure[4, 2] = 3e-4
    actual = INPUTS.values + departure
    assert judge(_identity(allowance=departure.copy()), "e", Output(actual)).verdict == PASS
    half = judge(_identity(allowance=departure / 2), "e", Output(actual))
    assert half.verdict == FAIL and half.worst == pytest.approx(1.5e-4 / 0.4)
    elsewhere = np.roll(departure, 1, axis=1)  # the same allowance on another channel takes nothing off
    assert judge(_identity(allowance=elsewhere), "e", Output(actual)).worst == pytest.approx(3e-4 / 0.4)


def test_samples_without_a_reference_or_outside_keep_are_left_out():
    expected = INPUTS.values.copy()
    expected[5] = np.nan  # e.g. a log curve's logarithm of a negative value
    keep = np.ones(len(expected), dtype=bool)
    keep[6] = False  # e.g. beside a baked curve's jump
    actual = INPUTS.values.copy()
    actual[5:7] += 0.5
    check = Check(TO_REFERENCE, "Log", "A", "B", probes=INPUTS, expected=expected, keep=keep)
    outcome = judge(check, "e", Output(actual))
    assert outcome.verdict == PASS and outcome.compared == 11 and outcome.undefined == 1
    assert np.isnan(outcome.errors[5]) and np.isnan(outcome.errors[6])


def test_an_output_not_finite_where_the_reference_is_fails():
    actual = INPUTS.values.copy()
    actual[7, 0] = np.nan
    outcome = judge(_identity(), "e", Output(actual))
    assert outcome.verdict == FAIL and outcome.worst == np.inf and outcome.worst_input.startswith("ramp[7] ")


def test_nothing_to_compare_fails():
    nothing = np.full_like(INPUTS.values, np.nan)
    check = Check(TO_REFERENCE, "Log", "A", "B", probes=INPUTS, expected=nothing)
    outcome = judge(check, "e", Output(INPUTS.values.copy()))
    assert outcome.verdict == FAIL and outcome.note == "no sample could be compared"


def test_an_engine_error_and_a_missing_reference_fail_with_their_words():
    error = judge(_identity(), "ocio default", Output(None, error="Traceback ...\nException: no such view 'X'"))
    assert error.verdict == FAIL and error.note == "Exception: no such view 'X'"
    check = Check(VIEW, "sRGB / X", "A", display="sRGB", view="X", probes=INPUTS, problem="no evaluation of 'X'")
    missing = judge(check, "e", Output(INPUTS.values.copy()))
    assert missing.verdict == FAIL and missing.note == "no evaluation of 'X'"


def test_a_view_file_ending_in_light_is_encoded_before_it_is_judged():
    """The check's ``encode`` (here a square root, as a 2.0 gamma display would) runs on the
    engine's output: light equal to the codes squared passes, the codes themselves do not."""
    codes = INPUTS.values.copy()
    check = Check(LUT, "luts/view.clf", "View", probes=INPUTS, expected=codes, metric=COLOUR, encode=np.sqrt)
    assert judge(check, "e", Output(codes**2)).verdict == PASS
    assert judge(check, "e", Output(codes)).verdict == FAIL


NON_FINITE = probes.Probes((RAMP, probes.non_finite()))


def test_a_display_output_of_a_non_finite_probe_must_be_a_code_of_the_display(default_spec):
    """NaN and -Inf shown on a display are codes in [0, peak's code]; a NaN out is a policy
    violation, named with the probe, even where every finite sample matches."""
    display = next(d for d in default_spec.displays if d.name == "sRGB - Display")
    finite = NON_FINITE.finite
    expected = np.where(finite[:, None], NON_FINITE.values, np.nan)
    check = Check(
        VIEW,
        "sRGB - Display / Colorimetric",
        "A",
        display=display.name,
        view="Colorimetric",
        probes=NON_FINITE,
        expected=expected,
        output=paths.DISPLAY,
        target=display,
    )
    clamped = np.where(finite[:, None], NON_FINITE.values, 0.0)
    assert judge(check, "e", Output(clamped)).verdict == PASS
    leaked = clamped.copy()
    leaked[11, 1] = np.nan  # NaN in channel 0 of the non-finite family gave NaN in green
    outcome = judge(check, "e", Output(leaked))
    assert outcome.verdict == FAIL and outcome.violations == 1
    assert (
        outcome.note
        == "non-finite policy: non-finite[0] NaN in channel 0 (nan, 0.180000007, 0.180000007) gave (0, nan, 0)"
    )
    assert policy_violations(check, leaked, tolerances.UINT16_STEP) == (0, "")  # an integer file holds no NaN


def test_a_data_output_passes_non_finite_values_through():
    finite = NON_FINITE.finite
    expected = np.where(finite[:, None], NON_FINITE.values, np.nan)
    check = Check(
        VIEW, "sRGB - Display / Raw", "Raw", view="Raw", probes=NON_FINITE, expected=expected, output=paths.DATA
    )
    assert judge(check, "e", Output(NON_FINITE.values.copy())).verdict == PASS
    zeroed = np.where(np.isnan(NON_FINITE.values), 0.0, NON_FINITE.values)
    outcome = judge(check, "e", Output(zeroed))
    assert outcome.verdict == FAIL and outcome.violations == 4  # the NaN samples: three channels and all


def test_an_itp_judgement_is_the_metrics_delta_e_whatever_file_step_came_first(default_spec):
    """The reference's ICtCp is kept per check and file step: a 16-bit file judged after a float
    output (and a float output after it) is judged as :func:`delta_e_itp` judges it alone."""
    from generator.metrics import delta_e_itp, dequantised

    display = next(d for d in default_spec.displays if d.eotf_name == "HLG")  # its EOTF goes on above 1
    expected = INPUTS.values * 0.8 + 0.3  # to 1.1: a 16-bit file's reference is clipped to 1
    check = Check(
        VIEW, "HLG / v", "A", probes=INPUTS, expected=expected, output=paths.DISPLAY, target=display, metric=ITP
    )
    off = expected + np.linspace(0.0, 2e-3, expected.size).reshape(expected.shape)
    worst = []
    for step in (0.0, tolerances.UINT16_STEP, 0.0):
        reference = np.clip(expected, 0.0, 1.0) if step else expected
        alone = delta_e_itp(display, dequantised(off, reference, step), reference)
        worst.append(judge(check, "e", Output(off, step=step)).worst)
        assert worst[-1] == pytest.approx(float(np.max(alone)), rel=1e-12)
    assert worst[0] == worst[2] != worst[1]
