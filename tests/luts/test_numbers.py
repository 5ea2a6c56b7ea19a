"""Fast, deterministic text of LUT tables (generator/luts/numbers.py)."""

from __future__ import annotations

import numpy as np
import pytest

from generator.luts import numbers

RNG_SEED = 7


def _reference_text(value: float, decimals: int) -> str:
    q = round(value * 10**decimals)
    text = f"{abs(q) / 10**decimals:.{decimals}f}".rstrip("0").rstrip(".")
    return ("-" if q < 0 else "") + text


def test_table_text_drops_trailing_zeros_and_spans_blocks():
    rng = np.random.default_rng(RNG_SEED)
    rows = numbers.TABLE_BLOCK + 300
    values = rng.uniform(-9.99, 9.99, (rows, 3))
    values[::7] = np.round(values[::7], 2)
    values[::11, 0] = 0.0
    values[::13, 1] = -1e-9  # rounds to zero: written without a sign
    values[::17, 2] = 1.0
    for decimals in (5, 6, 7):
        lines = numbers.table(values, decimals).decode("ascii").splitlines()
        assert len(lines) == rows
        rounded = numbers.rounded(values, decimals)
        assert lines == [" ".join(_reference_text(v, decimals) for v in row) for row in rounded]


@pytest.mark.parametrize("value", [10.0, -10.0, 9.9999996, np.nan, np.inf])
def test_a_value_outside_ten_once_rounded_or_not_finite_is_refused(value):
    with pytest.raises(ValueError, match="within"):
        numbers.table(np.array([[0.5, value, 0.0]]), 6)


def test_a_table_of_one_column_is_one_value_a_line():
    assert numbers.table(np.array([[0.0], [-0.0000004], [1.5], [-2.25]]), 6) == b"0\n0\n1.5\n-2.25\n"


def test_integers_are_written_as_python_writes_them_across_blocks():
    rng = np.random.default_rng(RNG_SEED)
    values = rng.integers(0, 65536, (numbers.TABLE_BLOCK + 300, 3))
    values[::7] = rng.integers(-100000, 100000, (len(values[::7]), 3))
    values[::11, 0], values[::13, 1], values[5] = 0, -1, (9, 10, 99)
    values[-1] = (100, 999, 1000)
    expected = "".join(" ".join(str(v) for v in row) + "\n" for row in values.tolist())
    assert numbers.integer_table(values).decode("ascii") == expected
    assert numbers.integer_table(np.array([[0], [7], [-12]])) == b"0\n7\n-12\n"


def test_a_number_is_text_that_reads_back_to_the_same_float():
    rng = np.random.default_rng(RNG_SEED)
    values = np.concatenate([rng.normal(0.0, 1.0, 500), 10.0 ** rng.uniform(-300, 300, 500), [0.1, -0.0078125, 1.0]])
    for value in values:
        assert float(numbers.number(value)) == value
    assert numbers.number(0.0) == numbers.number(-0.0) == "0"
    assert numbers.number(-0.0078125) == "-0.0078125"


@pytest.mark.parametrize("digits", [1, 3, 6, 9])
def test_significant_rounds_as_pythons_text_does(digits):
    """Every magnitude and sign, zeros, halves, powers of ten and non-finite values: the same
    doubles, and signs, as ``float(f"{v:.{digits}g}")``."""
    rng = np.random.default_rng(digits)
    values = np.concatenate(
        [
            rng.normal(size=20000) * 10.0 ** rng.integers(-30, 30, 20000),
            rng.integers(0, 2**20, 5000) / 2.0**12,  # exact binary fractions: ties of the text
            10.0 ** np.arange(-20, 21),
            [0.0, -0.0, 0.5, -2.5, 1.0000000005, 999999999.5, 9.9999999995, 5e-324, np.nan, np.inf, -np.inf],
        ]
    )
    got = numbers.significant(values, digits)
    text = np.array([float(f"{v:.{digits}g}") for v in values.tolist()])
    assert np.array_equal(got, text, equal_nan=True) and np.array_equal(np.signbit(got), np.signbit(text))


def test_significant_refuses_more_digits_than_its_margin_holds():
    with pytest.raises(ValueError, match="10 significant digits; allowed: 1 to 9"):
        numbers.significant([1.0], 10)
