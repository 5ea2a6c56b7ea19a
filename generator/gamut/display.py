"""The destination display of a gamut mapping, and the shared input policy.

Every gamut-mapping method acts on *linear* RGB of the destination display:
the caller has already applied the source-to-display matrix, so colours the
display cannot show have components below 0 or above 1. A method needs only
the display's RGB-to-XYZ matrix (its second row gives the luminance weights)
and its white chromaticity, held by :class:`DisplayGamut`.

Non-finite input policy, identical for every method (:func:`sanitize`):

* NaN becomes 0;
* -Inf becomes 0;
* +Inf becomes :data:`LARGEST`, the largest finite value, so it behaves as
  any very large value and maps to 1 in that channel;
* finite values beyond +/- :data:`LARGEST` are clamped to it, which keeps
  every intermediate product of the methods finite in float64.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Largest magnitude accepted, the largest finite IEEE 754 binary32 value; +Inf maps to it.
LARGEST = float(np.finfo(np.float32).max)

#: A display white's chromaticity must agree with its matrix's white this closely.
_WHITE_AGREEMENT = 1e-4


def sanitize(rgb) -> np.ndarray:
    """Apply the non-finite input policy and return float64 RGB.

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Linear display RGB, any real values.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64
        A new array: NaN and -Inf replaced by 0, +Inf by :data:`LARGEST`, and
        finite values clamped to [-LARGEST, LARGEST].

    Raises
    ------
    ValueError
        If the last axis is not of length 3.
    """
    values = np.array(rgb, dtype=np.float64)
    if values.ndim == 0 or values.shape[-1] != 3:
        raise ValueError(f"expected RGB of shape (..., 3), got {values.shape}")
    if not np.isfinite(values).all():  # finite input, the common case, skips the replacements' passes
        values = np.nan_to_num(values, nan=0.0, posinf=LARGEST, neginf=0.0)
    return np.clip(values, -LARGEST, LARGEST, out=values)


def matrix_tuple(matrix) -> tuple[tuple[float, float, float], ...]:
    """A finite, invertible 3x3 matrix as an immutable tuple of rows; ValueError otherwise."""
    m = np.asarray(matrix, dtype=np.float64)
    if m.shape != (3, 3) or not np.all(np.isfinite(m)):
        raise ValueError(f"expected a finite 3x3 matrix, got shape {m.shape}")
    if abs(np.linalg.det(m)) < 1e-12:
        raise ValueError("the matrix is singular")
    return tuple((float(r), float(g), float(b)) for r, g, b in m)


@dataclass(frozen=True)
class DisplayGamut:
    """A destination display: its linear RGB to CIE XYZ matrix and white.

    Parameters
    ----------
    rgb_to_xyz : array_like, shape (3, 3)
        Normalised primary matrix, ``XYZ = rgb_to_xyz @ rgb``; the white
        ``rgb = (1, 1, 1)`` has luminance ``Y = 1`` (SMPTE RP 177).
    white_xy : array_like, shape (2,)
        CIE 1931 chromaticity of the display white; it must agree with the
        matrix's white within 1e-4 in x and y.

    Both are stored as tuples so that the record is immutable and hashable.
    """

    rgb_to_xyz: tuple[tuple[float, float, float], ...]
    white_xy: tuple[float, float]

    def __post_init__(self) -> None:
        object.__setattr__(self, "rgb_to_xyz", matrix_tuple(self.rgb_to_xyz))
        white = np.asarray(self.white_xy, dtype=np.float64)
        if white.shape != (2,) or not np.all(np.isfinite(white)):
            raise ValueError(f"expected a finite white chromaticity (x, y), got {self.white_xy!r}")
        object.__setattr__(self, "white_xy", (float(white[0]), float(white[1])))
        implied = _xyz_to_xy(self.white_xyz)
        if np.max(np.abs(implied - white)) > _WHITE_AGREEMENT:
            raise ValueError(f"white {tuple(white)} disagrees with the matrix's white {tuple(implied)}")

    @classmethod
    def from_colourspace(cls, colourspace) -> DisplayGamut:
        """The display of a colour-science RGB colourspace (read, never modified)."""
        return cls(colourspace.matrix_RGB_to_XYZ, colourspace.whitepoint)

    @property
    def matrix(self) -> np.ndarray:
        """``rgb_to_xyz`` as a new float64 array of shape (3, 3)."""
        return np.array(self.rgb_to_xyz, dtype=np.float64)

    @property
    def luminance_weights(self) -> np.ndarray:
        """The Y row of ``rgb_to_xyz``, shape (3,): ``Y = rgb @ weights``."""
        return self.matrix[1]

    @property
    def white_xyz(self) -> np.ndarray:
        """XYZ of the display white ``rgb = (1, 1, 1)``."""
        return self.matrix.sum(axis=1)

    @property
    def primaries_xy(self) -> np.ndarray:
        """Chromaticities of the red, green and blue primaries, shape (3, 2)."""
        return _xyz_to_xy(self.matrix.T)


def _xyz_to_xy(xyz) -> np.ndarray:
    """Chromaticity of tristimulus values (..., 3)."""
    xyz = np.asarray(xyz, dtype=np.float64)
    return xyz[..., :2] / xyz.sum(axis=-1, keepdims=True)
