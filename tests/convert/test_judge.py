"""A written frame against the float64 reference of the spec that built its config, in the
written format's precision (generator/convert/judge.py)."""

from __future__ import annotations

import numpy as np
import pytest

from generator.convert import formats
from generator.convert.judge import Route, Verdict, judge
from generator.spec import resolved
from generator.verify.paths import LazyEndpoints
from tests.convert import images
from tests.convert.images import convert


@pytest.fixture(scope="module")
def judged(config):
    """``judge`` on the config's stored spec: (route, inputs (n, 3), written (n, 3), depth) to a
    verdict, the pixels at x = their index, y = 7."""
    spec = resolved.read_beside(config)
    ends = LazyEndpoints(spec)

    def run(route, inputs, written, depth="float"):
        positions = np.stack([np.arange(len(inputs)), np.full(len(inputs), 7)], axis=-1)
        return judge(spec, ends, route, inputs, written, positions, depth)

    return run


def _inputs(seed: int, low: float, high: float, count: int = 2000) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return rng.uniform(low, high, (count, 3)).astype(np.float32).astype(np.float64)


def _through(config, inputs, src, dst="", display="", view="") -> np.ndarray:
    return images.ocio_applied(config, inputs[None], src, dst, display, view)[0].astype(np.float64)


def test_verify_names_a_frame_that_departs_with_its_worst_pixel(tmp_path, capsys, build_config):
    """A config whose numbers are not its stored spec's (a matrix edited, nothing else) writes frames
    that depart; the run says where and fails."""
    import shutil

    folder = tmp_path / "edited"
    shutil.copytree(build_config((2, 1)).parent, folder)
    text = (folder / "config.ocio").read_text()
    import re

    block = text[text.index("name: ACEScct") :]
    match = re.search(r"matrix: \[([-0-9.e]+)", block)
    edited = block.replace(match.group(0), f"matrix: [{float(match.group(1)) * 1.01!r}", 1)
    (folder / "config.ocio").write_text(text[: text.index("name: ACEScct")] + edited)
    images.sequence(tmp_path / "in", "s", [1])
    code, out, _ = convert(
        capsys,
        tmp_path / "in" / "s.0001.exr",
        "--config",
        folder,
        "--from",
        "ACEScct",
        "--to",
        "ACEScg",
        "-o",
        tmp_path / "out",
        "--jobs",
        1,
        "--verify",
    )
    assert code == 1
    assert "DEPARTS" in out and "pixel (" in out and "above 0.0001" in out and "1 depart" in out


def test_what_ocio_writes_in_float_is_within_the_tolerance(config, judged):
    inputs = _inputs(1, -0.05, 2.0)
    verdict = judged(Route("ACEScg", "ACEScct"), inputs, _through(config, inputs, "ACEScg", "ACEScct"))
    assert verdict.passed and verdict.compared == len(inputs) and verdict.worst <= verdict.tolerance
    assert verdict.describe().startswith(f"{len(inputs)} pixels, worst ") and "within" in verdict.describe()


def test_one_pixel_off_fails_and_is_named_with_its_values(config, judged):
    inputs = _inputs(2, 0.0, 1.0)
    written = _through(config, inputs, "ACEScg", "ACEScct")
    written[123, 1] += 0.01
    verdict = judged(Route("ACEScg", "ACEScct"), inputs, written)
    assert not verdict.passed and verdict.worst > verdict.tolerance
    assert verdict.where.startswith("pixel (123, 7): input (") and f"{written[123, 1]:.9g}" in verdict.where
    assert verdict.describe().endswith(verdict.where) and "above" in verdict.describe()


@pytest.mark.parametrize("depth, one_code_fails", [("uint8", True), ("uint10", True), ("uint16", False)])
def test_codes_are_judged_in_their_own_precision(config, judged, depth, one_code_fails):
    """A view's output rounded to its codes passes; a code more than the rounding fails, but for
    a 16-bit code, finer than the tolerance."""
    inputs = _inputs(3, 0.0, 1.5)
    route = Route("ACEScg", display="sRGB - Display", view="Colorimetric")
    exact = _through(config, inputs, "ACEScg", display="sRGB - Display", view="Colorimetric")
    written = formats.dequantised(formats.quantised(exact, depth), depth)
    assert judged(route, inputs, written, depth).passed
    code = formats.step(written, exact, depth)
    off = written.copy()
    off[5] = np.clip(off[5] + np.where(off[5] < 0.5, 1.0, -1.0) * code, 0.0, 1.0)
    verdict = judged(route, inputs, off, depth)
    assert verdict.passed is not one_code_fails
    if one_code_fails:
        assert verdict.where.startswith("pixel (5, 7)")


def test_half_floats_are_judged_to_the_nearest_half_and_beyond_it_as_infinity(config, judged):
    """ACEScct codes up to 1.6 decode past the largest half (65504, at about code 1.47): a half
    file holds infinity there, which is what the reference rounds to."""
    inputs = _inputs(4, 0.0, 1.6)
    written = _through(config, inputs, "ACEScct", "ACEScg").astype(np.float16).astype(np.float64)
    assert np.isinf(written).any() and np.isfinite(written).any()
    assert judged(Route("ACEScct", "ACEScg"), inputs, written, "half").passed
    float_verdict = judged(Route("ACEScct", "ACEScg"), inputs, written, "float")
    assert not float_verdict.passed  # the same values, judged as floats, are a half's rounding off


def test_a_space_the_stored_spec_lacks_is_not_compared(judged):
    inputs = _inputs(5, 0.0, 1.0, 4)
    verdict = judged(Route("ACEScg", "Nope"), inputs, inputs)
    assert not verdict.passed and verdict.compared == 0 and verdict.describe() == verdict.note
    assert "no such colour space" in verdict.note


def test_a_verdict_without_comparisons_says_why():
    verdict = Verdict(0, float("nan"), 1e-4, "relative", False, note="no pixel could be compared")
    assert verdict.describe() == "no pixel could be compared"
    assert Verdict(10, 2e-5, 1e-4, "relative", True).describe() == "10 pixels, worst 2e-05 relative (within 0.0001)"
