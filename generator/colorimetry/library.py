"""The colour-space and display library, as data.

Names, aliases, families and encodings follow OCIO's built-in ACES studio
config (ocio://studio-config-latest); camera encodings outside it take aliases
in its pattern (curve_gamut, lower case). A record names a gamut (see
:mod:`~generator.colorimetry.gamuts`) and a curve (see
:mod:`~generator.colorimetry.curves`); nothing numeric lives here.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SpaceDef:
    """A scene-referred colour space: a gamut and the curve that encodes it."""

    name: str
    gamut: str | None
    curve: str
    aliases: tuple[str, ...] = ()
    family: str = ""
    encoding: str = "scene-linear"
    description: str = ""
    is_data: bool = False


@dataclass(frozen=True)
class DisplayDef:
    """A display: its gamut, EOTF (the encoding is its inverse) and peak luminance."""

    name: str
    gamut: str
    eotf: str
    aliases: tuple[str, ...] = ()
    peak: float = 100.0
    encoding: str = "sdr-video"
    description: str = ""


def _camera(log_name, lin_name, gamut, curve, log_aliases, lin_aliases, family) -> tuple[SpaceDef, SpaceDef]:
    """A camera's log encoding and its linear companion."""
    return (
        SpaceDef(log_name, gamut, curve, log_aliases, family, "log", f"{curve} encoded {gamut}"),
        SpaceDef(lin_name, gamut, "linear", lin_aliases, family, "scene-linear", f"Linear {gamut}"),
    )


_ACES = (
    SpaceDef(
        "ACES2065-1",
        "AP0",
        "linear",
        ("aces2065_1", "aces", "ACES - ACES2065-1", "lin_ap0", "lin_ap0_scene"),
        "ACES",
        "scene-linear",
        "The Academy Color Encoding System reference, AP0 primaries (SMPTE ST 2065-1)",
    ),
    SpaceDef(
        "ACEScg",
        "AP1",
        "linear",
        ("ACES - ACEScg", "lin_ap1", "lin_ap1_scene"),
        "ACES",
        "scene-linear",
        "ACEScg: linear AP1 (Academy S-2014-004)",
    ),
    SpaceDef(
        "ACEScct",
        "AP1",
        "ACEScct",
        ("ACES - ACEScct", "acescct_ap1"),
        "ACES",
        "log",
        "ACEScct: AP1, logarithmic with a toe (Academy S-2016-001)",
    ),
    SpaceDef(
        "ACEScc",
        "AP1",
        "ACEScc",
        ("ACES - ACEScc", "acescc_ap1"),
        "ACES",
        "log",
        "ACEScc: AP1, pure logarithmic (Academy S-2014-003)",
    ),
    SpaceDef(
        "ADX10",
        None,
        "ADX10",
        ("Input - ADX - ADX10",),
        "ACES",
        "log",
        "Academy Density Exchange, 10-bit (Academy S-2008-001)",
    ),
    SpaceDef(
        "ADX16",
        None,
        "ADX16",
        ("Input - ADX - ADX16",),
        "ACES",
        "log",
        "Academy Density Exchange, 16-bit (Academy S-2008-001)",
    ),
)

