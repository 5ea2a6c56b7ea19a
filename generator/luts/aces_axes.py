"""Where a baked ACES view's lattice puts its nodes.

An ACES view clamps its input in AP1 before anything else (:func:`basis`): ACES 2.0 to [0, its
tone scale's forward limit]; ACES 1.3's RRT to [0, half float's largest value], after its glow
and red modifier, which act on ACES2065-1 (a lattice clamping AP1 first leaves them out for a
colour outside AP1). Nodes are uniform in ``log2(x + toe)`` of the clamped AP1 values
(:class:`ViewAxis`), so the tone scale's toe and shoulder get nodes alike, less dense above
the brightest colours measured; a source layout's axis is the same over decoded source values,
mirrored below 0 where the source's gamut is not AP1 (:class:`SourceLogAxis`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator import reference
from generator.colorimetry.matrices import settled
from generator.colorimetry.transfer import Linear
from generator.luts import numbers
from generator.luts.axes import LogAxis
from generator.luts.lattice import SHAPER_DECIMALS
from generator.luts.source_axes import code_range
from generator.rendering import views
from generator.spec.schema import ColourSpace, Display, Spec

#: The axis's toe in the basis's linear values: it is uniform in log2(x + toe) below where it
#: thins out (:data:`SDR_THINNING`), the toe moved a little so that 1.0 falls on an entry of the
#: display layout's 1D table (measured at 65³ with the fit, SDR Rec.709 on sRGB, p99 / max in
#: ten-bit codes: toe 2^-9: AP0 0..1 4.1 / 38, dark 0.9 / 8.0; 2^-7: 3.8 / 32, 1.0 / 8.8; 2^-5:
#: 3.6 / 27, 2.3 / 14).
ACES_TOE = 2.0**-7

#: Where the axis thins out, for SDR and for HDR views: above this basis value its nodes are this
#: many times as dense per stop as below, up to the view's clamp (1024 in SDR, 4096 at 1000
#: cd/m²); the tone scale's shoulder is smooth there. A third above 64 (the brightest probes)
#: halved the uniform axis's excess (SDR Rec.709, AP0 0..1 p99 5.7 to 6.5 ten-bit codes uniform,
#: 3.8 to 4.9 thinned). A fifth above 32 then lowered every probe set's p99 of the SDR views on
#: three draws (greys 0.45 to 0.39 codes, camera 17.8 to 16.2); in HDR it put 1000 cd/m² bright
#: colours at 2.57 ΔE ITP against 1.43. HDR views peaking below :data:`HDR_LOW_PEAK` thin to a
#: quarter: their worst set's p99 fell on three draws at 500 cd/m² (Rec.2020 camera 2.29 to 1.75,
#: P3 bright 1.77 to 1.48), where at 1000 cd/m² bright colours rose (1.43 to 1.90)
#: (bench/aces_views.py, docs/aces-views.md).
SDR_THINNING, HDR_THINNING, HDR_LOW_THINNING = (32.0, 0.2), (64.0, 1.0 / 3.0), (64.0, 0.25)

#: Peak luminance (cd/m²) from which an HDR view thins out as :data:`HDR_THINNING`.
HDR_LOW_PEAK = 1000.0


def thinning(view) -> tuple[float, float]:
    """(basis value, relative density above it) where ``view``'s axis thins out."""
    if not view.is_hdr:
        return SDR_THINNING
    return HDR_LOW_THINNING if view.peak < HDR_LOW_PEAK else HDR_THINNING


#: Entries of the display layout's 1D table from the Log operator's value to the lattice
#: coordinate (two straight pieces meeting on an entry: the table is exact).
ACES_BEND_ENTRIES = 1025

#: Largest share of a source layout's intervals below 0, where a source whose gamut is smaller
#: than AP1 holds the view's saturated colours (measured at 65³, Linear Rec.709 to sRGB, SDR
#: Rec.709, p99 / max in ten-bit codes, with :data:`LINEAR_FLOOR` at -1: AP0 0..1 14 / 64,
#: bright 513 / 705 (clamped); at -64, shares 0.15, 0.25, 0.35: AP0 0..1 33 / 83, 23 / 57, 19 /
#: 76; bright 72 / 238, 59 / 203, 55 / 207; in gamut 1.6 / 4.6, 1.4 / 3.4, 1.5 / 4.1).
ACES_NEGATIVE_SHARE = 0.25

