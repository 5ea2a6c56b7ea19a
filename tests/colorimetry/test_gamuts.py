"""The gamut table against colour-science's datasets of the same gamuts."""

import colour
import numpy as np
import pytest

from generator.colorimetry.gamuts import COLOUR_KEYS, STANDARD, gamuts


@pytest.mark.parametrize("name", sorted(STANDARD))
def test_standard_gamut_matches_colour_science(name):
    space = colour.RGB_COLOURSPACES[COLOUR_KEYS.get(name, name)]
    ours = gamuts()[name]
    assert np.array_equal(np.array(ours.primaries), space.primaries)
    assert np.array_equal(np.array(ours.whitepoint), space.whitepoint)
    assert ours.citation


def test_every_library_gamut_resolves():
    from generator.colorimetry import library

    names = {s.gamut for s in library.SPACES if s.gamut} | {d.gamut for d in library.DISPLAYS}
    assert names <= set(gamuts())
    assert all(np.isfinite(gamuts()[n].rgb_to_xyz).all() for n in names)
