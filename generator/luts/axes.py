"""Where a lattice puts its nodes along each axis, in three layouts.

Here ``x`` is display-linear RGB divided by the display's peak
(``Display.clip_high``), so the display's cube is [0, 1] for SDR and HDR alike.

* :class:`LogAxis` (display axes; clip and scale): the coordinate is
  ``log2(x + toe)``, uniform, with 0 and 1 on nodes, and the lattice holds the
  same coordinate of the mapped colour (a 1D table after the lattice turns it
  into code values). Clip is then ``min(v, v(1))`` per channel and scale
  ``v_i - max(0, max_j v_j - v(1))``, up to the toe: both are linear inside
  every tetrahedron, because the planes where the largest channel changes
  (``v_i = v_j``) are the simplex faces when all axes share their nodes, and
  ``v = v(1)`` is a node plane. Tetrahedral interpolation reproduces them
  exactly; only the toe (values near ``toe``) and float rounding are left.
  HLG's inverse EOTF is not per channel (its OOTF scales by luminance), so the
  lattice's output is the coordinate of the grey with the same code
  (:func:`grey_linear`): exact for greys, smooth elsewhere because the
  luminance factor is smooth in log coordinates.
* :class:`Axis` (display axes; desaturate, rgc, perceptual): the display's code
  values of display-linear RGB (:func:`grey_code`) between 0 and the peak (or,
  for a config view ending in display light, the pre-shaper's curve, which an
  Exponent operator undoes exactly),
  linear in ``log(x)`` above it and in ``e / (e + knee)`` with
  ``e = |x| ** (1 / 2.4)`` below 0, which these methods need (they mix negative
  channels into the others).
* :class:`SourceAxis` (source axes: .cube, .spi3d): nodes uniform in a power of
  the display's code values up to the peak (a few shrinking geometrically toward
  black), in a root of ``x`` above it, linearly below 0; between two nodes the
  coordinate is linear in the display's code value (in ``log x`` above the
  peak), so greys, which tetrahedral interpolation takes from the diagonal
  nodes alone, are exact up to the shaper table, which is uniform in source
  values: :func:`source_axis` puts 0, the peak and every node on its entries
  (:func:`source_domain`, :func:`_entries`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.colorimetry import reference
from generator.colorimetry.transfer import Linear
from generator.spec.schema import ColourSpace, Display, Spec

#: Exponent of the negative extension of :class:`Axis` (``e = |x| ** (1 / NEGATIVE_GAMMA)``).
NEGATIVE_GAMMA = 2.4

#: ``e`` at the middle of the negative intervals of :class:`Axis`.
NEGATIVE_KNEE = 0.4

#: Fractions of an :class:`Axis` lattice's intervals given to negative and to over-range values.
DEFAULT_SHARES = (0.375, 0.375)

#: Methods baked on a :class:`LogAxis`: their mapping is linear per tetrahedron there.
LOG_METHODS = ("clip", "scale")

#: Bits of a :class:`LogAxis` from its toe to the peak, at least: the toe bends scale's
#: ``x_i / max`` below ``2 ** -bits`` of the peak, at most the display code of that value
#: (``2 ** (-35 / 2.6)`` of full scale, 0.09 ten-bit codes, for a 2.6 power).
LOG_TOE_BITS = 35.0

#: As :data:`LOG_TOE_BITS` for HLG, whose lattice is not exact: fewer bits give finer
#: steps above the toe against a larger toe for dark colours (measured at 33³, ACEScg to
#: Rec.2100-HLG, ΔE ITP, max over the probe sets: 0.41 at 16 bits (dark colours), 0.22 at
#: 20, 0.32 at 24).
HLG_TOE_BITS = 20.0

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


def _code_of_peak(display: Display) -> float:
    return float(reference.display_encode(display, np.full(3, display.clip_high))[0])


def grey_code(display: Display, x) -> np.ndarray:
    """Display code of the grey ``x`` (normalised display-linear, 1 = peak), divided by
    the code of the peak: 0 at black, 1 at the peak. Per channel for every EOTF
    but HLG, whose inverse EOTF depends on the grey's luminance."""
    x = np.asarray(x, dtype=np.float64)
    grey = np.repeat(x[..., None] * display.clip_high, 3, axis=-1)
    return reference.display_encode(display, grey)[..., 0] / _code_of_peak(display)


