"""An ACES 2.0 view baked for configs whose OCIO cannot run it (2.1 to 2.3).

The view runs, in the config::

    Matrix (scene reference -> AP1) -> Range clamp [0, upper] -> this CLF -> Range [0, 1]
    -> Matrix (limiting RGB at the peak -> CIE XYZ)

where the clamp is the view's own AP1 clamp (upper: the tone scale's forward limit) and
the CLF holds a Log shaper (``log2(x + toe)`` per channel, exact in every OCIO), a 3D
table (tetrahedral) of the rendering's limiting RGB over its peak, encoded by a mirrored
power with a linear toe (CLF's monCurve: sRGB's curve for SDR views), and the Exponent
undoing that encoding. What is linear (the matrices) and what is a clamp stays outside the
table, so the table holds the rendering unclamped; the toe keeps a channel crossing zero
smooth, where a pure power's infinite slope was not (max 76 against 32 ten-bit codes on
AP0 0..1). One file per view, whatever displays show it.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from generator.colorimetry.transfer import PiecewisePower
from generator.luts.fit import tetrahedra
from generator.luts.solve import interpolate
from generator.rendering import views
from generator.rendering.views import ACESView

#: Nodes a side: the plain recipe's 65, which the bench compares with.
ACES_LATTICE_SIZE = 65

#: The Log shaper's toe (AP1 linear): the axis is log2(x + toe), so black sits on a node and
#: the darkest decades keep nodes (bench/aces_views.py measured 2^-13 to 2^-10 alike).
ACES_LATTICE_TOE = 2.0**-10

#: The table's output encoding (gamma, offset of CLF's monCurve): sRGB's curve for SDR views;
#: for HDR views a steeper power, as PQ is, whose toe measured best in ΔE ITP (bench/aces_views.py).
SDR_CURVE, HDR_CURVE = (2.4, 0.055), (3.0, 0.02)

#: The table's values are whole 16-bit codes of the encoded range, as the file holds them:
#: 0.008 ten-bit codes at most, in two fifths of the text of float32 values.
CODE_STEPS = 65535.0


@dataclass(frozen=True)
class AcesLattice:
    """A baked ACES 2.0 view: the table (n, n, n, 3) indexed [r, g, b] over the log axis of
    AP1 in [0, ``upper``], holding the ``curve`` (gamma, offset) encoding of limiting RGB over
    the peak."""

    view: ACESView
    upper: float
    toe: float
    curve: tuple[float, float]
    cube: np.ndarray

    @property
    def size(self) -> int:
        """Nodes along each axis of the cube."""
        return self.cube.shape[0]

    @property
    def span(self) -> float:
        """log2 of the axis's range: the coordinate is (log2(x + toe) - log2(toe)) / span."""
        return float(np.log2(self.upper + self.toe) - np.log2(self.toe))


def axis_coordinate(ap1, upper: float, toe: float) -> np.ndarray:
    """Clamped AP1 values to the lattice coordinate in [0, 1]."""
    span = np.log2(upper + toe) - np.log2(toe)
    return (np.log2(np.clip(ap1, 0.0, upper) + toe) - np.log2(toe)) / span


def axis_value(u, upper: float, toe: float) -> np.ndarray:
    """A lattice coordinate back to AP1."""
    span = np.log2(upper + toe) - np.log2(toe)
    return np.exp2(np.asarray(u) * span + np.log2(toe)) - toe


def mon_decode(code, curve: tuple[float, float]) -> np.ndarray:
    """Code to linear as CLF's monCurveMirrorFwd: the piecewise power (gamma, offset), mirrored
    for negative codes."""
    code = np.asarray(code, dtype=np.float64)
    return np.sign(code) * PiecewisePower(*curve).decode(np.abs(code))


def mon_encode(linear, curve: tuple[float, float]) -> np.ndarray:
    """Linear to code, :func:`mon_decode`'s inverse (CLF's monCurveMirrorRev)."""
    linear = np.asarray(linear, dtype=np.float64)
    return np.sign(linear) * PiecewisePower(*curve).encode(np.abs(linear))