_CAMERAS = (
    *_camera(
        "ARRI LogC3 (EI800)",
        "Linear ARRI Wide Gamut 3",
        "ARRI Wide Gamut 3",
        "ARRI LogC3 (EI800)",
        ("arri_logc3_ei800", "logc3ei800_alexawide", "Input - ARRI - V3 LogC (EI800) - Wide Gamut"),
        ("lin_arri_wide_gamut_3", "lin_alexawide", "Input - ARRI - Linear - ALEXA Wide Gamut"),
        "Input/ARRI",
    ),
    *_camera(
        "ARRI LogC4",
        "Linear ARRI Wide Gamut 4",
        "ARRI Wide Gamut 4",
        "ARRI LogC4",
        ("arri_logc4",),
        ("lin_arri_wide_gamut_4", "lin_awg4"),
        "Input/ARRI",
    ),
    *_camera(
        "BMDFilm WideGamut Gen5",
        "Linear BMD WideGamut Gen5",
        "Blackmagic Wide Gamut",
        "BMDFilm Gen5",
        ("bmdfilm_widegamut_gen5",),
        ("lin_bmd_widegamut_gen5",),
        "Input/BlackmagicDesign",
    ),
    *_camera(
        "DaVinci Intermediate WideGamut",
        "Linear DaVinci WideGamut",
        "DaVinci Wide Gamut",
        "DaVinci Intermediate",
        ("davinci_intermediate_widegamut",),
        ("lin_davinci_widegamut",),
        "Input/BlackmagicDesign",
    ),
    *_camera(
        "CanonLog2 CinemaGamut D55",
        "Linear CinemaGamut D55",
        "Cinema Gamut",
        "Canon Log 2",
        ("canonlog2_cinemagamut_d55", "canonlog2_cgamutday", "Input - Canon - Canon-Log2 - Cinema Gamut Daylight"),
        ("lin_cinemagamut_d55", "lin_canoncgamutday", "Input - Canon - Linear - Canon Cinema Gamut Daylight"),
        "Input/Canon",
    ),
    SpaceDef(
        "CanonLog3 CinemaGamut D55",
        "Cinema Gamut",
        "Canon Log 3",
        ("canonlog3_cinemagamut_d55", "canonlog3_cgamutday", "Input - Canon - Canon-Log3 - Cinema Gamut Daylight"),
        "Input/Canon",
        "log",
        "Canon Log 3 encoded Cinema Gamut",
    ),
    *_camera("D-Log D-Gamut", "Linear D-Gamut", "D-Gamut", "D-Log", ("dlog_dgamut",), ("lin_dgamut",), "Input/DJI"),
    *_camera(
        "V-Log V-Gamut",
        "Linear V-Gamut",
        "V-Gamut",
        "V-Log",
        ("vlog_vgamut", "Input - Panasonic - V-Log - V-Gamut"),
        ("lin_vgamut", "Input - Panasonic - Linear - V-Gamut"),
        "Input/Panasonic",
    ),
    *_camera(
        "Log3G10 REDWideGamutRGB",
        "Linear REDWideGamutRGB",
        "REDWideGamutRGB",
        "Log3G10",
        ("log3g10_redwidegamutrgb", "rl3g10_rwg", "Input - RED - REDLog3G10 - REDWideGamutRGB"),
        ("lin_redwidegamutrgb", "lin_rwg", "Input - RED - Linear - REDWideGamutRGB"),
        "Input/RED",
    ),
    *_camera(
        "S-Log3 S-Gamut3",
        "Linear S-Gamut3",
        "S-Gamut3",
        "S-Log3",
        ("slog3_sgamut3", "Input - Sony - S-Log3 - S-Gamut3"),
        ("lin_sgamut3", "Input - Sony - Linear - S-Gamut3"),
        "Input/Sony",
    ),
    *_camera(
        "S-Log3 S-Gamut3.Cine",
        "Linear S-Gamut3.Cine",
        "S-Gamut3.Cine",
        "S-Log3",
        ("slog3_sgamut3cine", "slog3_sgamutcine", "Input - Sony - S-Log3 - S-Gamut3.Cine"),
        ("lin_sgamut3cine", "Input - Sony - Linear - S-Gamut3.Cine"),
        "Input/Sony",
    ),
    *_camera(
        "S-Log3 Venice S-Gamut3",
        "Linear Venice S-Gamut3",
        "Venice S-Gamut3",
        "S-Log3",
        ("slog3_venice_sgamut3", "Input - Sony - S-Log3 - Venice S-Gamut3"),
        ("lin_venice_sgamut3", "Input - Sony - Linear - Venice S-Gamut3"),
        "Input/Sony",
    ),
    *_camera(
        "S-Log3 Venice S-Gamut3.Cine",
        "Linear Venice S-Gamut3.Cine",
        "Venice S-Gamut3.Cine",
        "S-Log3",
        ("slog3_venice_sgamut3cine", "slog3_venice_sgamutcine", "Input - Sony - S-Log3 - Venice S-Gamut3.Cine"),
        ("lin_venice_sgamut3cine", "Input - Sony - Linear - Venice S-Gamut3.Cine"),
        "Input/Sony",
    ),
    SpaceDef(
        "Apple Log",
        "Rec.2020",
        "Apple Log",
        ("apple_log", "applelog_rec2020"),
        "Input/Apple",
        "log",
        "Apple Log encoded Rec.2020",
    ),
    *_camera(
        "Apple Log 2",
        "Linear Apple Wide Gamut",
        "Apple Wide Gamut",
        "Apple Log",
        ("apple_log_2", "applelog_applewg"),
        ("lin_apple_wide_gamut", "lin_applewg"),
        "Input/Apple",
    ),
    *_camera(
        "F-Log F-Gamut", "Linear F-Gamut", "F-Gamut", "F-Log", ("flog_fgamut",), ("lin_fgamut",), "Input/Fujifilm"
    ),
    SpaceDef(
        "F-Log2 F-Gamut", "F-Gamut", "F-Log2", ("flog2_fgamut",), "Input/Fujifilm", "log", "F-Log2 encoded F-Gamut"
    ),
    *_camera(
        "F-Log2 F-Gamut C",
        "Linear F-Gamut C",
        "F-Gamut C",
        "F-Log2",
        ("flog2_fgamutc",),
        ("lin_fgamutc",),
        "Input/Fujifilm",
    ),
    *_camera(
        "L-Log L-Gamut", "Linear L-Gamut", "Leica L-Gamut", "L-Log", ("llog_lgamut",), ("lin_lgamut",), "Input/Leica"
    ),
    *_camera("N-Log N-Gamut", "Linear N-Gamut", "N-Gamut", "N-Log", ("nlog_ngamut",), ("lin_ngamut",), "Input/Nikon"),
    *_camera(
        "Samsung Log Samsung Gamut",
        "Linear Samsung Gamut",
        "Samsung Log Gamut",
        "Samsung Log",
        ("samsunglog_samsunggamut",),
        ("lin_samsunggamut",),
        "Input/Samsung",
    ),
    SpaceDef(
        "Mi-Log Rec.2020",
        "Rec.2020",
        "Mi-Log",
        ("milog_rec2020",),
        "Input/Xiaomi",
        "log",
        "Xiaomi Mi-Log encoded Rec.2020",
    ),
    *_camera(
        "T-Log E-Gamut", "Linear E-Gamut", "E-Gamut", "T-Log", ("tlog_egamut",), ("lin_egamut",), "Input/FilmLight"
    ),
    *_camera(
        "T-LogE E-Gamut2",
        "Linear E-Gamut2",
        "E-Gamut2",
        "T-LogE",
        ("tloge_egamut2",),
        ("lin_egamut2",),
        "Input/FilmLight",
    ),
    SpaceDef("JPLog2 AP1", "AP1", "JPLog2", ("jplog2_ap1",), "ACES", "log", "JPLog2 encoded AP1"),
)

