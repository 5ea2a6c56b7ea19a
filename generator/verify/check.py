"""One check: the record an engine runs and the verifier judges, and how each output kind is judged.

:mod:`generator.verify.checks` (spaces, views) and :mod:`generator.verify.lut_checks` (LUT
files) build checks from these; engines run them and :mod:`generator.verify.judge` judges them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from generator import reference, tolerances
from generator.luts.curve1d import bake_curve
from generator.spec.schema import Display
from generator.verify import paths
from generator.verify.probes import Probes

TO_REFERENCE, FROM_REFERENCE, VIEW, LUT = "to reference", "from reference", "view", "LUT file"
KINDS = (TO_REFERENCE, FROM_REFERENCE, VIEW, LUT)
#: Metrics: largest per-channel relative error; colour relative error (over the largest
#: component, the float32 limit after a matrix); ΔE ITP for HDR displays.
RELATIVE, COLOUR, ITP, CODES = "relative", "colour relative", "ΔE ITP", "10-bit codes"


@dataclass(frozen=True, eq=False)
class Check:
    """One conversion an engine runs and the verifier judges.

    ``expected`` is None when the reference evaluation has nothing for the item
    (``problem`` says why): such a check fails. ``scale`` divides the colour
    error (a baked curve's error grows by its matrix's largest row sum); ``keep``
    marks the samples compared (a discontinuity band is left out);
    ``allowance`` is the float32 limit (:mod:`generator.verify.allowance`), an absolute
    difference per sample and channel taken off before the metric; ``encode``, a
    float64 function the engine's output goes through first (a view file ending in
    display light is encoded as its display space does).
    """

    kind: str
    item: str
    src: str
    dst: str = ""
    display: str = ""
    view: str = ""
    lut: str = ""
    interpolation: str = "linear"
    probes: Probes = field(default_factory=lambda: Probes(()), repr=False)
    expected: np.ndarray | None = field(default=None, repr=False)
    output: str = paths.CODE
    metric: str = RELATIVE
    tolerance: float = tolerances.ANALYTIC_RELATIVE
    target: Display | None = field(default=None, repr=False)
    scale: float = 1.0
    keep: np.ndarray | None = field(default=None, repr=False)
    allowance: np.ndarray | None = field(default=None, repr=False)
    problem: str = ""
    encode: paths.Evaluate | None = field(default=None, repr=False)

    @property
    def title(self) -> str:
        """The check's name in tables and for ``--only``."""
        if self.kind == VIEW:
            return f"{self.display} / {self.view} from {self.src}"
        if self.kind == LUT:
            return self.lut
        return f"{self.src} -> {self.dst}"


def evaluate(fn, values: np.ndarray) -> np.ndarray:
    """``fn(values)`` as float64, floating-point warnings silenced (NaN marks what is undefined)."""
    with np.errstate(all="ignore"):
        return np.asarray(fn(values), dtype=np.float64)


@lru_cache(maxsize=64)
def baked_lut(name: str, curve):
    """The LUT the build writes for ``curve`` (deterministic: the bake is re-run from the spec)."""
    return bake_curve(name, curve, curve.domain)


def discontinuity_band(end: paths.Endpoint | None, codes: np.ndarray, curve=None) -> np.ndarray | None:
    """Samples away from a baked curve's published discontinuities (None: keep all); the curve
    is ``end``'s when it is baked, else ``curve``."""
    curve = curve if end is None else end.curve if end.baked else None
    jumps = getattr(curve, "discontinuities", ())
    if not jumps:
        return None
    keep = np.ones(len(codes), dtype=bool)
    for jump in jumps:
        keep &= np.all(np.abs(codes - jump) > tolerances.DISCONTINUITY_BAND, axis=-1)
    return keep


def view_lut_tolerance(display: Display) -> float:
    """The bound for a config's baked view LUT: the LUT issue's in-gamut target on every probe
    set, in 10-bit codes (ΔE ITP for HDR displays). Its views are exact lattices but for float32,
    which each sample's allowance carries; a code, the issue's every-set bound, let a file scaled
    by 0.9991 pass."""
    return tolerances.LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP if display.is_hdr else tolerances.LUT_CLF_IN_GAMUT_CODES


def judging(
    out: paths.Endpoint | None, display: Display | None, baked_src: paths.Endpoint | None, view: str = ""
) -> dict:
    """Metric, tolerance, scale and target (Check fields) for an output kind (a baked source, a view)."""
    method = paths.view_method(view) if view else None
    if view and paths.is_aces13(view):
        display = _shown(display, view)
        # OCIO's ACES 1.x builtins depart from the CTL (black's offset, the red modifier's
        # saturation, rescaled tone-curve slopes): held to what was measured against them.
        return dict(
            metric=ITP if display.is_hdr else CODES,
            target=display,
            tolerance=tolerances.ACES13_OCIO_RED_DARK_DELTA_E_ITP if display.is_hdr else tolerances.ACES13_OCIO_CODES,
        )
    if method is not None and method not in paths.ANALYTIC_METHODS:
        display = _shown(display, view)
        return dict(metric=ITP if display.is_hdr else CODES, tolerance=view_lut_tolerance(display), target=display)
    if (
        baked_src is not None
        and baked_src.baked
        and baked_src.matrix is not None
        and (out is None or out.output == paths.LINEAR)
    ):
        gain = float(np.abs(baked_src.matrix).sum(1).max())
        return dict(metric=COLOUR, tolerance=tolerances.BAKED_CURVE_RELATIVE, scale=gain)
    if display is not None and display.is_hdr:
        return dict(metric=ITP, tolerance=tolerances.ANALYTIC_DELTA_E_ITP, target=display)
    if out is not None and out.output == paths.LINEAR:
        return dict(metric=COLOUR)
    tolerance = tolerances.BAKED_CURVE_RELATIVE if out is not None and out.baked else tolerances.ANALYTIC_RELATIVE
    return dict(metric=RELATIVE, tolerance=tolerance, target=display)


def _shown(display: Display | None, view: str) -> Display:
    """The display a view is judged on; ValueError without one."""
    if display is None:
        raise ValueError(f"the view {view!r} is judged on a display, and none was given")
    return display


@lru_cache(maxsize=32)
def display_code_limit(display: Display) -> float:
    """The largest code value ``display`` is sent: the largest over the corners of its
    light cube [0, peak]^3 (HLG's inverse OOTF lifts a saturated peak above the white's code)."""
    corners = np.array(np.meshgrid([0.0, 1.0], [0.0, 1.0], [0.0, 1.0])).reshape(3, -1).T * display.clip_high
    with np.errstate(all="ignore"):
        return float(np.nanmax(reference.display_encode(display, corners[1:])))
