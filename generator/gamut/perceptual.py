"""Hue-preserving gamut mapping in Oklab along lines toward a lightness focus.

A soft chroma compression (``threshold`` < 1, by default 0.8) or its limit
``threshold = 1``: a hue-preserving clip that leaves the display cube alone.

Method (docs/views.md gives the measurements behind it):

1. Display RGB -> XYZ -> *display-adapted* Oklab (B. Ottosson, "A perceptual
   color space for image processing", 2020). Oklab is defined for D65, so XYZ
   is first adapted with CAT02 (CIE 159:2004) from the display white to
   Oklab's: the display's greys ``k (1, 1, 1)`` are exactly
   ``(k^(1/3), 0, 0)`` and its white has ``L = 1``.
2. Each colour moves along a straight line of its hue plane (lightness ``L``
   against chroma ``C``) through a *focus* ``(L_f, -D)`` behind the neutral
   axis: ``D`` is ``focus_distance`` and ``L_f`` the lightness of the
   display's cusp of that hue (its most chromatic colour, on the cube edges),
   interpolated in hue in a table of :data:`CUSP_SAMPLES` points per edge.
   The line meets the axis at its grey ``L_a = (L D + C L_f) / (D + C)`` and
   climbs ``m = (L_a - L_f) / D`` per unit of chroma; lines do not cross
   where ``C >= 0``, and the line through the cusp is level, so output chroma
   never falls along a constant-``L`` chroma ramp. A line whose grey is
   beyond black or white holds no displayable colour of its hue: the colour
   goes to black (``L_a < 0``) or white (``L_a > 1``), continuously.
3. Along the line the display boundary chroma ``C_d`` is found by bisection
   (:data:`BISECTION_STEPS` fixed steps, "display RGB within [0, 1]"),
   anchored at the colour: from its chroma to :func:`chroma_bracket` if it is
   in the cube, else from the grey to its chroma, so a colour is never judged
   on the wrong side where a line leaves and re-enters the cube. The source
   boundary ``C_s`` is found alike when ``source_to_display`` is given, and
   the limit is ``max(C_s / C_d, 1)``; otherwise it is a fixed ratio. Where
   Oklab hue folds (:func:`hue_folds`), a colour outside the cube within
   :data:`FOLD_HUE_MARGIN` of the fold (:func:`fold_hues`) counts a point whose
   negative channels are within :data:`FOLD_SLACK` of its largest as inside,
   and the final clip removes the excursion.
4. With ``x = C / C_d``, threshold ``t`` and limit ``l``, the new ratio is
   ``x`` for ``x <= t``, ``t + (1 - t)(1 - (1 - u)^k)`` with
   ``u = (x - t) / (l - t)`` and ``k = (l - t) / (1 - t)`` for ``t < x < l``,
   and 1 beyond: slope 1 at ``t`` (C1), and the source boundary lands on the
   display boundary. For ``t = 1`` the new ratio is ``min(x, 1)``: a clip
   toward a focus (B. Ottosson, "sRGB gamut clipping", 2021) that leaves the
   cube untouched.
5. The output is the point of the same line at the new chroma ``C'``, so the
   Oklab hue and the line are kept (to float64 rounding; outside a folding
   display's cube, to the clip of step 3). Lightness becomes ``L_a + m C'``,
   moving toward ``L_f``. Back to RGB, a clip removes rounding excursions.
   Colours not compressed (``x <= t`` and ``L_a`` in [0, 1]) are returned
   unchanged, bit for bit.

``t = 1`` is what a 33³ lattice can hold: the cube maps to itself. Any
``t < 1`` bends the mapping inside the cube, which the lattice cannot follow.

Non-finite input follows :mod:`generator.gamut.display`: NaN -> 0, -Inf -> 0,
+Inf -> the largest value (so the colour is brighter than white: white). The
output is never NaN for any input.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from generator.colorimetry.matrices import von_kries
from generator.gamut.display import DisplayGamut, matrix_tuple, sanitize

#: Bisection steps for a boundary chroma; the bracket shrinks to 2^-40 of its width.
BISECTION_STEPS = 40

#: Upper end of the chroma bracket: every library display and source has C < 0.5 (AP1 green:
#: 0.49). A wider gamut's is twice its largest chroma (:func:`chroma_bracket`).
CHROMA_BRACKET = 1.0

#: Samples per edge of the cube's hue hexagon in the cusp table: within 2.5e-6 of the cusp
#: (but near a folding blue primary, where the cusp is ambiguous).
CUSP_SAMPLES = 1024

#: Negative channel, relative to the largest, counted inside the cube when the boundary of a
#: colour outside it is sought near a hue fold: above the 7e-4 of blue by which the line of a
#: colour beyond BT.709's blue edge leaves the cube before reaching it.
FOLD_SLACK = 1e-3

#: Hue (radians) beyond the fold's own span within which :data:`FOLD_SLACK` applies: applied
#: at every hue, the slack let boundary points leave the cube, and the clip moved them visibly.
FOLD_HUE_MARGIN = 0.02

#: RGB excursion still counted as inside a gamut during the bisection.
_INSIDE_SLACK = 1e-12

#: The cube's corners in hue order: the cusp of every hue lies on an edge between two.
_HEXAGON = np.array([[1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 1, 1], [0, 0, 1], [1, 0, 1], [1, 0, 0]], dtype=float)


def _colour():
    """colour-science, imported when a perceptual mapping first runs (it is slow to import)."""
    import colour

    return colour


def _hexagon_edges(samples: int, hexagon: np.ndarray) -> np.ndarray:
    """RGB along the cube's six edges between the corners of ``hexagon``, ``samples`` per edge."""
    s = np.linspace(0.0, 1.0, samples, endpoint=False)[:, None]
    return np.concatenate([hexagon[i] + s * (hexagon[i + 1] - hexagon[i]) for i in range(6)])


