"""A written frame against the float64 reference of the spec that built the config.

The frame's pixels are a verify check's probes (:func:`generator.verify.checks.conversion_check`):
the same expectation, metric, tolerance and float32 allowance as ``ocioforge verify``. The
written samples are compared in their own precision, never with a wider tolerance: an integer
file's value is the engine's rounded to its code, so half a code is taken off before the metric
(as verify does for its 16-bit files), and a half float's is the engine's rounded to the nearest
half, so half the gap to the next half toward the reference is (a half file holds nothing beyond
65504, nor an integer file anything outside 0 to 1: the reference is clipped there alike).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from generator.convert import formats
from generator.verify import probes as probe_sets
from generator.verify.checks import conversion_check
from generator.verify.judge import policy_violations, sample_errors


@dataclass(frozen=True)
class Route:
    """What a frame goes through: ``src`` to the colour space ``dst``, or to ``display`` through ``view``."""

    src: str
    dst: str = ""
    display: str = ""
    view: str = ""


@dataclass(frozen=True)
class Verdict:
    """How a written frame compares: samples compared, the worst error in the check's metric
    against its tolerance, and where (pixel, input, written and reference values)."""

    compared: int
    worst: float
    tolerance: float
    metric: str
    passed: bool
    where: str = ""
    note: str = ""

    def describe(self) -> str:
        """The verdict in one line: pixels compared, worst error against the tolerance."""
        if self.note and not self.compared:
            return self.note
        verdict = "within" if self.passed else "above"
        text = f"{self.compared} pixels, worst {self.worst:.3g} {self.metric} ({verdict} {self.tolerance:.3g})"
        return f"{text}, at {self.where}" if self.where and not self.passed else text


def _values(row) -> str:
    return "(" + ", ".join(f"{v:.9g}" for v in row) + ")"


def judge(
    spec, ends: dict, route: Route, inputs: np.ndarray, written: np.ndarray, positions: np.ndarray, depth: str
) -> Verdict:
    """``written`` (n, 3, float64, as read back) against the reference of ``inputs`` (n, 3) through
    ``route``; ``positions`` (n, 2) the pixels' x, y; ``depth`` the written sample type; ``ends``
    the spec's endpoints (:func:`generator.verify.paths.endpoints`, built once per process)."""
    finite = np.all(np.isfinite(inputs), axis=-1)
    order = np.concatenate([np.flatnonzero(finite), np.flatnonzero(~finite)])
    inputs, written, positions = inputs[order], written[order], positions[order]
    families = (
        probe_sets.Family("pixel", inputs[: int(finite.sum())]),
        probe_sets.Family(probe_sets.NON_FINITE, inputs[int(finite.sum()) :]),
    )
    check = conversion_check(spec, ends, probe_sets.Probes(families), route.src, route.dst, route.display, route.view)
    if check.expected is None:
        return Verdict(0, float("nan"), check.tolerance, check.metric, False, note=check.problem)
    check, written, step = _in_written_precision(check, written, depth)
    errors, _ = sample_errors(check, written, step)
    violations, why = policy_violations(check, written, step)
    compared = int(np.sum(~np.isnan(errors)))
    if compared == 0:
        return Verdict(
            0,
            float("nan"),
            check.tolerance,
            check.metric,
            violations == 0,
            note="no pixel could be compared (none finite with a finite reference)",
        )
    worst_index = int(np.nanargmax(errors))
    worst = float(errors[worst_index])
    x, y = (int(v) for v in positions[worst_index])
    where = (
        f"pixel ({x}, {y}): input {_values(inputs[worst_index])}, written {_values(written[worst_index])}, "
        f"reference {_values(check.expected[worst_index])}"
    )
    passed = worst <= check.tolerance and not violations
    return Verdict(compared, worst, check.tolerance, check.metric, passed, where, why)


def _in_written_precision(check, written: np.ndarray, depth: str):
    """The check, the written values and the step to judge them by, in ``depth``'s precision:
    an integer format's code step (the judge clips the reference to 0 to 1); for half floats
    the reference clipped to the half range, an infinity written there read as that range's
    end, and half the gap to the next half taken off as part of the allowance."""
    if formats.integer_bits(depth) or depth == "float":
        return check, written, formats.step(written, check.expected, depth)
    top = formats.HALF_MAX
    expected = np.clip(check.expected, -top, top)
    beyond = np.isinf(written) & (np.abs(check.expected) >= top) & (np.sign(written) == np.sign(check.expected))
    written = np.where(beyond, np.sign(written) * top, written)
    gap = formats.step(written, expected, depth)
    allowance = gap / 2.0 if check.allowance is None else check.allowance + gap / 2.0
    return replace(check, expected=expected, allowance=allowance), written, 0.0
