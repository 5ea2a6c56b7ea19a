"""Sampling the reference evaluation on a lattice, in one of two layouts.

* Display axes (:func:`display_lattice`): what is linear is applied exactly
  before the lattice (the source's decoding curve and the source-to-display
  matrix), then a per-channel shaper takes normalised display-linear RGB to
  the lattice coordinate. For clip and scale the shaper is a CLF Log operator
  (:class:`~generator.luts.axes.LogAxis`), the lattice holds the same
  coordinate of the mapped colour and a 1D table (``post``) turns it into code
  values; for the other methods an analytic pre-shaper and a 1D table lead to
  an :class:`~generator.luts.axes.Axis` and the lattice holds code values.
  CLF and the config's views use it.
* Source axes (:func:`~generator.luts.fit.source_lattice`): formats that hold no matrix (.cube,
  .spi3d) sample the whole transform in the source's own values; a 1D shaper
  table, uniform in source values, takes them to the coordinate of a
  :class:`~generator.luts.source_axes.SourceAxis`. A clipping plane of the display is
  oblique to these axes and crosses cells, so the node values are then fitted
  by least squares (:mod:`generator.luts.fit`) to colours of the kinds the probes measure,
  drawn from another seed, reweighted by their errors
  (:func:`~generator.luts.fit.reweighted_fit`);
  greys and colours with a zero channel stay exact.

Node values start from the reference evaluation
(:func:`~generator.reference.mapped_view`) at the *exact* preimage
of each node under the shaper as written (a piecewise-linear table, rounded as
in the file).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator import reference
from generator.colorimetry.transfer import PiecewisePower, Power, TransferFunction
from generator.gamut import METHODS
from generator.luts import numbers
from generator.luts.axes import DEFAULT_SHARES, LOG_METHODS, Axis, LogAxis, grey_code, grey_linear
from generator.spec.schema import ColourSpace, Display, Spec

#: Decimals written for lattice values holding display code values: 5e-6 of a code at
#: most (0.005 of a ten-bit code), which keeps the standalone pack under 30 MB.
CUBE_DECIMALS = 5

#: Decimals written for lattice values holding :class:`LogAxis` coordinates: a step of
#: 1e-7 is about 3e-6 bits, a relative 2e-6 of display-linear light (0.001 ten-bit codes);
#: also for a lattice holding a power ``x ** (1 / 6)`` of display light (a relative 3e-6).
LOG_DECIMALS = 7

#: Decimals written for shaper tables (lattice coordinates).
SHAPER_DECIMALS = 6

#: Display axes: normalised display-linear range the lattice covers (values beyond are
#: clamped): down to -16 and up to 32 times the display's peak (the over-range probes,
#: 16 times the peak in the ACEScg gamut, reach 27 in sRGB).
DISPLAY_RANGE = (-16.0, 32.0)

#: Perceptual's display axes reach this high instead (times the peak): a channel clamped at
#: 32 beside others far below 0 (ACEScg red at 64 times the peak is (109, -8.3, -1.5) in
#: sRGB) made a bright light's luminance fall below 0, so red practicals showed dark magenta
#: cores where the mapping goes to white. At 1024 times the peak, a channel there with the
#: other two at DISPLAY_RANGE's -16 still has a luminance of 45 times the peak or more on
#: every library display (Rec.2020's blue weighs 0.059), so a clamped colour stays white. Measured
#: on ramps of 400 ACEScg colours from 1 to 1000 times (sRGB): the largest fall of luminance
#: along a ramp 0.86 -> 0.20, ramps falling by more than 0.1 33 -> 12, error at 1000 times
#: 1023 -> 0 codes; over-range probes (up to 16 times) p99 187 -> 251, out of gamut 203 -> 178.
PERCEPTUAL_HIGH = 1024.0

#: A :class:`LogAxis` (clip and scale) reaches half-float's largest value times the peak
#: (:func:`log_axis_high`): its
#: mapping is linear inside every tetrahedron whatever the node spacing, so the range costs
#: no accuracy, and a highlight far beyond 32 times the peak (a practical light, the sun)
#: keeps its hue through Scale instead of being clamped per channel first.
LOG_DISPLAY_HIGH = 65504.0

#: Pre-shaper exponent for displays whose EOTF CLF cannot express (PQ, HLG): PQ is steep
#: near black, and the 1D table after a 1/2.4 power misses it there (measured: ΔE ITP 2.4
#: against 0.16 with 6, darkest probes, ARRI LogC4 to Rec.2100-PQ).
DEFAULT_GAMMA = 6.0

#: Display axes: 1D table entries per unit of the pre-shaped value (1 = the display's peak).
ENTRIES_PER_UNIT = 64

#: Entries of the 1D table after a :class:`LogAxis` lattice (coordinate to code value),
#: per unit of the peak's code value: its linear interpolation is within 0.002 ten-bit
#: codes of the display's encoding (an extended-range display reaching code 2.6 needs three
#: times as many: 0.045 ΔE ITP in gamut with 4096, 0.004 with 16384, Display P3 HDR).
POST_SIZE = 4096


@dataclass(frozen=True)
class PreShaper:
    """An analytic per-channel curve before the shaper table: the display's inverse EOTF
    where CLF has an operator for it (a mirrored power law, or the sRGB-like
    "moncurve" with ``offset``), else a mirrored 1/2.4 power."""

    gamma: float
    offset: float = 0.0
    scale: float = 1.0

    @classmethod
    def for_display(cls, display: Display, scaled: bool = True) -> PreShaper:
        """The display's own curve of normalised display light; ``scaled``, of the light itself
        divided by the code of the peak (``scale`` is the peak over the light of code 1: 10 for
        an extended-range display, whose codes pass 1 and whose linear toe sits at a tenth of
        the normalised value), so the peak stays at 1."""
        scale = display.clip_high / display.code_one if scaled else 1.0
        if isinstance(display.eotf, PiecewisePower):
            return cls(display.eotf.gamma, display.eotf.offset, scale)
        if isinstance(display.eotf, Power):
            return cls(display.eotf.exponent, 0.0, scale)
        return cls(DEFAULT_GAMMA)

    @property
    def norm(self) -> float:
        """The curve at ``scale``: dividing by it keeps the peak at 1, on a table entry."""
        return float(self._curve(np.array(self.scale)))

    def _curve(self, x) -> np.ndarray:
        if not self.offset:
            return np.sign(x) * np.abs(x) ** (1.0 / self.gamma)
        return np.sign(x) * PiecewisePower(self.gamma, self.offset).encode(np.abs(x))

    def forward(self, x) -> np.ndarray:
        """Shaper input of normalised display-linear ``x``: the curve, scaled to keep the peak at 1."""
        x = np.asarray(x, dtype=np.float64) * self.scale
        return self._curve(x) if self.scale == 1.0 else self._curve(x) / self.norm

    def inverse(self, w) -> np.ndarray:
        """Normalised display-linear values of shaper inputs ``w``: the inverse of :meth:`forward`."""
        w = np.asarray(w, dtype=np.float64) * (self.norm if self.scale != 1.0 else 1.0)
        if not self.offset:
            return np.sign(w) * np.abs(w) ** self.gamma / self.scale
        return np.sign(w) * PiecewisePower(self.gamma, self.offset).decode(np.abs(w)) / self.scale


@dataclass(frozen=True, eq=False)
class Lattice:
    """A sampled transform: optional exact steps, a shaper, a 3D table, an optional 1D table.

    ``decode`` and ``matrix`` (display axes only) are the source's curve and
    the source-to-normalised-display-linear matrix; ``pre`` the analytic
    shaper (a :class:`PreShaper` before ``shaper``, or a :class:`LogAxis`
    taking display-linear values to the lattice directly). ``domain`` is the
    input range of ``shaper`` (uniform entries over it) or, without a shaper,
    of the cube itself. ``cube[r, g, b]`` holds the values at the nodes,
    rounded as written (``decimals``): display code values, or with ``post``
    (a 1D table uniform over [0, 1]) the coordinates ``post`` turns into them,
    or with ``light`` values its exact inverse (an Exponent or Log operator)
    turns into normalised display-linear RGB, for the config to encode.
    """

    source: ColourSpace | None
    display: Display
    method: str
    decode: TransferFunction | None
    matrix: np.ndarray | None
    pre: PreShaper | LogAxis | None
    domain: tuple[float, float]
    shaper: np.ndarray | None
    cube: np.ndarray
    post: np.ndarray | None = None
    decimals: int = CUBE_DECIMALS
    light: PreShaper | LogAxis | None = None

    @property
    def size(self) -> int:
        """Nodes along each axis of the cube."""
        return self.cube.shape[0]


def as_pre_shaper(step: PreShaper | LogAxis | None) -> PreShaper:
    """``step`` (a lattice's ``pre`` or ``light``) where the layout makes it a :class:`PreShaper`;
    TypeError for a :class:`LogAxis` or None."""
    if not isinstance(step, PreShaper):
        raise TypeError(f"a lattice step is a {type(step).__name__}, not a PreShaper")
    return step


def shaper_table(lat: Lattice) -> np.ndarray:
    """``lat``'s shaper table; ValueError for a lattice without one."""
    if lat.shaper is None:
        raise ValueError("the lattice has no shaper table")
    return lat.shaper


def preimages(size: int, shaper: np.ndarray | None, domain: tuple[float, float]) -> np.ndarray:
    """Input values landing exactly on each node: the inverse of the written table.

    The table (non-decreasing, its entries uniform over ``domain``) is read by linear
    interpolation. A coordinate a flat run of the table takes (repeated values, as where a
    shaper is clamped at either end) lands on the run's first entry; any other lies strictly
    inside one rising segment, from the last entry of a run to the next entry, and has a single
    preimage there. Coordinates beyond the table's values land where it first reaches its end."""
    u = np.arange(size, dtype=np.float64) / (size - 1)
    table = shaper if shaper is not None else np.array([0.0, 1.0])
    return _table_preimages(u, table, np.linspace(domain[0], domain[1], table.size))


def _table_preimages(u: np.ndarray, table: np.ndarray, entries: np.ndarray) -> np.ndarray:
    """Where the piecewise-linear curve through (``entries``, ``table``) takes the values ``u``
    (``table`` non-decreasing, ``entries`` increasing): :func:`preimages`'s reading, with
    np.interp's arithmetic on each rising segment (np.interp itself cannot take a flat run's
    two ends, one x value twice, as breakpoints)."""
    u = np.clip(u, table[0], table[-1])
    above = np.searchsorted(table, u, side="left")  # first entry at or above u: a run's first
    exact = table[above] == u
    below = np.where(exact, above, above - 1)  # else strictly below u: the last entry of its run
    rise = np.where(exact, 1.0, table[above] - table[below])  # never 0 off the table's values
    slope = (entries[above] - entries[below]) / rise
    return slope * (u - table[below]) + entries[below]


def coordinates(lat: Lattice, code) -> np.ndarray:
    """Lattice coordinates in [0, 1] of source-layout input values, as a reader computes them:
    the shaper's entries are uniform over the domain, so the entry below a value is found by
    arithmetic (np.interp's search took 25 ms of a 65³ .cube bake's 0.39 s)."""
    if lat.shaper is None:
        code = np.clip(np.asarray(code, dtype=np.float64), *lat.domain)
        return (code - lat.domain[0]) / (lat.domain[1] - lat.domain[0])
    position, entry = table_position(lat, code)
    low = np.take(lat.shaper, entry, mode="clip")
    return low + (position - entry) * (np.take(lat.shaper, entry + 1, mode="clip") - low)


def table_position(lat: Lattice, code) -> tuple[np.ndarray, np.ndarray]:
    """The fractional entry of input values ``code`` in ``lat``'s shaper table (clamped to its
    domain) and the entry below it, as a reader finds them."""
    size = shaper_table(lat).size
    code = np.clip(np.asarray(code, dtype=np.float64), *lat.domain)
    position = (code - lat.domain[0]) / (lat.domain[1] - lat.domain[0]) * (size - 1)
    with np.errstate(invalid="ignore"):  # a NaN's entry is no index (taken in "clip" mode), its coordinate NaN
        entry = np.minimum(position.astype(np.int64), size - 2)  # clipped above: never negative
    return position, entry


def grid(axis: np.ndarray) -> np.ndarray:
    """Every combination of the per-axis values ``axis`` (n,), shape (n, n, n, 3), ``[r, g, b]`` order."""
    n = axis.size
    out = np.empty((n, n, n, 3))
    out[..., 0] = axis[:, None, None]
    out[..., 1] = axis[None, :, None]
    out[..., 2] = axis[None, None, :]
    return out


def node_values(
    display: Display,
    method: str,
    linear_axis: np.ndarray,
    matrix: np.ndarray | None,
    params,
    light: PreShaper | None = None,
    decimals: int = CUBE_DECIMALS,
) -> np.ndarray:
    """Mapped code values on the grid of per-axis linear values, ``[r, g, b]`` order (with
    ``light``, its forward curve of the mapped normalised display-linear values instead).
    Codes are not clipped above 1: HLG's inverse EOTF exceeds 1 for saturated colours."""
    nodes = grid(linear_axis)
    with np.errstate(all="ignore"):
        linear = reference.apply_matrix(matrix, nodes) if matrix is not None else nodes
        if light is not None:
            code = light.forward(reference.gamut_map(display, method, linear, params))
        else:
            code = reference.map_display_linear(display, method, linear, params)
    finite = code if np.isfinite(code).all() else np.nan_to_num(code)  # the replacements' passes only when needed
    return numbers.rounded(np.maximum(finite, 0.0), decimals)


def display_table(axis: Axis, pre: PreShaper) -> tuple[tuple[float, float], np.ndarray]:
    """The shaper table of an :class:`Axis` layout: pre-shaped values on a uniform grid
    with 0 and 1 on entries, to lattice coordinates. Returns (domain, values)."""
    w_low = -np.ceil(-pre.forward(axis.low) * ENTRIES_PER_UNIT) / ENTRIES_PER_UNIT
    w_high = np.ceil(pre.forward(axis.high) * ENTRIES_PER_UNIT) / ENTRIES_PER_UNIT
    count = round((w_high - w_low) * ENTRIES_PER_UNIT) + 1
    w = np.linspace(w_low, w_high, count)
    return (float(w_low), float(w_high)), numbers.rounded(axis.coordinate(pre.inverse(w)), SHAPER_DECIMALS)


def log_axis_high(display: Display, light: bool = False) -> float:
    """How far a :class:`LogAxis` reaches: :data:`LOG_DISPLAY_HIGH` where its lattice is exact,
    :data:`DISPLAY_RANGE`'s end for HLG code values (a lattice that is smooth, not exact: a
    longer range would coarsen its steps, 0.40 ΔE ITP against 0.22 at 33³)."""
    if display.eotf_name == "HLG" and not light:
        return DISPLAY_RANGE[1]
    return LOG_DISPLAY_HIGH * max(1.0, 1.0 / display.clip_high)  # a dim display: still 65504 cd/m² / 100


def display_axis(display: Display, size: int, method: str, light: bool = False) -> Axis | LogAxis:
    """The display layout's axis: normalised display-linear over :data:`DISPLAY_RANGE` (up to
    :data:`LOG_DISPLAY_HIGH` for clip and scale, :data:`PERCEPTUAL_HIGH` for perceptual).
    With ``light`` (the lattice holds display light, see :func:`display_lattice`) an
    :class:`Axis` is a power of display light inside the cube, where the pre-shaper is."""
    if method in LOG_METHODS:
        return LogAxis.layout(display, size, log_axis_high(display, light), exact=light)
    inside = PreShaper.for_display(display, scaled=False) if light else None
    high = PERCEPTUAL_HIGH if method == "perceptual" else DISPLAY_RANGE[1]
    return Axis.layout(display, size, DISPLAY_RANGE[0], high, DEFAULT_SHARES, inside=inside)


def encodes_in_clf(display: Display) -> bool:
    """Whether CLF has an operator for the display's inverse EOTF (a power law, or
    sRGB-like with a linear toe); not for PQ or HLG."""
    return isinstance(display.eotf, (Power, PiecewisePower))


#: HLG: scale applied to mapped colours before encoding them for a :class:`LogAxis` lattice.
#: BT.2100's HLG (no black lift) makes scene light homogeneous of degree 1 / gamma in
#: display light, so the grey with the same code as a colour scales with it; below the
#: code clip at 1 the lattice can hold the unclipped grey and leave the clip to the 1D
#: table, per channel, exactly. A quarter keeps every colour of the cube below the clip
#: (a channel's code reaches 1 at ``(1 / Y) ** (gamma - 1)``, 1.8 for Rec.2020 blue).
HLG_UNCLIPPED_SCALE = 0.25


def _log_lattice(display: Display, method: str, axis: LogAxis, params) -> tuple[np.ndarray, np.ndarray]:
    """Cube of mapped coordinates (the coordinate of the grey of the same code) and the
    1D table from coordinate to code value."""
    top = reference.display_encode(display, np.full(3, display.clip_high))[0]
    scale = HLG_UNCLIPPED_SCALE if display.eotf_name == "HLG" else 1.0
    with np.errstate(all="ignore"):
        mapped = METHODS[method](grid(axis.nodes()), None, params)  # clip and scale need no display gamut
        code = reference.display_encode(display, mapped * display.clip_high * scale)
        cube = axis.coordinate(grey_linear(display, np.nan_to_num(code) / top) / scale)
    # Mapped colours never pass the peak, so entries past the first one beyond it are never
    # read: they repeat it (an extended-range display would otherwise write codes past 10).
    # Entries a multiple of the lattice's intervals apart: every node's coordinate, the peak's
    # among them, falls on an entry (a tabulated EOTF's peak, between two, came out 0.73 codes low).
    wanted = POST_SIZE * int(np.ceil(top - 1e-9))
    x = axis.position(np.linspace(0.0, 1.0, (axis.size - 1) * -(-wanted // (axis.size - 1)) + 1))
    post = grey_code(display, np.minimum(x, x[np.argmax(x >= 1.0)])) * top
    return numbers.rounded(cube, LOG_DECIMALS), numbers.rounded(post, CUBE_DECIMALS)


def _log_light(display: Display, method: str, axis: LogAxis, params) -> np.ndarray:
    """Cube of the :class:`LogAxis` coordinates of the mapped colours (display light)."""
    mapped = METHODS[method](grid(axis.nodes()), None, params)  # clip and scale need no display gamut
    return numbers.rounded(axis.coordinate(mapped), LOG_DECIMALS)


def display_lattice(
    spec: Spec,
    display: Display,
    method: str,
    size: int,
    source: ColourSpace | None = None,
    params=None,
    light: bool = False,
) -> Lattice:
    """The display layout. With ``source``, the lattice's input is that space's code
    values (its curve and matrix come first); without, scene-reference linear RGB
    (the matrix is the caller's: :func:`~generator.reference.normalised_display_matrix`).

    With ``light`` the file ends in normalised display-linear RGB, for a config whose
    display space encodes it (a view of a display CLF cannot encode, PQ or HLG): the
    lattice holds the same curve of the mapped colour as its input (the pre-shaper's
    power inside the cube, :class:`LogAxis` coordinates for clip and scale), so what the
    mapping leaves alone passes through exactly, and an exact operator undoes the curve.
    ``params`` None takes the spec's (:func:`~generator.reference.method_params`)."""
    params = reference.method_params(spec, method, params, source, display)
    matrix = reference.normalised_display_matrix(spec, display)
    if source is not None:
        matrix = matrix @ reference.space_matrix(spec, source)
    decode = None if source is None else source.curve
    axis = display_axis(display, size, method, light)
    if isinstance(axis, LogAxis):
        if light:
            cube = _log_light(display, method, axis, params)
            return Lattice(
                source, display, method, decode, matrix, axis, (0.0, 1.0), None, cube, None, LOG_DECIMALS, light=axis
            )
        cube, post = _log_lattice(display, method, axis, params)
        return Lattice(source, display, method, decode, matrix, axis, (0.0, 1.0), None, cube, post, LOG_DECIMALS)
    pre = PreShaper.for_display(display, scaled=not light)
    domain, table = display_table(axis, pre)
    linear = pre.inverse(preimages(size, table, domain)) * display.clip_high
    if light:
        cube = node_values(display, method, linear, None, params, pre, LOG_DECIMALS)
        return Lattice(source, display, method, decode, matrix, pre, domain, table, cube, None, LOG_DECIMALS, pre)
    cube = node_values(display, method, linear, None, params)
    return Lattice(source, display, method, decode, matrix, pre, domain, table, cube)
