"""RGB <-> XYZ and RGB <-> RGB matrices, derived from primaries and white points.

The normalised primary matrix follows SMPTE RP 177-1993; chromatic adaptation
is a von Kries-type transform in the cone space of the chosen CAT, whose
published matrices are held here as data (tests check them against
colour-science's, value for value) so that deriving a matrix never imports
colour-science, which takes a second to load. Every gamut matrix is computed
from chromaticities.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass
from typing import ParamSpec

import numpy as np

#: Chromatic adaptation transforms a spec may name, mapped to colour-science's names.
#: "none" keeps XYZ unchanged across white points (no adaptation at all).
CATS = {
    "Bradford": "Bradford",
    "CAT02": "CAT02",
    "CAT16": "CAT16",
    "von Kries": "Von Kries",
    "XYZ scaling": "XYZ Scaling",
    "none": None,
}

#: XYZ to cone-like responses of each transform, as published: Bradford (K. M. Lam, 1985,
#: as in CIE 159:2004 annex and ICC.1), CAT02 (CIE 159:2004), CAT16 (C. Li et al., "Comprehensive
#: color solutions: CAM16, CAT16, and CAM16-UCS", Color Res. Appl. 42, 2017), von Kries
#: (the Hunt-Pointer-Estevez matrix normalised to equal-energy white) and XYZ scaling.
CONE_MATRICES = {
    "Bradford": ((0.8951, 0.2664, -0.1614), (-0.7502, 1.7135, 0.0367), (0.0389, -0.0685, 1.0296)),
    "CAT02": ((0.7328, 0.4296, -0.1624), (-0.7036, 1.6975, 0.0061), (0.0030, 0.0136, 0.9834)),
    "CAT16": ((0.401288, 0.650173, -0.051461), (-0.250268, 1.204414, 0.045854), (-0.002079, 0.048952, 0.953127)),
    "von Kries": ((0.40024, 0.70760, -0.08081), (-0.22630, 1.16532, 0.04570), (0.0, 0.0, 0.91822)),
    "XYZ scaling": ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
}


@dataclass(frozen=True)
class Gamut:
    """An RGB gamut: three primaries, the white point they are balanced to,
    and the white its values are relative to when adapting (the same, except
    for XYZ-like spaces whose white is E by construction but whose values are
    relative to another illuminant, such as CIE XYZ-D65)."""

    name: str
    primaries: tuple[tuple[float, float], tuple[float, float], tuple[float, float]]
    whitepoint: tuple[float, float]
    adapting_white: tuple[float, float] | None = None
    citation: str = ""
    #: The chromatic adaptation the gamut's publisher derives its matrices to other whites
    #: with (a key of CATS), where it publishes them; None otherwise.
    adaptation: str | None = None

    @property
    def white(self) -> tuple[float, float]:
        """The white point colours in this gamut are adapted to."""
        return self.adapting_white or self.whitepoint

    @property
    def rgb_to_xyz(self) -> np.ndarray:
        """The normalised primary matrix: linear RGB to CIE XYZ (SMPTE RP 177)."""
        return normalised_primary_matrix(self.primaries, self.whitepoint)

    @property
    def xyz_to_rgb(self) -> np.ndarray:
        """CIE XYZ to linear RGB: the inverse of :attr:`rgb_to_xyz`."""
        return np.linalg.inv(self.rgb_to_xyz)


def xy_to_XYZ(xy) -> np.ndarray:
    """Chromaticity (..., 2) to tristimulus with Y = 1."""
    xy = np.asarray(xy, dtype=np.float64)
    x, y = xy[..., 0], xy[..., 1]
    return np.stack([x / y, np.ones_like(x), (1.0 - x - y) / y], axis=-1)


_P = ParamSpec("_P")


def _remembered(derive: Callable[_P, np.ndarray]) -> Callable[_P, np.ndarray]:
    """``derive`` computed once per hashable arguments (chromaticities as tuples): a pack or a
    verify derives the same few matrices thousands of times. Each call gets its own copy;
    arguments that do not hash (arrays, lists) are derived anew."""
    cached: Callable[..., np.ndarray] = functools.lru_cache(maxsize=1024)(derive)

    @functools.wraps(derive)
    def matrix(*args: _P.args, **kwargs: _P.kwargs) -> np.ndarray:
        try:
            return cached(*args, **kwargs).copy()
        except TypeError:  # unhashable arguments
            return derive(*args, **kwargs)

    return matrix


@_remembered
def normalised_primary_matrix(primaries, whitepoint) -> np.ndarray:
    """RGB -> XYZ matrix of a gamut (SMPTE RP 177-1993, equation 3.3).

    Columns are the primaries' XYZ, scaled so that RGB (1, 1, 1) maps to the
    white point with Y = 1.
    """
    p = np.asarray(primaries, dtype=np.float64)
    columns = np.stack([p[:, 0], p[:, 1], 1.0 - p[:, 0] - p[:, 1]], axis=0)
    scale = np.linalg.solve(columns, xy_to_XYZ(whitepoint))
    return columns * scale[np.newaxis, :]


@_remembered
def adaptation_matrix(source_white, target_white, cat: str = "Bradford") -> np.ndarray:
    """XYZ -> XYZ chromatic adaptation from ``source_white`` to ``target_white`` (xy).

    ``cat`` is one of :data:`CATS`; "none" gives the identity.
    """
    if cat not in CATS:
        raise ValueError(f"unknown chromatic adaptation {cat!r}; allowed: {', '.join(CATS)}")
    if CATS[cat] is None or np.allclose(source_white, target_white, rtol=0, atol=1e-12):
        return np.eye(3)
    return von_kries(xy_to_XYZ(source_white), xy_to_XYZ(target_white), cat)


def von_kries(source_xyz, target_xyz, cat: str) -> np.ndarray:
    """XYZ -> XYZ von Kries adaptation in the cone space of ``cat`` (a key of
    :data:`CONE_MATRICES`) from white ``source_xyz`` to ``target_xyz`` (tristimulus values,
    whose scale is kept: the package's one chromatic adaptation)."""
    cones = np.array(CONE_MATRICES[cat], dtype=np.float64)
    gain = (cones @ np.asarray(target_xyz, dtype=np.float64)) / (cones @ np.asarray(source_xyz, dtype=np.float64))
    return (np.linalg.inv(cones) * gain[np.newaxis, :]) @ cones


def rgb_to_rgb(source: Gamut, target: Gamut, cat: str = "Bradford") -> np.ndarray:
    """Linear RGB of ``source`` to linear RGB of ``target``:
    M_target⁻¹ · CAT(w_source → w_target) · M_source."""
    return target.xyz_to_rgb @ adaptation_matrix(source.white, target.white, cat) @ source.rgb_to_xyz


def rgb_to_xyz_adapted(source: Gamut, xyz_white, cat: str = "Bradford") -> np.ndarray:
    """Linear RGB of ``source`` to XYZ relative to ``xyz_white`` (e.g. CIE XYZ-D65)."""
    return adaptation_matrix(source.white, xyz_white, cat) @ source.rgb_to_xyz


#: Float64 residue, relative to a matrix's largest entry (at least 1), of a derivation whose
#: exact value is an integer: gamuts sharing a primary or white (Rec.709 and P3-D65 share
#: blue; P3's and Rec.2020's red lie on x + y = 1, z = 0) give exact 0s and 1s, which the
#: inversions and products leave 1e-17 to 1e-15 off. An entry nearer an integer than this
#: without being it would take chromaticities given to 14 digits.
EXACT_RESIDUE = 1e-14


def settled(matrix) -> np.ndarray:
    """``matrix`` as written: entries within :data:`EXACT_RESIDUE` (relative) of an integer
    are that integer, and no zero is negative."""
    m = np.asarray(matrix, dtype=np.float64)
    whole = np.rint(m)
    residue = EXACT_RESIDUE * max(1.0, float(np.abs(m).max(initial=0.0)))
    return np.where(np.abs(m - whole) < residue, whole, m) + 0.0


def apply_matrix(matrix, rgb) -> np.ndarray:
    """Apply a 3x3 matrix to colours along the last axis of ``rgb``, channel by channel: each
    output is (m0 r + m2 b) + m1 g, whatever the layout of ``rgb`` (einsum summed in that order
    for contiguous colours, in another for strided ones, and took 2.7 times as long)."""
    m = np.asarray(matrix, dtype=np.float64)
    v = np.asarray(rgb, dtype=np.float64)
    if m.shape != (3, 3) or v.shape[-1:] != (3,):
        raise ValueError(f"apply_matrix takes a 3x3 matrix and colours (..., 3), got {m.shape} and {v.shape}")
    r, g, b = v[..., 0], v[..., 1], v[..., 2]
    out = np.empty(v.shape)
    for i in range(3):
        row = out[..., i]
        np.multiply(r, m[i, 0], out=row)
        row += b * m[i, 2]
        row += g * m[i, 1]
    return out


def channel_max(rgb: np.ndarray) -> np.ndarray:
    """``rgb.max(axis=-1)`` of colours along the last axis (3), elementwise over the channels:
    numpy reduces along an axis of three thirty times slower (measured 9.6 ms against 0.3 ms
    for 262144 colours)."""
    return np.maximum(np.maximum(rgb[..., 0], rgb[..., 1]), rgb[..., 2])


def channel_min(rgb: np.ndarray) -> np.ndarray:
    """``rgb.min(axis=-1)``, as :func:`channel_max`."""
    return np.minimum(np.minimum(rgb[..., 0], rgb[..., 1]), rgb[..., 2])
