"""The tolerances: the figures derived from standards (one PQ code in ΔE ITP, float32's and
sixteen-bit files' steps), published rounding, the tables' keys, and the documentation's values."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from generator import tolerances
from generator.colorimetry import library
from generator.luts import aces_probes, probes
from generator.metrics import delta_e_itp
from generator.spec.allowed import LUT_FORMATS

DOCS = Path(__file__).resolve().parents[1] / "docs" / "tolerances.md"
#: The tolerances: the module's upper-case names.
NAMES = sorted(name for name in vars(tolerances) if name.isupper())


def test_one_pq_code_on_a_grey_is_the_delta_e_itp_the_hdr_targets_use(default_spec):
    display = next(d for d in default_spec.displays if d.eotf_name == "ST 2084")
    grey = np.linspace(0.01, 0.99, 50)[:, None] * np.ones(3)
    for codes in (tolerances.LUT_CLF_IN_GAMUT_CODES, tolerances.LUT_CLF_SCALE_CODES):
        error = delta_e_itp(display, grey + codes / 1023.0, grey)
        assert np.allclose(error, codes * tolerances.DELTA_E_ITP_PER_PQ_CODE, rtol=1e-9)


def test_the_steps_of_float32_and_sixteen_bit_files():
    """IEEE 754 binary32's unit roundoff is half its machine epsilon, 2^-24; a 16-bit file's code
    step is 1 / 65535 of its range."""
    assert float(np.finfo(np.float32).eps) / 2.0 == tolerances.FLOAT32_UNIT_ROUNDOFF
    assert 1.0 / float(np.iinfo(np.uint16).max) == tolerances.UINT16_STEP


@pytest.mark.parametrize("decimals", [1, 3, 6, 10])
def test_published_rounding_holds_every_figure_that_rounds_to_the_published_one(decimals):
    """A figure is published as round(x, decimals): x is within half a unit of the last place
    (and float64's representation of the decimal) of it, and a figure a unit away is not."""
    x = np.random.default_rng(decimals).uniform(-50.0, 50.0, 2000)
    published = np.round(x, decimals)
    assert np.all(np.abs(x - published) <= tolerances.published_rounding(decimals))
    assert np.all(np.abs(x + 10.0**-decimals - published) > tolerances.published_rounding(decimals))
    assert abs(45.7566 - 45.757) <= tolerances.published_rounding(3) < abs(45.7564 - 45.757)


def test_every_tolerance_is_a_positive_finite_figure():
    for name in NAMES:
        value = getattr(tolerances, name)
        figures = [v for table in value.values() for v in table.values()] if isinstance(value, dict) else [value]
        assert all(np.isfinite(f) and f > 0.0 for f in figures), name


def test_the_tables_name_library_pairs_formats_and_probe_sets():
    spaces = {s.name for s in library.SPACES}
    displays = {d.name for d in library.DISPLAYS}
    for (source, display), by_set in tolerances.OCIOBAKELUT_P99.items():
        assert source in spaces and display in displays and set(by_set) == set(probes.SETS)
    for (fmt, display), by_set in tolerances.LUT_ACES_P99.items():
        assert fmt in LUT_FORMATS and display in displays and set(by_set) == set(aces_probes.SETS)


#: A word of a figure: digits and the operators the documentation writes (2^-24, 1.5 × 2^-23, 720/1023).
FIGURE_WORD = re.compile(r"[0-9.e^/×*+-]+")


def documented_value(cell: str) -> tuple[float, int | None]:
    """The figure a table cell starts with, before its unit ("0.035 ΔE ITP", "30 MB"), and its
    decimals when it is a decimal rounded to them (None for an exact figure, 1e-4 or 2^-24)."""
    words = cell.split()
    count = next((i for i, word in enumerate(words) if not FIGURE_WORD.fullmatch(word)), len(words))
    expression = " ".join(words[:count]).replace("×", "*").replace("^", "**")
    scale = 1e6 if words[count : count + 1] == ["MB"] else 1.0
    decimal = re.fullmatch(r"\d+(?:\.(\d+))?", expression)
    value = float(eval(expression, {"__builtins__": {}}))  # digits and operators only (FIGURE_WORD)
    return value * scale, None if decimal is None else len(decimal[1] or "")


@pytest.mark.parametrize("name", NAMES)
def test_every_tolerance_is_documented_with_its_value(name):
    rows = dict(re.findall(r"^\| `([A-Z0-9_]+)` \| ([^|]*?) \|", DOCS.read_text(), re.M))
    assert name in rows
    value = getattr(tolerances, name)
    if isinstance(value, dict):
        assert rows[name] == "a table"
        return
    figure, decimals = documented_value(rows[name])
    if decimals is None:
        assert figure == pytest.approx(value, rel=1e-12)
    else:
        assert abs(figure - value) <= tolerances.published_rounding(decimals)
