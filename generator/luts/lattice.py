"""Sampling the reference evaluation on a lattice, in one of two layouts.

* Display axes (:func:`display_lattice`): what is linear is applied exactly
  before the lattice (the source's decoding curve and the source-to-display
  matrix), then an analytic pre-shaper and a 1D table take display-linear
  RGB to the lattice coordinate of :class:`~generator.luts.axes.Axis`: the
  display's code values with 0 and the peak on nodes. CLF and the config's
  views use it.
* Source axes (:func:`source_lattice`): formats that hold no matrix (.cube,
  .spi3d) sample the whole transform in the source's own values; a 1D shaper
  table, uniform in source values, takes them to the lattice coordinate of the
  same :class:`Axis` applied to the decoded source value, so that greys land on
  the lattice diagonal exactly where the display would put them.

Node values are the reference evaluation (:func:`~generator.colorimetry.reference.mapped_view`)
at the *exact* preimage of each node under the shaper as written (a
piecewise-linear table, rounded as in the file), so the only error left is
interpolation inside the cells.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.colorimetry import reference
from generator.colorimetry.transfer import Linear, PiecewisePower, Power
from generator.luts import numbers
from generator.luts.axes import Axis, shares
from generator.spec.schema import ColourSpace, Display, Spec

#: Decimals written for lattice values (display code values): 5e-6 of a code at most
#: (0.005 of a ten-bit code), which keeps the standalone pack under 30 MB.
CUBE_DECIMALS = 5

#: Decimals written for shaper tables (lattice coordinates).
SHAPER_DECIMALS = 6

#: Display axes: normalised display-linear range the lattice covers (values beyond are
#: clamped): down to -16 and up to 32 times the display's peak.
DISPLAY_RANGE = (-16.0, 32.0)

#: Pre-shaper exponent for displays whose EOTF CLF cannot express (PQ, HLG): PQ is steep
#: near black, and the 1D table after a 1/2.4 power misses it there (measured: ΔE ITP 2.4
#: against 0.16 with 6, darkest probes, ARRI LogC4 to Rec.2100-PQ).
DEFAULT_GAMMA = 6.0

#: Display axes: 1D table entries per unit of the pre-shaped value (1 = the display's peak).
ENTRIES_PER_UNIT = 64

#: Source axes: range of linear sources, in units of display white (1.0 = 100 cd/m²).
LINEAR_SOURCE_RANGE = (-1.0, 64.0)

#: Source axes: entries of the 1D shaper table.
SOURCE_SHAPER_SIZE = 2048


@dataclass(frozen=True)
class PreShaper:
    """An analytic per-channel curve before the shaper table: the display's inverse EOTF
    where CLF has an operator for it (a mirrored power law, or the sRGB-like
    "moncurve" with ``offset``), else a mirrored 1/2.4 power."""

    gamma: float
    offset: float = 0.0

    @classmethod
    def for_display(cls, display: Display) -> PreShaper:
        if isinstance(display.eotf, PiecewisePower):
            return cls(display.eotf.gamma, display.eotf.offset)
        return cls(display.eotf.exponent if isinstance(display.eotf, Power) else DEFAULT_GAMMA)

    def forward(self, x) -> np.ndarray:
        x = np.asarray(x, dtype=np.float64)
        if not self.offset:
            return np.sign(x) * np.abs(x) ** (1.0 / self.gamma)
        return np.sign(x) * PiecewisePower(self.gamma, self.offset).encode(np.abs(x))

    def inverse(self, w) -> np.ndarray:
        w = np.asarray(w, dtype=np.float64)
        if not self.offset:
            return np.sign(w) * np.abs(w) ** self.gamma
        return np.sign(w) * PiecewisePower(self.gamma, self.offset).decode(np.abs(w))


@dataclass(frozen=True, eq=False)
class Lattice:
    """A sampled transform: optional exact steps, a shaper table, a 3D table.

    ``decode`` and ``matrix`` (display axes only) are the source's curve and
    the source-to-normalised-display-linear matrix; ``pre`` the analytic
    pre-shaper. ``domain`` is the input range of ``shaper`` (uniform entries
    over it) or, without a shaper, of the cube itself. ``cube[r, g, b]`` holds
    display code values at the nodes, rounded as written.
    """

    source: ColourSpace | None
    display: Display
    method: str
    decode: object | None
    matrix: np.ndarray | None
    pre: PreShaper | None
    domain: tuple[float, float]
    shaper: np.ndarray | None
    cube: np.ndarray

    @property
    def size(self) -> int:
        return self.cube.shape[0]


def _preimages(size: int, shaper: np.ndarray | None, domain: tuple[float, float]) -> np.ndarray:
    """Input values landing exactly on each node: the inverse of the written table."""
    u = np.arange(size, dtype=np.float64) / (size - 1)
    grid = np.linspace(domain[0], domain[1], shaper.size if shaper is not None else 2)
    table = shaper if shaper is not None else np.array([0.0, 1.0])
    increasing = np.concatenate([[True], np.diff(table) > 0])  # drop flat runs: keep the first entry of each
    return np.interp(u, table[increasing], grid[increasing])


def _evaluate(display: Display, method: str, linear_axis: np.ndarray, matrix: np.ndarray, params) -> np.ndarray:
    """Mapped code values on the grid of per-axis linear values, ``[r, g, b]`` order."""
    n = linear_axis.size
    grid = np.empty((n, n, n, 3))
    grid[..., 0] = linear_axis[:, None, None]
    grid[..., 1] = linear_axis[None, :, None]
    grid[..., 2] = linear_axis[None, None, :]
    with np.errstate(all="ignore"):
        linear = reference.apply_matrix(matrix, grid) if matrix is not None else grid
        code = reference.map_display_linear(display, method, linear, params)
    return numbers.rounded(np.clip(np.nan_to_num(code), 0.0, 1.0), CUBE_DECIMALS)


def display_table(axis: Axis, pre: PreShaper) -> tuple[tuple[float, float], np.ndarray]:
    """The shaper table of the display layout: pre-shaped values on a uniform grid with
    0 and 1 on entries, to lattice coordinates. Returns (domain, values)."""
    w_low = -np.ceil(-pre.forward(axis.low) * ENTRIES_PER_UNIT) / ENTRIES_PER_UNIT
    w_high = np.ceil(pre.forward(axis.high) * ENTRIES_PER_UNIT) / ENTRIES_PER_UNIT
    count = int(round((w_high - w_low) * ENTRIES_PER_UNIT)) + 1
    w = np.linspace(w_low, w_high, count)
    return (float(w_low), float(w_high)), numbers.rounded(axis.coordinate(pre.inverse(w)), SHAPER_DECIMALS)


def display_axis(display: Display, size: int, method: str) -> Axis:
    """The display layout's axis: normalised display-linear over :data:`DISPLAY_RANGE`."""
    return Axis.layout(display, size, *DISPLAY_RANGE, shares(method))


