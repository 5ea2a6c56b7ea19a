"""Baking a decoding curve into a 1D LUT as dense as its bound needs (generator/luts/curve1d.py),
read back by OCIO and colour-science."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.colorimetry.transfer import Function
from generator.luts.curve1d import MAX_SIZE, MIN_SIZE, bake_curve, curve_file

#: A log curve of 16 stops over codes 0 to 1, and its inverse.
TOE = 2.0**-8


def _log_decode(code):
    return 2.0 ** (code * 16.0 - 8.0) - TOE


def _log_encode(linear):
    return (np.log2(linear + TOE) + 8.0) / 16.0


def _read(path, code, shaper: float = 1.0) -> np.ndarray:
    """Codes 0 to 1 through OCIO: the shaper's root (clamped below 0), then the file."""
    steps = [ocio.FileTransform(str(path), interpolation=ocio.INTERP_LINEAR)]
    if shaper != 1.0:
        steps.insert(0, ocio.ExponentTransform(value=[1.0 / shaper] * 3 + [1.0], negativeStyle=ocio.NEGATIVE_CLAMP))
    pixels = np.ascontiguousarray(np.repeat(np.asarray(code)[:, None], 3, axis=1), dtype=np.float32)
    processor = ocio.Config.CreateRaw().getProcessor(ocio.GroupTransform(steps))
    processor.getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS).applyRGB(pixels)
    return pixels[:, 0].astype(np.float64)


def test_a_table_with_evenly_spaced_rows_is_baked_on_its_rows():
    """A 10-bit table whose top row flags a clip (linear 100 after 20 at the row before): the
    LUT's entries fall on every row, so its interpolation is the table's own (a uniform LUT
    of 131073 entries was 2.9e-3 off there)."""
    from generator.colorimetry.transfer import Tabulated
    from generator.luts.curve1d import bake_curve

    code = tuple(i / 1023 for i in range(1024))
    curve = Tabulated("clip.csv", code, (*tuple(20.0 * c**2.4 for c in code[:-1]), 100.0))
    baked = bake_curve("Clip", curve, curve.domain)
    assert (len(baked.values) - 1) % 1023 == 0 and baked.shaper == 1.0
    assert baked.max_relative_error <= tolerances.BAKED_CURVE_RELATIVE


