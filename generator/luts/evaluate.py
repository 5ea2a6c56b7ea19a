"""A display-layout lattice file (:func:`generator.luts.lattice.display_lattice`, an
:class:`~generator.luts.axes.Axis` behind a :class:`~generator.luts.lattice.PreShaper`)
evaluated in float64 as OCIO runs it: the pre-shaper, the Range that clamps its output to
the shaper's domain, the shaper table (linear), the 3D table (tetrahedral) and, for a file
ending in display light, the pre-shaper's exact inverse.

A view whose mapping no lattice holds (:data:`generator.luts.view.LATTICE_DEFINED`) is
this evaluation: the verifier compares OCIO with it, and bench/lut_accuracy.py measures
how far the file, through OCIO, departs from the mapping itself.
"""

from __future__ import annotations

import numpy as np

from generator import tolerances
from generator.luts import lattice
from generator.luts.fit import tetrahedra
from generator.luts.lattice import Lattice, PreShaper, as_pre_shaper, grid, preimages, shaper_table
from generator.luts.solve import interpolate


def coordinates(lat: Lattice, linear) -> np.ndarray:
    """The lattice coordinates (0 to 1 along each axis, shape (m, 3)) of normalised
    display-linear RGB ``linear`` (..., 3) in ``lat``'s file: the pre-shaper, then the Range
    that clamps to the shaper's domain and the shaper table (:func:`lattice.coordinates`).
    NaN reads as 0."""
    flat = np.asarray(linear, dtype=np.float64).reshape(-1, 3)
    with np.errstate(all="ignore"):
        return lattice.coordinates(lat, as_pre_shaper(lat.pre).forward(np.nan_to_num(flat, nan=0.0)))


def index_rounding(lat: Lattice, linear) -> np.ndarray:
    """How far float32 may move the lattice coordinates (m, 3) of normalised display-linear
    ``linear`` (..., 3) through the rounding of the shaper table's fractional index
    (FLOAT32_TABLE_INDEX_ROUNDINGS units of it): times the table's step there."""
    flat = np.nan_to_num(np.asarray(linear, dtype=np.float64).reshape(-1, 3), nan=0.0)
    if lat.shaper is None:
        return np.zeros_like(flat)
    with np.errstate(all="ignore"):
        position, entry = lattice.table_position(lat, as_pre_shaper(lat.pre).forward(flat))
    step = np.abs(lat.shaper[entry + 1] - lat.shaper[entry])
    return tolerances.FLOAT32_TABLE_INDEX_ROUNDINGS * tolerances.FLOAT32_UNIT_ROUNDOFF * position * step


def display_file(lat: Lattice, linear) -> np.ndarray:
    """The output of ``lat``'s file for normalised display-linear RGB ``linear`` (..., 3),
    1 = the display's peak: code values, or normalised display light for a file ending in
    light. A colour with a NaN channel gives NaN (the verifier holds non-finite probes to the
    display's range instead); an infinity is clamped by the Range."""
    if not isinstance(lat.pre, PreShaper) or lat.shaper is None or lat.post is not None:
        raise ValueError("display_file evaluates a display-layout lattice behind a pre-shaper")
    linear = np.asarray(linear, dtype=np.float64)
    out = at_coordinates(lat, coordinates(lat, linear))
    out[np.isnan(linear.reshape(-1, 3)).any(axis=1)] = np.nan
    return out.reshape(linear.shape)


def at_coordinates(lat: Lattice, coordinate: np.ndarray) -> np.ndarray:
    """``lat``'s file from its lattice coordinates (m, 3) on: the 3D table (tetrahedral) and,
    for a file ending in light, the pre-shaper's exact inverse; shape (m, 3)."""
    index = np.clip(coordinate, 0.0, 1.0).T * (lat.size - 1)
    nodes, weights = tetrahedra(np.ascontiguousarray(index), lat.size)
    out = interpolate(nodes, weights, lat.cube.reshape(-1, 3).T).T
    return out if lat.light is None else as_pre_shaper(lat.light).inverse(out)


def cell_inputs(lat: Lattice) -> np.ndarray:
    """One normalised display-linear input ((n - 1)³, 3) in every cell of ``lat``'s file: the
    middle of its pre-shaped span on each axis."""
    shaped = preimages(lat.size, lat.shaper, lat.domain)
    return grid(as_pre_shaper(lat.pre).inverse((shaped[1:] + shaped[:-1]) / 2.0)).reshape(-1, 3)


def shaper_inputs(lat: Lattice, other: float = 0.5) -> np.ndarray:
    """Colours (3 (2 k - 1), 3), normalised display-linear, with one channel on each of the
    ``k`` entries of ``lat``'s shaper table and on the middle between neighbours, the other
    two at ``other``: every entry of the table (one column, for the three channels) is read
    where the file's output moves with it (a grey far below black or above the peak maps to
    black or white, whatever its coordinate)."""
    entries = np.linspace(lat.domain[0], lat.domain[1], shaper_table(lat).size)
    linear = as_pre_shaper(lat.pre).inverse(np.sort(np.concatenate([entries, (entries[1:] + entries[:-1]) / 2.0])))
    out = np.full((3, linear.size, 3), other)
    for channel in range(3):
        out[channel, :, channel] = linear
    return out.reshape(-1, 3)
