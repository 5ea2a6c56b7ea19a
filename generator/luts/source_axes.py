"""Where a source-layout lattice (.cube, .spi3d) puts its nodes.

:class:`SourceAxis`: nodes uniform in a power of the display's code values up
to the peak (a few shrinking geometrically toward black), in a root of ``x``
above it, linearly below 0, where ``x`` is display-linear RGB divided by the
display's peak. Between two nodes the coordinate is linear in the display's
code value (in ``log x`` above the peak), so greys, which tetrahedral
interpolation takes from the diagonal nodes alone, are exact up to the shaper
table, which is uniform in source values: :func:`source_axis` puts 0, the peak
and every node on its entries (:func:`source_domain`, :func:`_entries`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator import reference
from generator.colorimetry.transfer import Linear
from generator.luts.axes import grey_code, grey_linear
from generator.spec.schema import ColourSpace, Display, Spec

#: Fraction of a :class:`SourceAxis` lattice's intervals above the peak when the source
#: reaches :data:`SOURCE_ABOVE_RANGE` times it, in proportion to ``log(high)`` below that
#: (measured at 33³ on the bench's pairs: 14 of 32 intervals balance in-gamut against
#: over-range colours).
SOURCE_ABOVE_SHARE = 0.45

#: Multiple of the peak for which :data:`SOURCE_ABOVE_SHARE` is measured.
SOURCE_ABOVE_RANGE = 16.0

#: (The SourceAxis figures below were measured with the fit of :mod:`generator.luts.fit` at 65536
#: colours per set and three reweighted passes; its defaults since are within a few percent.)
#: :class:`SourceAxis` nodes above the peak are uniform in ``x ** (1 / root)``, the brightest cells
#: smaller than in a logarithmic spacing: a clipping plane's error grows with a cell's size in
#: light (measured at 33³, clip, over-range p99 in ten-bit codes, logarithmic and sixth root: ARRI
#: LogC4 to Rec.1886 159 and 143, at a cost to ACEScg to sRGB, 82 and 96).
SOURCE_ABOVE_ROOT = 6.0

#: :class:`SourceAxis` nodes from the toe to the peak are uniform in this power of code values:
#: clipping planes cross the cells of bright saturated colours, which code values alone make large
#: (measured at 33³, clip, out-of-gamut p99 in ten-bit codes, powers 1 and 1.25: ACEScg to sRGB
#: 67.5 and 61.1, ARRI LogC4 to Rec.1886 95.3 and 87.2; its dark p99 9.1 and 10.4).
SOURCE_CODE_POWER = 1.25

#: Source axes: range of linear sources and the top of encoded ones, in units of the
#: display's peak (for SDR, display white; the over-range probes reach 16).
SOURCE_RANGE = (-1.0, 16.0)

#: Source axes: entries of the 1D shaper table, for encoded and for linear sources. A linear
#: source's table is uniform in linear light, 1e-3 of the peak apart at 16384 entries, coarse near
#: black (measured at 33³, ACEScg to Rec.2100-PQ, ΔE ITP p99: dark colours 21.3, greys from 1e-4 to
#: 16 times white 20.7; 15.4 and 12.2 at 65536, Resolve's limit, which would add 1.3 MB to each
#: file and 16 MB to the standalone pack).
SOURCE_SHAPER_SIZES = (4096, 16384)

#: Nodes of a :class:`SourceAxis` next to black, each :data:`SOURCE_TOE_RATIO` times the next, the
#: last that ratio below the first node of a spacing uniform in code values: a display channel's
#: zero plane crosses the cells next to black, where code values are steepest, so dark colours need
#: cells that shrink with them (measured at 33³, clip, ACEScct to sRGB, dark p99: 27.3 ten-bit
#: codes without, 5.0 with one, 3.1 with two; in-gamut 26.9 and 29.0).
SOURCE_TOE_NODES = 2

#: Ratio of successive toe nodes of a :class:`SourceAxis`.
SOURCE_TOE_RATIO = 4.0

#: Fraction of a :class:`SourceAxis` lattice's intervals between 0 and the most negative
#: source value of the display's in-gamut colours when that reaches
#: :data:`SOURCE_NEGATIVE_RANGE` below 0, in proportion below that (measured at 33³, scale,
#: Linear Rec.709 to Gamma 2.6 P3-D65, which reaches 0.225, in-gamut p99: 155 ten-bit codes
#: with one interval below 0, 22 with 6 more; to Rec.2100-PQ, 21.2 and 8.2 ΔE ITP).
SOURCE_NEGATIVE_SHARE = 0.2

#: Reach below 0 (normalised source value) for which :data:`SOURCE_NEGATIVE_SHARE` is measured.
SOURCE_NEGATIVE_RANGE = 0.2


@dataclass(frozen=True, eq=False)
class SourceAxis:
    """Nodes of a source-layout axis (normalised display-linear values of the decoded
    source, increasing), and the nodes of 0 and of ``min(1, high)``."""

    display: Display
    values: np.ndarray
    zero: int
    one: int

    @classmethod
    def layout(cls, display: Display, size: int, low: float, high: float, reach: float = 0.0) -> SourceAxis:
        """One interval below 0 (when ``low < 0``), :data:`SOURCE_ABOVE_SHARE` of them
        above the peak (when ``high > 1``, uniform in ``x ** (1 / SOURCE_ABOVE_ROOT)``),
        the rest uniform in the :data:`SOURCE_CODE_POWER` power of code values between
        but for :data:`SOURCE_TOE_NODES` next to black. ``reach`` (>= 0) is how far
        below 0 the display's in-gamut colours go in the source: then
        :data:`SOURCE_NEGATIVE_SHARE` of the intervals span [-reach, 0], spaced in
        code values mirrored."""
        n = size - 1
        reach = min(reach, -low) if low < 0 else 0.0
        mirrored = round(n * SOURCE_NEGATIVE_SHARE * min(1.0, reach / SOURCE_NEGATIVE_RANGE))
        below = (1 if low < 0 else 0) + mirrored - (1 if reach == -low and mirrored else 0)
        spread = min(1.0, np.log(max(high, 1.0)) / np.log(SOURCE_ABOVE_RANGE))
        above = 0 if high <= 1 else max(1, round(n * SOURCE_ABOVE_SHARE * spread))
        inside = n - below - above
        toe = SOURCE_TOE_NODES if inside > 2 * SOURCE_TOE_NODES else 0
        if inside < 1:
            raise ValueError(f"a lattice of {size} nodes is too small for this axis")
        top = min(high, 1.0)
        steps, code = np.linspace(0.0, 1.0, inside - toe + 1), grey_code(display, top)
        cube = grey_linear(display, steps ** (1.0 / SOURCE_CODE_POWER) * code)
        cube[-1] = top
        dark = grey_linear(display, steps[1] * code) * SOURCE_TOE_RATIO ** -np.arange(toe, 0, -1, dtype=np.float64)
        root = np.linspace(1.0, high ** (1.0 / SOURCE_ABOVE_ROOT), above + 1)[1:]
        over = root**SOURCE_ABOVE_ROOT if above else np.zeros(0)
        negative = -grey_linear(display, np.linspace(1.0, 0.0, mirrored + 1)[:-1] * grey_code(display, reach))
        start = [low] if below > mirrored else []
        values = np.concatenate([start, negative, [0.0], dark, cube[1:], over])
        return cls(display, values, below, below + inside)

    @property
    def size(self) -> int:
        """Nodes along the axis."""
        return self.values.size

    def coordinate(self, x) -> np.ndarray:
        """Lattice coordinate in [0, 1]: between two nodes, linear in the display's code
        value inside [0, 1], in ``log x`` above 1, in ``x`` below 0."""
        nodes = self.values
        x = np.clip(np.asarray(x, dtype=np.float64), nodes[0], nodes[-1])
        k = np.clip(np.searchsorted(nodes, x, side="right") - 1, 0, nodes.size - 2)
        a, b = nodes[k], nodes[k + 1]
        with np.errstate(divide="ignore", invalid="ignore"):
            code = [grey_code(self.display, np.clip(v, 0.0, 1.0)) for v in (x, a, b)]
            inside = (code[0] - code[1]) / (code[2] - code[1])
            above = np.log(np.maximum(x, 1.0) / np.maximum(a, 1.0)) / np.log(np.maximum(b, 1.0) / np.maximum(a, 1.0))
            below = (x - a) / (b - a)
        fraction = np.where(k >= self.one, above, np.where(k < self.zero, below, inside))
        return (k + np.clip(np.nan_to_num(fraction), 0.0, 1.0)) / (nodes.size - 1)


def code_range(source: ColourSpace, display: Display) -> tuple[float, float, bool]:
    """Codes of the source layout before alignment, and whether the top is the curve's own."""
    if isinstance(source.curve, Linear):
        return SOURCE_RANGE[0] * display.clip_high, SOURCE_RANGE[1] * display.clip_high, False
    low, high = (float(v) for v in getattr(source.curve, "domain", (0.0, 1.0)))
    with np.errstate(all="ignore"):
        top = float(source.curve.encode(np.array(SOURCE_RANGE[1] * display.clip_high)))
    capped = not (np.isfinite(top) and low < top < high)
    return low, (high if capped else top), capped


