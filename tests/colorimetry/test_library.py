"""The colour-space and display library against OCIO's built-in ACES studio configs, and the gamuts
and curves it names."""

from __future__ import annotations

import re
from functools import cache

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.colorimetry import library
from generator.colorimetry.curves import CURVES
from generator.colorimetry.gamuts import gamuts

#: The studio configs the library follows: the newest OCIO 2.6 ships, and the one before it.
STUDIO = "studio-config-v5.0.0_aces-v2.1_ocio-v2.6"
PREVIOUS_STUDIO = "studio-config-v4.0.0_aces-v2.0_ocio-v2.5"
#: ADX decodes straight to ACES2065-1 (generator.colorimetry.adx), with no curve of the registry.
SPECIAL_CURVES = {"ADX10", "ADX16"}


@cache
def studio_spaces(name: str = STUDIO) -> dict:
    config = ocio.Config.CreateFromFile(f"ocio://{name}")
    spaces = config.getColorSpaces(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL)
    return {space.getName(): space for space in spaces}


def test_every_library_gamut_resolves():
    names = {s.gamut for s in library.SPACES if s.gamut} | {d.gamut for d in library.DISPLAYS}
    assert names <= set(gamuts())
    assert all(np.isfinite(gamuts()[n].rgb_to_xyz).all() for n in names)


def test_every_curve_and_eotf_is_a_named_curve():
    assert {s.curve for s in library.SPACES} - SPECIAL_CURVES <= set(CURVES)
    assert {d.eotf for d in library.DISPLAYS} <= set(CURVES)
    assert {s.name for s in library.SPACES if s.curve in SPECIAL_CURVES} == SPECIAL_CURVES
    assert all(s.gamut is None for s in library.SPACES if s.curve in SPECIAL_CURVES)


def test_names_and_aliases_name_one_space_or_display_each_without_case():
    """OCIO compares names without case, and a display's name and aliases are its colour space's."""
    names = [n.lower() for entry in (*library.SPACES, *library.DISPLAYS) for n in (entry.name, *entry.aliases)]
    assert len(names) == len(set(names))


def test_a_space_the_studio_config_lacks_has_an_alias_in_its_pattern():
    """Lower case, words joined by underscores (curve_gamut, lin_gamut), as the studio config's."""
    lacking = [s for s in library.SPACES if s.name not in studio_spaces()]
    assert len(lacking) > 10
    for space in lacking:
        assert any(re.fullmatch(r"[a-z0-9]+(_[a-z0-9]+)*", a) for a in space.aliases), space.name


def test_every_camera_log_gamut_has_a_linear_space():
    linear = {s.gamut for s in library.SPACES if s.encoding == "scene-linear" and s.curve == "linear"}
    for space in library.SPACES:
        if space.encoding == "log" and space.gamut is not None:
            assert space.gamut in linear, space.name


def test_only_raw_is_data_and_data_has_no_gamut():
    assert [s.name for s in library.SPACES if s.is_data] == ["Raw"]
    assert [s.name for s in library.SPACES if s.gamut is None] == ["ADX10", "ADX16", "Raw"]


@pytest.mark.parametrize("space", library.SPACES, ids=lambda s: s.name)
def test_a_space_the_studio_config_has_is_described_as_there(space):
    """Its aliases (but the namespaced ocio: ones v5 adds), encoding, data flag and menu categories
    are the studio config's; its family is either config's (v5 moved Sony's Venice gamuts to
    Input/Sony/Legacy)."""
    studio = studio_spaces().get(space.name)
    if studio is None:
        assert space.family.startswith("Input/") or space.family == "ACES" or space.name.startswith(("Linear ", "CIE "))
        return
    theirs = {a for a in studio.getAliases() if not a.startswith("ocio:")}
    assert theirs <= set(space.aliases)
    assert (space.encoding, space.is_data) == (studio.getEncoding(), studio.isData())
    categories = library.STUDIO_CATEGORIES.get(space.name, ("file-io",))
    assert set(categories) == set(studio.getCategories())
    previous = studio_spaces(PREVIOUS_STUDIO).get(space.name)
    assert space.family in {studio.getFamily(), previous.getFamily() if previous else None}


def test_every_studio_category_names_a_library_space():
    assert set(library.STUDIO_CATEGORIES) <= {s.name for s in library.SPACES}
    assert all(categories[0] == "file-io" for categories in library.STUDIO_CATEGORIES.values())


@pytest.mark.parametrize("display", library.DISPLAYS, ids=lambda d: d.name)
def test_a_display_the_studio_config_has_is_described_as_there(display):
    """Its aliases and encoding; the HDR ones' 1000 cd/m² is what the studio config's display
    names (e.g. HLG's builtin, REC.2100-HLG-1000nit) and views assume."""
    studio = studio_spaces().get(display.name)
    if studio is None:
        assert display.name == "Gamma 2.6 DCI-P3 - Display"  # DCI white: the studio config has none
        return
    theirs = {a for a in studio.getAliases() if not a.startswith("ocio:")}
    assert theirs <= set(display.aliases)
    assert display.encoding == studio.getEncoding()
    assert display.peak == (100.0 if display.encoding == "sdr-video" else 1000.0)
