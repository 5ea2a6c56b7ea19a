"""Transfer-function records as OCIO transforms, in the decode direction (code -> linear).

Analytic where the target version can express the curve exactly; otherwise a
baked 1D LUT file, recorded in the ``bakes`` dictionary the caller writes out.
"""

from __future__ import annotations

import PyOpenColorIO as ocio

from generator.colorimetry import transfer
from generator.colorimetry.curves import CURVES
from generator.luts.curve1d import BakedCurve, bake_curve
from generator.luts.names import add_file, file_stems, slug
from generator.ocio.capabilities import clamped_code_domain, curve_chain
from generator.spec.schema import Spec

INVERSE = ocio.TRANSFORM_DIR_INVERSE
FORWARD = ocio.TRANSFORM_DIR_FORWARD


def _is_custom(curve_name: str) -> bool:
    return curve_name.startswith("custom")


def curve_label(spec: Spec, owner: str, curve_name: str) -> str:
    """The stem of a curve's baked file (``<stem>_to_linear.spi1d``) in ``spec``'s config: a
    library curve's own name, or for a custom curve the name of the space or display
    (``owner``) it belongs to, unique among the library's curves and the spec's other baked
    custom curves (:func:`generator.luts.names.file_stems`). The build and the verifier
    both name a space's file here."""
    if not _is_custom(curve_name):
        return curve_name
    owners = [(s.name, s.curve_name, s.curve) for s in spec.colour_spaces if not (s.is_data or s.special)]
    owners += [(d.name, d.eotf_name, d.eotf) for d in spec.displays]
    baked = [
        name for name, c_name, curve in owners if _is_custom(c_name) and is_baked(c_name, curve, spec.ocio_version)
    ]
    return file_stems([*baked, owner], taken=(slug(n) for n in CURVES))[owner]


def _log(curve: transfer.LogCamera) -> ocio.Transform:
    """LogCameraTransform, or LogAffineTransform without a break. The base is set apart:
    LogAffineTransform's constructor has no ``base`` argument in any OCIO 2.x Python."""
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


def _baked(name: str, curve, bakes: dict[str, BakedCurve]) -> list:
    """Normalise the code to [0, 1] over the domain, apply the shaper, look up the LUT."""
    baked = bake_curve(name, curve, curve.domain)
    add_file(bakes, baked.filename, baked)
    lo, hi = baked.domain
    steps = []
    if (lo, hi) != (0.0, 1.0):
        scale = 1.0 / (hi - lo)
        steps.append(
            ocio.MatrixTransform(
                matrix=[scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, 1], offset=[-lo * scale] * 3 + [0.0]
            )
        )
    if baked.shaper != 1:
        steps.append(ocio.ExponentTransform(value=[1.0 / baked.shaper] * 3 + [1.0], negativeStyle=ocio.NEGATIVE_CLAMP))
    steps.append(ocio.FileTransform(src=baked.filename, interpolation=ocio.INTERP_LINEAR, direction=FORWARD))
    return steps


def is_baked(name: str, curve, version: tuple[int, int]) -> bool:
    """Whether ``curve`` is expressed as a baked 1D LUT at ``version``."""
    if isinstance(curve, transfer.Tabulated):
        return True
    return isinstance(curve, transfer.Function) and curve_chain(name, version) is None


def decode_transforms(name: str, curve, version: tuple[int, int], bakes: dict[str, BakedCurve]) -> list:
    """OCIO transforms taking code values of ``curve`` to linear."""
    if isinstance(curve, transfer.Linear):
        return []
    if isinstance(curve, transfer.Power):
        return [ocio.ExponentTransform(value=[curve.exponent] * 3 + [1.0], negativeStyle=ocio.NEGATIVE_MIRROR)]
    if isinstance(curve, transfer.PiecewisePower):
        style = ocio.NEGATIVE_MIRROR if curve.mirror else ocio.NEGATIVE_LINEAR
        return [
            ocio.ExponentWithLinearTransform(
                gamma=[curve.gamma] * 3 + [1.0], offset=[curve.offset] * 3 + [0.0], negativeStyle=style
            )
        ]
    if isinstance(curve, transfer.LogCamera):
        return [_log(curve)]
    if is_baked(name, curve, version):
        return _baked(name, curve, bakes)
    return [
        ocio.BuiltinTransform(style, INVERSE if inverse else FORWARD) for style, inverse in curve_chain(name, version)
    ]


def code_clamp(curve_name: str, version: tuple[int, int]) -> list:
    """A RangeTransform clamping a scene space's codes to where the builtin expressing
    ``curve_name`` at ``version`` is defined, when the builtin does not clamp by itself
    (:data:`~generator.ocio.capabilities.BUILTIN_CLAMPED_DOMAIN`); otherwise nothing."""
    domain = clamped_code_domain(curve_name, version)
    if domain is None:
        return []
    lo, hi = domain
    return [ocio.RangeTransform(minInValue=lo, maxInValue=hi, minOutValue=lo, maxOutValue=hi)]


def group(transforms: list, direction=FORWARD) -> ocio.Transform | None:
    """One transform for a list: None when empty, the transform itself when single, else a group."""
    if not transforms:
        return None
    if len(transforms) == 1 and direction == FORWARD:
        return transforms[0]
    return ocio.GroupTransform(transforms, direction=direction)