def _oklab_white_xyz() -> np.ndarray:
    """XYZ of Oklab's white (L = 1, a = b = 0)."""
    return _colour().Oklab_to_XYZ(np.array([1.0, 0.0, 0.0]))


@dataclass(frozen=True)
class PerceptualParams:
    """Parameters of the Oklab chroma compression.

    Parameters
    ----------
    threshold : float
        Fraction of the display boundary chroma (along each line) left
        untouched, in [0, 1]. The default 0.8 is a soft compression; 1 leaves
        the whole display cube untouched and clips the rest onto its boundary
        along the lines, which bakes into a 33³ lattice within 0.01 ten-bit
        codes in gamut where the soft default cannot (about 45: see the module
        docstring for the trade-off).
    limit : float
        Chroma, as a multiple (>= 1) of the display boundary chroma, that lands
        on the boundary when ``threshold`` < 1 and ``source_to_display`` is None.
    focus_distance : float
        Distance ``D`` (> 0, Oklab chroma units) of the focus behind the neutral
        axis: small values tilt the lines more (lightness moves more toward
        the cusp's), large ones approach compression at constant lightness.
    source_to_display : array_like (3, 3), optional
        The matrix the caller applied (display RGB = matrix @ source RGB). The
        source gamut is its image of the unit cube; its boundary chroma along
        each line sets the limit there.
    """

    threshold: float = 0.8
    limit: float = 1.25
    focus_distance: float = 0.5
    source_to_display: tuple[tuple[float, float, float], ...] | None = None

    def __post_init__(self) -> None:
        if not 0.0 <= self.threshold <= 1.0:
            raise ValueError(f"threshold must lie in [0, 1], got {self.threshold}")
        if not 1.0 <= self.limit < np.inf:
            raise ValueError(f"limit must be finite and at least 1, got {self.limit}")
        if not 0.0 < self.focus_distance < np.inf:
            raise ValueError(f"focus_distance must be positive and finite, got {self.focus_distance}")
        if self.source_to_display is not None:
            object.__setattr__(self, "source_to_display", matrix_tuple(self.source_to_display))


def adapted_matrix(display: DisplayGamut) -> np.ndarray:
    """Display RGB to Oklab-white-adapted XYZ, shape (3, 3) (CAT02 von Kries)."""
    return von_kries(display.white_xyz, _oklab_white_xyz(), "CAT02") @ display.matrix


def display_to_oklab(rgb: np.ndarray, display: DisplayGamut) -> np.ndarray:
    """Finite linear display RGB (..., 3) to display-adapted Oklab (..., 3)."""
    return _colour().XYZ_to_Oklab(rgb @ adapted_matrix(display).T)


def oklab_to_display(lab: np.ndarray, display: DisplayGamut) -> np.ndarray:
    """Display-adapted Oklab (..., 3) to linear display RGB (..., 3)."""
    return _colour().Oklab_to_XYZ(lab) @ np.linalg.inv(adapted_matrix(display)).T


