"""A display-layout lattice file (:func:`generator.luts.lattice.display_lattice`, an
:class:`~generator.luts.axes.Axis` behind a :class:`~generator.luts.lattice.PreShaper`)
evaluated in float64 as OCIO runs it: the pre-shaper, the Range that clamps its output to
the shaper's domain, the shaper table (linear), the 3D table (tetrahedral) and, for a file
ending in display light, the pre-shaper's exact inverse.

A view whose mapping no lattice holds (:data:`generator.luts.view.LATTICE_DEFINED`) is
this evaluation: the verifier compares OCIO with it, and bench/lut_accuracy.py measures
how far it departs from the mapping itself.
"""

from __future__ import annotations

import numpy as np

from generator.luts.fit import tetrahedral_weights
from generator.luts.lattice import Lattice, PreShaper
from generator.luts.solve import interpolate


def display_file(lat: Lattice, linear) -> np.ndarray:
    """The output of ``lat``'s file for normalised display-linear RGB ``linear`` (..., 3),
    1 = the display's peak: code values, or normalised display light for a file ending in
    light. A colour with a NaN channel gives NaN (the verifier holds non-finite
    probes to the display's range instead); an infinity is clamped by the Range."""
    if not isinstance(lat.pre, PreShaper) or lat.shaper is None or lat.post is not None:
        raise ValueError("display_file evaluates a display-layout lattice behind a pre-shaper")
    linear = np.asarray(linear, dtype=np.float64)
    flat = linear.reshape(-1, 3)
    number = ~np.isnan(flat).any(axis=1)
    with np.errstate(all="ignore"):
        shaped = np.clip(lat.pre.forward(np.nan_to_num(flat, nan=0.0)), *lat.domain)
    entries = np.linspace(lat.domain[0], lat.domain[1], lat.shaper.size)
    index = np.interp(shaped, entries, lat.shaper) * (lat.size - 1)
    nodes, weights = tetrahedral_weights(index, lat.size)
    out = interpolate(nodes.T, weights.T, lat.cube.reshape(-1, 3).T).T
    if lat.light is not None:
        out = lat.light.inverse(out)
    out[~number] = np.nan
    return out.reshape(linear.shape)
