"""The gamuts the library knows: primaries and white points as data.

Standard gamuts take their chromaticities from colour-science's datasets (which
cite the standards); camera gamuts colour-science lacks come from
:mod:`generator.colorimetry.vendor`; CIE RGB is derived from the CIE 1931
colour-matching functions by :mod:`generator.colorimetry.spectral`. Matrices
are never stored: :class:`~generator.colorimetry.matrices.Gamut` derives them.
"""

from __future__ import annotations

from functools import cache
from types import MappingProxyType

from generator.colorimetry.matrices import Gamut

D65 = (0.3127, 0.3290)
E = (1.0 / 3.0, 1.0 / 3.0)
XYZ_PRIMARIES = ((1.0, 0.0), (0.0, 1.0), (0.0, 0.0))

#: Our gamut name -> colour-science RGB_COLOURSPACES key.
_FROM_COLOUR = {
    "AP0": "ACES2065-1",
    "AP1": "ACEScg",
    "Rec.709": "ITU-R BT.709",
    "Rec.2020": "ITU-R BT.2020",
    "P3-D65": "P3-D65",
    "DCI-P3": "DCI-P3",
    "Adobe RGB (1998)": "Adobe RGB (1998)",
    "ProPhoto RGB": "ProPhoto RGB",
    "ARRI Wide Gamut 3": "ARRI Wide Gamut 3",
    "ARRI Wide Gamut 4": "ARRI Wide Gamut 4",
    "S-Gamut3": "S-Gamut3",
    "S-Gamut3.Cine": "S-Gamut3.Cine",
    "Venice S-Gamut3": "Venice S-Gamut3",
    "Venice S-Gamut3.Cine": "Venice S-Gamut3.Cine",
    "REDWideGamutRGB": "REDWideGamutRGB",
    "Cinema Gamut": "Cinema Gamut",
    "V-Gamut": "V-Gamut",
    "Blackmagic Wide Gamut": "Blackmagic Wide Gamut",
    "DaVinci Wide Gamut": "DaVinci Wide Gamut",
    "D-Gamut": "DJI D-Gamut",
    "F-Gamut": "F-Gamut",
    "F-Gamut C": "F-Gamut C",
    "N-Gamut": "N-Gamut",
    "E-Gamut": "FilmLight E-Gamut",
    "E-Gamut2": "FilmLight E-Gamut 2",
}


def _rounded(values) -> tuple:
    return tuple(tuple(float(v) for v in row) for row in values)


def _from_colour() -> dict[str, Gamut]:
    import colour

    gamuts = {}
    for name, key in _FROM_COLOUR.items():
        space = colour.RGB_COLOURSPACES[key]
        gamuts[name] = Gamut(
            name=name,
            primaries=_rounded(space.primaries),
            whitepoint=tuple(float(v) for v in space.whitepoint),
            citation=f"colour-science RGB_COLOURSPACES[{key!r}]",
        )
    return gamuts


def _derived() -> dict[str, Gamut]:
    from generator.colorimetry.spectral import cie_rgb_primaries

    return {
        "CIE XYZ-D65": Gamut("CIE XYZ-D65", XYZ_PRIMARIES, E, adapting_white=D65, citation="CIE 15:2018"),
        "CIE XYZ-E": Gamut("CIE XYZ-E", XYZ_PRIMARIES, E, citation="CIE 15:2018"),
        "CIE RGB": Gamut(
            "CIE RGB",
            _rounded(cie_rgb_primaries()),
            E,
            citation="CIE 1931: monochromatic 700 / 546.1 / 435.8 nm, equal-energy white",
        ),
    }


def _vendor() -> dict[str, Gamut]:
    from generator.colorimetry.vendor import VENDOR_GAMUTS

    return {
        name: Gamut(name, _rounded(g.primaries), tuple(g.whitepoint), citation=g.citation)
        for name, g in VENDOR_GAMUTS.items()
    }


@cache
def gamuts() -> MappingProxyType:
    """Every named gamut, read-only."""
    return MappingProxyType({**_from_colour(), **_vendor(), **_derived()})