#: Half float's largest value: where ACES 1.3's RRT clamps AP1.
HALF_MAX = 65504.0

#: A linear source's values below this are clamped (in a source layout, whose 1D table is
#: uniform in light): AP1's cube reaches -720 in Linear Rec.709, the brightest probes (64)
#: about -40.
LINEAR_FLOOR = -64.0

#: A grey renders as the view's brightest once its luminance is within this share of the
#: brightest's (above that level a grey's rendering is its clamp's to float64 rounding).
PEAK_REACHED = 1e-6


def linear_high(view) -> float:
    """How far a linear source's table reaches: twice the lowest power of two at which a grey of
    the view's basis renders as the grey at its clamp, up to the clamp. A table uniform in light
    steps by this over its entries; from ACEScg at 65³, capping the clamp's 1024 (SDR) and 4096
    (HDR 1000 nits) at 256 and 1024 lowered every probe set's p99, bright colours up to the
    clamp included (bench/lut_accuracy.py, docs/aces-views.md)."""
    b = basis(view)
    levels = np.append(2.0 ** np.arange(0, int(np.ceil(np.log2(b.upper))) + 1), b.upper)
    greys = np.repeat(levels[:, None], 3, axis=1) @ np.linalg.inv(b.from_aces).T
    light = views.evaluate(view, greys)[:, 1]
    reached = np.abs(light - light[-1]) <= PEAK_REACHED * light[-1]
    return float(min(b.upper, 2.0 * levels[int(np.argmax(reached))]))


@dataclass(frozen=True, eq=False)
class Basis:
    """The RGB a view clamps its input in: ``from_aces`` (ACES2065-1 to it), [0, ``upper``]."""

    name: str
    from_aces: np.ndarray
    upper: float


