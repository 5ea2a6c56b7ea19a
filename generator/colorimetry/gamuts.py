"""The gamuts the library knows: primaries and white points as data.

Standard and camera gamuts are plain data citing the document that publishes
them (held against colour-science's datasets by the tests); camera gamuts
colour-science lacks come from :mod:`generator.colorimetry.vendor`; CIE RGB is derived from the CIE 1931
colour-matching functions by :mod:`generator.colorimetry.spectral`. Matrices
are never stored: :class:`~generator.colorimetry.matrices.Gamut` derives them.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from functools import cache

from generator.colorimetry.matrices import Gamut
from generator.colorimetry.vendor import VENDOR_GAMUTS

D65 = (0.3127, 0.3290)
E = (1.0 / 3.0, 1.0 / 3.0)
XYZ_PRIMARIES = ((1.0, 0.0), (0.0, 1.0), (0.0, 0.0))

#: Standard and camera gamuts: primaries (R, G, B) and white point as xy, with the
#: document that publishes them. The test suite holds each against colour-science's
#: dataset of the same gamut (COLOUR_KEYS); they live here as plain data so that loading
#: a spec does not import colour-science.
STANDARD = {
    "AP0": (((0.7347, 0.2653), (0.0, 1.0), (0.0001, -0.077)), (0.32168, 0.33767), "SMPTE ST 2065-1:2012"),
    "AP1": (((0.713, 0.293), (0.165, 0.83), (0.128, 0.044)), (0.32168, 0.33767), "Academy S-2014-004"),
    "Rec.709": (((0.64, 0.33), (0.3, 0.6), (0.15, 0.06)), D65, "ITU-R BT.709-6"),
    "Rec.2020": (((0.708, 0.292), (0.17, 0.797), (0.131, 0.046)), D65, "ITU-R BT.2020-2"),
    "P3-D65": (((0.68, 0.32), (0.265, 0.69), (0.15, 0.06)), D65, "SMPTE EG 432-1:2010"),
    "DCI-P3": (((0.68, 0.32), (0.265, 0.69), (0.15, 0.06)), (0.314, 0.351), "SMPTE RP 431-2:2011"),
    "Adobe RGB (1998)": (
        ((0.64, 0.33), (0.21, 0.71), (0.15, 0.06)),
        D65,
        "Adobe RGB (1998) Color Image Encoding 2005-05",
    ),
    "ProPhoto RGB": (
        ((0.7347, 0.2653), (0.1596, 0.8404), (0.0366, 0.0001)),
        (0.3457, 0.3585),
        "ISO 22028-2:2013 (ROMM RGB)",
    ),
    "ARRI Wide Gamut 3": (((0.684, 0.313), (0.221, 0.848), (0.0861, -0.102)), D65, "ARRI, ALEXA Log C Curve, 2012"),
    "ARRI Wide Gamut 4": (
        ((0.7347, 0.2653), (0.1424, 0.8576), (0.0991, -0.0308)),
        D65,
        "ARRI, ALEXA 35 LogC4 Specification, 2022",
    ),
    "S-Gamut3": (((0.73, 0.28), (0.14, 0.855), (0.1, -0.05)), D65, "Sony, S-Gamut3/S-Log3 Technical Summary, 2016"),
    "S-Gamut3.Cine": (
        ((0.766, 0.275), (0.225, 0.8), (0.089, -0.087)),
        D65,
        "Sony, S-Gamut3.Cine/S-Log3 Technical Summary, 2016",
    ),
    "Venice S-Gamut3": (
        (
            (0.740464264304292, 0.27936437475066),
            (0.089241145423286, 0.893809528608105),
            (0.110488236673827, -0.052579333080476),
        ),
        D65,
        "Sony, VENICE S-Gamut3 to ACES matrix (primaries derived by colour-science)",
    ),
    "Venice S-Gamut3.Cine": (
        (
            (0.775901871567345, 0.274502392854799),
            (0.188682902773355, 0.828684937020288),
            (0.101337382499301, -0.089187517306263),
        ),
        D65,
        "Sony, VENICE S-Gamut3.Cine to ACES matrix (primaries derived by colour-science)",
    ),
    "REDWideGamutRGB": (
        ((0.780308, 0.304253), (0.121595, 1.493994), (0.095612, -0.084589)),
        D65,
        "RED, REDWideGamutRGB and Log3G10, 2017",
    ),
    "Cinema Gamut": (((0.74, 0.27), (0.17, 1.14), (0.08, -0.1)), D65, "Canon, Cinema Gamut, 2014"),
    "V-Gamut": (((0.73, 0.28), (0.165, 0.84), (0.1, -0.03)), D65, "Panasonic, V-Log/V-Gamut Reference Manual, 2014"),
    "Blackmagic Wide Gamut": (
        ((0.7177215, 0.3171181), (0.228041, 0.861569), (0.1005841, -0.0820452)),
        (0.312717, 0.3290312),
        "Blackmagic Design, Generation 5 Color Science, 2021",
    ),
    "DaVinci Wide Gamut": (
        ((0.8, 0.313), (0.1682, 0.9877), (0.079, -0.1155)),
        D65,
        "Blackmagic Design, DaVinci Wide Gamut Intermediate, 2020",
    ),
    "D-Gamut": (((0.71, 0.31), (0.21, 0.88), (0.09, -0.08)), D65, "DJI, D-Log and D-Gamut White Paper, 2017"),
    "F-Gamut": (((0.708, 0.292), (0.17, 0.797), (0.131, 0.046)), D65, "Fujifilm, F-Log Data Sheet, 2016"),
    "F-Gamut C": (((0.7347, 0.2653), (0.0263, 0.9737), (0.1173, -0.0224)), D65, "Fujifilm, F-Log2 C Data Sheet, 2024"),
    "N-Gamut": (((0.708, 0.292), (0.17, 0.797), (0.131, 0.046)), D65, "Nikon, N-Log Specification Document, 2018"),
    "E-Gamut": (((0.8, 0.3177), (0.18, 0.9), (0.065, -0.0805)), D65, "FilmLight, E-Gamut, 2018"),
    "E-Gamut2": (((0.83, 0.31), (0.15, 0.95), (0.065, -0.0805)), D65, "FilmLight, E-Gamut2, 2023"),
}

#: colour-science's RGB_COLOURSPACES key for each entry of STANDARD (for the cross-check).
COLOUR_KEYS = {
    "AP0": "ACES2065-1",
    "AP1": "ACEScg",
    "Rec.709": "ITU-R BT.709",
    "Rec.2020": "ITU-R BT.2020",
    "P3-D65": "P3-D65",
    "DCI-P3": "DCI-P3",
    "Adobe RGB (1998)": "Adobe RGB (1998)",
    "ProPhoto RGB": "ProPhoto RGB",
    "D-Gamut": "DJI D-Gamut",
    "E-Gamut": "FilmLight E-Gamut",
    "E-Gamut2": "FilmLight E-Gamut 2",
}


#: The chromatic adaptation behind each camera gamut's published matrices to ACES2065-1,
#: as OCIO's builtin camera transforms (the ACES studio config's spaces) carry them: ARRI's,
#: Canon's and Sony's (their ACES input transforms) reproduce with CAT02, Panasonic's and
#: RED's with Bradford (each within 3e-6 of the builtin's matrix, which the tests hold);
#: the studio config (v5.0.0) adapts Blackmagic's, DaVinci's and DJI's gamuts with CAT02
#: too (within 1e-7 of its matrices; Bradford was 5e-3 off). A space of one of these gamuts
#: is adapted so, whatever the spec's chromatic_adaptation, so that its name means the same
#: numbers as in that config.
PUBLISHED_ADAPTATION = {
    "ARRI Wide Gamut 3": "CAT02",
    "ARRI Wide Gamut 4": "CAT02",
    "Cinema Gamut": "CAT02",
    "S-Gamut3": "CAT02",
    "S-Gamut3.Cine": "CAT02",
    "Venice S-Gamut3": "CAT02",
    "Venice S-Gamut3.Cine": "CAT02",
    "V-Gamut": "Bradford",
    "REDWideGamutRGB": "Bradford",
    "Blackmagic Wide Gamut": "CAT02",
    "DaVinci Wide Gamut": "CAT02",
    "D-Gamut": "CAT02",
}

#: Of PUBLISHED_ADAPTATION, the gamuts whose vendor publishes no matrix to ACES: their
#: adaptation is the ACES studio config's, not a publisher's.
STUDIO_CONFIG_ADAPTATION = ("Blackmagic Wide Gamut", "DaVinci Wide Gamut", "D-Gamut")


def _rounded(values) -> tuple:
    return tuple(tuple(float(v) for v in row) for row in values)


def _standard() -> dict[str, Gamut]:
    return {
        name: Gamut(name, primaries, white, citation=cite, adaptation=PUBLISHED_ADAPTATION.get(name))
        for name, (primaries, white, cite) in STANDARD.items()
    }


def _xyz() -> dict[str, Gamut]:
    return {
        "CIE XYZ-D65": Gamut("CIE XYZ-D65", XYZ_PRIMARIES, E, adapting_white=D65, citation="CIE 15:2018"),
        "CIE XYZ-E": Gamut("CIE XYZ-E", XYZ_PRIMARIES, E, citation="CIE 15:2018"),
    }


def _cie_rgb() -> Gamut:
    from generator.colorimetry.spectral import cie_rgb_primaries  # lazy: colour-science takes seconds

    return Gamut(
        "CIE RGB",
        _rounded(cie_rgb_primaries()),
        E,
        citation="CIE 1931: monochromatic 700 / 546.1 / 435.8 nm, equal-energy white",
    )


def _vendor() -> dict[str, Gamut]:
    return {
        name: Gamut(name, _rounded(g.primaries), (g.whitepoint[0], g.whitepoint[1]), citation=g.citation)
        for name, g in VENDOR_GAMUTS.items()
    }


class _Gamuts(Mapping):
    """Read-only name -> Gamut; derived gamuts are computed when first looked up
    (CIE RGB integrates the colour-matching functions, which imports colour-science)."""

    def __init__(self, ready: dict[str, Gamut], derived: dict[str, Callable[[], Gamut]]):
        self._ready, self._derived = dict(ready), dict(derived)

    def __getitem__(self, name: str) -> Gamut:
        if name not in self._ready:
            self._ready[name] = self._derived[name]()
        return self._ready[name]

    def __iter__(self) -> Iterator[str]:
        return iter([*dict.fromkeys([*self._ready, *self._derived])])

    def __len__(self) -> int:
        return len(set(self._ready) | set(self._derived))


@cache
def gamuts() -> Mapping[str, Gamut]:
    """Every named gamut, read-only."""
    return _Gamuts({**_standard(), **_vendor(), **_xyz()}, {"CIE RGB": _cie_rgb})
