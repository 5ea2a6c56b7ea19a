"""The spec's colorimetric fields: transfer-function parameters OCIO and float32 can evaluate."""

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


@pytest.mark.parametrize("table, key, allowed", [
    ("family = 'gamma', exponent = 1e308", "exponent", "0.2 to 10"),
    ("family = 'gamma', exponent = 0.001", "exponent", "0.2 to 10"),
    ("family = 'piecewise_gamma', gamma = 12, offset = 0.05", "gamma", "> 1 and <= 10"),
    ("family = 'piecewise_gamma', gamma = 2.4, offset = 5", "offset", "> 0 and <= 0.9"),
    (f"{LOG}, lin_side_slope = -5.0", "lin_side_slope", "> 0"),
    (f"{LOG}, lin_side_slope = 5.0, lin_side_break = 0.01, linear_slope = 0", "linear_slope", "> 0"),
    (f"{LOG}, lin_side_slope = 5.0, lin_side_break = -1", "lin_side_break", "> -0.01"),
    (f"{LOG}, lin_side_slope = 5.0, linear_slope = 2", "linear_slope", "needs lin_side_break"),
    ("family = 'log_camera', base = 1, log_side_slope = 0.25, log_side_offset = 0.4, lin_side_slope = 5.0, "
     "lin_side_offset = 0.05", "base", "> 1"),
])
def test_transfer_parameters_out_of_range_name_the_parameter_and_the_range(table, key, allowed):
    error = transfer_error(table)
    assert error.field == f"custom_space[0].transfer.{key}"
    assert allowed in error.message


@pytest.mark.parametrize("table", [
    "family = 'gamma', exponent = 0.2", "family = 'gamma', exponent = 10",
    "family = 'piecewise_gamma', gamma = 10, offset = 0.9",
    f"{LOG}, lin_side_slope = 5.0, lin_side_break = -0.005, linear_slope = 3",
])
def test_transfer_parameters_at_the_ends_of_their_ranges_load(table):
    space = load.parse(f"{SPACE}transfer = {{ {table} }}\n", "show.toml", None).space("C")
    assert space.curve_name.startswith("custom")


def gamut_error(primaries: str, white: str) -> SpecError:
    with pytest.raises(SpecError) as error:
        load.parse(f"[[custom_space]]\nname = 'C'\nprimaries = {primaries}\nwhite = {white}\n", "show.toml", None)
    assert "\n" not in str(error.value)
    return error.value


@pytest.mark.parametrize("primaries", ["[[0.64, 0.33], [0.64, 0.33], [0.15, 0.06]]",
                                       "[[0.3, 0.3], [0.31, 0.31], [0.32, 0.32]]"])
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
