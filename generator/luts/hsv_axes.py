"""Coordinates of the desaturate view's lattice in OCIO's HSV (:mod:`generator.luts.hsv`).

OCIO's RGB_TO_HSV (OpenColorIO 2.0 and later, ``FixedFunctionOpCPU.cpp``) extends
HSV to negative channels: for a colour with minimum ``m < 0 < M`` (its maximum),
``V = M + m``, and ``S = (M - m) / M`` in [1, 2] when ``M >= -m``,
``(M - m) / -m`` otherwise; all-negative colours have ``V < 0`` and ``S <= 1``.
In the lattice coordinates

* ``kappa`` along hue: within each sixth of the hue circle ``h_Y`` is linear in
  ``H``, and ``kappa`` is linear in ``1 / h_Y``, with the six primaries and
  secondaries on nodes;
* ``u`` along saturation: ``S`` up to 1, ``1 / (2 - S)`` above (nodes even up to 1,
  at the middle, then :data:`SATURATION_NODES_ABOVE`, to :data:`SATURATION_REACH`);
* ``V`` itself, piecewise linear (:data:`VALUE_NODES`), with 0 on a node;

the colour's RGB, its luminance and ``Y / h_Y`` are *trilinear* inside every cell
on either side of ``V = 0`` and of ``S = 1`` (both node planes): ``V' = V`` where
``S <= 1`` and ``V >= 0`` (inside the display: untouched), else
``V' = V ((2u - 1) + (1 - u) / h_Y)`` for ``V > 0`` and ``V ((1 - 2u) + u / h_Y)``
for ``V < 0`` (negative where ``Y < 0``: the clamp makes it black, as the method
does). Trilinear interpolation reproduces the lattice exactly; only the 1D
tables and float32 arithmetic remain.

OCIO's HSV is singular on the cone ``M = -m``, where ``V`` is the difference of
two equal magnitudes and ``S`` reaches 2: the colour's size is ``|V| u``. The
shared file therefore takes ``t = 2 - S`` first (exact in float32 for ``S`` in
[1, 2], so a multiple of 2**-23) and maps it to ``u``'s coordinate in a
half-float-domain table, whose entries are spaced 2**-11 relative down to
``t = 2**-14`` and 2**-24 apart below, among the subnormal halves: every ``t`` OCIO
gives there is an entry, read exactly, down to ``t = 2**-23`` (``u`` up to
:data:`SATURATION_REACH`). What is left is OCIO's own float32 rounding of ``S``
and ``V`` near the cone, relative ``2**-24`` times about ``u`` (``t`` is uncertain by
about 2**-23 absolute: a colour 1e-5 from the cone keeps its size to about 1%), and
the float32 resolution of the lattice coordinates (:func:`float32_resolution`), which
the verifier carries as the view's float32 limit. Only on the cone itself (``S`` = 2
in float32) is the colour's size lost: it comes out black.
"""

from __future__ import annotations

import numpy as np

from generator import tolerances

#: Nodes a side: three per sixth of the hue circle (the lattice is exact, so size only buys
#: float32 precision).
HSV_SIZE = 19

#: Largest ``u = 1 / (2 - S)`` the lattice reaches: ``t = 2 - S`` down to 2**-23, the
#: smallest ``t`` OCIO's float32 ``S`` in [1, 2] leaves short of the cone (a subnormal
#: half, on an entry of the shared table). Clamped at 2**14 (``t`` 6e-5), colours nearer
#: the cone came out as if that far from it, too dark: sRGB-linear (-1, 0.5, 1.00002)
#: 261 ten-bit codes, (-2, 1.5, 2.00001) 674.
SATURATION_REACH = 2.0**23