def grey_linear(display: Display, code) -> np.ndarray:
    """Inverse of :func:`grey_code`."""
    code = np.asarray(code, dtype=np.float64)
    grey = np.repeat(code[..., None] * _code_of_peak(display), 3, axis=-1)
    return reference.display_decode(display, grey)[..., 0] / display.clip_high


def _ratio_to_peak(high: float, share: float) -> float:
    """``t = 1 / toe`` with ``log(1 + t) = share * log(1 + high * t)``: the peak ``share`` of
    the way from 0 to ``high`` in ``log(x + toe)`` (Newton's method from ``toe << 1``)."""
    t = high ** (share / (1.0 - share))
    for _ in range(8):
        f = np.log1p(t) - share * np.log1p(high * t)
        t -= f / (1.0 / (1.0 + t) - share * high / (1.0 + high * t))
    return float(t)


@dataclass(frozen=True)
class LogAxis:
    """Nodes uniform in ``log2(x + toe)`` from ``x = 0`` (node 0) through 1 (node
    ``one``) to ``high`` (the last node); values below 0 are clamped to 0."""

    size: int
    one: int
    toe: float

    @classmethod
    def layout(cls, display: Display, size: int, high: float, exact: bool = False) -> LogAxis:
        """The fewest nodes below the peak leaving at least :data:`LOG_TOE_BITS`
        (:data:`HLG_TOE_BITS` for HLG code values, unless ``exact``: the lattice then
        holds display light, not HLG's code) between the toe and the peak, or all but
        one in a small lattice."""
        wanted = HLG_TOE_BITS if display.eotf_name == "HLG" and not exact else LOG_TOE_BITS
        n = size - 1
        if n < 2:
            raise ValueError(f"a lattice of {size} nodes is too small for this axis")
        one = next((k for k in range(1, n) if np.log2(high) * k / (n - k) >= wanted), n - 1)
        return cls(size, one, 1.0 / _ratio_to_peak(high, one / n))

    @property
    def _ratio(self) -> float:
        """``(x + toe) / toe`` at ``x = 1``: the node ``one`` steps of it."""
        return (1.0 + self.toe) / self.toe

    @property
    def span(self) -> float:
        """Bits of ``x + toe`` from node 0 to the last node."""
        return float(np.log2(self._ratio) * (self.size - 1) / self.one)

    @property
    def high(self) -> float:
        return float(self.position(1.0))

    def coordinate(self, x) -> np.ndarray:
        """Lattice coordinate in [0, 1] of ``x``."""
        x = np.maximum(np.asarray(x, dtype=np.float64), 0.0)
        return np.clip(np.log2(x / self.toe + 1.0) / self.span, 0.0, 1.0)

    def position(self, v) -> np.ndarray:
        """``x`` at coordinate ``v`` (inverse of :meth:`coordinate`); exactly 1 at node ``one``."""
        v = np.clip(np.asarray(v, dtype=np.float64), 0.0, 1.0)
        x = self.toe * (2.0 ** (v * self.span) - 1.0)
        return np.where(np.isclose(v * (self.size - 1), self.one, rtol=0, atol=1e-12), 1.0, x)

    def nodes(self) -> np.ndarray:
        return self.position(np.arange(self.size) / (self.size - 1))


