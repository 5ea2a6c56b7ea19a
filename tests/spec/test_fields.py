"""The spec's colorimetric fields: transfer-function parameters OCIO and float32 can evaluate."""

import numpy as np
import pytest

from generator.spec import load
from generator.spec.schema import SpecError

SPACE = "[[custom_space]]\nname = 'C'\ngamut = 'Rec.709'\n"
LOG = "family = 'log_camera', base = 10, log_side_slope = 0.25, log_side_offset = 0.4, lin_side_offset = 0.05"


def transfer_error(table: str) -> SpecError:
    with pytest.raises(SpecError) as error:
        load.parse(f"{SPACE}transfer = {{ {table} }}\n", "show.toml", None)
    assert "\n" not in str(error.value)
    return error.value


@pytest.mark.parametrize(
    "table, key, allowed",
    [
        ("family = 'gamma', exponent = 1e308", "exponent", "0.2 to 10"),
        ("family = 'gamma', exponent = 0.001", "exponent", "0.2 to 10"),
        ("family = 'piecewise_gamma', gamma = 12, offset = 0.05", "gamma", "> 1 and <= 10"),
        ("family = 'piecewise_gamma', gamma = 2.4, offset = 5", "offset", "> 0 and <= 0.9"),
        (f"{LOG}, lin_side_slope = -5.0", "lin_side_slope", "> 0"),
        (f"{LOG}, lin_side_slope = 5.0, lin_side_break = 0.01, linear_slope = 0", "linear_slope", "> 0"),
        (f"{LOG}, lin_side_slope = 5.0, lin_side_break = -1", "lin_side_break", "> -0.01"),
        (f"{LOG}, lin_side_slope = 5.0, linear_slope = 2", "linear_slope", "needs lin_side_break"),
        (
            "family = 'log_camera', base = 1, log_side_slope = 0.25, log_side_offset = 0.4, lin_side_slope = 5.0, "
            "lin_side_offset = 0.05",
            "base",
            "> 1",
        ),
    ],
)
def test_transfer_parameters_out_of_range_name_the_parameter_and_the_range(table, key, allowed):
    error = transfer_error(table)
    assert error.field == f"custom_space[0].transfer.{key}"
    assert allowed in error.message


@pytest.mark.parametrize(
    "table",
    [
        "family = 'gamma', exponent = 0.2",
        "family = 'gamma', exponent = 10",
        "family = 'piecewise_gamma', gamma = 10, offset = 0.9",
        f"{LOG}, lin_side_slope = 5.0, lin_side_break = -0.005, linear_slope = 3",
    ],
)
def test_transfer_parameters_at_the_ends_of_their_ranges_load(table):
    space = load.parse(f"{SPACE}transfer = {{ {table} }}\n", "show.toml", None).space("C")
    assert space.curve_name.startswith("custom")


def gamut_error(primaries: str, white: str) -> SpecError:
    with pytest.raises(SpecError) as error:
        load.parse(f"[[custom_space]]\nname = 'C'\nprimaries = {primaries}\nwhite = {white}\n", "show.toml", None)
    assert "\n" not in str(error.value)
    return error.value


@pytest.mark.parametrize(
    "primaries", ["[[0.64, 0.33], [0.64, 0.33], [0.15, 0.06]]", "[[0.3, 0.3], [0.31, 0.31], [0.32, 0.32]]"]
)
def test_repeated_or_collinear_primaries_are_an_error(primaries):
    error = gamut_error(primaries, "'D65'")
    assert error.field == "custom_space[0].primaries"
    assert "span no triangle" in error.message


@pytest.mark.parametrize("white", ["[0.5, 0.1]", "[0.395, 0.195]"])
def test_a_white_outside_or_on_the_edge_of_the_triangle_is_an_error(white):
    error = gamut_error("[[0.64, 0.33], [0.3, 0.6], [0.15, 0.06]]", white)
    assert error.field == "custom_space[0].white"
    assert "outside the primaries' triangle" in error.message


def test_every_library_gamut_passes_the_triangle_check():
    from generator.colorimetry.gamuts import gamuts
    from generator.spec import fields

    for name, gamut in gamuts().items():
        fields.check_triangle(gamut.primaries, gamut.whitepoint, name, "primaries", "white")