@lru_cache(maxsize=32)
def bake(view: ACESView, size: int = ACES_LATTICE_SIZE) -> AcesLattice:
    """The lattice of ACES 2.0 view ``view``, sampled from the float64 reference."""
    t = views.tables(view)
    curve = HDR_CURVE if view.is_hdr else SDR_CURVE
    axis = axis_value(np.linspace(0.0, 1.0, size), upper(view), ACES_LATTICE_TOE)
    ap1 = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)
    rgb = views.output_rgb(view, ap1 @ t.ap1_to_ap0.T) / (view.render_peak / 100.0)
    cube = np.round(mon_encode(rgb, curve) * CODE_STEPS) / CODE_STEPS
    return AcesLattice(view, upper(view), ACES_LATTICE_TOE, curve, cube.reshape(size, size, size, 3))


def file_output(lat: AcesLattice, ap1) -> np.ndarray:
    """The file alone, in float64: AP1 (m, 3; clamped to [0, upper] as the config does before
    it) to limiting RGB over the peak, unclamped."""
    u = axis_coordinate(np.asarray(ap1, dtype=np.float64), lat.upper, lat.toe)
    nodes, weights = tetrahedra(np.ascontiguousarray(u.T * (lat.size - 1)), lat.size)
    return mon_decode(interpolate(nodes, weights, lat.cube.reshape(-1, 3).T).T, lat.curve)


def evaluate(lat: AcesLattice, aces) -> np.ndarray:
    """ACES2065-1 (..., 3) through the baked view as OCIO runs it, in float64: CIE XYZ,
    1.0 = 100 cd/m² (the display then encodes)."""
    t = views.tables(lat.view)
    aces = np.asarray(aces, dtype=np.float64)
    flat = np.nan_to_num(aces.reshape(-1, 3), nan=0.0)
    rgb = np.clip(file_output(lat, flat @ t.ap0_to_ap1.T), 0.0, 1.0)
    return (rgb @ to_xyz(lat.view).T).reshape(aces.shape)


def to_xyz(view: ACESView) -> np.ndarray:
    """Normalised limiting RGB (1 = the peak) to CIE XYZ, 1.0 = 100 cd/m² (with the white
    scaling of a white simulation)."""
    t = views.tables(view)
    return t.limit_to_xyz * (view.render_peak / 100.0) * t.display_scale


def ocio_file(lat: AcesLattice) -> bytes:
    """The CLF of the lattice, written by PyOpenColorIO: Log shaper, LUT3D (16-bit codes),
    Exponent (monCurveMirrorFwd)."""
    import PyOpenColorIO as ocio

    from generator.luts import transforms  # with PyOpenColorIO, when a file is written

    cube = transforms.lut3d(lat.cube)
    # Written as 16-bit integer codes (OCIO keeps six digits, 1.5e-6 of the range, and values
    # beyond it): two thirds of the text of float32 values.
    cube.setFileOutputBitDepth(ocio.BIT_DEPTH_UINT16)
    log, decode = transforms.log_shaper(lat.span, lat.toe), transforms.mon_curve(*lat.curve)
    group = ocio.GroupTransform([log, cube, decode])
    group.getFormatMetadata().setID(f"ocioforge:{file_name(lat.view)[:-4]}")
    group.getFormatMetadata().addChildElement(
        "Description",
        f"ocioforge ACES view LUT: {lat.view.name}; AP1 clamped to [0, {lat.upper:g}] to limiting "
        f"RGB over the peak, {lat.size}^3 on a log2(x + {lat.toe:g}) axis, encoded by a monCurve of gamma "
        f"{lat.curve[0]:g} and offset {lat.curve[1]:g}, which the last operator undoes.",
    )
    return group.write("Academy/ASC Common LUT Format", ocio.Config.CreateRaw()).encode("utf-8")


def file_name(view: ACESView) -> str:
    """The view's file in a config's LUT folder, named after the view."""
    from generator.luts.names import slug

    return f"{slug(view.name)}_{ACES_LATTICE_SIZE}.clf"


def baked_file(view: ACESView) -> bytes:
    """The CLF of ``view``'s lattice (what a build's workers bake)."""
    return ocio_file(bake(view))


def upper(view: ACESView) -> float:
    """The view's AP1 clamp, where its lattice's axis ends: the tone scale's forward limit."""
    return float(views.tables(view).tone.forward_limit)
