"""What verify prints and writes about failures: the summary's rows agree with their FAIL counts."""

from __future__ import annotations

import PyOpenColorIO as ocio

from generator.verify.checks import LUT, TO_REFERENCE, VIEW
from generator.verify.report import groups, summary
from generator.verify.run import verify


def _group_rows_failing(result) -> list[tuple]:
    return [(key, g["max"], g["tolerance"]) for key, g in groups(result).items() if g["FAIL"]]


def test_a_group_with_failures_shows_a_worst_over_its_own_tolerance(config_copy):
    """An HDR display's matrix raised by 1.4e-4: its analytic views (0.01 ΔE ITP) fail, and the
    group row had shown the largest error beside the baked views' 0.035, as though within it."""
    cfg = ocio.Config.CreateFromFile(str(config_copy))
    space = cfg.getColorSpace("Rec.2100-PQ - Display")
    group = space.getTransform(ocio.COLORSPACE_DIR_FROM_REFERENCE)
    matrix = next(t for t in group if isinstance(t, ocio.MatrixTransform))
    matrix.setMatrix([v * 1.00014 if i % 4 < 3 and i < 12 else v for i, v in enumerate(matrix.getMatrix())])
    space.setTransform(group, ocio.COLORSPACE_DIR_FROM_REFERENCE)
    cfg.addColorSpace(space)
    config_copy.write_text(cfg.serialize(), encoding="utf-8")
    result = verify(config_copy, ("ocio",), density="quick", kinds=(VIEW,), only="Rec.2100-PQ")
    rows = _group_rows_failing(result)
    assert rows and all(worst > tolerance for _, worst, tolerance in rows), rows


def test_a_row_not_computed_says_so(config_copy):
    """A LUT file OCIO cannot read fails without a number: its line had read '- > 0.0001'."""
    lut = config_copy.parent / "luts" / "n_log_to_linear.spi1d"
    lines = lut.read_text().splitlines()
    lines[len(lines) // 2] = "not a number"
    lut.write_text("\n".join(lines) + "\n")
    result = verify(config_copy, ("ocio",), density="quick", kinds=(LUT, TO_REFERENCE), only="n_log")
    text = summary(result)
    failing = [line for line in text.splitlines() if line.startswith("FAIL:")]
    assert failing and all(": not computed" in line for line in failing), failing
    assert not any(" - > " in line for line in text.splitlines())
