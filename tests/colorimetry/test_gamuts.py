"""The gamut table against colour-science's datasets of the same gamuts."""

import colour
import numpy as np
import pytest

from generator import tolerances
from generator.colorimetry.gamuts import COLOUR_KEYS, PUBLISHED_ADAPTATION, STANDARD, gamuts


@pytest.mark.parametrize("name", sorted(STANDARD))
def test_standard_gamut_matches_colour_science(name):
    space = colour.RGB_COLOURSPACES[COLOUR_KEYS.get(name, name)]
    ours = gamuts()[name]
    assert np.array_equal(np.array(ours.primaries), space.primaries)
    assert np.array_equal(np.array(ours.whitepoint), space.whitepoint)
    assert ours.citation


#: OCIO's builtin camera transform of each gamut with published matrices, and the curve it decodes.
BUILTINS = {
    "ARRI Wide Gamut 3": ("ARRI_ALEXA-LOGC-EI800-AWG_to_ACES2065-1", "ARRI LogC3 (EI800)"),
    "ARRI Wide Gamut 4": ("ARRI_LOGC4_to_ACES2065-1", "ARRI LogC4"),
    "Cinema Gamut": ("CANON_CLOG3-CGAMUT_to_ACES2065-1", "Canon Log 3"),
    "S-Gamut3": ("SONY_SLOG3-SGAMUT3_to_ACES2065-1", "S-Log3"),
    "S-Gamut3.Cine": ("SONY_SLOG3-SGAMUT3.CINE_to_ACES2065-1", "S-Log3"),
    "Venice S-Gamut3": ("SONY_SLOG3-SGAMUT3-VENICE_to_ACES2065-1", "S-Log3"),
    "Venice S-Gamut3.Cine": ("SONY_SLOG3-SGAMUT3.CINE-VENICE_to_ACES2065-1", "S-Log3"),
    "V-Gamut": ("PANASONIC_VLOG-VGAMUT_to_ACES2065-1", "V-Log"),
    "REDWideGamutRGB": ("RED_LOG3G10-RWG_to_ACES2065-1", "Log3G10"),
}


#: Camera gamuts with no OCIO builtin, and the ACES studio config's linear space of each.
STUDIO_SPACES = {
    "Blackmagic Wide Gamut": "Linear BMD WideGamut Gen5",
    "DaVinci Wide Gamut": "Linear DaVinci WideGamut",
    "D-Gamut": "Linear D-Gamut",
}


def test_every_published_adaptation_is_checked():
    assert set(PUBLISHED_ADAPTATION) == set(BUILTINS) | set(STUDIO_SPACES)


@pytest.mark.parametrize("name", sorted(STUDIO_SPACES))
def test_published_adaptation_reproduces_the_studio_configs_matrix(name):
    """Blackmagic's, DaVinci's and DJI's gamuts, which OCIO has no builtin for, as the ACES
    studio config converts them (CAT02; Bradford, the spec's default, was 5e-3 off)."""
    import PyOpenColorIO as ocio

    from generator.colorimetry.matrices import rgb_to_rgb

    config = ocio.Config.CreateFromFile("ocio://studio-config-latest")
    pixels = np.ascontiguousarray(np.eye(3), dtype=np.float32)
    config.getProcessor(STUDIO_SPACES[name], "ACES2065-1").getDefaultCPUProcessor().applyRGB(pixels)
    studio = pixels.astype(np.float64).T
    gamut, aces = gamuts()[name], gamuts()["AP0"]
    assert (
        np.abs(rgb_to_rgb(gamut, aces, gamut.adaptation) - studio).max() <= tolerances.PUBLISHED_CAMERA_MATRIX_ABSOLUTE
    )
    assert (
        np.abs(rgb_to_rgb(gamut, aces, "Bradford") - studio).max() > 100 * tolerances.PUBLISHED_CAMERA_MATRIX_ABSOLUTE
    )


@pytest.mark.parametrize("name", sorted(BUILTINS))
def test_published_adaptation_reproduces_the_builtin_camera_matrix(name):
    """The gamut's matrix to ACES2065-1, derived with its publisher's adaptation, is OCIO's
    builtin's (the vendor's published matrix, read back through the builtin on colours whose
    decoded values are known); the spec's default, Bradford, is not for the CAT02 gamuts."""
    import PyOpenColorIO as ocio

    from generator.colorimetry.curves import CURVES
    from generator.colorimetry.matrices import rgb_to_rgb

    builtin, curve = BUILTINS[name]
    linear = np.eye(3) * 0.5 + 0.1
    pixels = np.ascontiguousarray(CURVES[curve].encode(linear), dtype=np.float32)
    ocio.Config.CreateRaw().getProcessor(ocio.BuiltinTransform(builtin)).getDefaultCPUProcessor().applyRGB(pixels)
    published = np.linalg.solve(linear, pixels.astype(np.float64)).T
    gamut, aces = gamuts()[name], gamuts()["AP0"]
    derived = rgb_to_rgb(gamut, aces, gamut.adaptation)
    assert np.abs(derived - published).max() <= tolerances.PUBLISHED_CAMERA_MATRIX_ABSOLUTE
    if gamut.adaptation != "Bradford":
        assert (
            np.abs(rgb_to_rgb(gamut, aces, "Bradford") - published).max()
            > 100 * tolerances.PUBLISHED_CAMERA_MATRIX_ABSOLUTE
        )
