"""The per-display LUT a config's gamut-mapped view references.

The view is scene-reference linear RGB -> :func:`~generator.reference.normalised_display_matrix`
(an OCIO MatrixTransform, exact, kept in the config) -> this CLF (pre-shaper,
Range, LUT1D, LUT3D in display axes, see :mod:`generator.luts.lattice`); for
desaturate, the matrix is followed by OCIO's RGB_TO_HSV, the shared coordinates
file, this file and HSV_TO_RGB (:mod:`generator.luts.hsv`). The function is
pure: it returns the file's name and bytes; the config writer writes them, and
:mod:`generator.ocio.view_luts` measures them through OCIO as the config runs them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

from generator import reference
from generator.luts import formats, hsv, hsv_axes, lattice
from generator.luts.axes import LOG_METHODS
from generator.luts.names import file_stems
from generator.spec.schema import Display, Spec

#: Lattice size of the config's view LUTs.
VIEW_SIZE = 33

#: Lattice size of a view LUT for clip and scale on a :class:`~generator.luts.axes.LogAxis`:
#: the mapping is linear inside every tetrahedron, so 17³ measures as 33³ (0.011 ten-bit
#: codes at most into sRGB; HLG's view ends in display light, which the config encodes,
#: so its lattice is exact too) in a seventh of the bytes.
LOG_VIEW_SIZE = 17


#: The method whose config view is an HSV lattice (:mod:`generator.luts.hsv`), exact but for
#: its 1D tables; its standalone bakes keep the display layout.
HSV_METHOD = "desaturate"

#: Methods whose config view is defined by its lattice: soft compressions that move colours
#: inside the display, lifting channels from 0 where code values are steepest, and that
#: turn sharply where their lines graze the cube's edges, so that no lattice holds them
#: (:mod:`generator.gamut.perceptual`). Such a view is its 33³ file
#: (:func:`generator.luts.evaluate.display_file`): verify holds OCIO to that, and
#: bench/lut_accuracy.py measures how far the file departs from the mapping.
LATTICE_DEFINED = ("perceptual",)


def view_size(display: Display, method: str) -> int:
    """The lattice size of the config's view LUT of ``method`` on ``display``."""
    return LOG_VIEW_SIZE if method in LOG_METHODS else VIEW_SIZE


@dataclass(frozen=True)
class ViewLut:
    """A view's baked LUT.

    ``matrix`` takes scene-reference linear RGB to the file's input (normalised
    display-linear RGB, 1 = the display's peak); the config applies it as a
    MatrixTransform before a FileTransform of ``filename``. The file's output is
    display code values, or with ``light`` normalised display-linear RGB (for an
    HDR display, :func:`ends_in_light`: the config encodes). Measured through OCIO
    as the config runs it by :func:`generator.ocio.view_luts.view_figures` (a build does not).
    """

    filename: str
    data: bytes
    matrix: tuple[tuple[float, float, float], ...]
    spec: Spec = field(repr=False)
    display: Display = field(repr=False)
    method: str
    beside: tuple[tuple[str, bytes], ...] = field(default=(), repr=False)
    light: bool = False
    hsv: bool = False


def ends_in_light(display: Display) -> bool:
    """Whether the view files of ``display`` end in normalised display light, for the
    config's display space to encode: HDR displays (CLF has no PQ or HLG operator, and an
    extended range's codes pass 1)."""
    return display.is_hdr or not lattice.encodes_in_clf(display)


def view_filename(spec: Spec, display: Display, method: str, size: int | None = None) -> str:
    """The file of the config's view of ``method`` on ``display`` (``size``: a lattice in
    display axes of that size, for a desaturate bake other than the config's HSV view),
    named after the display, uniquely among ``spec``'s displays (:func:`file_stems`)."""
    stem = file_stems([*(d.name for d in spec.displays), display.name])[display.name]
    if method == HSV_METHOD and size is None:
        return f"view_{stem}_{method}_hsv{hsv_axes.HSV_SIZE}.clf"
    return f"view_{stem}_{method}_{size or view_size(display, method)}.clf"


@lru_cache(maxsize=64)
def bake_view_lut_cached(spec: Spec, display: Display, method: str) -> ViewLut:
    """:func:`bake_view_lut` with default size and parameters, once per process for the same
    spec, display and method (a view LUT does not depend on the target OCIO version)."""
    return bake_view_lut(spec, display, method)


def bake_view_lut(spec: Spec, display: Display, method: str, size: int | None = None, params=None) -> ViewLut:
    """Bake the view of ``display`` with gamut mapping ``method`` (measured through OCIO when its
    figures are asked for).

    Parameters
    ----------
    spec : Spec
    display : Display
    method : str
        A key of :data:`generator.gamut.METHODS`.
    size : int, optional
        Lattice nodes a side (at most 129, OCIO's limit); default :func:`view_size`.
    params : optional
        The method's parameters.
    """
    if method == HSV_METHOD and size is None and params is None:
        return _bake_hsv_view(spec, display)
    size = size or view_size(display, method)
    light = ends_in_light(display)
    lat = (
        view_lattice(spec, display, method)
        if size == view_size(display, method) and params is None
        else lattice.display_lattice(spec, display, method, size, params=params, light=light)
    )
    name = view_filename(spec, display, method, size)
    output = (
        "normalised linear RGB (the config encodes it), gamut mapping {}, {}^3 lattice."
        if light
        else "code values, gamut mapping {}, {}^3 lattice in the display's code values."
    )
    text = (
        f"ocioforge view LUT: normalised {display.name} linear RGB (1 = peak, after the config's matrix) "
        f"to {output.format(method, size)}"
    )
    data = formats.clf(lat, f"ocioforge:{name[:-4]}", text, include_matrix=False)
    return _measured(spec, display, method, name, data, {}, lat.matrix, light)


@lru_cache(maxsize=64)
def view_lattice(spec: Spec, display: Display, method: str) -> lattice.Lattice:
    """The lattice of the config's view of ``method`` on ``display`` (not an HSV view), once
    per process: default size and parameters."""
    return lattice.display_lattice(spec, display, method, view_size(display, method), light=ends_in_light(display))


def _measured(
    spec: Spec,
    display: Display,
    method: str,
    name: str,
    data: bytes,
    beside: dict,
    matrix,
    light: bool,
    hsv_view: bool = False,
) -> ViewLut:
    """The view file ``data`` (with the files ``beside`` it, name to bytes) as a :class:`ViewLut`,
    measured when its figures are asked for."""
    matrix = tuple(tuple(float(v) for v in row) for row in matrix)
    return ViewLut(name, data, matrix, spec, display, method, tuple(beside.items()), light, hsv_view)


def _bake_hsv_view(spec: Spec, display: Display) -> ViewLut:
    """The desaturate view of ``display`` as an HSV lattice, measured through OCIO."""
    name = view_filename(spec, display, HSV_METHOD)
    text = (
        f"ocioforge view LUT: OCIO HSV of normalised {display.name} linear RGB (1 = peak, after the config's "
        f"matrix, RGB_TO_HSV and {hsv.SHARED_FILE}) to the HSV of its desaturated colour (before "
        "HSV_TO_RGB); trilinear."
    )
    data = hsv.hsv_clf(hsv.hsv_lattice(display), f"ocioforge:{name[:-4]}", text)
    return _measured(
        spec,
        display,
        HSV_METHOD,
        name,
        data,
        {hsv.SHARED_FILE: hsv.shared_clf()},
        reference.normalised_display_matrix(spec, display),
        True,
        True,
    )
