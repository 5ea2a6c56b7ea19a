"""The config's names: a spec's colour space may take no name the build generates."""

from pathlib import Path

import pytest

from generator.spec import load
from generator.spec.schema import SpecError

SPACES = 'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
CUSTOM = "[[custom_space]]\nname = {name!r}\naliases = {aliases!r}\ngamut = 'Rec.709'\n"
SRGB = "[[display]]\nname = 'sRGB - Display'\nviews = ['Colorimetric', 'Raw']\n"


def error(text: str) -> SpecError:
    with pytest.raises(SpecError) as raised:
        load.parse(SPACES + text, "show.toml", Path("."))
    assert "\n" not in str(raised.value)
    return raised.value


@pytest.mark.parametrize(
    "name, aliases, top, field, owner",
    [
        ("sRGB - Display", [], "", "custom_space[0].name", "the generated display colour space of display[0]"),
        ("Mine", ["srgb_display"], "", "custom_space[0].aliases[0]", "an alias of the generated display colour space"),
        ("CIE XYZ-D65 - Display-referred", [], "", "custom_space[0].name", "the generated display-referred reference"),
        ("cie_xyz_d65_display", [], "", "custom_space[0].name", "the generated display-referred reference"),
        (
            "Colorimetric - sRGB - Display",
            [],
            "display_view_spaces = true\n",
            "custom_space[0].name",
            "the generated display-view colour space of view 'Colorimetric' on display[0]",
        ),
        ("scene_linear", [], "", "custom_space[0].name", "the role 'scene_linear'"),
    ],
)
def test_a_custom_space_may_not_take_a_generated_name(name, aliases, top, field, owner):
    raised = error(top + CUSTOM.format(name=name, aliases=aliases) + SRGB)
    assert raised.field == field
    assert f"is taken by {owner}" in raised.message


def test_display_view_names_are_free_without_display_view_spaces():
    spec = load.parse(
        SPACES
        + "display_view_spaces = false\n"
        + CUSTOM.format(name="Colorimetric - sRGB - Display", aliases=[])
        + SRGB,
        "show.toml",
        Path("."),
    )
    assert spec.space("Colorimetric - sRGB - Display").family == "Custom"


def test_display_view_names_are_taken_when_the_spec_leaves_display_view_spaces_out():
    """Left out, display_view_spaces is the default spec's (true): the build generates the names."""
    raised = error(CUSTOM.format(name="Colorimetric - sRGB - Display", aliases=[]) + SRGB)
    assert raised.field == "custom_space[0].name" and "display-view colour space" in raised.message


def test_a_display_may_not_take_a_colour_space_or_another_displays_name():
    raised = error("[[display]]\nname = 'ACEScg'\ngamut = 'Rec.709'\neotf = 'sRGB'\n")
    assert raised.field == "display[0].name" and "library colour space 'ACEScg'" in raised.message
    raised = error(SRGB + SRGB)
    assert raised.field == "display[1].name" and "listed twice (display[0])" in raised.message


@pytest.mark.parametrize(
    "target, ok",
    [
        ("Nope", False),
        ("ACEScg", True),
        ("scene_linear", True),
        ("sRGB - Display", True),
        ("CIE XYZ-D65 - Display-referred", True),
    ],
)
def test_a_file_rule_names_a_colour_space_display_or_role(target, ok):
    text = SRGB + f"[[file_rule]]\nname = 'Default'\ncolour_space = {target!r}\n"
    if ok:
        assert load.parse(SPACES + text, "show.toml", Path(".")).file_rules[-1].colour_space == target
    else:
        raised = error(text)
        assert raised.field == "file_rule[0].colour_space" and "not among" in raised.message


def test_a_name_taken_twice_names_the_field_the_spec_wrote_second():
    """A role the spec names like a display is the role's error; a display named like a
    default role is the display's."""
    raised = error(SRGB + "[roles]\n'sRGB - Display' = 'ACEScg'\n")
    assert raised.field == "roles.sRGB - Display" and "display colour space of display[0]" in raised.message
    raised = error("[[display]]\nname = 'scene_linear'\ngamut = 'Rec.709'\neotf = 'sRGB'\n")
    assert raised.field == "display[0].name" and "the role 'scene_linear'" in raised.message