@lru_cache(maxsize=32)
def _hexagon_hues(display: DisplayGamut) -> tuple[np.ndarray, np.ndarray]:
    """Unwrapped Oklab hue, increasing overall, and lightness along the hexagon of cube edges
    (:func:`cusp_table`)."""
    hexagon = _HEXAGON
    for _ in range(2):
        rgb = _hexagon_edges(CUSP_SAMPLES, hexagon)
        lab = display_to_oklab(rgb, display)
        hue = np.unwrap(np.arctan2(lab[:, 2], lab[:, 1]))
        if hue[-1] > hue[0]:
            break
        hexagon = hexagon[::-1]  # primaries listed clockwise in xy: hue grows from red through magenta
    return hue, lab[:, 0]


def _turning_back(hue: np.ndarray) -> np.ndarray:
    """Where the hexagon's hue has not yet passed its previous maximum (a fold)."""
    return np.concatenate([[False], hue[1:] <= np.maximum.accumulate(hue)[:-1]])


@lru_cache(maxsize=32)
def cusp_table(display: DisplayGamut) -> tuple[np.ndarray, np.ndarray]:
    """Hue (radians in [0, 2 pi)) and lightness of the display's cusps, increasing in hue.

    Sampled along the hexagon of cube edges, in the direction of increasing hue
    (red, yellow, green, ... for primaries listed counter-clockwise in xy, red,
    magenta, blue, ... for clockwise ones); where Oklab hue turns back along it
    (near a blue primary) the samples are skipped until the hue passes its previous
    maximum, so the table is a function of hue. Read-only arrays.
    """
    hue, lightness = _hexagon_hues(display)
    keep = ~_turning_back(hue)
    table = np.mod(hue[keep], 2.0 * np.pi), lightness[keep]
    for array in table:
        array.flags.writeable = False
    return table


@lru_cache(maxsize=32)
def fold_hues(display: DisplayGamut) -> tuple[float, float] | None:
    """Centre and half-width (radians) of the Oklab hues over which the hexagon's hue turns
    back (BT.709's and BT.2020's blue, not P3's); None where it never does."""
    hue, _ = _hexagon_hues(display)
    back = _turning_back(hue)
    if not back.any():
        return None
    low, high = float(hue[back].min()), float(np.maximum.accumulate(hue)[back].max())
    return float(np.mod(0.5 * (low + high), 2.0 * np.pi)), 0.5 * (high - low)


def hue_folds(display: DisplayGamut) -> bool:
    """Whether Oklab hue turns back somewhere along the display cube's hue hexagon (near
    BT.709's and BT.2020's blue primaries; not for P3): only then does a colour's line leave
    and re-enter the cube, and only then, near those hues, is :data:`FOLD_SLACK` used."""
    return fold_hues(display) is not None


def _fold_slack(hue_cos, hue_sin, display: DisplayGamut) -> np.ndarray:
    """:data:`FOLD_SLACK` for hues within :data:`FOLD_HUE_MARGIN` of the display's fold, 0 elsewhere."""
    fold = fold_hues(display)
    if fold is None:
        return np.zeros(np.shape(hue_cos))
    centre, half = fold
    turn = np.abs(np.angle((hue_cos + 1j * hue_sin) * np.exp(-1j * centre)))
    return np.where(turn <= half + FOLD_HUE_MARGIN, FOLD_SLACK, 0.0)


def focus_lightness(hue_cos, hue_sin, display: DisplayGamut) -> np.ndarray:
    """Cusp lightness of the display at each unit hue direction ``(cos h, sin h)``."""
    hue, lightness = cusp_table(display)
    return np.interp(np.mod(np.arctan2(hue_sin, hue_cos), 2.0 * np.pi), hue, lightness, period=2.0 * np.pi)


def line_through(lightness, chroma, focus, focus_distance: float) -> tuple[np.ndarray, np.ndarray]:
    """The grey ``L_a`` and the slope ``m`` (dL/dC) of the line from ``(focus, -D)`` through ``(L, C)``."""
    axis = (lightness * focus_distance + chroma * focus) / (focus_distance + chroma)
    return axis, (axis - focus) / focus_distance


