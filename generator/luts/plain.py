"""The plain recipe public generators use to bake an ACES view, which ocioforge's baked views
are measured against (bench/aces_views.py, bench/lut_accuracy.py, the tests).

ACES2065-1 to AP1, the ACEScct curve as the shaper (its codes from 0 to 1), and a 65³ table
of the display's code values sampled from the float64 reference at the nodes, read with
tetrahedral interpolation.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from generator import reference
from generator.colorimetry.curves import CURVES
from generator.luts.fit import tetrahedra
from generator.luts.solve import interpolate
from generator.rendering import views
from generator.spec.schema import Display, Spec

#: Nodes a side of the plain recipe's table.
PLAIN_SIZE = 65


def plain_recipe(spec: Spec, display: Display, view, size: int = PLAIN_SIZE) -> Callable[[np.ndarray], np.ndarray]:
    """ACES2065-1 (m, 3) to ``display``'s code values through ``view`` (an ACES view) as the
    plain recipe bakes it: the table is sampled once, here."""
    cct = CURVES["ACEScct"]
    t = views.tables(view)
    axis = cct.decode(np.linspace(0.0, 1.0, size))
    ap1 = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)
    cube = np.ascontiguousarray(
        reference.display_xyz_encode(spec, display, views.evaluate(view, ap1 @ t.ap1_to_ap0.T)).T
    )

    def run(aces: np.ndarray) -> np.ndarray:
        u = np.clip(cct.encode(aces @ t.ap0_to_ap1.T), 0.0, 1.0)
        nodes, weights = tetrahedra(np.ascontiguousarray(u.T * (size - 1)), size)
        return interpolate(nodes, weights, cube).T

    return run