#: ``u`` at the saturation nodes above 1, up to :data:`SATURATION_REACH`. Each is ``1 / t``
#: for a half float ``t``: the shared table is interpolated between half floats, so its
#: kinks (where the cells' widths change) must sit on them, or it is off by up to a
#: quarter of the slope's jump times the spacing (3e-4 of ``u`` at u = 3, measured on an
#: ACEScct ramp). The file reads ``u``'s coordinate in float32, which resolves 6e-8 of it
#: near 1/2 to 1: a cell of width ``w`` resolves ``u`` to ``18 w`` times that, and a colour
#: of luminance near 0 turns it into a visible code (its mixed value
#: ``V ((2u - 1) + (1 - u) / h_Y)`` is a difference of large terms). OCIO's own HSV resolves
#: ``u`` to about ``6e-8 u**2``, so the cells widen with ``u`` (nodes geometric from 1 put
#: 1.3e-6 of error, 2.2 ten-bit codes on Rec.1886, into such colours): a cell from ``u_k``
#: keeps its width within ``u_k**2 / 2`` (as 2 to 4 does), and the last two, 256 to 8192
#: and 8192 to 2**23, within an eighth of u_k**2.
SATURATION_NODES_ABOVE = (8 / 7, 4 / 3, 2.0, 4.0, 8.0, 32.0, 256.0, 8192.0, SATURATION_REACH)

#: The value axis: V at each node in lattice order. A float32 coordinate holds about 7
#: digits, so V = 0 sits at coordinate 0 (dark colours keep their relative precision) and
#: the negative values, whose colours are strongly outside the display or just beyond
#: OCIO HSV's cone, come after the positive ones, with -0 at coordinate 1, where float32
#: resolves 6e-8: the cells there shrink geometrically (by 16), so a small negative V keeps
#: about 1e-6 of its relative precision (with one cell from -1/16 to -0 it kept 5e-3, 0.6
#: ten-bit codes on an ACEScct ramp near black). Toward +0 the first cell is 2**-16 wide
#: for OCIO's GPU path: its shader forms a 3D table's coordinate as ``(x (N - 1) + 0.5) / N``
#: in float32, which resolves about 3e-8 of a cell wherever x is, so a first cell from 0 to
#: 1/64 drew colours a billionth of the peak black (0.36 ten-bit codes on Gamma 2.6; 2**-16
#: leaves 5e-13 of light, 0.02 codes). The cells above grow by 256, then 16, then 4 up to 16,
#: then 16: a GPU's 8-bit texture weights (bench/lut_accuracy.py) err by the node values' spread
#: across a cell, and these cells keep every figure of the earlier 1/64, 1/16, ... 64 ladder
#: but the dark set's p99, which falls from 2.3 to 1.1 codes. The shared half-domain table
#: takes V to its node's coordinate, linearly between nodes (all half floats); the cell
#: between the largest half float and -256 is never entered. Values beyond are clamped (V
#: from -256 to 65504 times the display's peak): the mapped value is linear in V across a
#: cell, so a wide top cell costs only float32 resolution, while a clamp at 1024 left
#: colours far outside the gamut whose luminance is below a thousandth of V dimmer than the
#: mapping (scene 20 on a 1 cd/m² display, 216 ten-bit codes).
VALUE_NODES = (
    0.0,
    2.0**-16,
    2.0**-8,
    1 / 16,
    0.25,
    1.0,
    4.0,
    16.0,
    256.0,
    65504.0,
    -256.0,
    -16.0,
    -1.0,
    -(2.0**-4),
    -(2.0**-8),
    -(2.0**-12),
    -(2.0**-16),
    -(2.0**-20),
    -0.0,
)

#: Nodes of :data:`VALUE_NODES` at or above 0.
POSITIVE_VALUE_NODES = 10

#: Hue passes the shared table as ``H / 6`` (the display's file scales it back: the matrix
#: between keeps OCIO from composing the two tables into one).
SHARED_SCALE = 6.0

#: Saturation OCIO's HSV_TO_RGB clamps to (2 would be a pole).
OCIO_MAX_SATURATION = 1.999