def shaper_domain(source: ColourSpace, shaper: ColourSpace, display: Display) -> tuple[float, float]:
    """Input range of a lattice spaced by a named shaper space: the source values of the light
    that space encodes from code 0 to code 1 (as ociobakelut's shaper space), within the
    source's own codes (the curve's domain below, a tabulated curve's top)."""
    low, high, capped = code_range(source, display)
    with np.errstate(all="ignore"):
        lo, hi = (float(v) for v in source.curve.encode(shaper.curve.decode(np.array([0.0, 1.0]))))
    if not isinstance(source.curve, Linear):
        lo = max(lo, low)
    if capped:
        hi = min(hi, high)
    return (lo, hi) if np.isfinite(lo) and np.isfinite(hi) and lo < hi else (low, high)


def source_domain(source: ColourSpace, display: Display) -> tuple[float, float]:
    """Input range of a source layout: for linear sources about ``SOURCE_RANGE[0]`` times
    the display's peak, for encoded ones the bottom of their code range, up to at least
    the code of ``SOURCE_RANGE[1]`` times the peak (at least 16 times display white) or
    the top of their code range. The ends are moved by less than a step of the shaper
    table so that the codes of 0 and of the peak fall on its entries."""
    count = SOURCE_SHAPER_SIZES[isinstance(source.curve, Linear)]
    low, high, capped = code_range(source, display)
    with np.errstate(all="ignore"):
        zero, one = (float(v) for v in source.curve.encode(np.array([0.0, display.clip_high])))
    step = (high - low) / (count - 1)
    zero = max(zero, low) if zero > low - 1e-3 * step else zero  # a curve's black a rounding below its domain
    if not np.isfinite(zero) or not low <= zero < high:
        return low, high
    aligned = np.isfinite(one) and zero < one < high and one - zero >= step
    parts = (np.ceil if capped else np.floor)((one - zero) / step) if aligned else 0.0
    while True:
        step = (one - zero) / parts if aligned else step
        start = zero - np.floor((zero - low) / step) * step
        if not capped or start + (count - 1) * step <= high:  # never past the curve's own domain
            return float(start), float(start + (count - 1) * step)
        parts, step = parts + 1.0, step * (1.0 - 1.0 / count)