_UTILITY = (
    SpaceDef(
        "sRGB Encoded Rec.709 (sRGB)",
        "Rec.709",
        "sRGB",
        (
            "srgb_encoded_rec709_srgb",
            "srgb_texture",
            "srgb_tx",
            "sRGB",
            "srgb_rec709_scene",
            "Utility - sRGB - Texture",
            "Input - Generic - sRGB - Texture",
            "sRGB - Texture",
        ),
        "Utility",
        "sdr-video",
        "sRGB piecewise encoding of Rec.709 primaries (IEC 61966-2-1)",
    ),
    SpaceDef(
        "Gamma 1.8 Encoded Rec.709",
        "Rec.709",
        "Gamma 1.8",
        (
            "g18_encoded_rec709",
            "g18_rec709",
            "g18_rec709_tx",
            "g18_rec709_scene",
            "Gamma 1.8 Rec.709 - Texture",
            "Utility - Gamma 1.8 - Rec.709 - Texture",
        ),
        "Utility",
        "sdr-video",
    ),
    SpaceDef(
        "Gamma 2.2 Encoded Rec.709",
        "Rec.709",
        "Gamma 2.2",
        (
            "g22_encoded_rec709",
            "g22_rec709",
            "g22_rec709_tx",
            "g22_rec709_scene",
            "Gamma 2.2 Rec.709 - Texture",
            "Utility - Gamma 2.2 - Rec.709 - Texture",
        ),
        "Utility",
        "sdr-video",
    ),
    SpaceDef(
        "Gamma 2.4 Encoded Rec.709",
        "Rec.709",
        "Gamma 2.4",
        (
            "g24_encoded_rec709",
            "g24_rec709",
            "rec709_display",
            "g24_rec709_tx",
            "g24_rec709_scene",
            "Gamma 2.4 Rec.709 - Texture",
            "Utility - Rec.709 - Display",
        ),
        "Utility",
        "sdr-video",
    ),
    SpaceDef(
        "Camera Rec.709",
        "Rec.709",
        "Rec.709",
        ("camera_rec709", "rec709_camera", "Utility - Rec.709 - Camera"),
        "Utility/ITU",
        "sdr-video",
        "ITU-R BT.709 camera OETF",
    ),
    SpaceDef(
        "sRGB Encoded P3-D65",
        "P3-D65",
        "sRGB",
        (
            "srgb_encoded_p3d65",
            "srgb_p3d65",
            "srgb_displayp3",
            "srgb_p3d65_scene",
            "srgb_encoded_p3d65_tx",
            "sRGB Encoded P3-D65 - Texture",
        ),
        "Utility",
        "sdr-video",
    ),
    SpaceDef(
        "Gamma 2.2 Encoded AdobeRGB",
        "Adobe RGB (1998)",
        "Adobe RGB (1998)",
        ("g22_encoded_adobergb", "adobergb", "g22_adobergb_scene"),
        "Utility",
        "sdr-video",
        "Adobe RGB (1998): the standard's exponent 563/256 (2.19921875), as the ACES studio config",
    ),
    SpaceDef(
        "sRGB Encoded AP1",
        "AP1",
        "sRGB",
        ("srgb_encoded_ap1", "srgb_ap1", "srgb_ap1_scene", "srgb_encoded_ap1_tx", "sRGB Encoded AP1 - Texture"),
        "Utility",
        "sdr-video",
    ),
    SpaceDef(
        "Gamma 2.2 Encoded AP1",
        "AP1",
        "Gamma 2.2",
        ("g22_encoded_ap1", "g22_ap1", "g22_ap1_tx", "g22_ap1_scene", "Gamma 2.2 AP1 - Texture"),
        "Utility",
        "sdr-video",
    ),
    SpaceDef(
        "CIE XYZ-D65 - Scene-referred",
        "CIE XYZ-D65",
        "linear",
        ("cie_xyz_d65_scene", "lin_ciexyzd65_scene", "lin_ciexyzd65"),
        "Utility",
        "scene-linear",
        "CIE 1931 XYZ relative to D65",
    ),
    SpaceDef(
        "CIE XYZ-E - Scene-referred",
        "CIE XYZ-E",
        "linear",
        ("cie_xyz_e_scene", "lin_ciexyze"),
        "Utility",
        "scene-linear",
        "CIE 1931 XYZ relative to the equal-energy illuminant E",
    ),
    SpaceDef(
        "Linear CIE RGB",
        "CIE RGB",
        "linear",
        ("lin_ciergb", "cie_rgb"),
        "Utility",
        "scene-linear",
        "CIE 1931 RGB: monochromatic primaries 700 / 546.1 / 435.8 nm, equal-energy white",
    ),
    SpaceDef(
        "Linear AdobeRGB",
        "Adobe RGB (1998)",
        "linear",
        ("lin_adobergb", "lin_adobergb_scene", "Utility - Linear - Adobe RGB"),
        "Utility",
    ),
    SpaceDef(
        "Linear P3-D65",
        "P3-D65",
        "linear",
        ("lin_p3d65", "lin_displayp3", "lin_p3d65_scene", "Linear Display P3", "Utility - Linear - P3-D65"),
        "Utility",
        "scene-linear",
        "",
    ),
    SpaceDef("Linear DCI-P3", "DCI-P3", "linear", ("lin_p3dci", "lin_dcip3"), "Utility"),
    SpaceDef("Linear ProPhoto RGB", "ProPhoto RGB", "linear", ("lin_prophoto", "lin_romm"), "Utility"),
    SpaceDef(
        "Linear Rec.2020",
        "Rec.2020",
        "linear",
        ("lin_rec2020", "lin_rec2020_scene", "Utility - Linear - Rec.2020"),
        "Utility",
        "scene-linear",
        "",
    ),
    SpaceDef(
        "Linear Rec.709 (sRGB)",
        "Rec.709",
        "linear",
        (
            "lin_rec709_srgb",
            "lin_rec709",
            "lin_rec709_scene",
            "lin_srgb",
            "Utility - Linear - sRGB",
            "Utility - Linear - Rec.709",
        ),
        "Utility",
        "scene-linear",
        "",
    ),
    SpaceDef(
        "Raw", None, "linear", ("none", "Utility - Raw"), "Utility", "data", "Data: never colour managed", is_data=True
    ),
)