def basis(view) -> Basis:
    """Where ``view`` (an :class:`~generator.rendering.views.ACESView`) clamps its input."""
    if view.version == "2.0":
        t = views.tables(view)
        return Basis("AP1", t.ap0_to_ap1, float(t.tone.forward_limit))
    t = views.tables(views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"])
    return Basis("AP1", t.ap0_to_ap1, HALF_MAX)


def basis_matrix(spec: Spec, space: ColourSpace, view) -> np.ndarray:
    """Linear RGB of ``space`` to ``view``'s basis."""
    return basis(view).from_aces @ reference.to_aces_matrix(spec) @ reference.space_matrix(spec, space)


def _toe_for(upper: float, share: float) -> float:
    """The toe with 1.0 ``share`` of the way from 0 to ``upper`` in ``log2(x + toe)`` (bisection in log2(toe))."""
    low, high = -60.0, np.log2(upper)
    for _ in range(200):
        middle = (low + high) / 2.0
        toe = 2.0**middle
        if np.log2(1.0 / toe + 1.0) / np.log2(upper / toe + 1.0) > share:
            low = middle
        else:
            high = middle
    return float(2.0 ** ((low + high) / 2.0))


@dataclass(frozen=True)
class ViewAxis:
    """Lattice coordinate of values ``x`` from 0 to ``high``: two straight pieces in
    ``log2(x + toe)``, 0 to ``bend`` up to ``light``, ``bend`` to 1 above."""

    toe: float
    light: float
    high: float
    bend: float

    @classmethod
    def layout(cls, toe: float, high: float, light: float, density: float) -> ViewAxis:
        """``light`` at the share of the coordinate that ``density`` (nodes per stop above it, relative
        to below) gives it (all of it, when ``high`` is below ``light``)."""
        if high <= light:
            return cls(toe, high, high, 1.0)
        below, above = (np.log2((light + toe) / toe), np.log2((high + toe) / (light + toe)))
        return cls(toe, light, high, float(below / (below + density * above)))

    def _log(self, x) -> np.ndarray:
        return np.log2(np.asarray(x, dtype=np.float64) / self.toe + 1.0)

    def coordinate(self, x) -> np.ndarray:
        """Coordinate in [0, 1] of ``x`` (clamped to [0, ``high``])."""
        level = self._log(np.clip(np.asarray(x, dtype=np.float64), 0.0, self.high))
        light, high = float(self._log(self.light)), float(self._log(self.high))
        if self.bend >= 1.0:
            return level / high
        return np.where(
            level <= light, level / light * self.bend, self.bend + (level - light) / (high - light) * (1.0 - self.bend)
        )


def view_axes(view, toe: float = ACES_TOE) -> tuple[LogAxis, ViewAxis, np.ndarray]:
    """The display layout's Log operator (a :class:`~generator.luts.axes.LogAxis` from 0 to the
    view's clamp over :data:`ACES_BEND_ENTRIES` entries, 1.0 on one, toe near ``toe``),
    the :class:`ViewAxis` of the same toe thinning out (:func:`thinning`) on the entry nearest
    its level, and the 1D table between them (lattice coordinates at the entries, as written)."""
    light, density = thinning(view)
    upper, n = basis(view).upper, ACES_BEND_ENTRIES - 1
    share = np.log2(1.0 / toe + 1.0) / np.log2(upper / toe + 1.0)
    log = LogAxis(ACES_BEND_ENTRIES, round(share * n), _toe_for(upper, round(share * n) / n))
    wanted = ViewAxis.layout(log.toe, upper, light, density)
    light = float(log.position(np.round(log.coordinate(wanted.light) * n) / n))
    axis = ViewAxis.layout(log.toe, upper, light, density)
    return log, axis, numbers.rounded(axis.coordinate(log.position(np.linspace(0.0, 1.0, n + 1))), SHAPER_DECIMALS)


@dataclass(frozen=True)
class SourceLogAxis:
    """A source layout's axis over decoded source values ``x`` from ``low`` (<= 0) up: the
    :class:`ViewAxis` ``positive`` above 0, mirrored ``log2(-x / toe + 1)`` below, 0 on node ``zero``."""

    size: int
    zero: int
    low: float
    positive: ViewAxis

    @classmethod
    def layout(
        cls, size: int, low: float, high: float, thin: tuple[float, float], toe: float = ACES_TOE
    ) -> SourceLogAxis:
        """Nodes below 0 in proportion to the bits of the mirrored log there (none when ``low`` is
        0); above 0 the :class:`ViewAxis` thinning out as ``thin`` (:func:`thinning`) says."""
        positive = ViewAxis.layout(toe, high, *thin)
        bits_below, bits_above = (np.log2(max(-low, 0.0) / toe + 1.0), np.log2(high / toe + 1.0))
        share = min(bits_below / (bits_below + bits_above), ACES_NEGATIVE_SHARE)
        zero = 0 if low >= 0.0 else int(np.clip(round(share * (size - 1)), 1, size - 3))
        return cls(size, zero, min(low, 0.0), positive)

    def coordinate(self, x) -> np.ndarray:
        """Lattice coordinate in [0, 1] of decoded source values ``x`` (clamped to the axis)."""
        x = np.clip(np.asarray(x, dtype=np.float64), self.low, self.positive.high)
        n, zero, toe = self.size - 1, self.zero, self.positive.toe
        above = zero + (n - zero) * self.positive.coordinate(x)
        if not zero:
            return above / n
        below = zero * (1.0 - np.log2(np.maximum(-x, 0.0) / toe + 1.0) / np.log2(-self.low / toe + 1.0))
        return np.where(x >= 0.0, above, below) / n


def source_range(spec: Spec, source: ColourSpace, display: Display, view) -> tuple[float, float]:
    """Decoded source values the source layout covers: those of the view's basis cube, within the
    source's code range (a linear source's from :data:`LINEAR_FLOOR` to :func:`linear_high`); 0
    from below where the source's gamut is the basis (its lower faces are the view's clamp)."""
    corners = np.indices((2, 2, 2)).reshape(3, -1).T * basis(view).upper
    linear = corners @ np.linalg.inv(settled(basis_matrix(spec, source, view))).T
    low, high = float(linear.min()), float(linear.max())
    low = 0.0 if low > -1e-9 * high else low
    if isinstance(source.curve, Linear):
        return max(low, LINEAR_FLOOR), min(high, linear_high(view))
    code_low, code_high, capped = code_range(source, display)
    with np.errstate(all="ignore"):
        floor, top = (float(v) for v in source.curve.decode(np.array([code_low, code_high])))
    return max(low, floor), (min(high, top) if capped else high)


def same_basis(spec: Spec, source: ColourSpace, view) -> bool:
    """Whether ``source``'s linear RGB is ``view``'s basis (the matrix is the identity as written):
    its domain's clamp is then the view's own."""
    return bool(np.array_equal(settled(basis_matrix(spec, source, view)), np.eye(3)))
