"""The ACES views a config offers: the studio config's names, each with its output transform.

A view is one of the ACES studio configs' view transforms, named as there (ACES 2.0 from
``studio-config-v5.0.0``, ACES 1.3 from ``studio-config-v2.2.0``), or a custom display's own
ACES 2.0 view, whose peak luminance, primaries and white are the algorithm's parameters.
Every view ends in CIE XYZ of the display's light (:func:`evaluate`), as the studio
configs' view transforms do; the display then encodes.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import cast

import numpy as np

from generator.colorimetry.curves import HALF_MAX
from generator.rendering import aces2, aces13
from generator.rendering.aces2_params import XY, ACES2Params, Triangle
from generator.rendering.aces2_presets import D65, P3, PRESETS, REC709, REC2020

#: The studio configs' view with the meaning of our Colorimetric view (scene light to XYZ).
UNTONEMAPPED = "Un-tone-mapped"

#: Asked for in a display's views: the display's own ACES 2.0 view (a library display's
#: studio view, a custom display's from its own peak, primaries and white).
OWN_ACES2 = "ACES 2.0"


@dataclass(frozen=True)
class ACESView:
    """An ACES view: its name, ACES version ("2.0" or "1.3"), OCIO builtin style ("" for a
    custom display's own view), peak luminance (cd/m²: as named; the cinema presets render at
    a higher peak, scaled), limiting primaries and white (xy)."""

    name: str
    version: str
    style: str
    peak: float
    limiting: tuple[tuple[float, float], ...]
    white: tuple[float, float]
    params: ACES2Params | None = None

    @property
    def render_peak(self) -> float:
        """An ACES 2.0 view's rendering peak (cd/m²), its limiting RGB's largest value times 100."""
        if self.params is None:
            raise ValueError(f"{self.name!r} is an ACES {self.version} view, without ACES 2.0 parameters")
        return float(self.params.peak_luminance)

    @property
    def is_hdr(self) -> bool:
        """Whether the view's peak is above 100 cd/m²."""
        return self.peak > 100.0 + 1e-9


#: ACES 1.3 limiting gamuts by the name their builtins' styles give (xy, then white).
_LIMITS13 = {"REC709": REC709, "P3": P3, "REC2020": REC2020}


def _limit13(preset) -> tuple[tuple[tuple[float, float], ...], tuple[float, float]]:
    """An ACES 1.3 view's limiting gamut as its style names it (Rec.709 for plain SDR video,
    P3 for plain SDR cinema), with D65 white."""
    style = preset.style.rsplit(" - ", 1)[-1]
    for key in ("REC2020", "REC709", "P3"):
        if f"{key}lim" in style:
            return _LIMITS13[key], D65
    return _LIMITS13["P3" if "CINEMA" in style else "REC709"], D65


@lru_cache(maxsize=1)
def catalogue() -> dict[str, ACESView]:
    """Every studio ACES view by name: the ACES 2.0 presets, then ACES 1.3's."""
    out = {}
    for name, preset in PRESETS.items():
        p = preset.params
        out[name] = ACESView(
            name,
            "2.0",
            preset.style,
            float(p.peak_luminance * p.linear_scale),
            p.limiting_primaries,
            p.limiting_white,
            p,
        )
    for name, preset13 in aces13.PRESETS13.items():
        limiting, white = _limit13(preset13)
        out[name] = ACESView(name, "1.3", preset13.style, float(preset13.peak_luminance), limiting, white)
    return out


def own_view(display_name: str, peak: float, primaries, white) -> ACESView:
    """A custom display's own ACES 2.0 view: its peak, primaries and white as the parameters
    (ValueError, naming the parameter, where the algorithm cannot take them)."""
    params = ACES2Params(  # it checks the shapes and stores tuples of floats
        float(peak),
        cast(Triangle, tuple(map(tuple, np.asarray(primaries, dtype=float).tolist()))),
        cast(XY, tuple(np.asarray(white, dtype=float).tolist())),
    )
    kind = "HDR" if peak > 100.0 else "SDR"
    return ACESView(
        f"ACES 2.0 - {kind} {peak:g} nits ({display_name})",
        "2.0",
        "",
        float(peak),
        params.limiting_primaries,
        params.limiting_white,
        params,
    )


@lru_cache(maxsize=64)
def _tables(params: ACES2Params):
    return aces2.tables(params)


def evaluate(view: ACESView, aces) -> np.ndarray:
    """ACES2065-1 (..., 3) through ``view`` to CIE XYZ of the display (1.0 = 100 cd/m², or an
    SDR view's display peak, as the studio configs' view transforms end). Infinite channels
    are taken as half float's largest; a colour with a NaN channel gives NaN."""
    aces = np.asarray(aces, dtype=np.float64)
    nan = np.isnan(aces).any(axis=-1)
    finite = np.nan_to_num(aces, nan=0.0, posinf=HALF_MAX, neginf=-HALF_MAX)
    if view.version == "2.0":
        out = aces2.forward(finite, _tables(view.params))
    else:
        out = np.asarray(aces13.forward13(finite, aces13.PRESETS13[view.name]), dtype=np.float64)
    out[nan] = np.nan
    return out


def output_rgb(view: ACESView, aces) -> np.ndarray:
    """An ACES 2.0 view's rendering before its clamps (limiting RGB, 1.0 = 100 cd/m²):
    what a lattice samples."""
    return aces2.output_rgb(aces, _tables(view.params))


def tables(view: ACESView):
    """The ACES 2.0 tables of ``view`` (computed once per process)."""
    return _tables(view.params)