def ocio_rgb_to_hsv(rgb) -> np.ndarray:
    """OCIO's extended-range RGB_TO_HSV (module docstring), float64, shape (..., 3)."""
    c = np.asarray(rgb, dtype=np.float64)
    red, green, blue = c[..., 0], c[..., 1], c[..., 2]
    low, high = c.min(axis=-1), c.max(axis=-1)
    delta = high - low
    spread = np.where(delta > 0.0, delta, 1.0)
    hue = np.where(
        red == high,
        (green - blue) / spread,
        np.where(green == high, 2.0 + (blue - red) / spread, 4.0 + (red - green) / spread),
    )
    hue = np.where(delta > 0.0, np.where(hue < 0.0, hue + 6.0, hue) / 6.0, 0.0)
    saturation = np.where((delta > 0.0) & (high != 0.0), delta / np.where(high != 0.0, high, 1.0), 0.0)
    saturation = np.where(-low > high, delta / np.where(low < 0.0, -low, 1.0), saturation)
    value = np.where(low < 0.0, high + low, high)
    return np.stack([hue, saturation, value], axis=-1)


def hue_shape(hue) -> np.ndarray:
    """The fully saturated colour of value 1 at each hue (OCIO's HSV_TO_RGB pattern), (..., 3)."""
    h = (np.asarray(hue, dtype=np.float64) % 1.0) * 6.0
    return np.clip(np.stack([np.abs(h - 3.0) - 1.0, 2.0 - np.abs(h - 2.0), 2.0 - np.abs(h - 4.0)], axis=-1), 0.0, 1.0)


def ocio_hsv_to_rgb(hsv, max_saturation: float = OCIO_MAX_SATURATION) -> np.ndarray:
    """OCIO's extended-range HSV_TO_RGB, the inverse of :func:`ocio_rgb_to_hsv`, float64
    (saturation clamped to [0, ``max_saturation``], as OCIO does)."""
    x = np.asarray(hsv, dtype=np.float64)
    saturation, value = np.clip(x[..., 1], 0.0, max_saturation), x[..., 2]
    low = np.where(saturation > 1.0, value * (1.0 - saturation) / (2.0 - saturation), value * (1.0 - saturation))
    high = np.where(saturation > 1.0, value - low, value)
    low = np.where(value < 0.0, value / (2.0 - saturation), low)
    high = np.where(value < 0.0, value - low, high)
    return hue_shape(x[..., 0]) * (high - low)[..., None] + low[..., None]


def _corner_inverse_luminance(weights: np.ndarray) -> np.ndarray:
    """``1 / h_Y`` at the hues 0, 1/6, ..., 1 (red, yellow, green, cyan, blue, magenta, red)."""
    return 1.0 / (hue_shape(np.arange(7) / 6.0) @ weights)


def hue_to_kappa(hue, weights: np.ndarray) -> np.ndarray:
    """``kappa / 6`` in [0, 1]: the sixth of the hue circle plus the fraction of its span of ``1 / h_Y``."""
    h = np.asarray(hue, dtype=np.float64)
    sixth = np.minimum(np.floor(h * 6.0), 5.0).astype(int)
    ends = _corner_inverse_luminance(weights)
    inverse = 1.0 / (hue_shape(h) @ weights)
    return (sixth + (inverse - ends[sixth]) / (ends[sixth + 1] - ends[sixth])) / 6.0


def kappa_to_hue(kappa, weights: np.ndarray) -> np.ndarray:
    """The inverse of :func:`hue_to_kappa` (``h_Y`` is linear in hue within each sixth)."""
    k = np.asarray(kappa, dtype=np.float64) * 6.0
    sixth = np.minimum(np.floor(k), 5.0).astype(int)
    ends = _corner_inverse_luminance(weights)
    luminance = 1.0 / (ends[sixth] + (k - sixth) * (ends[sixth + 1] - ends[sixth]))
    corner = 1.0 / ends
    return (sixth + (luminance - corner[sixth]) / (corner[sixth + 1] - corner[sixth])) / 6.0


def saturation_nodes() -> np.ndarray:
    """``u`` at the saturation nodes: evenly from 0 to 1, with 1 at the middle node (a
    coordinate of exactly 1/2, so a colour with a zero channel, ``S = 1``, lands on the
    node plane in float32 and keeps ``S' = 1`` exactly: a saturation a rounding below 1
    lifts the zero channel, visibly on a pure-power display), then
    :data:`SATURATION_NODES_ABOVE`."""
    return np.concatenate([np.linspace(0.0, 1.0, len(SATURATION_NODES_ABOVE) + 1), SATURATION_NODES_ABOVE])