def _entries(position: np.ndarray, zero: int, count: int) -> np.ndarray:
    """Table entries (fractional) for nodes at fractional entry ``position``: the nodes
    closer to 0 than one step spread evenly over the step above 0 (the table is
    linear there, so they stay nodes of a single segment), the others on the nearest
    entries, strictly increasing on either side of 0."""
    entry = np.clip(np.rint(position), 0.0, count - 1.0)
    dense = zero + 1
    while dense < position.size and position[dense] - position[zero] < 1.0:
        dense += 1
    if dense > zero + 1:
        entry[zero + 1 : dense] = position[zero] + np.arange(1, dense - zero) / (dense - zero - 1)
    rank = np.arange(position.size - dense)
    rest = np.maximum(entry[dense:], entry[dense - 1] + 1.0)
    entry[dense:] = np.maximum.accumulate(rest - rank) + rank
    gap = zero - np.arange(zero + 1)  # below 0: each node at least one entry below the next
    entry[: zero + 1] = np.minimum.accumulate((entry[: zero + 1] + gap)[::-1])[::-1] - gap
    return np.clip(entry, np.arange(position.size), count - 1.0 - np.arange(position.size)[::-1])


def display_reach(spec: Spec, source: ColourSpace, display: Display) -> float:
    """How far below 0 the display's in-gamut colours go in the source's linear values
    (normalised by the display's peak): 0 when the source's gamut holds the display's."""
    to_display = reference.scene_to_display_matrix(spec, display) @ reference.space_matrix(spec, source)
    corners = np.indices((2, 2, 2)).reshape(3, -1).T.astype(np.float64)
    return float(max(0.0, -(corners @ np.linalg.inv(to_display).T).min()))


def source_axis(spec: Spec, source: ColourSpace, display: Display, size: int) -> SourceAxis:
    """The source layout's axis over the decoded source domain, its nodes moved to
    entries of the shaper table (0 and the peak are entries already, see
    :func:`_entries`): a cell of the lattice then spans whole steps of the table, or
    lies within one, and the coordinate is linear in code values across it."""
    lo, hi = source_domain(source, display)
    count = SOURCE_SHAPER_SIZES[isinstance(source.curve, Linear)]
    with np.errstate(all="ignore"):
        low, high = (float(v) / display.clip_high for v in source.curve.decode(np.array([lo, hi])))
        axis = SourceAxis.layout(display, size, low, high, display_reach(spec, source, display))
        position = (source.curve.encode(axis.values * display.clip_high) - lo) / (hi - lo) * (count - 1)
    entry = _entries(position, axis.zero, count)
    with np.errstate(all="ignore"):
        values = source.curve.decode(lo + entry * (hi - lo) / (count - 1)) / display.clip_high
    values[axis.zero] = 0.0
    values[axis.one] = axis.values[axis.one]
    return SourceAxis(display, values, axis.zero, axis.one)
