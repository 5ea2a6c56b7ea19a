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
* :class:`~generator.luts.source_axes.SourceAxis` (source axes: .cube, .spi3d),
  in :mod:`generator.luts.source_axes`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator import reference
from generator.spec.schema import Display

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
        one in a small lattice. Three nodes are too few: the toe then sits a few bits below
        the peak, and scale's over-range colours came out 26 ten-bit codes off (ACEScg into
        sRGB; from four nodes, 0.013)."""
        wanted = HLG_TOE_BITS if display.eotf_name == "HLG" and not exact else LOG_TOE_BITS
        n = size - 1
        if n < 3:
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
        """The largest value the axis reaches (its last node)."""
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
        """The value at each node, first to last."""
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
    def layout(
        cls,
        display: Display,
        size: int,
        low: float,
        high: float,
        shares: tuple[float, float] = DEFAULT_SHARES,
        knee: float = NEGATIVE_KNEE,
        inside=None,
    ) -> Axis:
        """Share ``size - 1`` intervals between negatives, the cube and over-range values
        (``shares`` of them, fewer for negatives when ``low`` is above -1)."""
        n = size - 1
        below = 0 if low >= 0 else max(1, round(n * shares[0] * min(1.0, -low)))
        above = 0 if high <= 1 else max(1, round(n * shares[1]))
        while n - below - above < 1 and max(below, above) > 1:  # rounding up both shares left the cube none
            below, above = (below - 1, above) if below >= above else (below, above - 1)
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
