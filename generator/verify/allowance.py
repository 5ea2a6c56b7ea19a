"""The float32 limit of a check: how far an engine computing in float32 may land from
the float64 reference for reasons no config can change, per sample and channel.

Float32 keeps 24 bits of each value; a 3x3 matrix product adds rounding in
proportion to |M||x| (Higham 2002, 3.5), so a channel near zero beside large
ones carries an absolute error, and a display or camera curve that is steep
there (a pure power law at 0) turns it into a visible code difference. The
verifier takes exactly that much off before its metric, computed here from
the reference evaluation; tolerances are never widened for it. So it does for
OCIO's own tabulation of the PQ curve, which no config can change either
(:func:`builtin_encoding_allowance`).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from generator import reference, tolerances
from generator.colorimetry.curves import PQ_PEAK
from generator.colorimetry.matrices import apply_matrix
from generator.gamut.simple import desaturate
from generator.luts import aces_lattice, hsv_axes
from generator.luts.evaluate import at_coordinates, coordinates, index_rounding
from generator.luts.hsv import luminance_weights
from generator.luts.view import view_lattice
from generator.ocio.capabilities import HALF_DOMAIN, PQ_BUILTIN, curve_chain, pq_builtin_tables
from generator.ocio.curves import curve_label
from generator.rendering import views
from generator.spec.schema import Display, Spec
from generator.verify import paths


def _input_side(linear, codes: np.ndarray, values: np.ndarray, constant: float = 0.0) -> np.ndarray:
    """|c f'(c)| of a decoding curve (a forward difference of 1e-7 relative), with ``|c|`` no
    smaller than the curve's ``constant`` (the magnitude of the code-side constants its
    float32 evaluation carries, e.g. a log segment's offset): u of it is the change of
    linear a rounding of the code, or of those constants, makes."""
    step = 1e-7 * np.maximum(np.abs(codes), 1e-3)
    with np.errstate(all="ignore"):
        slope = (linear(codes + step) - values) / step
    return np.nan_to_num(np.abs(np.maximum(np.abs(codes), constant) * slope), nan=0.0, posinf=0.0)


def float32_shift(src: paths.Endpoint, dst_matrix, codes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The reference values of ``codes`` and how far float32 evaluation alone may move
    the destination's linear values, per sample and channel.

    The source curve is a few float32 operations: its linear values carry
    FLOAT32_MATRIX_ROUNDINGS u of both the input side (|c f'(c)|, what a code's
    rounding becomes, with |c| at least the curve's code_constant where it has one: a
    log segment's offset) and the output side (the value), and one more u for storing it;
    each matrix product adds FLOAT32_MATRIX_ROUNDINGS u of |M||x|.
    """
    u, k = tolerances.FLOAT32_UNIT_ROUNDOFF, tolerances.FLOAT32_MATRIX_ROUNDINGS
    to_linear, matrix = src.linear, src.matrix
    if to_linear is None or matrix is None:
        raise ValueError(f"{src.name!r} has no linear values to shift")
    with np.errstate(all="ignore"):
        linear = to_linear(codes)
        ref = apply_matrix(matrix, linear)
        constant = getattr(src.curve, "code_constant", 0.0)
        source = u * ((1.0 + k) * np.abs(linear) + k * _input_side(to_linear, codes, linear, constant))
        to_dst = np.abs(np.linalg.inv(dst_matrix))
        return ref, apply_matrix(to_dst, apply_matrix(np.abs(matrix), source) + k * u * np.abs(ref))