def display_lattice(spec: Spec, display: Display, method: str, size: int, source: ColourSpace | None = None,
                    params=None) -> Lattice:
    """The display layout. With ``source``, the lattice's input is that space's code
    values (its curve and matrix come first); without, scene-reference linear RGB
    (the matrix is the caller's: :func:`view_matrix`)."""
    pre = PreShaper.for_display(display)
    axis = display_axis(display, size, method)
    domain, table = display_table(axis, pre)
    linear = pre.inverse(_preimages(size, table, domain)) * display.clip_high
    cube = _evaluate(display, method, linear, None, params)
    matrix = view_matrix(spec, display)
    if source is not None:
        matrix = matrix @ reference.space_matrix(spec, source)
    return Lattice(source, display, method, None if source is None else source.curve, matrix, pre, domain, table, cube)


def view_matrix(spec: Spec, display: Display) -> np.ndarray:
    """Scene-reference linear RGB to normalised display-linear RGB (1 = the display's peak)."""
    return reference.scene_to_display_matrix(spec, display) / display.clip_high


def source_domain(source: ColourSpace, display: Display) -> tuple[float, float]:
    """Input range of a source layout: code 0 to 1 for encoded sources; for linear ones
    :data:`LINEAR_SOURCE_RANGE` times the display's peak (at least 16x display white)."""
    if isinstance(source.curve, Linear):
        low, high = LINEAR_SOURCE_RANGE
        return low * display.clip_high, high * display.clip_high
    return tuple(float(v) for v in getattr(source.curve, "domain", (0.0, 1.0)))


def source_axis(source: ColourSpace, display: Display, size: int, method: str) -> Axis:
    """The source layout's axis: the display's axis over the decoded source domain."""
    lo, hi = source_domain(source, display)
    with np.errstate(all="ignore"):
        low, high = (float(v) / display.clip_high for v in source.curve.decode(np.array([lo, hi])))
    return Axis.layout(display, size, low, high, shares(method))


def source_lattice(spec: Spec, source: ColourSpace, display: Display, method: str, size: int,
                   shaper: str | ColourSpace = "auto", params=None) -> Lattice:
    """The source layout. ``shaper``: "auto" (the display's axis on the decoded source),
    "none" (the cube directly over the source domain) or a colour space whose
    curve, applied to the decoded source values, spaces the nodes."""
    domain = source_domain(source, display)
    table = None
    if shaper != "none":
        codes = np.linspace(domain[0], domain[1], SOURCE_SHAPER_SIZE)
        with np.errstate(all="ignore"):
            linear = source.curve.decode(codes)
        if shaper == "auto":
            coordinate = source_axis(source, display, size, method).coordinate(linear / display.clip_high)
        else:
            encoded = shaper.curve.encode(linear)
            coordinate = (encoded - encoded[0]) / (encoded[-1] - encoded[0])
        table = numbers.rounded(coordinate, SHAPER_DECIMALS)
    codes = _preimages(size, table, domain)
    with np.errstate(all="ignore"):
        linear = source.curve.decode(codes)
    matrix = reference.scene_to_display_matrix(spec, display) @ reference.space_matrix(spec, source)
    cube = _evaluate(display, method, linear, matrix, params)
    return Lattice(source, display, method, None, None, None, domain, table, cube)
