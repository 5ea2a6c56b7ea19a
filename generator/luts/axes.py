"""Where a lattice puts its nodes along each axis: the display's own code values.

A 3D LUT interpolates between nodes; it is exact wherever the function it
samples is multilinear within a cell. Clipping to the display cube, and every
gamut mapping that leaves in-gamut colours alone, is the identity in display
code values inside the cube and constant beyond its faces. So the axis
(:class:`Axis`) is the display's encoding of display-linear RGB, normalised so
that 0 and the peak land exactly on two nodes, ``zero`` and ``one``: in-gamut
colours are reproduced exactly and clipping kinks fall on node planes, never
inside a cell.

Beyond the cube the axis goes on with two extensions, each reaching an end node
at a finite limit (values past it are clamped by the LUT's input range):

* above the peak (over-range), the coordinate is linear in ``log(x)``: the
  mappings that divide by the largest channel (``scale``, ``desaturate``)
  depend on ratios of channels, which a constant node ratio samples evenly
  (measured against ``x ** (-1 / 2.4)`` spacing: 1.7 against 5.9 ten-bit
  codes, the largest error of ``scale`` into sRGB at 33³);
* below 0, linear in ``e / (e + knee)`` with ``e = |x| ** (1 / 2.4)``:
  fine steps near 0, where desaturation is most sensitive, coarse far out.

How the intervals are shared depends on the mapping (:data:`SHARES`): clip and
scale are constant below 0 (one interval suffices), so half the lattice goes to
over-range values; the others bend below 0 as well.

Here ``x`` is display-linear RGB divided by the display's peak
(``Display.clip_high``), so the cube is [0, 1] for SDR and HDR alike.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.colorimetry import reference
from generator.spec.schema import Display

#: Exponent of the negative extension (``e = |x| ** (1 / NEGATIVE_GAMMA)``).
NEGATIVE_GAMMA = 2.4

#: ``e`` at the middle of the negative intervals.
NEGATIVE_KNEE = 0.4

#: Fractions of a lattice's intervals given to negative and to over-range values, by
#: gamut-mapping method (measured on the probes of :mod:`generator.luts.probes`, 33³).
SHARES = {"clip": (0.03, 0.5), "scale": (0.03, 0.5)}

#: Shares for the methods not in :data:`SHARES`.
DEFAULT_SHARES = (0.375, 0.375)


def shares(method: str) -> tuple[float, float]:
    """Negative and over-range shares of the lattice for ``method``."""
    return SHARES.get(method, DEFAULT_SHARES)


def grey_code(display: Display, x) -> np.ndarray:
    """Display code of the grey ``x`` (normalised display-linear, 1 = peak), divided by
    the code of the peak: 0 at black, 1 at the peak. Per channel for every EOTF
    but HLG, whose inverse EOTF depends on the grey's luminance."""
    x = np.asarray(x, dtype=np.float64)
    grey = np.repeat(x[..., None] * display.clip_high, 3, axis=-1)
    top = reference.display_encode(display, np.full(3, display.clip_high))[0]
    return reference.display_encode(display, grey)[..., 0] / top


def grey_linear(display: Display, code) -> np.ndarray:
    """Inverse of :func:`grey_code`."""
    code = np.asarray(code, dtype=np.float64)
    top = reference.display_encode(display, np.full(3, display.clip_high))[0]
    grey = np.repeat(code[..., None] * top, 3, axis=-1)
    return reference.display_decode(display, grey)[..., 0] / display.clip_high


@dataclass(frozen=True)
class Axis:
    """Node positions along one lattice axis.

    Node indices run from 0 to ``size - 1``; ``zero`` and ``one`` are the
    nodes of normalised display-linear 0 and 1; ``low`` (<= 0) and ``high``
    (>= 1) are the values at the end nodes. Between ``zero`` and ``one`` the
    index is linear in the display's code value (:func:`grey_code`).
    """

    display: Display
    size: int
    zero: int
    one: int
    low: float
    high: float
    knee: float = NEGATIVE_KNEE

    @classmethod
    def layout(cls, display: Display, size: int, low: float, high: float,
               shares: tuple[float, float] = DEFAULT_SHARES, knee: float = NEGATIVE_KNEE) -> Axis:
        """Share ``size - 1`` intervals between negatives, the cube and over-range values
        (``shares`` of them, fewer for negatives when ``low`` is above -1)."""
        n = size - 1
        below = 0 if low >= 0 else max(1, round(n * shares[0] * min(1.0, -low)))
        above = 0 if high <= 1 else max(1, round(n * shares[1]))
        if n - below - above < 1:
            raise ValueError(f"a lattice of {size} nodes is too small for this axis")
        return cls(display, size, below, n - above, min(low, 0.0), max(high, 1.0), knee)

    def _negative(self, v):
        e = np.abs(v) ** (1.0 / NEGATIVE_GAMMA)
        return e / (e + self.knee)

    def index(self, x) -> np.ndarray:
        """Node index (float, within [0, size - 1]) of normalised display-linear ``x``."""
        x = np.clip(np.asarray(x, dtype=np.float64), self.low, self.high)
        n, a, b = self.size - 1, self.zero, self.one
        inside = a + (b - a) * grey_code(self.display, np.clip(x, 0.0, 1.0))
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
        inside = grey_linear(self.display, np.clip((k - a) / (b - a), 0.0, 1.0))
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