def float32_allowance(src: paths.Endpoint, dst_matrix, encode, codes: np.ndarray, shifted=None) -> np.ndarray | None:
    """The code difference float32 evaluation alone may make, per sample and channel:
    the destination's linear values moved by :func:`float32_shift` either way, and
    encoded. Where the destination curve is steep (a power law near zero) this is far
    more than the tolerance, and no float32 engine can do better. ``shifted``: that
    :func:`float32_shift`, when already computed."""
    if src.matrix is None or src.linear is None or dst_matrix is None or encode is None:
        return None
    ref, shift = shifted or float32_shift(src, dst_matrix, codes)
    with np.errstate(all="ignore"):
        moved = [encode(ref + sign * apply_matrix(dst_matrix, shift)) for sign in (1.0, -1.0)]
        base = encode(ref)
        allowance = np.maximum(np.abs(moved[0] - base), np.abs(moved[1] - base))
    return np.where(np.isfinite(allowance), allowance, 0.0)


def determinate(src: paths.Endpoint, dst: paths.Endpoint, codes: np.ndarray) -> np.ndarray:
    """Samples whose destination linear values (ADX: exposures) all stand clear of their
    float32 noise: a bounded encoding has no code for a non-positive exposure, so one
    that float32 may move through zero has no determinate code."""
    if dst.matrix is None:
        raise ValueError(f"{dst.name!r} has no linear values to compare")
    ref, shift = float32_shift(src, dst.matrix, codes)
    with np.errstate(invalid="ignore"):
        return np.all(np.abs(apply_matrix(np.linalg.inv(dst.matrix), ref)) > shift, axis=-1)


def _rgc_shift(display: Display, linear: np.ndarray, shift: np.ndarray) -> np.ndarray:
    """The ACES gamut compression (a fixed function): RGC_OCIO_SCALED of max(1, largest
    component) of the normalised display RGB."""
    scale = np.maximum(1.0, np.max(np.abs(linear / display.clip_high), axis=-1, keepdims=True))
    return tolerances.RGC_OCIO_SCALED * scale * display.clip_high * np.ones_like(linear)


def _desaturate_shift(display: Display, linear: np.ndarray, shift: np.ndarray) -> np.ndarray:
    """Desaturate: the luminance's share of ``shift`` times the mixed colour per unit
    luminance, ``(c - m) / (Y - m)`` for a colour whose smallest channel ``m`` is negative (a
    colour of luminance near 0 maps near black, up to 1 / (smallest luminance weight) times
    its luminance's rounding), plus the float32 resolution of its HSV values through the
    view (:func:`hsv_rounding_shift`)."""
    weights = luminance_weights(display)
    luminance = linear @ weights
    low = np.minimum(linear.min(axis=-1), 0.0)
    with np.errstate(all="ignore"):
        per_luminance = np.where(low[..., None] < 0.0, (linear - low[..., None]) / (luminance - low)[..., None], 0.0)
    return np.nan_to_num(per_luminance) * (shift @ weights)[..., None] + hsv_rounding_shift(display, linear)


#: Views whose mapping OCIO computes with operators of its own (a fixed function, OCIO's
#: HSV), method to the departure those may make (:func:`_operator_shift`).
OPERATOR_SHIFTS = {"rgc": _rgc_shift, "desaturate": _desaturate_shift}


def _operator_shift(display: Display, view: str, linear: np.ndarray, shift: np.ndarray) -> np.ndarray:
    """The departure OCIO's own operators for a view's mapping may make, in display-linear
    RGB, given the float32 ``shift`` of the display's linear values ``linear``
    (:data:`OPERATOR_SHIFTS`; 0 for the other views)."""
    method = OPERATOR_SHIFTS.get(paths.view_method(view) or "")
    return np.zeros_like(linear) if method is None else method(display, linear, shift)


