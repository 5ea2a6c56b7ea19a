"""A show's 3D LUT files (.cube, .spi3d) read by colour-science and applied as OpenColorIO applies
them: the input clamped to the file's domain, then trilinear or tetrahedral interpolation, in float64.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

#: The LUT files a look may name, which colour-science's ``read_LUT`` reads (it reads no CLF).
SUFFIXES = (".cube", ".spi3d")

#: Interpolations OpenColorIO offers a 3D LUT: its INTERP_LINEAR (trilinear), INTERP_TETRAHEDRAL.
INTERPOLATIONS = ("linear", "tetrahedral")


class LutFileError(ValueError):
    """A LUT file a look names that cannot be read as a 3D LUT."""


@dataclass(frozen=True, eq=False)
class Lut3D:
    """A 3D table ``table[r, g, b]`` over the input ``domain`` ((min rgb), (max rgb))."""

    table: np.ndarray
    domain: np.ndarray


def read_lut3d(path: str | Path) -> Lut3D:
    """The 3D LUT in the file at ``path``, through colour-science's ``read_LUT``."""
    import colour  # for start-up time only: colour-science takes a second to import

    try:
        lut = colour.read_LUT(str(path))
    except Exception as error:  # colour raises ValueError, IndexError and others on a malformed file
        raise LutFileError(f"colour-science cannot read it ({type(error).__name__}: {error})") from None
    if not isinstance(lut, colour.LUT3D):
        raise LutFileError(f"it holds a {type(lut).__name__}, not a 3D LUT alone")
    domain = np.asarray(lut.domain, dtype=np.float64)
    return Lut3D(np.asarray(lut.table, dtype=np.float64), domain)


@lru_cache(maxsize=16)
def _cached(path: str, mtime_ns: int, size: int) -> Lut3D:
    return read_lut3d(path)


def cached_lut3d(path: str | Path) -> Lut3D:
    """:func:`read_lut3d`, read again when the file changes."""
    stat = Path(path).stat()
    return _cached(str(path), stat.st_mtime_ns, stat.st_size)


def apply_lut3d(lut: Lut3D, rgb, interpolation: str = "linear") -> np.ndarray:
    """``rgb`` (..., 3) through ``lut``: clamped to its domain, scaled onto the lattice, then
    trilinear (``linear``) or tetrahedral interpolation, as OpenColorIO's Lut3D op does."""
    rgb = np.asarray(rgb, dtype=np.float64)
    size = np.asarray(lut.table.shape[:3])
    low, high = lut.domain
    position = (np.clip(np.nan_to_num(rgb, nan=0.0), low, high) - low) / (high - low) * (size - 1)
    base = np.minimum(np.floor(position).astype(int), size - 2)
    frac = position - base
    if interpolation == "tetrahedral":
        return _tetrahedral(lut.table, base, frac)
    return _trilinear(lut.table, base, frac)


def _node(table: np.ndarray, base: np.ndarray, corner) -> np.ndarray:
    return table[base[..., 0] + corner[0], base[..., 1] + corner[1], base[..., 2] + corner[2]]


def _trilinear(table: np.ndarray, base: np.ndarray, frac: np.ndarray) -> np.ndarray:
    out = np.zeros(base.shape[:-1] + (table.shape[-1],))
    for corner in np.ndindex(2, 2, 2):
        weight = np.prod(np.where(np.asarray(corner) == 1, frac, 1.0 - frac), axis=-1)
        out += weight[..., None] * _node(table, base, corner)
    return out


def _tetrahedral(table: np.ndarray, base: np.ndarray, frac: np.ndarray) -> np.ndarray:
    """The tetrahedron of the cell's six holding the sample, by the order of its fractions."""
    order = np.argsort(-frac, axis=-1, kind="stable")  # largest fraction first
    f = np.take_along_axis(frac, order, axis=-1)
    corner = np.zeros(base.shape, dtype=int)
    out = (1.0 - f[..., 0:1]) * _node(table, base, (0, 0, 0))
    weights = (f[..., 0] - f[..., 1], f[..., 1] - f[..., 2], f[..., 2])
    for step in range(3):
        np.put_along_axis(corner, order[..., step : step + 1], 1, axis=-1)
        out = out + weights[step][..., None] * table[
            base[..., 0] + corner[..., 0], base[..., 1] + corner[..., 1], base[..., 2] + corner[..., 2]
        ]
    return out