@dataclass(frozen=True)
class Axis:
    """Node positions along one display-layout axis for the methods not in :data:`LOG_METHODS`.

    Node indices run from 0 to ``size - 1``; ``zero`` and ``one`` are the
    nodes of normalised display-linear 0 and 1; ``low`` (<= 0) and ``high``
    (>= 1) are the values at the end nodes. Between ``zero`` and ``one`` the
    index is linear in the display's code value (:func:`grey_code`), or in
    ``inside.forward(x)`` when that curve is set.
    """

    display: Display
    size: int
    zero: int
    one: int
    low: float
    high: float
    knee: float = NEGATIVE_KNEE
    inside: object | None = None

    @classmethod
    def layout(cls, display: Display, size: int, low: float, high: float,
               shares: tuple[float, float] = DEFAULT_SHARES, knee: float = NEGATIVE_KNEE,
               inside=None) -> Axis:
        """Share ``size - 1`` intervals between negatives, the cube and over-range values
        (``shares`` of them, fewer for negatives when ``low`` is above -1)."""
        n = size - 1
        below = 0 if low >= 0 else max(1, round(n * shares[0] * min(1.0, -low)))
        above = 0 if high <= 1 else max(1, round(n * shares[1]))
        if n - below - above < 1:
            raise ValueError(f"a lattice of {size} nodes is too small for this axis")
        return cls(display, size, below, n - above, min(low, 0.0), max(high, 1.0), knee, inside)

    def _inside(self, x):
        """The cube's part of the axis, 0 to 1 for ``x`` in [0, 1]."""
        return grey_code(self.display, x) if self.inside is None else self.inside.forward(x)

    def _inside_inverse(self, w):
        return grey_linear(self.display, w) if self.inside is None else self.inside.inverse(w)

    def _negative(self, v):
        e = np.abs(v) ** (1.0 / NEGATIVE_GAMMA)
        return e / (e + self.knee)

    def index(self, x) -> np.ndarray:
        """Node index (float, within [0, size - 1]) of normalised display-linear ``x``."""
        x = np.clip(np.asarray(x, dtype=np.float64), self.low, self.high)
        n, a, b = self.size - 1, self.zero, self.one
        inside = a + (b - a) * self._inside(np.clip(x, 0.0, 1.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            above = b + (n - b) * np.log(np.maximum(x, 1.0)) / np.log(self.high)
            below = a - a * self._negative(np.minimum(x, 0.0)) / self._negative(self.low) if a else inside
        return np.where(x > 1.0, above, np.where(x < 0.0, below, inside))

    def coordinate(self, x) -> np.ndarray:
        """Lattice coordinate in [0, 1] of ``x``."""
        return self.index(x) / (self.size - 1)

    def position(self, index) -> np.ndarray:
        """Normalised display-linear value at node index ``index`` (inverse of :meth:`index`)."""
        k = np.clip(np.asarray(index, dtype=np.float64), 0.0, self.size - 1)
        n, a, b = self.size - 1, self.zero, self.one
        inside = self._inside_inverse(np.clip((k - a) / (b - a), 0.0, 1.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            above = self.high ** ((np.maximum(k, b) - b) / max(n - b, 1))
            r = (a - np.minimum(k, a)) / max(a, 1) * self._negative(self.low)
            below = -((self.knee * r / (1.0 - r)) ** NEGATIVE_GAMMA)
        x = np.where(k > b, above, np.where(k < a, below, inside))
        x = np.where(k >= n, self.high, x) if b < n else x
        return np.where(k <= 0, self.low, x) if a > 0 else x

    def nodes(self) -> np.ndarray:
        """Normalised display-linear values of every node, shape (size,)."""
        return self.position(np.arange(self.size, dtype=np.float64))


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


def _code_range(source: ColourSpace, display: Display) -> tuple[float, float, bool]:
    """Codes of the source layout before alignment, and whether the top is the curve's own."""
    if isinstance(source.curve, Linear):
        return SOURCE_RANGE[0] * display.clip_high, SOURCE_RANGE[1] * display.clip_high, False
    low, high = (float(v) for v in getattr(source.curve, "domain", (0.0, 1.0)))
    with np.errstate(all="ignore"):
        top = float(source.curve.encode(np.array(SOURCE_RANGE[1] * display.clip_high)))
    capped = not (np.isfinite(top) and low < top < high)
    return low, (high if capped else top), capped


def source_domain(source: ColourSpace, display: Display) -> tuple[float, float]:
    """Input range of a source layout: for linear sources about ``SOURCE_RANGE[0]`` times
    the display's peak, for encoded ones the bottom of their code range, up to at least
    the code of ``SOURCE_RANGE[1]`` times the peak (at least 16 times display white) or
    the top of their code range. The ends are moved by less than a step of the shaper
    table so that the codes of 0 and of the peak fall on its entries."""
    count = SOURCE_SHAPER_SIZES[isinstance(source.curve, Linear)]
    low, high, capped = _code_range(source, display)
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
        entry[zero + 1:dense] = position[zero] + np.arange(1, dense - zero) / (dense - zero - 1)
    rank = np.arange(position.size - dense)
    rest = np.maximum(entry[dense:], entry[dense - 1] + 1.0)
    entry[dense:] = np.maximum.accumulate(rest - rank) + rank
    gap = zero - np.arange(zero + 1)  # below 0: each node at least one entry below the next
    entry[:zero + 1] = np.minimum.accumulate((entry[:zero + 1] + gap)[::-1])[::-1] - gap
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
