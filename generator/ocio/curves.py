"""Transfer-function records as OCIO transforms, in the decode direction (code -> linear).

Analytic where the target version can express the curve exactly; otherwise a
baked 1D LUT file, recorded in the ``bakes`` dictionary the caller writes out.
"""

from __future__ import annotations

import PyOpenColorIO as ocio

from generator.colorimetry import transfer
from generator.colorimetry.curves import CURVES
from generator.luts import transforms
from generator.luts.curve1d import BakedCurve, bake_curve
from generator.luts.names import add_file, file_stems, slug
from generator.ocio.capabilities import clamped_code_domain, curve_chain
from generator.spec.schema import Spec

INVERSE, FORWARD = transforms.INVERSE, transforms.FORWARD


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


def _baked(name: str, curve, bakes: dict[str, BakedCurve]) -> list:
    """The baked curve's decoding (:func:`~generator.luts.transforms.baked_decode`), its LUT the
    .spi1d file recorded in ``bakes``."""
    baked = bake_curve(name, curve, curve.domain)
    add_file(bakes, baked.filename, baked)
    table = ocio.FileTransform(src=baked.filename, interpolation=ocio.INTERP_LINEAR, direction=FORWARD)
    return transforms.baked_decode(baked.domain, baked.shaper, table)


def is_baked(name: str, curve, version: tuple[int, int]) -> bool:
    """Whether ``curve`` is expressed as a baked 1D LUT at ``version``."""
    if isinstance(curve, transfer.Tabulated):
        return True
    return isinstance(curve, transfer.Function) and curve_chain(name, version) is None


def decode_transforms(name: str, curve, version: tuple[int, int], bakes: dict[str, BakedCurve]) -> list:
    """OCIO transforms taking code values of ``curve`` to linear: exact operators
    (:func:`~generator.luts.transforms.analytic_decode`), else a baked LUT or OCIO's builtins."""
    analytic = transforms.analytic_decode(curve)
    if analytic is not None:
        return analytic
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
    return [transforms.range_transform(*domain, out=domain)]


def group(steps: list, direction=FORWARD) -> ocio.Transform | None:
    """One transform for a list: None when empty, the transform itself when single, else a group."""
    if not steps:
        return None
    if len(steps) == 1 and direction == FORWARD:
        return steps[0]
    return ocio.GroupTransform(steps, direction=direction)
