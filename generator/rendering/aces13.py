"""The ACES 1.3 Output Transforms (RRT + ODT) of the ACES studio config, forward and inverse.

Each preset is one view transform of OpenColorIO's ACES 1.3 studio config
(``ocio://studio-config-v2.2.0_aces-v1.3_ocio-v2.4``), named as there, and follows the
Academy's CTL (aces-dev v1.3) of the transforms its description cites (``Preset13.ctl``,
the v1.3 files' names). :func:`forward13` gives CIE XYZ
exactly where OpenColorIO's builtin of that view (``ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65
- ...``) gives it: relative to D65 as the display sees it (adapted from the ACES white,
or not, for the white simulations; DCI displays' XYZ pre-adapted from DCI white, which
OpenColorIO's display then adapts back), with 1.0 the display's peak for SDR (48 cd/m²
cinema, 100 cd/m² video) and 1.0 = 100 cd/m² for HDR. Both stop before the display
encoding: the CTL's final clamp to the display's RGB cube is the display's.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from types import MappingProxyType

import numpy as np

from generator.rendering.aces13_odt import SdrOdt, sdr_odt_forward, sdr_odt_inverse
from generator.rendering.aces13_rrt import rrt_sweeteners, rrt_sweeteners_inverse, rrt_tonescale, rrt_tonescale_inverse
from generator.rendering.aces13_spline import SegmentedSpline
from generator.rendering.aces13_ssts import HdrOdt, hdr_odt_forward, hdr_odt_inverse

#: DCI-P3's white (SMPTE RP 431-2), the encoding white of the DCI cinema ODTs.
DCI_WHITE = (0.314, 0.351)

STYLE_PREFIX = "ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - "


@dataclass(frozen=True)
class Preset13:
    """One ACES 1.3 output transform: the studio config's view name, OpenColorIO's builtin
    style, ``kind`` ("sdr" or "hdr"), the display's peak luminance (cd/m²), the CTL
    transforms it follows, and its ODT's parameters."""

    view: str
    style: str
    kind: str
    peak_luminance: float
    ctl: tuple[str, ...]
    odt: SdrOdt | HdrOdt

    @property
    def output_scale(self) -> float:
        """cd/m² of XYZ's Y = 1."""
        return self.peak_luminance if self.kind == "sdr" else 100.0


def _sdr(view: str, style: str, peak: float, ctl: tuple[str, ...], **odt) -> Preset13:
    return Preset13(view, STYLE_PREFIX + style, "sdr", peak, ctl, SdrOdt(**odt))


def _hdr(view: str, style: str, mid: float, peak: float, limiting: str, ctl: tuple[str, ...]) -> Preset13:
    return Preset13(view, STYLE_PREFIX + style, "hdr", peak, ctl, HdrOdt(0.0001, mid, peak, limiting))


