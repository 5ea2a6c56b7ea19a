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