def boundary_chroma(
    axis, slope, hue_cos, hue_sin, rgb_to_xyz: np.ndarray, inside=None, outside=None, slack=0.0
) -> np.ndarray:
    """Chroma at which the line ``L = axis + slope C`` of a hue leaves an RGB cube, by bisection.

    Parameters
    ----------
    axis, slope : numpy.ndarray, shape (...)
        The line's grey lightness and its lightness per unit chroma.
    hue_cos, hue_sin : numpy.ndarray, shape (...)
        The unit hue direction.
    rgb_to_xyz : numpy.ndarray, shape (3, 3)
        RGB (whose unit cube is the gamut) to adapted XYZ.
    inside, outside : numpy.ndarray, shape (...), optional
        The bracket: a chroma taken as inside (default 0, the grey) and one
        taken as outside (default :data:`CHROMA_BRACKET`).
    slack : float or numpy.ndarray, shape (..., 1), optional
        Negative excursion, relative to a point's largest channel, still counted as
        inside (:data:`FOLD_SLACK` where a hue fold needs it); 0 keeps the strict test.

    Returns
    -------
    numpy.ndarray, shape (...)
        The inside end of the final bracket, within 2^-40 of its width below a
        boundary crossing; 0 where the grey is outside [0, 1].
    """
    from colour.models.oklab import MATRIX_1_LMS_TO_XYZ, MATRIX_2_LAB_TO_LMS

    to_lms = np.asarray(MATRIX_2_LAB_TO_LMS)
    to_rgb = np.linalg.solve(rgb_to_xyz, np.asarray(MATRIX_1_LMS_TO_XYZ))
    # Non-linear LMS is affine in the chroma along the line: lms' = p + c q.
    p = axis[..., None] * to_lms[:, 0]
    q = slope[..., None] * to_lms[:, 0] + hue_cos[..., None] * to_lms[:, 1] + hue_sin[..., None] * to_lms[:, 2]
    inside_low = np.zeros(np.shape(axis)) if inside is None else np.array(inside, dtype=np.float64)
    outside_high = (
        np.full(np.shape(axis), chroma_bracket(rgb_to_xyz)) if outside is None else np.array(outside, dtype=np.float64)
    )
    slack = np.asarray(slack, dtype=np.float64)
    slack = slack[..., 0] if slack.ndim else slack
    top = 1.0 + _INSIDE_SLACK
    # Channel by channel and cubed by products: reductions over an axis of three and a float
    # power are most of a bisection step's time in numpy (x * x * x is within 2 ulp of x ** 3).
    for _ in range(BISECTION_STEPS):
        middle = 0.5 * (inside_low + outside_high)
        lms = p + middle[..., None] * q
        rgb = (lms * lms * lms) @ to_rgb.T
        r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
        low = -np.maximum(slack * np.maximum(np.maximum(np.maximum(r, g), b), 0.0), _INSIDE_SLACK)
        within = (r >= low) & (g >= low) & (b >= low) & (r <= top) & (g <= top) & (b <= top)
        inside_low = np.where(within, middle, inside_low)
        outside_high = np.where(within, outside_high, middle)
    return np.where((axis >= 0.0) & (axis <= 1.0), inside_low, 0.0)


def compress_ratio(ratio: np.ndarray, threshold: float, limit) -> np.ndarray:
    """The compression curve on ``x = C / C_d`` (step 4 of the module docstring).

    Parameters
    ----------
    ratio : numpy.ndarray
        Non-negative ratios, finite or +Inf.
    threshold : float
        In [0, 1]; 1 gives ``min(x, 1)``.
    limit : numpy.ndarray or float
        Broadcastable to ``ratio``, each >= 1.

    Returns
    -------
    numpy.ndarray
        Non-decreasing in ``ratio``, equal to it up to ``threshold``, at most 1.
    """
    if threshold >= 1.0:
        return np.minimum(ratio, 1.0)
    span = limit - threshold
    u = np.clip((ratio - threshold) / span, 0.0, 1.0)
    compressed = threshold + (1.0 - threshold) * (1.0 - (1.0 - u) ** (span / (1.0 - threshold)))
    return np.where(ratio <= threshold, ratio, compressed)


def _anchored(chroma, inside, bracket: float) -> tuple[np.ndarray | None, np.ndarray | None]:
    """Bisection bracket agreeing with the colours' own membership: from their chroma outwards
    for colours inside, from the grey to their chroma for the others."""
    if inside is None:
        return None, None
    return np.where(inside, chroma, 0.0), np.where(inside, bracket, np.minimum(chroma, bracket))


def chroma_bracket(rgb_to_xyz: np.ndarray) -> float:
    """Upper end of the bisection bracket for the gamut of ``rgb_to_xyz`` (RGB to adapted XYZ):
    :data:`CHROMA_BRACKET`, or twice the gamut's largest Oklab chroma, which lies on its cube's
    hexagon of edges (ProPhoto RGB's blue reaches 1.41)."""
    lab = _colour().XYZ_to_Oklab(_hexagon_edges(64, _HEXAGON) @ np.asarray(rgb_to_xyz).T)
    return float(max(CHROMA_BRACKET, 2.0 * np.hypot(lab[:, 1], lab[:, 2]).max()))


