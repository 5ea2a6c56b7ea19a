"""Judging an engine's output for a check: errors per sample, the worst input, a verdict.

Samples compared: finite inputs whose reference value is finite (where the
reference is undefined, e.g. the logarithm of a negative value in a log curve
without a linear toe, the sample is counted as undefined and left out), inside
the check's ``keep`` mask. An engine output that is not finite where the
reference is finite is an error of +Inf.

Non-finite input policy (the NaN / ±Inf probes), for every generated config:

* display outputs (views and display spaces) are finite and within the
  display's code range [0, peak encoded]: the display clamp sends NaN and
  -Inf to 0; which finite value an Inf gives is not specified, since a matrix
  mixes it with other channels (Inf - Inf is NaN, then 0);
* data outputs (the Raw view and data spaces) are the input, NaN and Inf included;
* an integer file (16-bit TIFF or PNG) holds neither, only [0, 1];
* scene and code outputs are unspecified for a non-finite pixel (OCIO
  propagates or replaces it depending on the operator and the optimisation
  flags); the finite pixels of the same image must still match.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass, field

import numpy as np

from generator import tolerances
from generator.colorimetry.matrices import channel_max
from generator.metrics import (
    colour_relative_error,
    delta_e_of_ictcp,
    dequantised,
    ictcp_of_codes,
    percentile_99,
    relative_error,
)
from generator.verify import paths
from generator.verify.check import CODES, COLOUR, ITP, Check, display_code_limit

PASS, FAIL, APPROX, NOT_RUN = "pass", "FAIL", "approx", "not run"


@dataclass(frozen=True)
class Output:
    """What an engine returned for one check: values read back, or the error it gave.

    ``variant`` names the file path (e.g. "EXR float", "TIFF uint16"), ``step``
    the quantisation step of the file the values were read from (0 for float).
    """

    values: np.ndarray | None = field(repr=False)
    variant: str = ""
    step: float = 0.0
    error: str = ""


@dataclass(frozen=True, eq=False)
class Outcome:
    """One row of the verify table."""

    check: Check
    engine: str
    verdict: str
    worst: float = float("nan")
    p99: float = float("nan")
    worst_input: str = ""
    compared: int = 0
    undefined: int = 0
    violations: int = 0
    note: str = ""
    errors: np.ndarray | None = field(default=None, repr=False)
    values: np.ndarray | None = field(default=None, repr=False)
    step: float = 0.0


#: ICtCp of a check's compared reference values, by file step: every engine's output is judged
#: against the same values, and decoding them to ICtCp is most of a ΔE ITP judgement.
_REFERENCE_ICTCP: weakref.WeakKeyDictionary[Check, dict[float, np.ndarray]] = weakref.WeakKeyDictionary()


def _reference_ictcp(check: Check, safe: np.ndarray, step: float) -> np.ndarray:
    """ICtCp of ``safe``, the reference values ``check`` compares for files of ``step``."""
    by_step = _REFERENCE_ICTCP.setdefault(check, {})
    if step not in by_step:
        by_step[step] = ictcp_of_codes(check.target, safe)
    return by_step[step]


def _finite(rgb: np.ndarray) -> np.ndarray:
    """Whether each colour (n, 3) is finite in every channel, channel by channel (numpy reduces
    over an axis of three many times slower)."""
    return np.isfinite(rgb[:, 0]) & np.isfinite(rgb[:, 1]) & np.isfinite(rgb[:, 2])


def sample_errors(check: Check, actual: np.ndarray, step: float) -> tuple[np.ndarray, int]:
    """Per-sample errors in the check's metric (NaN where not compared) and the undefined count."""
    expected = check.expected
    if expected is None:
        raise ValueError(f"{check.title}: the reference evaluation gave nothing to compare")
    if step:
        expected = np.clip(expected, 0.0, 1.0)
    compared = check.probes.finite & _finite(expected)
    undefined = int(np.sum(check.probes.finite & ~compared))
    if check.keep is not None:
        compared &= check.keep
    safe = np.where(compared[:, None], expected, 0.0)
    slack = step if check.allowance is None else step + 2.0 * check.allowance
    with np.errstate(all="ignore"):
        got = dequantised(np.where(compared[:, None], actual, 0.0), safe, slack)
        if check.metric == ITP:
            errors = delta_e_of_ictcp(ictcp_of_codes(check.target, got), _reference_ictcp(check, safe, step))
        elif check.metric == CODES:
            errors = channel_max(np.abs(got - safe)) * 1023.0
        elif check.metric == COLOUR:
            errors = colour_relative_error(got, safe) / check.scale
        else:
            errors = channel_max(relative_error(got, safe))
    errors = np.where(_finite(actual), errors, np.inf)
    return np.where(compared, errors, np.nan), undefined


def policy_violations(check: Check, actual: np.ndarray, step: float = 0.0) -> tuple[int, str]:
    """Non-finite probes whose output breaks the policy above: count, first one described.
    An integer file (``step`` > 0) holds no NaN or Inf, only [0, 1]: nothing to check there."""
    special = ~check.probes.finite
    inputs = check.probes.values
    if step:
        return 0, ""
    if check.output == paths.DATA:
        bad = special & ~np.all((actual == inputs) | (np.isnan(actual) & np.isnan(inputs)), axis=-1)
    elif check.output == paths.DISPLAY and check.target is not None:
        limit = display_code_limit(check.target)
        slack = tolerances.ANALYTIC_RELATIVE * max(limit, tolerances.RELATIVE_FLOOR)
        with np.errstate(invalid="ignore"):
            inside = np.isfinite(actual) & (actual >= -slack) & (actual <= limit + slack)
        bad = special & ~np.all(inside, axis=-1)
    else:
        return 0, ""
    if not bad.any():
        return 0, ""
    first = int(np.flatnonzero(bad)[0])
    got = ", ".join(f"{v:.6g}" for v in actual[first])
    return int(bad.sum()), f"non-finite policy: {check.probes.describe(first)} gave ({got})"


def judged_output(check: Check, values) -> np.ndarray:
    """An engine's raw output as the check judges it (a view file ending in light, encoded)."""
    values = np.asarray(values, dtype=np.float64).reshape(-1, 3)
    return values if check.encode is None else check.encode(values)


def judge(check: Check, engine: str, output: Output) -> Outcome:
    """The verdict on ``output``: FAIL on an engine error, a missing reference, a
    policy violation or an error above the check's tolerance."""
    name = f"{engine} ({output.variant})" if output.variant else engine
    if output.error:
        return Outcome(check, name, FAIL, note=output.error.strip().splitlines()[-1][:300])
    if check.expected is None:
        return Outcome(check, name, FAIL, note=check.problem)
    actual = judged_output(check, output.values)
    errors, undefined = sample_errors(check, actual, output.step)
    compared = int(np.sum(np.isfinite(errors) | np.isinf(errors)))
    if compared == 0:
        return Outcome(check, name, FAIL, undefined=undefined, note="no sample could be compared", errors=errors)
    worst_index = int(np.nanargmax(errors))
    worst = float(errors[worst_index])
    violations, note = policy_violations(check, actual, output.step)
    verdict = PASS if worst <= check.tolerance and not violations else FAIL
    return Outcome(
        check,
        name,
        verdict,
        worst,
        percentile_99(errors),
        check.probes.describe(worst_index),
        compared,
        undefined,
        violations,
        note,
        errors,
        actual if verdict == FAIL else None,
        output.step,
    )