@pytest.mark.parametrize("rows", [1024, 4096])
def test_a_smooth_table_with_evenly_spaced_rows_is_baked_on_its_rows(rows):
    """A smooth 10-bit (or 12-bit) table, which a smaller uniform LUT holds within the bound too:
    it is still baked on its rows, as README promises, so OCIO interpolates the table's own rows
    (a 1025-entry LUT, chosen as smaller, put its entries between them, 4.7e-6 off)."""
    from generator.colorimetry.transfer import Tabulated
    from generator.luts.curve1d import bake_curve

    code = np.arange(rows) / (rows - 1)
    curve = Tabulated("smooth.csv", tuple(code), tuple(code**2.2))
    baked = bake_curve("Smooth", curve, curve.domain)
    intervals = len(baked.values) - 1
    assert intervals % (rows - 1) == 0 and baked.shaper == 1.0
    on_rows = np.asarray(baked.values)[:: intervals // (rows - 1)]
    assert np.array_equal(on_rows, (code**2.2).astype(np.float32).astype(np.float64))


def test_a_log_curve_read_through_ocio_is_within_the_bound(tmp_path):
    """The file OCIO reads decodes every code to within the bound (relative, floored) of the
    curve's own formula, as the bake measured it; colour-science reads the same values, float32
    as written."""
    import colour

    curve = Function("Test Log", _log_decode, _log_encode)
    baked = bake_curve("Test Log", curve, curve.domain)
    assert baked.filename == "test_log_to_linear.spi1d" and baked.shaper == 1.0
    assert len(baked.values) - 1 >= MIN_SIZE and baked.max_relative_error <= tolerances.BAKED_CURVE_RELATIVE / 2
    path = tmp_path / baked.filename
    path.write_bytes(curve_file(baked))
    read = colour.read_LUT(str(path)).table.astype(np.float32)
    np.testing.assert_array_equal(read, np.asarray(baked.values, dtype=np.float32))
    assert np.array_equal(read.astype(np.float64), baked.values)
    code = np.random.default_rng(7).random(20000).astype(np.float32).astype(np.float64)
    exact = _log_decode(code)
    assert np.max(np.abs(_read(path, code) - exact) / np.maximum(np.abs(exact), tolerances.RELATIVE_FLOOR)) <= (
        tolerances.BAKED_CURVE_RELATIVE
    )


@pytest.mark.parametrize(
    "decode, encode, shaper",
    [(np.sqrt, np.square, 2.0), (lambda c: c**3, np.cbrt, 1.0 / 3.0)],
    ids=["square-root toe", "cube-root encoding"],
)
def test_a_toe_is_unfolded_by_its_shaper_at_the_smallest_size(tmp_path, decode, encode, shaper):
    """A square root's infinite slope at 0 (Apple Log's toe), or a cube root's where the curve
    is flat (N-Log's): the shaper makes the curve linear in the table's position, so the
    smallest LUT holds it exactly, read by OCIO after the shaper's root."""
    curve = Function("Toe", decode, encode)
    baked = bake_curve("Toe", curve, curve.domain)
    assert baked.shaper == shaper and len(baked.values) == MIN_SIZE + 1
    assert baked.max_relative_error <= 1e-12
    path = tmp_path / baked.filename
    path.write_bytes(curve_file(baked))
    code = np.linspace(0.0, 1.0, 4097)
    np.testing.assert_allclose(_read(path, code, shaper), decode(code), rtol=1e-5, atol=1e-7)


def test_a_declared_jump_is_left_out_and_an_undeclared_one_measured():
    """A curve stepping up at code 0.5: declared as the formula's own discontinuity, the
    smallest LUT holds the rest exactly; undeclared, no LUT holds it, and the bake says how far
    off the largest one is (for the build to refuse)."""

    def decode(code):
        return np.where(code < 0.5, 0.5 * code, 0.5 * code + 0.1)

    def encode(linear):
        return np.where(linear < 0.25, 2.0 * linear, np.where(linear < 0.35, 0.5, 2.0 * (linear - 0.1)))

    declared = Function("Step", decode, encode, (0.0, 1.0), (0.5,))
    baked = bake_curve("Step", declared, declared.domain)
    assert len(baked.values) == MIN_SIZE + 1 and baked.max_relative_error <= 1e-12
    undeclared = Function("Step", decode, encode)
    baked = bake_curve("Step", undeclared, undeclared.domain)
    assert len(baked.values) == MAX_SIZE + 1 and baked.max_relative_error > tolerances.BAKED_CURVE_RELATIVE


def test_a_curve_over_another_domain_is_sampled_over_it():
    curve = Function("Wide", lambda c: 2.0 * c, lambda x: 0.5 * x, (-0.25, 1.5))
    baked = bake_curve("Wide", curve, curve.domain)
    assert baked.domain == (-0.25, 1.5) and baked.shaper == 1.0
    np.testing.assert_allclose(baked.values, 2.0 * np.linspace(-0.25, 1.5, len(baked.values)), rtol=1e-7)


def test_the_search_stops_at_the_best_size_and_chooses_as_a_search_of_every_size(default_spec):
    """A shaper is searched no further than the smallest size within bound found so far, and not
    at all after rows within bound: every curve the default 2.1 build bakes gets the LUT that
    searching every shaper to MAX_SIZE picks."""
    from generator.luts import curve1d
    from generator.ocio.curves import is_baked

    bound = tolerances.BAKED_CURVE_RELATIVE / 2
    owners = [(s.curve_name, s.curve) for s in default_spec.colour_spaces if not (s.is_data or s.special)]
    baked = {name: curve for name, curve in owners if is_baked(name, curve, (2, 1))}
    assert len(baked) >= 5
    for name, curve in baked.items():
        lo, hi = curve.domain
        jumps = tuple((j - lo) / (hi - lo) for j in getattr(curve, "discontinuities", ()))
        everything = []
        rows = curve1d._row_intervals(curve, (lo, hi))
        if rows:
            error = max(curve1d._lut_errors(curve1d._Shaped(curve, (lo, hi), 1.0), (0.0, 1.0), rows + 1, jumps))
            everything.append((error > bound, False, rows, error, -1, 1.0))
        for index, k in enumerate(curve1d.SHAPER_EXPONENTS):
            size, error = curve1d._smallest(curve1d._Shaped(curve, (lo, hi), k), tuple(j ** (1.0 / k) for j in jumps))
            everything.append((error > bound, True, size, error, index, k))
        *_, size, error, _, shaper = min(everything)
        chosen = bake_curve(name, curve, (lo, hi))
        assert (len(chosen.values) - 1, chosen.shaper, chosen.max_relative_error) == (size, shaper, error), name
