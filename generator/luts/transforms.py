"""Each operator a config and a standalone file share, as the one PyOpenColorIO transform.

The config (:mod:`generator.ocio`) and the CLF writer (:mod:`generator.luts.formats`,
:mod:`generator.luts.hsv`, through :mod:`generator.luts.clf`) both build their
operators here, so a config and a CLF cannot drift apart: a curve's decoding, a
matrix, a lattice's shapers and tables.
"""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio

from generator.colorimetry import transfer
from generator.colorimetry.matrices import settled

FORWARD = ocio.TRANSFORM_DIR_FORWARD
INVERSE = ocio.TRANSFORM_DIR_INVERSE


def matrix_transform(matrix, offset=(0.0, 0.0, 0.0), direction=FORWARD) -> ocio.MatrixTransform:
    """A 3x3 ``matrix`` (entries :func:`~generator.colorimetry.matrices.settled`) with ``offset``."""
    m44 = np.eye(4)
    m44[:3, :3] = settled(matrix)
    return ocio.MatrixTransform(
        matrix=[float(v) for v in m44.ravel()], offset=[*(float(v) for v in offset), 0.0], direction=direction
    )


def scale_transform(scale: float, direction=FORWARD) -> ocio.MatrixTransform:
    """Every channel times ``scale``."""
    return matrix_transform(np.eye(3) * scale, direction=direction)


def normalise_transform(lo: float, hi: float) -> ocio.MatrixTransform:
    """``lo``..``hi`` to 0..1 per channel, unclamped."""
    scale = 1.0 / (hi - lo)
    return matrix_transform(np.eye(3) * scale, offset=[-lo * scale] * 3)


def range_transform(lo: float, hi: float, out: tuple[float, float] = (0.0, 1.0)) -> ocio.RangeTransform:
    """``lo``..``hi`` to ``out``, clamped at both ends."""
    return ocio.RangeTransform(minInValue=lo, maxInValue=hi, minOutValue=out[0], maxOutValue=out[1])


def power(exponent: float, style=ocio.NEGATIVE_MIRROR, direction=FORWARD) -> ocio.ExponentTransform:
    """``x ** exponent`` per channel (CLF's basicMirrorFwd; basicFwd with NEGATIVE_CLAMP)."""
    return ocio.ExponentTransform(value=[exponent] * 3 + [1.0], negativeStyle=style, direction=direction)


def mon_curve(gamma: float, offset: float, mirror: bool = True, direction=FORWARD) -> ocio.Transform:
    """The piecewise power with a linear toe, code to linear (CLF's monCurveFwd, mirrored or
    continued linearly below zero)."""
    return ocio.ExponentWithLinearTransform(
        gamma=[gamma] * 3 + [1.0],
        offset=[offset] * 3 + [0.0],
        negativeStyle=ocio.NEGATIVE_MIRROR if mirror else ocio.NEGATIVE_LINEAR,
        direction=direction,
    )


def log_camera(curve: transfer.LogCamera) -> ocio.Transform:
    """A LogCamera curve's decoding: LogCameraTransform, or LogAffineTransform without a break.
    The base is set apart: LogAffineTransform's constructor has no ``base`` argument in any
    OCIO 2.x Python."""
    args = dict(
        logSideSlope=[curve.log_side_slope] * 3,
        logSideOffset=[curve.log_side_offset] * 3,
        linSideSlope=[curve.lin_side_slope] * 3,
        linSideOffset=[curve.lin_side_offset] * 3,
        direction=INVERSE,
    )
    if curve.lin_side_break is None:
        t = ocio.LogAffineTransform(**args)
    else:
        t = ocio.LogCameraTransform(linSideBreak=[curve.lin_side_break] * 3, **args)
        if curve.linear_slope is not None:
            t.setLinearSlopeValue([curve.linear_slope] * 3)
    t.setBase(curve.base)
    return t


def analytic_decode(curve) -> list | None:
    """Transforms taking code values of ``curve`` to linear where OCIO has an exact operator for
    it in every version (none for a linear curve); None where it has not."""
    if isinstance(curve, transfer.Linear):
        return []
    if isinstance(curve, transfer.Power):
        return [power(curve.exponent)]
    if isinstance(curve, transfer.PiecewisePower):
        return [mon_curve(curve.gamma, curve.offset, curve.mirror)]
    if isinstance(curve, transfer.LogCamera):
        return [log_camera(curve)]
    return None


def baked_decode(domain: tuple[float, float], shaper: float, table: ocio.Transform) -> list:
    """A baked curve's decoding (:class:`~generator.luts.curve1d.BakedCurve`): code normalised to
    [0, 1] over ``domain``, the shaper's power (clamping below 0), then ``table``, the 1D LUT
    (the config's FileTransform of its .spi1d, a CLF's own LUT1D)."""
    lo, hi = domain
    steps = [] if (lo, hi) == (0.0, 1.0) else [normalise_transform(lo, hi)]
    if shaper != 1:
        steps.append(power(1.0 / shaper, ocio.NEGATIVE_CLAMP))
    return [*steps, table]


def log_shaper(span, toe, direction=FORWARD) -> ocio.LogAffineTransform:
    """Linear ``x`` to ``log2(x + toe) / span - log2(toe) / span`` (CLF's linToLog; logToLin back);
    ``span`` and ``toe`` are one value for every channel or one per channel."""
    spans, toes = (np.broadcast_to(np.asarray(v, dtype=np.float64), (3,)) for v in (span, toe))
    t = ocio.LogAffineTransform(
        logSideSlope=[float(v) for v in 1.0 / spans],
        logSideOffset=[float(v) for v in -np.log2(toes) / spans],
        linSideSlope=[1.0] * 3,
        linSideOffset=[float(v) for v in toes],
        direction=direction,
    )
    t.setBase(2.0)
    return t


def lut1d(values, half_domain: bool = False) -> ocio.Lut1DTransform:
    """A 1D table: ``values`` (n,) for every channel, or (n, 3) per channel; linear interpolation."""
    rows = np.asarray(values, dtype=np.float64)
    rows = np.repeat(rows[:, None], 3, axis=1) if rows.ndim == 1 else rows
    t = ocio.Lut1DTransform(length=rows.shape[0], inputHalfDomain=half_domain)
    t.setData(np.ascontiguousarray(rows, dtype=np.float32).ravel())
    return t


def lut3d(cube, interpolation=ocio.INTERP_TETRAHEDRAL) -> ocio.Lut3DTransform:
    """A 3D table of ``cube[r, g, b]`` (n, n, n, 3)."""
    t = ocio.Lut3DTransform(gridSize=cube.shape[0])
    t.setInterpolation(interpolation)
    t.setData(np.ascontiguousarray(cube, dtype=np.float32).ravel())
    return t