def hsv_rounding_shift(display: Display, linear: np.ndarray) -> np.ndarray:
    """How far the desaturate view's output may move, per channel, when each of the OCIO
    HSV values of display-linear ``linear`` moves by its float32 resolution through the view
    (:func:`generator.luts.hsv_axes.float32_resolution`), either way, summed over the three
    (to first order a bound): the mapping's own sensitivity, which is large where a colour
    of luminance near 0 maps near black."""
    gamut, peak = reference.display_gamut(display), display.clip_high
    with np.errstate(all="ignore"):
        values = hsv_axes.ocio_rgb_to_hsv(np.nan_to_num(linear.reshape(-1, 3)) / peak)
        delta = hsv_axes.float32_resolution(values)
        top = 2.0 - 1.0 / hsv_axes.SATURATION_REACH

        def mapped(v):
            v = np.stack([v[:, 0], np.clip(v[:, 1], 0.0, top), v[:, 2]], axis=-1)
            return desaturate(hsv_axes.ocio_hsv_to_rgb(v, max_saturation=2.0), gamut)

        base, total = mapped(values), np.zeros_like(values)
        for axis in range(3):
            worst = np.zeros_like(values)
            for sign in (1.0, -1.0):
                moved = values.copy()
                moved[:, axis] += sign * delta[:, axis]
                worst = np.maximum(worst, np.abs(mapped(moved) - base))
            total += worst
    return (np.nan_to_num(total) * peak).reshape(linear.shape)


def mapped_allowance(
    src: paths.Endpoint,
    back: np.ndarray,
    display: Display,
    view: str,
    codes: np.ndarray,
    expected: np.ndarray,
    shifted=None,
) -> np.ndarray | None:
    """:func:`float32_allowance` for a gamut-mapped view: the float32 shift of the display's
    linear values (and the mapping operator's own departure) applied to the mapped light,
    which the display encoding then meets where it is: a mapping can move a channel from
    below 0 to just above it, where a power law is steepest."""
    if src.matrix is None or src.linear is None:
        return None
    ref, shift = shifted or float32_shift(src, back, codes)
    with np.errstate(all="ignore"):
        shift = shift + _operator_shift(display, view, apply_matrix(np.linalg.inv(back), ref), shift)
    return _encoded_shift(display, expected, shift)


def hsv_file_allowance(display: Display, view: str, light: np.ndarray, expected: np.ndarray) -> np.ndarray:
    """The allowance of an HSV view's display file checked on its own: the view operator's
    rounding (:func:`_operator_shift`) of the display light ``light`` (1 = 100 cd/m²) the
    file's input stands for, applied to the mapped light and encoded."""
    with np.errstate(all="ignore"):
        shift = _operator_shift(display, view, light, np.zeros_like(light))
    return _encoded_shift(display, expected, shift)


def _encoded_shift(display: Display, expected: np.ndarray, shift: np.ndarray) -> np.ndarray:
    """The code difference a shift of the display light behind codes ``expected`` makes,
    either way, within the display's range."""
    with np.errstate(all="ignore"):
        light = np.clip(reference.display_decode(display, expected), 0.0, display.clip_high)
        moved = [
            reference.display_encode(display, np.clip(light + sign * shift, 0.0, display.clip_high))
            for sign in (1.0, -1.0)
        ]
        allowance = np.maximum(np.abs(moved[0] - expected), np.abs(moved[1] - expected))
    return np.where(np.isfinite(allowance), allowance, 0.0)


def view_allowance(spec: Spec, src, back, display, view, codes, expected, clip_encode, shifted=None):
    """The allowance of a view check: :func:`float32_allowance` through the Colorimetric
    view for clip, :func:`lattice_allowance` for a view defined by its lattice (``spec``
    rebuilds it), :func:`mapped_allowance` for the other gamut-mapped views. ``shifted``:
    ``float32_shift(src, back, codes)``, shared by the views of one display."""
    if expected is None:
        return None
    method = paths.view_method(view)
    if method == "clip":
        return float32_allowance(src, back, clip_encode, codes, shifted)
    if method in paths.lattice_defined():
        return lattice_allowance(spec, src, back, display, method, codes, shifted)
    found = None if method is not None else reference.aces_view_of(display, view)
    if found is not None and found.version == "2.0" and paths.aces_baked(spec, display, view):
        return aces_file_allowance(spec, src, back, display, view, codes, expected, shifted)
    return mapped_allowance(src, back, display, view, codes, expected, shifted)