#: Every library colour space, in the order configs list them.
SPACES: tuple[SpaceDef, ...] = _ACES + _CAMERAS + _UTILITY

#: Hosts' menu categories of the library spaces that OCIO's built-in ACES studio config
#: (studio-config-v5.0.0_aces-v2.1_ocio-v2.6) lists beyond file-io; every other library space
#: has file-io alone, as there (a working-space menu of camera encodings is not a studio's).
STUDIO_CATEGORIES: dict[str, tuple[str, ...]] = {
    "ACES2065-1": ("file-io", "texture"),
    "ACEScct": ("file-io", "working-space"),
    "ACEScg": ("file-io", "working-space", "texture"),
    "Linear P3-D65": ("file-io", "working-space", "texture"),
    "Linear Rec.709 (sRGB)": ("file-io", "working-space", "texture"),
    "Linear AdobeRGB": ("file-io", "texture"),
    "Linear Rec.2020": ("file-io", "texture"),
    "sRGB Encoded Rec.709 (sRGB)": ("file-io", "texture"),
    "Gamma 1.8 Encoded Rec.709": ("file-io", "texture"),
    "Gamma 2.2 Encoded Rec.709": ("file-io", "texture"),
    "Gamma 2.4 Encoded Rec.709": ("file-io", "texture"),
    "sRGB Encoded P3-D65": ("file-io", "texture"),
    "Gamma 2.2 Encoded AdobeRGB": ("file-io", "texture"),
    "sRGB Encoded AP1": ("file-io", "texture"),
    "Gamma 2.2 Encoded AP1": ("file-io", "texture"),
    "Raw": ("file-io", "texture"),
}

