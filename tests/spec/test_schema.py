"""The records a spec resolves to: the error's form, names, a display's looks and range, context
variables as OpenColorIO resolves them, and finding a colour space by any of its names."""

from __future__ import annotations

import dataclasses

import PyOpenColorIO as ocio
import pytest

from generator.spec.schema import Display, Look, SpecError, context_variables, with_context

CONTEXT = {"SHOT": "sh010", "SEQ": "sq01", "_V2": "v2"}


def test_a_spec_error_is_one_line_naming_file_and_field():
    error = SpecError("show.toml", "display[0].name", "unknown display")
    assert isinstance(error, ValueError)
    assert str(error) == "show.toml:display[0].name: unknown display"
    assert (error.source, error.field, error.message) == ("show.toml", "display[0].name", "unknown display")


def test_a_colour_space_is_found_by_its_name_or_an_alias_without_case(default_spec):
    acescg = default_spec.space("ACEScg")
    assert acescg.all_names[0] == "ACEScg" and acescg.all_names[1:] == acescg.aliases
    for name in ("acescg", "LIN_AP1", "ACES - ACEScg"):
        assert default_spec.space(name) is acescg
    with pytest.raises(KeyError):
        default_spec.space("ACEScgg")
    assert default_spec.reference is default_spec.space(default_spec.scene_reference)
    names = default_spec.space_names
    assert len(names) == len(set(names)) and {"ACEScg", "lin_ap1"} <= set(names)
    kept = dataclasses.replace(default_spec, left_out=("Offcut",))
    assert kept.space_names == [*names, "Offcut"]
    with pytest.raises(KeyError):
        kept.space("Offcut")


def test_a_views_looks_are_the_names_of_its_looks_string(default_spec):
    """The string in OCIO's syntax: names after an optional +, separated by commas, spaces around
    ignored."""
    display = dataclasses.replace(
        default_spec.displays[0], looks=(("Colorimetric", "+Show Look, +Shot Grade"), ("Scale", " Grade ,, + B "))
    )
    assert display.view_looks("Colorimetric") == ("Show Look", "Shot Grade")
    assert display.view_looks("Scale") == ("Grade", "B")
    assert display.view_looks("Raw") == ()


def test_a_displays_range_and_its_code_one(default_spec):
    """1.0 is 100 cd/m²: an SDR display shows up to 1, an HDR one up to its peak; code 1 of an
    absolute SDR display is its peak, of any other display 1."""
    srgb = next(d for d in default_spec.displays if d.name == "sRGB - Display")
    pq = next(d for d in default_spec.displays if d.eotf_name == "ST 2084")
    assert (srgb.is_hdr, srgb.clip_high, srgb.code_one) == (False, 1.0, 1.0)
    assert (pq.is_hdr, pq.clip_high, pq.code_one) == (True, 10.0, 1.0)
    wall = Display(srgb.name, srgb.gamut, srgb.eotf, srgb.eotf_name, srgb.views, peak=1500.0, absolute=True)
    assert (wall.is_hdr, wall.clip_high, wall.code_one) == (False, 15.0, 15.0)


@pytest.mark.parametrize(
    "text, names",
    [
        ("shots/$SHOT.cc", ("SHOT",)),
        ("${SEQ}/${SHOT}.ccc", ("SEQ", "SHOT")),
        ("%SHOT%_%SEQ%.cube", ("SHOT", "SEQ")),
        ("$SEQ$SHOT/$SEQ", ("SEQ", "SHOT")),
        ("$_V2 %_V2% ${_V2}", ("_V2",)),
        ("grade.cc", ()),
        ("100% a$ b $1", ()),
    ],
)
def test_context_variables_are_found_and_filled_as_ocio_resolves_them(text, names):
    assert context_variables(text) == names
    context = ocio.Context()
    for name, value in CONTEXT.items():
        context[name] = value
    assert with_context(text, CONTEXT) == context.resolveStringVar(text)


def test_a_looks_variables_are_its_files_and_its_ccc_ids():
    look = Look("Shot Grade", "ACEScct", file="${SEQ}/grades.ccc", cccid="$SHOT")
    assert look.variables == ("SEQ", "SHOT")
    assert Look("Show Look", "ACEScct").variables == ()