def _half_values() -> np.ndarray:
    """Every half float, by bit pattern (the entries of a half-domain table), float64."""
    return np.arange(65536, dtype=np.uint16).view(np.float16).astype(np.float64)


def _coordinates(hue: np.ndarray, t: np.ndarray, value: np.ndarray) -> np.ndarray:
    """Lattice coordinates ``(H / 6, u's, V's)`` of hue, ``t = 2 - S`` and value, float64:
    ``u = 2 - t`` up to 1, ``1 / t`` beyond, linear in ``u`` between its nodes; V linear
    between :data:`VALUE_NODES`, by its sign bit (+0 at coordinate 0, -0 at 1: OCIO
    interpolates a float between the two half floats around it, so a V between the
    smallest negative half float and 0 reads the entries of both, and -0's entry must
    continue the negative side's); beyond the nodes, clamped."""
    grid = np.linspace(0.0, 1.0, HSV_SIZE)
    with np.errstate(divide="ignore"):
        u = np.where(t >= 1.0, 2.0 - t, 1.0 / np.maximum(t, 0.0))
    nodes, split = np.array(VALUE_NODES), POSITIVE_VALUE_NODES
    v = np.where(
        np.signbit(value), np.interp(value, nodes[split:], grid[split:]), np.interp(value, nodes[:split], grid[:split])
    )
    return np.stack([np.clip(hue, 0.0, 1.0) / SHARED_SCALE, np.interp(u, saturation_nodes(), grid), v], axis=-1)


def shared_table() -> np.ndarray:
    """The shared half-domain table (65536 entries by half-float bit pattern, 3 columns) of
    ``(H, t = 2 - S, V)``: :func:`_coordinates` of each half float; NaN goes to 0."""
    x = np.nan_to_num(_half_values(), nan=0.0, posinf=np.inf, neginf=-np.inf)
    return _coordinates(x, x, x)


def table_inputs() -> np.ndarray:
    """OCIO HSV values (n, 3) reading every entry of the shared table the view can reach, one
    column at a time: hue on every half float from 0 to 1, ``t = 2 - S`` on every half float
    from 1 / SATURATION_REACH to 2, V on every finite half float of either sign; the other
    two at values of their own columns' nodes."""
    halves = _half_values()
    finite = halves[np.isfinite(halves)]
    hue = finite[(finite >= 0.0) & (finite <= 1.0) & ~np.signbit(finite)]
    t = finite[(finite >= 1.0 / SATURATION_REACH) & (finite <= 2.0)]
    rows = [
        np.stack([hue, np.full_like(hue, 0.5), np.full_like(hue, 0.5)], axis=-1),
        np.stack([np.full_like(t, 0.25), 2.0 - t, np.full_like(t, 0.5)], axis=-1),
        np.stack([np.full_like(finite, 0.25), np.full_like(finite, 0.5), finite], axis=-1),
    ]
    return np.concatenate(rows)


def _saturation_of_u(u: np.ndarray) -> np.ndarray:
    return np.where(u <= 1.0, u, 2.0 - 1.0 / np.maximum(u, 1.0))


def shared_coordinates(values: np.ndarray) -> np.ndarray:
    """What the shared file does to OCIO HSV ``values`` (n, 3), in float64 without its
    sampling: ``(H / 6, u's coordinate, V's coordinate)``, clamped as the table clamps. Its
    Matrix adds +0 to V, so a V of -0 reads +0's entry (both give black)."""
    values = np.asarray(values, dtype=np.float64)
    return _coordinates(values[:, 0], 2.0 - values[:, 1], values[:, 2] + 0.0)


def lattice_coordinates(values: np.ndarray, weights: np.ndarray) -> np.ndarray:
    """The display lattice's coordinates of OCIO HSV ``values`` (n, 3), in float64 without
    the files' sampling: :func:`shared_coordinates` with the hue through :func:`hue_to_kappa`
    (the display file's first table; ``weights``, its luminance weights summing to 1)."""
    coordinates = shared_coordinates(values)
    coordinates[:, 0] = hue_to_kappa(np.clip(np.asarray(values, dtype=np.float64)[:, 0], 0.0, 1.0), weights)
    return coordinates