def compress_along_lines(
    chroma, axis, slope, hue_cos, hue_sin, display: DisplayGamut, params: PerceptualParams, rgb=None
) -> tuple[np.ndarray, np.ndarray]:
    """The chroma compression along each line (steps 3 and 4).

    Parameters
    ----------
    chroma : numpy.ndarray, shape (...)
        Oklab chroma, finite and non-negative.
    axis, slope : numpy.ndarray, shape (...)
        The line of each colour (:func:`line_through`).
    hue_cos, hue_sin : numpy.ndarray, shape (...)
        The unit hue direction.
    display : DisplayGamut
    params : PerceptualParams
    rgb : numpy.ndarray, shape (..., 3), optional
        The colours themselves (linear display RGB). Where given, each
        bisection is anchored at the colour (step 3): a colour of the display
        cube has ``C <= C_d``, one outside it ``C >= C_d``, and a colour not
        strictly inside the source gamut ``C >= C_s``. Without it, every
        colour of a line shares one boundary and the result is exactly
        non-decreasing along the line.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray), shapes (...)
        The compressed chroma, never above ``chroma``; and the ratio
        ``C / C_d`` (+Inf where the boundary chroma is 0 and the chroma is not).
    """
    matrix = adapted_matrix(display)
    in_display: np.ndarray | None = None
    slack: float | np.ndarray = 0.0
    if rgb is not None:
        in_display = np.all((rgb >= 0.0) & (rgb <= 1.0), axis=-1)
        slack = np.where(in_display, 0.0, _fold_slack(hue_cos, hue_sin, display))[..., None]
    display_chroma = boundary_chroma(
        axis, slope, hue_cos, hue_sin, matrix, *_anchored(chroma, in_display, chroma_bracket(matrix)), slack
    )
    found = display_chroma > 0.0
    limit: float | np.ndarray
    if params.source_to_display is None:
        limit = params.limit
    else:
        to_display = np.array(params.source_to_display)
        in_source = None
        if rgb is not None:
            source_rgb = rgb @ np.linalg.inv(to_display).T
            in_source = np.all((source_rgb > _INSIDE_SLACK) & (source_rgb < 1.0 - _INSIDE_SLACK), axis=-1)
        source_matrix = matrix @ to_display
        source = boundary_chroma(
            axis, slope, hue_cos, hue_sin, source_matrix, *_anchored(chroma, in_source, chroma_bracket(source_matrix))
        )
        limit = np.where(found, np.maximum(source / np.where(found, display_chroma, 1.0), 1.0), 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(chroma > 0.0, chroma / display_chroma, 0.0)
    compressed = np.where(found, compress_ratio(ratio, params.threshold, limit) * display_chroma, 0.0)
    compressed = np.minimum(compressed, chroma)
    return np.where(ratio <= params.threshold, chroma, compressed), ratio


def perceptual(rgb, display: DisplayGamut, params: PerceptualParams | None = None) -> np.ndarray:
    """Hue-preserving gamut mapping in Oklab toward a lightness focus (module docstring).

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Linear display RGB, any values (non-finite per the module policy).
    display : DisplayGamut
    params : PerceptualParams, optional
        Defaults: threshold 0.8, limit 1.25, focus distance 0.5,
        no source gamut.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64, within [0, 1], never NaN.
    """
    params = params or PerceptualParams()
    c = sanitize(rgb)
    lab = display_to_oklab(c, display)
    chroma = np.hypot(lab[..., 1], lab[..., 2])
    coloured = chroma > 0.0
    hue_cos = np.where(coloured, lab[..., 1] / np.where(coloured, chroma, 1.0), 1.0)
    hue_sin = np.where(coloured, lab[..., 2] / np.where(coloured, chroma, 1.0), 0.0)
    focus = focus_lightness(hue_cos, hue_sin, display)
    axis, slope = line_through(lab[..., 0], chroma, focus, params.focus_distance)

    new_chroma, ratio = compress_along_lines(chroma, axis, slope, hue_cos, hue_sin, display, params, c)
    lightness = np.clip(axis + slope * new_chroma, 0.0, 1.0)
    mapped = oklab_to_display(np.stack([lightness, new_chroma * hue_cos, new_chroma * hue_sin], axis=-1), display)
    on_axis = (axis >= 0.0) & (axis <= 1.0)
    # A line whose grey is beyond black or white holds no displayable colour of its hue.
    mapped = np.where(on_axis[..., None], mapped, np.where(axis > 1.0, 1.0, 0.0)[..., None])
    untouched = (ratio <= params.threshold) & on_axis
    return np.clip(np.where(untouched[..., None], c, mapped), 0.0, 1.0)