def aces_file_allowance(spec: Spec, src, back, display, view, codes, expected, shifted=None) -> np.ndarray | None:
    """For an ACES 2.0 view a 2.1 to 2.3 config runs from its baked file: the float32 shift of
    the input carried into AP1 and moved through the file one channel at a time either way and
    encoded, summed over the channels (to first order a bound), plus the file's Log operator's
    rounding of the luminance near its toe (:data:`~generator.tolerances.ACES_LOG_ROUNDINGS`),
    the colour scaled either way, and of its chromaticity (p and q each moved either way by
    :data:`~generator.tolerances.ACES_CHROMA_ROUNDINGS`); then :func:`mapped_allowance`'s shift of
    the light after it. Near black a pure-power display turns that rounding into codes."""
    mapped = mapped_allowance(src, back, display, view, codes, expected, shifted)
    if mapped is None:
        return None
    found = reference.aces_view_of(display, view)
    lat = aces_lattice.bake(found)
    u = tolerances.FLOAT32_UNIT_ROUNDOFF
    ref, shift = shifted or float32_shift(src, back, codes)
    to_ap1 = views.tables(found).ap0_to_ap1 @ reference.to_aces_matrix(spec)
    to_xyz = aces_lattice.to_xyz(found)

    def at(coordinate):
        light = np.clip(aces_lattice.output_at(lat, coordinate), 0.0, 1.0) @ to_xyz.T
        return reference.display_xyz_encode(spec, display, light)

    def encoded(ap1):
        return at(lat.coordinate(ap1))

    with np.errstate(all="ignore"):
        ap1 = np.nan_to_num(apply_matrix(to_ap1, ref)).reshape(-1, 3)
        reach = apply_matrix(np.abs(to_ap1 @ back), np.nan_to_num(shift)).reshape(
            -1, 3
        ) + tolerances.FLOAT32_MATRIX_ROUNDINGS * u * np.abs(ap1)
        start = np.nan_to_num(np.asarray(expected, dtype=np.float64).reshape(-1, 3))
        moved = np.zeros_like(start)
        for channel in range(3):
            step = np.zeros_like(ap1)
            step[:, channel] = reach[:, channel]
            moved += np.maximum(np.abs(encoded(ap1 + step) - start), np.abs(encoded(ap1 - step) - start))
        # the Log operator rounds the luminance alone: the colour scaled, its chromaticity kept
        luminance = np.maximum(ap1, 0.0) @ lat.axes.ryb[1]
        scale = tolerances.ACES_LOG_ROUNDINGS * u * lat.axes.log.toe / np.where(luminance > 0.0, luminance, np.inf)
        moved += np.maximum(
            np.abs(encoded(ap1 * (1.0 + scale[:, None])) - start),
            np.abs(encoded(ap1 * np.maximum(1.0 - scale, 0.0)[:, None]) - start),
        )
        pq, lum = lat.axes.chromaticity(np.clip(ap1, 0.0, lat.upper))
        for channel in range(2):
            step = np.zeros_like(pq)
            step[:, channel] = tolerances.ACES_CHROMA_ROUNDINGS * u
            moved += np.maximum(
                *(np.abs(at(lat.axes.placed(np.clip(pq + sign * step, 0.0, 1.0), lum)) - start) for sign in (1.0, -1.0))
            )
    return mapped + np.where(np.isfinite(moved), moved, 0.0).reshape(np.shape(mapped))