#: The ACES views of each library display, in the order the studio configs give them (ACES
#: 2.0 from v5.0.0, ACES 1.3 from v2.2.0; a display v2.2.0 lacks has no 1.3 view). A view
#: whose peak passes the display's (ours clip there: 1000 cd/m² on the PQ displays) is left
#: out; a custom display with that peak takes it.
STUDIO_VIEWS: dict[str, tuple[str, ...]] = {
    "sRGB - Display": (
        "ACES 2.0 - SDR 100 nits (Rec.709)",
        "ACES 1.0 - SDR Video",
        "ACES 1.0 - SDR Video (D60 sim on D65)",
    ),
    "Gamma 2.2 Rec.709 - Display": ("ACES 2.0 - SDR 100 nits (Rec.709)",),
    "Rec.1886 Rec.709 - Display": (
        "ACES 2.0 - SDR 100 nits (Rec.709)",
        "ACES 1.0 - SDR Video",
        "ACES 1.0 - SDR Video (D60 sim on D65)",
    ),
    "Display P3 - Display": (
        "ACES 2.0 - SDR 100 nits (P3 D65)",
        "ACES 1.0 - SDR Video",
        "ACES 1.0 - SDR Video (D60 sim on D65)",
    ),
    "Display P3 HDR - Display": ("ACES 2.0 - HDR 1000 nits (P3 D65)", "ACES 2.0 - SDR 100 nits (Rec.709)"),
    "Gamma 2.6 P3-D65 - Display": (
        "ACES 2.0 - SDR 100 nits (P3 D65)",
        "ACES 2.0 - SDR 100 nits (Rec.709)",
        "ACES 1.0 - SDR Cinema",
        "ACES 1.1 - SDR Cinema (D60 sim on D65)",
        "ACES 1.1 - SDR Cinema (Rec.709 lim)",
    ),
    "Gamma 2.6 DCI-P3 - Display": ("ACES 1.0 - SDR Cinema (D60 sim on DCI)", "ACES 1.1 - SDR Cinema (D65 sim on DCI)"),
    "Rec.2100-PQ - Display": (
        "ACES 2.0 - HDR 1000 nits (P3 D65)",
        "ACES 2.0 - HDR 1000 nits (Rec.2020)",
        "ACES 2.0 - HDR 500 nits (P3 D65)",
        "ACES 2.0 - HDR 500 nits (Rec.2020)",
        "ACES 2.0 - SDR 100 nits (Rec.709)",
        "ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim)",
    ),
    "Rec.2100-HLG - Display": ("ACES 2.0 - HDR 1000 nits (P3 D65)", "ACES 1.1 - HDR Video (1000 nits & Rec.2020 lim)"),
    "ST2084-P3-D65 - Display": (
        "ACES 2.0 - HDR 1000 nits (P3 D65)",
        "ACES 2.0 - HDR 500 nits (P3 D65)",
        "ACES 2.0 - HDR 108 nits (P3 D65)",
        "ACES 2.0 - SDR 100 nits (Rec.709)",
        "ACES 1.1 - HDR Video (1000 nits & P3 lim)",
        "ACES 1.1 - HDR Cinema (108 nits & P3 lim)",
    ),
}


def _inside(xy, primaries, slack: float) -> bool:
    """Whether chromaticity ``xy`` lies inside the triangle ``primaries``, within ``slack``."""
    p = np.asarray(primaries, dtype=float)
    for i in range(3):
        a, b, c = p[i], p[(i + 1) % 3], p[(i + 2) % 3]
        edge = b - a
        normal = np.array([-edge[1], edge[0]]) / np.hypot(*edge)
        side = np.sign(np.dot(normal, c - a))
        if side * np.dot(normal, np.asarray(xy) - a) < -slack:
            return False
    return True


#: How far outside a display's triangle a view's limiting primary may lie (xy distance): P3's
#: red lies 0.0012 outside BT.2020's, and the studio configs show P3-limited views on Rec.2100.
LIMIT_SLACK_XY = 2e-3


def cannot_show(view: ACESView, display_primaries, display_peak: float, display_hdr: bool) -> str:
    """Why a display (its primaries, peak in cd/m², HDR or not) cannot show ``view``, or ""."""
    if view.is_hdr and not display_hdr:
        return f"it is an HDR view ({view.peak:g} cd/m²) and the display is SDR"
    if view.is_hdr and view.peak > display_peak + 1e-9:
        return f"its peak, {view.peak:g} cd/m², passes the display's, {display_peak:g}"
    outside = [
        c
        for c, xy in zip(("red", "green", "blue"), view.limiting)
        if not _inside(xy, display_primaries, LIMIT_SLACK_XY)
    ]
    if outside:
        return f"its limiting {' and '.join(outside)} primar{'ies lie' if len(outside) > 1 else 'y lies'} outside the display's gamut"
    return ""


def resolve(name: str, display_name: str, peak: float, primaries, white) -> ACESView | None:
    """The ACES view called ``name`` on a display (its name, peak in cd/m², primaries and
    white): a studio view, or the display's own ACES 2.0 view; None for any other name."""
    known = catalogue().get(name)
    if known is not None:
        return known
    if name.startswith(OWN_ACES2 + " - ") and name.endswith(f"({display_name})"):
        try:
            own = own_view(display_name, peak, primaries, white)
        except ValueError:
            return None
        return own if own.name == name else None
    return None


def is_aces_name(name: str) -> bool:
    """Whether ``name`` may name an ACES view (a studio view, or a display's own)."""
    return name in catalogue() or name == OWN_ACES2 or name.startswith(OWN_ACES2 + " - ")