def hsv_of_coordinates(coordinates: np.ndarray) -> np.ndarray:
    """The OCIO HSV values a display file's input ``coordinates`` (n, 3) stand for (the
    inverse of :func:`shared_coordinates` within its clamps)."""
    c = np.asarray(coordinates, dtype=np.float64)
    grid = np.linspace(0.0, 1.0, HSV_SIZE)
    u = np.interp(c[:, 1], grid, saturation_nodes())
    nodes, split = np.array(VALUE_NODES), POSITIVE_VALUE_NODES
    value = np.where(
        c[:, 2] <= grid[split - 1],
        np.interp(c[:, 2], grid[:split], nodes[:split]),
        np.interp(c[:, 2], grid[split:], nodes[split:]),
    )
    hue = np.clip(c[:, 0] * SHARED_SCALE, 0.0, 1.0)  # the file's first table clamps (no wrap past red)
    return np.stack([hue, _saturation_of_u(u), value], axis=-1)


def _cell_width(nodes: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Width of the cell of ``nodes`` (increasing) holding each ``x``."""
    k = np.clip(np.searchsorted(nodes, x) - 1, 0, len(nodes) - 2)
    return nodes[k + 1] - nodes[k]


def saturation_coordinate_resolution(values: np.ndarray) -> np.ndarray:
    """How far float32 leaves the saturation ``S`` of OCIO HSV ``values`` (n, 3) uncertain
    through its lattice coordinate, absolute: 6e-8 relative at each of
    FLOAT32_COORDINATE_ROUNDINGS steps, times the width of its cell of ``u`` per unit of
    coordinate, turned back into ``S`` (``dS = du / u**2`` above 1)."""
    values = np.asarray(values, dtype=np.float64)
    steps = tolerances.FLOAT32_COORDINATE_ROUNDINGS * tolerances.FLOAT32_UNIT_ROUNDOFF
    saturation = values[:, 1]
    with np.errstate(divide="ignore"):
        u = np.where(saturation <= 1.0, saturation, 1.0 / np.maximum(2.0 - saturation, 1.0 / SATURATION_REACH))
    du = steps * shared_coordinates(values)[:, 1] * (HSV_SIZE - 1) * _cell_width(saturation_nodes(), u)
    return np.where(u > 1.0, du / np.maximum(u, 1.0) ** 2, du)


def float32_resolution(values: np.ndarray) -> np.ndarray:
    """How far float32 leaves each of OCIO HSV ``values`` (n, 3) uncertain on the way through
    the view, absolute: the hue, a value in [0, 1] rounded by each of the
    FLOAT32_HSV_ROUNDINGS operators it passes (:mod:`generator.tolerances`); saturation and
    value, by OCIO's RGB_TO_HSV (a few units of the largest channel) and by their lattice
    coordinates, which float32 resolves to 6e-8 relative at each of
    FLOAT32_COORDINATE_ROUNDINGS steps, times the width of their cell per unit of coordinate."""
    values = np.asarray(values, dtype=np.float64)
    u32, n = tolerances.FLOAT32_UNIT_ROUNDOFF, HSV_SIZE - 1
    operators, steps = tolerances.FLOAT32_HSV_ROUNDINGS * u32, tolerances.FLOAT32_COORDINATE_ROUNDINGS * u32
    saturation, value = values[:, 1], values[:, 2]
    coordinates = shared_coordinates(values)
    ds = operators * np.maximum(saturation, 1.0) + saturation_coordinate_resolution(values)
    nodes = np.array(VALUE_NODES)
    positive, negative = nodes[:POSITIVE_VALUE_NODES], -nodes[POSITIVE_VALUE_NODES:][::-1]
    cell = np.where(value >= 0.0, _cell_width(positive, np.abs(value)), _cell_width(negative, np.abs(value)))
    dv = operators * np.abs(value) + steps * coordinates[:, 2] * n * cell
    return np.stack([np.full(len(values), operators), ds, dv], axis=-1)