def lattice_allowance(
    spec: Spec,
    src: paths.Endpoint,
    back: np.ndarray,
    display: Display,
    method: str,
    codes: np.ndarray,
    shifted=None,
) -> np.ndarray | None:
    """For a view defined by its lattice (:func:`paths.lattice_codes`): the float32 shift of
    the display's linear values (:func:`float32_shift`) carried through the file with the
    file's own rounding (:func:`lattice_file_allowance`). The file's pre-shaper is the
    display's curve, steepest at 0, where the shift of a zero channel meets it."""
    if src.matrix is None or src.linear is None:
        return None
    ref, shift = shifted or float32_shift(src, back, codes)
    with np.errstate(all="ignore"):
        linear = apply_matrix(np.linalg.inv(back), ref)
    return lattice_file_allowance(spec, display, method, linear, shift)


#: Displacements of a lattice coordinate, each axis -1, 0 or +1 times its reach: a tetrahedral
#: lattice is linear on pieces bounded, around a node, by planes through it, so its largest
#: change over a box around a node is at one of these (diagonals included).
_BOX = np.array([d for d in np.ndindex(3, 3, 3) if d != (1, 1, 1)], dtype=np.float64) - 1.0


def lattice_file_allowance(
    spec: Spec, display: Display, method: str, linear: np.ndarray, shift: np.ndarray | None = None
) -> np.ndarray:
    """How far float32 evaluation may move the codes of a view file defined by its lattice at
    display-linear ``linear`` (1.0 = 100 cd/m²): each lattice coordinate may move by what the
    input's ``shift`` (if any) moves it, plus its float32 rounding (FLOAT32_MATRIX_ROUNDINGS u
    of a coordinate within [0, 1]: its Range's multiply-add and its shaper table's
    interpolation; and the rounding of the table's index, :func:`index_rounding`); the
    largest change of the file's output over that box (:data:`_BOX`). Near black, a
    coordinate's rounding times the lattice's slope is a large share of the light."""
    lat, peak = view_lattice(spec, display, method), display.clip_high

    def codes(coordinate):
        out = at_coordinates(lat, coordinate.reshape(-1, 3)).reshape(linear.shape)
        return out if lat.light is None else reference.display_encode(display, out * peak)

    with np.errstate(all="ignore"):
        start = coordinates(lat, linear / peak).reshape(linear.shape)
        reach = tolerances.FLOAT32_MATRIX_ROUNDINGS * tolerances.FLOAT32_UNIT_ROUNDOFF + index_rounding(
            lat, linear / peak
        ).reshape(linear.shape)
        if shift is not None:
            moves = [
                np.abs(coordinates(lat, (linear + sign * np.nan_to_num(shift)) / peak).reshape(linear.shape) - start)
                for sign in (1.0, -1.0)
            ]
            reach = reach + np.maximum(*moves)
        base, worst = codes(start), np.zeros_like(linear)
        for direction in _BOX:
            worst = np.maximum(worst, np.abs(codes(start + direction * reach) - base))
    return np.where(np.isfinite(worst), worst, 0.0)


@lru_cache(maxsize=4)
def _half_floats(top: float = np.inf) -> np.ndarray:
    """Every finite half float from 0 to ``top``, ascending, as float64 (read-only: shared)."""
    halves = np.arange(0x7C00, dtype=np.uint16).view(np.float16).astype(np.float64)
    halves = halves[halves <= top]
    halves.flags.writeable = False
    return halves