def quiet_error(text: str, base=None) -> SpecError:
    """The SpecError ``text`` raises, with no warning on the way (stderr must hold one line)."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(SpecError) as error:
            load.parse(text, "show.toml", base)
    assert "\n" not in str(error.value)
    return error.value


def test_a_tabulated_value_beyond_float32_is_refused_naming_file_and_line(tmp_path):
    (tmp_path / "c.csv").write_text("0,0\n1,1e39\n")
    error = quiet_error(f"{SPACE}transfer = {{ family = 'tabulated', file = 'c.csv' }}\n", tmp_path)
    assert error.field == "custom_space[0].transfer.file"
    assert "line 2: linear value 1e+39 is beyond float32's range" in error.message


@pytest.mark.parametrize(
    "table, words",
    [
        ("family = ['gamma'], exponent = 2.2", "expected a string, got ['gamma']; allowed: linear, gamma"),
        ("family = { a = 1 }", "expected a string, got {'a': 1}"),
        ("exponent = 2.2", "missing; allowed: linear, gamma, piecewise_gamma"),
    ],
)
def test_a_family_that_is_no_string_or_missing_lists_the_families(table, words):
    error = quiet_error(f"{SPACE}transfer = {{ {table} }}\n")
    assert error.field == "custom_space[0].transfer.family" and words in error.message


@pytest.mark.parametrize("extreme", ["base = 1e300, log_side_slope = 0.25", "base = 10, log_side_slope = 1e300"])
def test_an_overflowing_log_camera_is_one_error_without_warnings(extreme):
    error = quiet_error(
        f"{SPACE}transfer = {{ family = 'log_camera', {extreme}, log_side_offset = 0.4, "
        "lin_side_slope = 5, lin_side_offset = 0.05 }\n"
    )
    assert error.field == "custom_space[0].transfer" and "departs inf" in error.message


@pytest.mark.parametrize(
    "gamma, offset, accepted",
    [
        (2.4, 1e-9, False),
        (2.4, 1e-7, False),
        (2.4, 1e-6, True),
        (2.4, 0.055, True),
        (10, 1e-9, False),
        (10, 1e-4, False),
        (10, 1e-3, True),
        (1.0000001, 0.05, False),
    ],
)
def test_a_piecewise_gamma_ocio_evaluates_otherwise_is_refused(gamma, offset, accepted):
    """OCIO evaluates an offset below 1e-6 as 1e-6 (a toe 1e4 times less steep at 1e-9, which
    verify measured 1.9e4 off), and with gamma 10 and an offset up to 1e-4 its inverse toe's
    slope overflows float32 (inf at 0): refused, and what OCIO follows accepted."""
    text = f"{SPACE}transfer = {{ family = 'piecewise_gamma', gamma = {gamma}, offset = {offset} }}\n"
    if accepted:
        assert load.parse(text, "show.toml", None).space("C").curve.offset == offset
        return
    error = quiet_error(text)
    assert error.field == "custom_space[0].transfer"
    assert "OCIO evaluates a piecewise_gamma curve in float32" in error.message


@pytest.mark.parametrize(
    "gamma, offset, accepted",
    [(1.001, 0.5, False), (1.2, 0.3, False), (1.5, 0.5, False), (1.5, 0.45, True), (2.4, 0.9, True)],
)
def test_a_piecewise_gamma_whose_toe_reaches_code_1_is_refused(gamma, offset, accepted):
    """The break, offset / (gamma - 1), at or above code 1 leaves no power segment: code 1 would
    decode to 0.67 (gamma 1.001, offset 0.5), a straight line OCIO and the reference agree on."""
    text = f"{SPACE}transfer = {{ family = 'piecewise_gamma', gamma = {gamma}, offset = {offset} }}\n"
    if accepted:
        assert load.parse(text, "show.toml", None).space("C").curve.decode(1.0) == pytest.approx(1.0, abs=1e-15)
        return
    error = quiet_error(text)
    assert error.field == "custom_space[0].transfer.offset"
    assert "decodes to" in error.message and "allowed: an offset below gamma - 1" in error.message


def test_log_camera_breaks_are_refused_from_where_float32_departs_upward():
    """A break far above black puts the codes verify probes (those of its linear values, above 1
    from a break of 100) on a toe that float32 loses: refused from 10 up, 1000 among them."""

    def refused(brk):
        try:
            load.parse(
                f"{SPACE}transfer = {{ {LOG}, lin_side_slope = 5, lin_side_break = {brk} }}\n", "show.toml", None
            )
        except SpecError:
            return True
        return False

    assert [refused(b) for b in (0.01, 1, 10, 50, 100, 1e3, 1e10)] == [False, False, True, True, True, True, True]


PRIMARIES = "380,{a},0,0\n500,{a},1,0\n600,0,0,1\n780,0,0,1\n"


def test_spectra_of_huge_values_give_the_chromaticity_of_their_shape_without_warnings(tmp_path):
    import warnings

    from generator.spec import fields

    (tmp_path / "huge.csv").write_text(PRIMARIES.format(a="1e308"))
    (tmp_path / "unit.csv").write_text(PRIMARIES.format(a="1"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        huge = fields.spectral_primaries("huge.csv", tmp_path, "show.toml", "p")
    unit = fields.spectral_primaries("unit.csv", tmp_path, "show.toml", "p")
    assert np.allclose(huge, unit, rtol=0, atol=1e-15) and np.all(np.isfinite(huge))


def test_a_spectrum_without_a_normal_float_is_refused(tmp_path):
    (tmp_path / "w.csv").write_text("380,5e-324\n780,5e-324\n")
    error = quiet_error(
        "[[custom_space]]\nname = 'C'\nprimaries = [[0.64, 0.33], [0.3, 0.6], [0.15, 0.06]]\nwhite = 'w.csv'\n",
        tmp_path,
    )
    assert error.field == "custom_space[0].white" and "below the smallest normal float" in error.message


def test_a_chromaticity_derived_from_a_spectrum_is_checked_as_a_typed_one(monkeypatch, tmp_path):
    from generator.colorimetry import spectral
    from generator.spec import fields

    (tmp_path / "p.csv").write_text(PRIMARIES.format(a="1"))
    monkeypatch.setattr(spectral, "read_primaries_spectra_csv", lambda path: np.array([[0.0, 0.0]] * 3))
    with pytest.raises(SpecError) as error:
        fields.spectral_primaries("p.csv", tmp_path, "show.toml", "custom_space[0].primaries_spectra")
    assert "p.csv: column r's chromaticity [0.0, 0.0] is not plausible" in error.value.message