_PRESETS = (
    _sdr(
        "ACES 1.0 - SDR Video",
        "SDR-VIDEO_1.0",
        100.0,
        ("ODT.Academy.Rec709_100nits_dim", "ODT.Academy.RGBmonitor_100nits_dim", "ODT.Academy.Rec2020_100nits_dim"),
        dim_surround=True,
    ),
    _sdr(
        "ACES 1.0 - SDR Video (D60 sim on D65)",
        "SDR-VIDEO-D60sim-D65_1.0",
        100.0,
        ("ODT.Academy.Rec709_D60sim_100nits_dim", "ODT.Academy.RGBmonitor_D60sim_100nits_dim"),
        dim_surround=True,
        white_scale=0.955,
        adapt_to_d65=False,
    ),
    _sdr(
        "ACES 1.1 - SDR Video (P3 lim)",
        "SDR-VIDEO-P3lim_1.1",
        100.0,
        ("ODT.Academy.Rec2020_P3D65limited_100nits_dim",),
        dim_surround=True,
        limiting="P3-D65",
    ),
    _sdr(
        "ACES 1.1 - SDR Video (Rec.709 lim)",
        "SDR-VIDEO-REC709lim_1.1",
        100.0,
        ("ODT.Academy.Rec2020_Rec709limited_100nits_dim",),
        dim_surround=True,
        limiting="Rec.709",
    ),
    _hdr(
        "ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim)",
        "HDR-VIDEO-1000nit-15nit-REC2020lim_1.1",
        15.0,
        1000.0,
        "Rec.2020",
        ("RRTODT.Academy.Rec2020_1000nits_15nits_ST2084", "RRTODT.Academy.Rec2020_1000nits_15nits_HLG"),
    ),
    _hdr(
        "ACES 1.1 - HDR Video (2000 nits & Rec.2020 lim)",
        "HDR-VIDEO-2000nit-15nit-REC2020lim_1.1",
        15.0,
        2000.0,
        "Rec.2020",
        ("RRTODT.Academy.Rec2020_2000nits_15nits_ST2084",),
    ),
    _hdr(
        "ACES 1.1 - HDR Video (4000 nits & Rec.2020 lim)",
        "HDR-VIDEO-4000nit-15nit-REC2020lim_1.1",
        15.0,
        4000.0,
        "Rec.2020",
        ("RRTODT.Academy.Rec2020_4000nits_15nits_ST2084",),
    ),
    _hdr(
        "ACES 1.1 - HDR Video (1000 nits & P3 lim)",
        "HDR-VIDEO-1000nit-15nit-P3lim_1.1",
        15.0,
        1000.0,
        "P3-D65",
        ("RRTODT.Academy.P3D65_1000nits_15nits_ST2084",),
    ),
    _hdr(
        "ACES 1.1 - HDR Video (2000 nits & P3 lim)",
        "HDR-VIDEO-2000nit-15nit-P3lim_1.1",
        15.0,
        2000.0,
        "P3-D65",
        ("RRTODT.Academy.P3D65_2000nits_15nits_ST2084",),
    ),
    _hdr(
        "ACES 1.1 - HDR Video (4000 nits & P3 lim)",
        "HDR-VIDEO-4000nit-15nit-P3lim_1.1",
        15.0,
        4000.0,
        "P3-D65",
        ("RRTODT.Academy.P3D65_4000nits_15nits_ST2084",),
    ),
    _sdr(
        "ACES 1.0 - SDR Cinema",
        "SDR-CINEMA_1.0",
        48.0,
        ("ODT.Academy.P3D60_48nits", "ODT.Academy.P3D65_48nits"),
        dim_surround=False,
    ),
    _sdr(
        "ACES 1.1 - SDR Cinema (Rec.709 lim)",
        "SDR-CINEMA-REC709lim_1.1",
        48.0,
        ("ODT.Academy.P3D65_Rec709limited_48nits",),
        dim_surround=False,
        limiting="Rec.709",
    ),
    _sdr(
        "ACES 1.0 - SDR Cinema (D60 sim on DCI)",
        "SDR-CINEMA-D60sim-DCI_1.0",
        48.0,
        ("ODT.Academy.P3DCI_D60sim_48nits",),
        dim_surround=False,
        white_scale=0.96,
        roll_white=0.918,
        adapt_to_d65=False,
        encoding_white=DCI_WHITE,
    ),
    _sdr(
        "ACES 1.1 - SDR Cinema (D60 sim on D65)",
        "SDR-CINEMA-D60sim-D65_1.1",
        48.0,
        ("ODT.Academy.P3D65_D60sim_48nits",),
        dim_surround=False,
        white_scale=0.964,
        adapt_to_d65=False,
    ),
    _sdr(
        "ACES 1.1 - SDR Cinema (D65 sim on DCI)",
        "SDR-CINEMA-D65sim-DCI_1.1",
        48.0,
        ("ODT.Academy.P3DCI_D65sim_48nits",),
        dim_surround=False,
        white_scale=0.9575,
        roll_white=0.908,
        encoding_white=DCI_WHITE,
    ),
    _hdr(
        "ACES 1.1 - HDR Cinema (108 nits & P3 lim)",
        "HDR-CINEMA-108nit-7.2nit-P3lim_1.1",
        7.2,
        108.0,
        "P3-D65",
        ("RRTODT.Academy.P3D65_108nits_7.2nits_ST2084",),
    ),
)

#: View name -> preset, read-only.
PRESETS13 = MappingProxyType({preset.view: preset for preset in _PRESETS})


def _preset(preset: str | Preset13) -> Preset13:
    if isinstance(preset, Preset13):
        return preset
    if preset not in PRESETS13:
        raise KeyError(f"unknown ACES 1.3 output transform {preset!r}; known: {', '.join(PRESETS13)}")
    return PRESETS13[preset]


@cache
def _spline(odt: HdrOdt) -> SegmentedSpline:
    return odt.spline


def finite_or_black(colours) -> np.ndarray:
    """Float64 colours (..., 3), those with a non-finite component replaced by black, as
    OpenColorIO's builtins render them (the CTL's arithmetic gives NaN)."""
    colours = np.asarray(colours, dtype=np.float64)
    return np.where(np.isfinite(colours).all(axis=-1, keepdims=True), colours, 0.0)


def forward13(aces, preset: str | Preset13) -> np.ndarray:
    """ACES2065-1 (..., 3) to display CIE XYZ through the preset's RRT and ODT; a colour with
    a non-finite component counts as black.

    Mid grey on 1000-nit HDR video: 15 cd/m² from the tone scale, shown as
    (15 - 0.0001) / (1000 - 0.0001) · 1000 once black is stretched to 0:

    >>> xyz = forward13([0.18, 0.18, 0.18], "ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim)")
    >>> round(float(xyz[1]) * 100.0, 5)
    14.9999
    """
    p, aces = _preset(preset), finite_or_black(aces)
    if isinstance(p.odt, HdrOdt):
        return hdr_odt_forward(rrt_sweeteners(aces), p.odt, _spline(p.odt))
    return sdr_odt_forward(rrt_tonescale(aces), p.odt)


def inverse13(xyz, preset: str | Preset13) -> np.ndarray:
    """Display CIE XYZ (..., 3), normalised as :func:`forward13` gives it, back to ACES2065-1
    through the CTL's inverse ODT and inverse RRT (see those modules for what they do not undo);
    a colour with a non-finite component counts as black."""
    p, xyz = _preset(preset), finite_or_black(xyz)
    if isinstance(p.odt, HdrOdt):
        return rrt_sweeteners_inverse(hdr_odt_inverse(xyz, p.odt, _spline(p.odt)))
    return rrt_tonescale_inverse(sdr_odt_inverse(xyz, p.odt))