#: Every library display.
DISPLAYS: tuple[DisplayDef, ...] = (
    DisplayDef("sRGB - Display", "Rec.709", "sRGB", ("srgb_display", "srgb_rec709_display")),
    DisplayDef("Gamma 2.2 Rec.709 - Display", "Rec.709", "Gamma 2.2", ("g22_rec709_display",)),
    DisplayDef(
        "Rec.1886 Rec.709 - Display",
        "Rec.709",
        "Gamma 2.4",
        ("rec1886_rec709_display", "g24_rec709_display"),
        description="ITU-R BT.1886 with black at zero: a pure 2.4 power",
    ),
    DisplayDef("Display P3 - Display", "P3-D65", "sRGB", ("displayp3_display", "srgb_p3d65_display")),
    DisplayDef(
        "Display P3 HDR - Display",
        "P3-D65",
        "sRGB extended",
        ("displayp3_hdr_display", "srgbe_p3d65_display"),
        1000.0,
        "edr-video",
        "Display P3 with the extended sRGB encoding of EDR screens: 1.0 = 100 cd/m², values above 1 up to the peak",
    ),
    DisplayDef(
        "Gamma 2.6 P3-D65 - Display", "P3-D65", "Gamma 2.6", ("g26_p3d65_display", "P3-D65 - Display", "p3d65_display")
    ),
    DisplayDef(
        "Gamma 2.6 DCI-P3 - Display",
        "DCI-P3",
        "Gamma 2.6",
        ("g26_dcip3_display", "p3dci_display"),
        description="DCI-P3 primaries and DCI white, gamma 2.6 (SMPTE RP 431-2)",
    ),
    DisplayDef(
        "Rec.2100-PQ - Display",
        "Rec.2020",
        "ST 2084",
        ("rec2100_pq_display", "pq_rec2020_display"),
        1000.0,
        "hdr-video",
    ),
    DisplayDef(
        "Rec.2100-HLG - Display", "Rec.2020", "HLG", ("rec2100_hlg_display", "hlg_rec2020_display"), 1000.0, "hdr-video"
    ),
    DisplayDef(
        "ST2084-P3-D65 - Display",
        "P3-D65",
        "ST 2084",
        ("st2084_p3d65_display", "pq_p3d65_display"),
        1000.0,
        "hdr-video",
    ),
)
