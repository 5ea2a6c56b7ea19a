"""The desaturate view as an exact lattice in OCIO's extended-range HSV.

Desaturation (:func:`generator.gamut.simple.desaturate`) keeps a colour's hue
(the hue of HSV, which no positive scaling or grey added changes) and its
luminance ``Y``, and sets the smallest channel to 0: the mixed colour has HSV
saturation 1 and value ``Y / h_Y(H)``, where ``h_Y(H)`` is the luminance of the
hue's fully saturated colour of value 1. The final scale into the cube is a
clamp of that value at 1. A config view can therefore run::

    display RGB -> FixedFunction RGB_TO_HSV -> shared file -> display's file -> FixedFunction HSV_TO_RGB

where a shared file (:func:`shared_clf`, the same for every display) turns
OCIO's ``(H, S, V)`` into ``(H / 6, u, V)`` lattice coordinates and the display's
file (a CLF: Matrix, LUT1D, LUT3D trilinear, LUT1D) takes them to ``(H, S', V')``.

The coordinates, OCIO's HSV and the float32 limits are in :mod:`generator.luts.hsv_axes`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import PyOpenColorIO as ocio

from generator import reference
from generator.luts import numbers, transforms
from generator.luts.clf import clf_file
from generator.luts.hsv_axes import (
    HSV_SIZE,
    SHARED_SCALE,
    VALUE_NODES,
    _saturation_of_u,
    hue_shape,
    hue_to_kappa,
    kappa_to_hue,
    lattice_coordinates,
    ocio_hsv_to_rgb,
    saturation_nodes,
    shared_table,
)
from generator.spec.schema import Display

#: Entries of the display file's 1D tables (hue to ``kappa``, and back with the clamp of
#: the value), a multiple of six plus one so the six primaries and secondaries, where
#: ``kappa`` bends, are on entries. Their linear interpolation is the file's main error,
#: amplified where a colour of luminance near 0 maps to ``V ((2u - 1) + (1 - u) / h_Y)``, a
#: difference of two large terms, near blue, where ``1 / h_Y`` is steep and curved: on an
#: ACEScct blue ramp near black, Gamma 2.6 DCI-P3, 1.04 ten-bit codes off with 6145
#: entries, 0.29 with 12289, where OCIO's own float32 HSV of those colours is uncertain by
#: 0.16 (through verify, every check the same with 24577).
HSV_ENTRIES = 6 * 2048 + 1

#: Name of the shared file in a config's LUT folder.
SHARED_FILE = "hsv_coordinates.clf"

#: Significant digits of the 3D table's and the shared table's values (over range about 7e12):
#: 9 keep every float32; the file holds float32 of them.
HSV_DIGITS = 9

#: Decimals of the 1D tables' values (lattice coordinates and hue, within [0, 1]).
HSV_TABLE_DECIMALS = 9


@dataclass(frozen=True)
class HsvLattice:
    """The file's parts: ``pre`` and ``post`` 1D tables (entries, 3) and the cube (n, n, n, 3)
    indexed [hue, saturation, value]. The file's input is the shared table's output."""

    display: Display
    pre: np.ndarray
    cube: np.ndarray
    post: np.ndarray

    @property
    def size(self) -> int:
        """Nodes along each axis of the cube."""
        return self.cube.shape[0]


def luminance_weights(display: Display) -> np.ndarray:
    """The display's relative luminance of its RGB, weights summing to 1."""
    weights = reference.display_gamut(display).luminance_weights
    return weights / weights.sum()


def hsv_lattice(display: Display) -> HsvLattice:
    """The desaturate view of ``display`` (module docstring)."""
    weights = luminance_weights(display)
    u, v = saturation_nodes(), np.array(VALUE_NODES)
    x = np.linspace(0.0, 1.0, HSV_ENTRIES)
    pre = np.stack([hue_to_kappa(x, weights), x, x], axis=-1)
    post = np.stack([kappa_to_hue(x, weights), x, x], axis=-1)

    kappa, uu, value = np.meshgrid(np.linspace(0.0, 1.0, HSV_SIZE), u, v, indexing="ij")
    hue, saturation = kappa_to_hue(kappa, weights), _saturation_of_u(uu)
    luminance = ocio_hsv_to_rgb(np.stack([hue, saturation, value], axis=-1), max_saturation=2.0) @ weights
    inside = (uu <= 1.0) & (value >= 0.0)
    mixed_value = np.where(inside, value, luminance / (hue_shape(hue) @ weights))
    cube = np.stack([kappa, np.minimum(uu, 1.0), mixed_value], axis=-1)
    return HsvLattice(display, pre, cube, post)


