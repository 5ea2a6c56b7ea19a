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
    from colour.algebra import table_interpolation_tetrahedral, table_interpolation_trilinear  # start-up time

    rgb = np.asarray(rgb, dtype=np.float64)
    low, high = lut.domain
    # scaled onto the lattice first, as OCIO does: a NaN lands on the domain's minimum
    with np.errstate(invalid="ignore"):
        unit = np.clip(np.nan_to_num((rgb - low) / (high - low), nan=0.0), 0.0, 1.0)
    interpolate = table_interpolation_tetrahedral if interpolation == "tetrahedral" else table_interpolation_trilinear
    return interpolate(unit, lut.table)