@lru_cache(maxsize=8)
def _pq_table(curve, size: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """OCIO's ST-2084 table of ``size`` codes from 0 to 1 (HALF_DOMAIN: every half-float code
    up to 1) as (lights, codes), the lights in float32 as OCIO stores them, and its inverse
    tabulated at every half-float light (the default optimisation's); where several codes give
    one light (the codes below PQ's black), the first, so the inverse departs most there."""
    codes = _half_floats(1.0) if size == HALF_DOMAIN else np.linspace(0.0, 1.0, size)
    lights = np.asarray(curve.decode(codes), dtype=np.float32).astype(np.float64)
    lights, first = np.unique(lights, return_index=True)
    return lights, codes[first], np.interp(_half_floats(), lights, codes[first])


def pq_table_departure(curve, size: int, light: np.ndarray, exact: np.ndarray | None = None) -> np.ndarray:
    """How far OCIO's encoding of display ``light`` (1 = 100 cd/m²) through the inverse of its
    ST-2084 table of ``size`` (:data:`generator.ocio.capabilities.PQ_BUILTIN_TABLES`) lands from
    PQ ``curve`` (``exact``: its codes, when already computed): the larger of the exact inverse (PQ
    interpolated linearly between the lights of the table's codes) and the default optimisation's
    (that inverse tabulated at every half-float light, interpolated linearly). Both chords cut PQ's
    steep curvature near black, where the half floats and the table's codes are coarse."""
    lights, codes, tabulated = _pq_table(curve, size)
    light = np.asarray(light, dtype=np.float64)
    with np.errstate(all="ignore"):
        if exact is None:
            exact = np.asarray(curve.encode(light), dtype=np.float64)
        inverse = np.interp(light, lights, codes)
        fast = np.interp(light, _half_floats(), tabulated)
    return np.nan_to_num(np.maximum(np.abs(inverse - exact), np.abs(fast - exact)))


def _pq_builtin_departure(
    spec: Spec, owner: str, curve_name: str, curve, decode, top: float, expected: np.ndarray
) -> np.ndarray | None:
    """:func:`pq_table_departure` at codes ``expected`` of the curve ``owner`` encodes with,
    over the libraries that read the config, where the ST-2084 builtin expresses it (light
    from ``decode``, clipped to [0, ``top``]); None otherwise."""
    chain = curve_chain(curve_label(spec, owner, curve_name), spec.ocio_version) or ()
    if PQ_BUILTIN not in {style for style, _ in chain}:
        return None
    with np.errstate(all="ignore"):
        light = np.clip(decode(expected), 0.0, top)
        exact = np.asarray(curve.encode(light), dtype=np.float64)
    tables = pq_builtin_tables(spec.ocio_version)
    return np.max([pq_table_departure(curve, size, light, exact) for size in tables], axis=0)


def builtin_encoding_allowance(spec: Spec, display: Display, expected: np.ndarray) -> np.ndarray | None:
    """The code departure of OCIO's own evaluation of ``display``'s encoding at codes ``expected``,
    per sample and channel, over the libraries that read the config (:func:`pq_table_departure`
    for a display the ST-2084 builtin encodes); None when the encoding is exact."""
    return _pq_builtin_departure(
        spec,
        display.name,
        display.eotf_name,
        display.eotf,
        lambda codes: reference.display_decode(display, codes),
        display.clip_high,
        expected,
    )


def scene_encoding_allowance(spec: Spec, space, expected: np.ndarray) -> np.ndarray | None:
    """As :func:`builtin_encoding_allowance` for a scene space the ST-2084 builtin encodes (its
    codes clamped to the signal range, 0 to 10000 cd/m²): OCIO 2.1 to 2.3 read the config with
    a 4096-code table, 1.2e-4 relative off near black."""
    return _pq_builtin_departure(spec, space.name, space.curve_name, space.curve, space.curve.decode, PQ_PEAK, expected)


def with_encoding(
    allowance: np.ndarray | None, spec: Spec, display: Display | None, expected: np.ndarray | None, space=None
) -> np.ndarray | None:
    """``allowance`` plus :func:`builtin_encoding_allowance` for a check whose output is
    ``display``'s codes ``expected``, or :func:`scene_encoding_allowance` for one whose output
    is scene ``space``'s codes (unchanged otherwise)."""
    if expected is None or (display is None and space is None):
        return allowance
    encoding = (
        builtin_encoding_allowance(spec, display, expected)
        if display is not None
        else scene_encoding_allowance(spec, space, expected)
    )
    if encoding is None:
        return allowance
    return encoding if allowance is None else allowance + encoding