def trilinear(cube: np.ndarray, coordinate: np.ndarray, weight_bits: int | None = None) -> np.ndarray:
    """The lattice ``cube`` (n, n, n, 3) interpolated trilinearly in float64 at lattice
    ``coordinate`` (m, 3) in [0, 1], as the file's LUT3D is; with ``weight_bits``, each
    weight rounded to that many bits, as a GPU's texture filtering rounds them."""
    n = cube.shape[0]
    index = np.clip(coordinate, 0.0, 1.0) * (n - 1)
    base = np.clip(np.floor(index).astype(int), 0, n - 2)
    fraction = index - base
    if weight_bits:
        fraction = np.round(fraction * 2**weight_bits) / 2**weight_bits
    out = np.zeros(coordinate.shape)
    for corner in np.ndindex(2, 2, 2):
        weight = np.prod([fraction[:, k] if corner[k] else 1.0 - fraction[:, k] for k in range(3)], axis=0)
        out += weight[:, None] * cube[base[:, 0] + corner[0], base[:, 1] + corner[1], base[:, 2] + corner[2]]
    return out


def apply(lat: HsvLattice, values: np.ndarray, weight_bits: int | None = None) -> np.ndarray:
    """The view's two files on OCIO HSV ``values`` (n, 3) in float64, their 1D tables' exact
    functions in place of the tables: the HSV of the mapped colour, for HSV_TO_RGB (with
    ``weight_bits``, the lattice's weights rounded as a GPU's texture filtering rounds them)."""
    weights = luminance_weights(lat.display)
    mapped = trilinear(lat.cube, lattice_coordinates(values, weights), weight_bits)
    return np.stack([kappa_to_hue(mapped[:, 0], weights), mapped[:, 1], np.clip(mapped[:, 2], 0.0, 1.0)], axis=-1)


def hsv_clf(lat: HsvLattice, identifier: str, description: str) -> bytes:
    """The CLF of ``lat``, written by OCIO (:mod:`generator.luts.clf`): Matrix (hue back from the
    shared table's ``H / 6``), LUT1D (hue to ``kappa``; the other coordinates pass), LUT3D
    (trilinear), LUT1D."""
    steps = [
        transforms.matrix_transform(np.diag([SHARED_SCALE, 1.0, 1.0])),
        transforms.lut1d(numbers.rounded(lat.pre, HSV_TABLE_DECIMALS)),
        transforms.lut3d(numbers.significant(lat.cube, HSV_DIGITS), ocio.INTERP_LINEAR),
        transforms.lut1d(numbers.rounded(lat.post, HSV_TABLE_DECIMALS)),
    ]
    return clf_file(steps, identifier, description)


def shared_steps() -> list:
    """The shared file's transforms: a Matrix taking OCIO's ``(H, S, V)`` to ``(H, 2 - S, V)``,
    then one half-domain LUT1D (:func:`shared_table`)."""
    matrix = transforms.matrix_transform(np.diag([1.0, -1.0, 1.0]), offset=[0.0, 2.0, 0.0])
    matrix.setFileOutputBitDepth(ocio.BIT_DEPTH_F16)  # the LUT1D after it reads half floats
    return [matrix, transforms.lut1d(numbers.significant(shared_table(), HSV_DIGITS), half_domain=True)]


@lru_cache(maxsize=1)
def shared_clf() -> bytes:
    """The shared CLF of :func:`shared_steps`, written by OCIO."""
    return clf_file(
        shared_steps(),
        "ocioforge:hsv_coordinates",
        "ocioforge: OCIO HSV (H, S, V) to the desaturate views' lattice coordinates (H / 6, "
        "saturation's u = 1 / (2 - S) above S = 1, value's), shared by every display.",
    )
