"""The ACES 2.0 Output Transform presets, as data: every ``..._2.0`` builtin of OpenColorIO 2.6.

Each preset is one of the Academy's (aces-output v2.0, 2025: the limiting and encoding
chromaticities, peak, ``scale_white`` and ``linear_scale_factor`` of its ``Output.Academy.*.ctl``)
as OpenColorIO's builtin ``ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - <preset>_2.0`` runs it, keyed
by its view name: the ACES studio config's (v4 and v5, OCIO 2.5 and 2.6) where it names the
builtin, otherwise one in the same pattern, "ACES 2.0 - <SDR|HDR> <peak> nits (<limiting gamut>)",
with "D60 sim." for a D60 white scaled into a D65 or XYZ-E encoding gamut and "in <encoding>"
where that gamut is not the limiting one's.

The cinema presets (108 and 300 nits) aim the tone scale at 225 and 625 cd/m² and scale the result
by 0.48: their peaks are stated in units where 48 cd/m² is 100. The XYZ-E presets encode for a
DCDM; the 100 nit one does not scale its D60 white (its DCDM encoding's 48 / 52.37 does).
"""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType

from generator.rendering.aces2_params import ACES2Params

#: The encodings' and limits' chromaticities (red, green, blue) as aces-output writes them.
REC709 = ((0.64, 0.33), (0.30, 0.60), (0.15, 0.06))
P3 = ((0.68, 0.32), (0.265, 0.69), (0.15, 0.06))
REC2020 = ((0.708, 0.292), (0.170, 0.797), (0.131, 0.046))
XYZ = ((1.0, 0.0), (0.0, 1.0), (0.0, 0.0))
D65 = (0.3127, 0.3290)
D60 = (0.32168, 0.33767)
E = (1.0 / 3.0, 1.0 / 3.0)
GAMUTS = {
    "Rec.709": (REC709, D65),
    "P3 D65": (P3, D65),
    "Rec.2020": (REC2020, D65),
    "XYZ": (XYZ, E),
    "Rec.709 D60": (REC709, D60),
    "P3 D60": (P3, D60),
    "Rec.2020 D60": (REC2020, D60),
}
#: The prefix of OpenColorIO's builtin names.
STYLE_PREFIX = "ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - "
#: The cinema presets' scale: 48 cd/m² shown as 100.
CINEMA_SCALE = 0.48


@dataclass(frozen=True)
class ACES2Preset:
    """A view: its name, OpenColorIO's builtin for it and the transform's parameters."""

    view: str
    style: str
    params: ACES2Params


#: (view, builtin's preset part, peak, limiting gamut, encoding gamut, scale_white, linear scale).
_ROWS = (
    ("ACES 2.0 - SDR 100 nits (Rec.709)", "SDR-100nit-REC709", 100, "Rec.709", "Rec.709", None, 1.0),
    ("ACES 2.0 - SDR 100 nits (P3 D65)", "SDR-100nit-P3-D65", 100, "P3 D65", "P3 D65", None, 1.0),
    ("ACES 2.0 - HDR 108 nits (P3 D65)", "HDR-108nit-P3-D65", 225, "P3 D65", "P3 D65", None, CINEMA_SCALE),
    ("ACES 2.0 - HDR 300 nits (P3 D65)", "HDR-300nit-P3-D65", 625, "P3 D65", "P3 D65", None, CINEMA_SCALE),
    *(
        (f"ACES 2.0 - HDR {n} nits (P3 D65)", f"HDR-{n}nit-P3-D65", n, "P3 D65", "P3 D65", None, 1.0)
        for n in (500, 1000, 2000, 4000)
    ),
    *(
        (f"ACES 2.0 - HDR {n} nits (Rec.2020)", f"HDR-{n}nit-REC2020", n, "Rec.2020", "Rec.2020", None, 1.0)
        for n in (500, 1000, 2000, 4000)
    ),
    (
        "ACES 2.0 - SDR 100 nits (Rec.709 D60 sim.)",
        "SDR-100nit-REC709-D60-in-REC709-D65",
        100,
        "Rec.709 D60",
        "Rec.709",
        None,
        1.0,
    ),
    (
        "ACES 2.0 - SDR 100 nits (Rec.709 D60 sim. in P3 D65)",
        "SDR-100nit-REC709-D60-in-P3-D65",
        100,
        "Rec.709 D60",
        "P3 D65",
        None,
        1.0,
    ),
    (
        "ACES 2.0 - SDR 100 nits (Rec.709 D60 sim. in Rec.2020)",
        "SDR-100nit-REC709-D60-in-REC2020-D65",
        100,
        "Rec.709 D60",
        "Rec.2020",
        None,
        1.0,
    ),
    ("ACES 2.0 - SDR 100 nits (P3 D60 sim.)", "SDR-100nit-P3-D60-in-P3-D65", 100, "P3 D60", "P3 D65", None, 1.0),
    ("ACES 2.0 - SDR 100 nits (P3 D60 in XYZ)", "SDR-100nit-P3-D60-in-XYZ-E", 100, "P3 D60", "XYZ", False, 1.0),
    (
        "ACES 2.0 - HDR 108 nits (P3 D60 sim.)",
        "HDR-108nit-P3-D60-in-P3-D65",
        225,
        "P3 D60",
        "P3 D65",
        None,
        CINEMA_SCALE,
    ),
    (
        "ACES 2.0 - HDR 300 nits (P3 D60 sim. in XYZ)",
        "HDR-300nit-P3-D60-in-XYZ-E",
        625,
        "P3 D60",
        "XYZ",
        None,
        CINEMA_SCALE,
    ),
    *(
        (f"ACES 2.0 - HDR {n} nits (P3 D60 sim.)", f"HDR-{n}nit-P3-D60-in-P3-D65", n, "P3 D60", "P3 D65", None, 1.0)
        for n in (500, 1000, 2000, 4000)
    ),
    *(
        (
            f"ACES 2.0 - HDR {n} nits (P3 D60 sim. in Rec.2020)",
            f"HDR-{n}nit-P3-D60-in-REC2020-D65",
            n,
            "P3 D60",
            "Rec.2020",
            None,
            1.0,
        )
        for n in (500, 1000, 2000, 4000)
    ),
    *(
        (
            f"ACES 2.0 - HDR {n} nits (Rec.2020 D60 sim.)",
            f"HDR-{n}nit-REC2020-D60-in-REC2020-D65",
            n,
            "Rec.2020 D60",
            "Rec.2020",
            None,
            1.0,
        )
        for n in (500, 1000, 2000, 4000)
    ),
)


def _preset(view: str, part: str, peak: float, limiting: str, encoding: str, scale_white, scale: float) -> ACES2Preset:
    params = ACES2Params(peak, *GAMUTS[limiting], *GAMUTS[encoding], scale_white=scale_white, linear_scale=scale)
    return ACES2Preset(view=view, style=f"{STYLE_PREFIX}{part}_2.0", params=params)


#: Every preset by view name (read-only).
PRESETS = MappingProxyType({row[0]: _preset(*row) for row in _ROWS})
