"""What every name in a built config should do, evaluated from the spec alone.

An :class:`Endpoint` is one colour space of the config as the resolved spec
describes it: how its code values decode to the scene reference and how the
scene reference encodes to them, both through
:mod:`generator.colorimetry.reference` (the one reference evaluation). The
verifier composes two endpoints, or an endpoint and a view, into the expected
result of an OCIO conversion; it never reads the config for this.

Two documented policies of the generated configs enter the expectation:

* a curve baked into a 1D LUT (:func:`generator.ocio.curves.is_baked`) is
  defined on its domain only: codes outside it are clamped to it, and encoded
  values are clamped to it (:class:`generator.colorimetry.transfer.Function`);
  so is a curve an OCIO builtin expresses, on the codes the builtin decodes
  (:data:`generator.ocio.capabilities.BUILTIN_CODE_DOMAIN`: Canon Log 2 and 3
  from 0 to 1, Apple Log from 0) or the scene space clamps its codes to
  (:data:`generator.ocio.capabilities.BUILTIN_CLAMPED_DOMAIN`: ST 2084 from 0 to 1);
* a display space decodes its code values, clips display light to
  [0, peak] (OCIO's range clamp runs both ways) and goes to CIE XYZ-D65; OCIO
  reaches the scene reference from there through the config's default view
  transform, Colorimetric, so the inverse of the scene-to-XYZ matrix.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

import numpy as np

from generator import reference
from generator.colorimetry import adx
from generator.colorimetry.curves import HALF_MAX
from generator.colorimetry.matrices import apply_matrix
from generator.colorimetry.transfer import Function, Linear, Tabulated
from generator.luts import aces_lattice
from generator.luts.axes import LOG_METHODS
from generator.luts.evaluate import display_file
from generator.luts.lattice import DISPLAY_RANGE, log_axis_high
from generator.luts.view import HSV_METHOD, LATTICE_DEFINED, ends_in_light, view_lattice
from generator.ocio.capabilities import aces_analytic, builtin_code_domain
from generator.ocio.curves import curve_label, is_baked
from generator.ocio.emit import INVERTED_AS_COLORIMETRIC
from generator.rendering import views
from generator.spec.allowed import COLORIMETRIC_ALIASES, VIEW_METHODS
from generator.spec.namespace import DISPLAY_REFERENCE, display_view_space
from generator.spec.schema import ColourSpace, Display, Spec

#: Output kinds, which choose the metric: scene or display light, code values, a display's codes.
LINEAR, CODE, DISPLAY, DATA = "linear", "code", "display", "data"
COLORIMETRIC = "Colorimetric"
RAW = "Raw"

Evaluate = Callable[[np.ndarray], np.ndarray]


@dataclass(frozen=True)
class Endpoint:
    """One colour space of a config, as the spec defines it.

    ``decode`` takes code values to the scene reference (None where the config
    offers only the forward direction); ``encode`` the reverse (None where the
    reference evaluation has nothing for a view the config offers: the verifier
    fails such a check rather than pass it unchecked). ``output`` is
    one of LINEAR, CODE, DISPLAY, DATA; ``display`` is set for display spaces
    and display-view spaces; ``baked`` names the curve of a space whose curve
    is a baked LUT ("" otherwise). ``matrix`` takes the space's linear RGB to
    the reference and ``linear`` its codes to that linear RGB (for ADX, relative
    exposure): the float32 limit of a check is computed from them. ``valid`` is
    set for bounded encodings (ADX, 10- or 16-bit integer density): the codes it
    accepts; the verifier compares only those, inside ``code_range``, and only
    colours the encoding represents.
    """

    name: str
    decode: Evaluate | None
    encode: Evaluate | None
    code_range: tuple[float, float]
    output: str
    display: Display | None = None
    baked: str = ""
    matrix: np.ndarray | None = None
    linear: Evaluate | None = None
    curve: object = None
    valid: Callable[[np.ndarray], np.ndarray] | None = None
    view: str = ""


def space_is_baked(spec: Spec, space: ColourSpace) -> bool:
    """Whether the config expresses ``space``'s curve as a baked 1D LUT file."""
    return not (space.is_data or space.special) and is_baked(space.curve_name, space.curve, spec.ocio_version)


def eotf_is_baked(spec: Spec, display: Display) -> bool:
    """Whether the config expresses ``display``'s EOTF as a baked 1D LUT file (HLG is OCIO's
    display builtin)."""
    label = curve_label(spec, display.name, display.eotf_name)
    return display.eotf_name != "HLG" and is_baked(label, display.eotf, spec.ocio_version)


def code_range(spec: Spec, space: ColourSpace) -> tuple[float, float]:
    """The code values ``space`` represents: a baked curve's domain, ADX16 up to the code
    that decodes to half-float max (where OCIO's builtin clamps), otherwise [0, 1]."""
    if space.special == "adx16":
        top = float(np.min(reference.from_reference(spec, space, np.full(3, HALF_MAX))))
        return (0.0, min(1.0, top))
    if space_is_baked(spec, space) and isinstance(space.curve, Function | Tabulated):
        lo, hi = space.curve.domain
        return (float(lo), float(hi))
    return (0.0, 1.0)


def _scene_endpoint(spec: Spec, space: ColourSpace) -> Endpoint:
    lo, hi = code_range(spec, space)
    # Code values unless the curve is the identity, whatever the encoding's label says.
    output = DATA if space.is_data else LINEAR if isinstance(space.curve, Linear) else CODE
    if space.special:
        return _adx_endpoint(spec, space)
    if space.is_data:
        return Endpoint(
            space.name,
            lambda c: reference.to_reference(spec, space, c),
            lambda r: reference.from_reference(spec, space, r),
            (lo, hi),
            output,
            matrix=np.eye(3),
            linear=space.curve.decode,
            curve=space.curve,
        )
    matrix = reference.space_matrix(spec, space)
    baked = space_is_baked(spec, space)
    domain = (lo, hi) if baked else builtin_code_domain(space.curve_name, spec.ocio_version)
    if domain is None:
        return Endpoint(
            space.name,
            lambda c: reference.to_reference(spec, space, c),
            lambda r: reference.from_reference(spec, space, r),
            (lo, hi),
            output,
            matrix=matrix,
            linear=space.curve.decode,
            curve=space.curve,
        )
    low, high = domain

    def decode(codes):
        return reference.to_reference(spec, space, np.clip(codes, low, high))

    def encode(ref):
        return np.clip(reference.from_reference(spec, space, ref), low, high)

    label = curve_label(spec, space.name, space.curve_name) if baked else ""
    return Endpoint(
        space.name,
        decode,
        encode,
        (lo, hi),
        output,
        baked=label,
        matrix=matrix,
        linear=lambda c: space.curve.decode(np.clip(c, low, high)),
        curve=space.curve,
    )


def _adx_endpoint(spec: Spec, space: ColourSpace) -> Endpoint:
    """ADX: codes -> printing density -> relative exposure (its "linear"), then a matrix to ACES.

    Codes are valid where every channel's exposure stays within half-float range
    up to the next half-float density above it: OCIO's builtin looks the exposure
    up in a half-domain LUT whose entries are clamped at half-float max, so an
    input one half-float step below the clamp already interpolates toward it.
    """
    bits = int(space.special[3:])

    def density(codes):
        return apply_matrix(adx.CDD_TO_CID, adx.adx_to_cdd(codes, bits))

    def exposure(codes):
        return 10.0 ** adx.cid_to_log_exposure(density(codes))

    def valid(codes):
        with np.errstate(all="ignore"):
            above = np.nextafter(density(codes).astype(np.float16), np.float16(np.inf)).astype(np.float64)
            return np.all(10.0 ** adx.cid_to_log_exposure(above) <= HALF_MAX, axis=-1)

    return Endpoint(
        space.name,
        lambda c: reference.to_reference(spec, space, c),
        lambda r: reference.from_reference(spec, space, r),
        code_range(spec, space),
        CODE,
        matrix=reference.adx_reference_matrix(spec) @ adx.EXP_TO_ACES,
        linear=exposure,
        valid=valid,
    )


def _display_endpoint(spec: Spec, display: Display) -> Endpoint:
    to_display = reference.display_matrix(spec, display) @ reference.scene_to_display_reference(spec)
    back = np.linalg.inv(to_display)

    def light(codes):
        return np.clip(reference.display_decode(display, codes), 0.0, display.clip_high)

    return Endpoint(
        display.name,
        lambda c: apply_matrix(back, light(c)),
        lambda r: reference.colorimetric_view(spec, display, r),
        (0.0, 1.0),
        DISPLAY,
        display,
        matrix=back,
        linear=light,
    )


def _xyz_endpoint(spec: Spec) -> Endpoint:
    matrix = reference.scene_to_display_reference(spec)
    inverse = np.linalg.inv(matrix)
    return Endpoint(
        DISPLAY_REFERENCE,
        lambda c: apply_matrix(inverse, c),
        lambda r: apply_matrix(matrix, r),
        (0.0, 1.0),
        LINEAR,
        matrix=inverse,
        linear=lambda c: np.asarray(c, dtype=np.float64),
    )


#: Gamut-mapping methods the config expresses analytically; the others are a baked
#: 3D LUT (CLF) over normalised display-linear RGB (see generator.ocio.emit).
ANALYTIC_METHODS = ("clip", "rgc")


def view_method(view: str) -> str | None:
    """The gamut-mapping method of a view: the spec's VIEW_METHODS (Colorimetric is clip)."""
    return "clip" if view in COLORIMETRIC_ALIASES else VIEW_METHODS.get(view)


def lut_range(display: Display, method: str | None = None) -> tuple[float, float] | None:
    """Display-linear range (1.0 = 100 cd/m²) a baked view LUT covers per channel; it clamps
    beyond (clip and scale treat every negative channel as 0, as their lattice does). None for
    an HSV view, whose lattice clamps OCIO's HSV value instead (from -256 to 65504 times the
    peak, :mod:`generator.luts.hsv`)."""
    if method == HSV_METHOD:
        return None
    high = log_axis_high(display, ends_in_light(display)) if method in LOG_METHODS else DISPLAY_RANGE[1]
    return (DISPLAY_RANGE[0] * display.clip_high, high * display.clip_high)


def view_function(spec: Spec, display: Display, view: str) -> Evaluate | None:
    """Scene reference to ``display``'s codes through ``view``; None when the spec's
    evaluation offers nothing for it (Raw is handled by the caller: no conversion).

    Colorimetric is :func:`reference.colorimetric_view`; a gamut-mapped view is
    ``reference.mapped_view`` with the view's method. A baked view clamps
    display-linear RGB to the range its LUT covers before mapping, as the LUT does. A view
    defined by its lattice (:data:`generator.luts.view.LATTICE_DEFINED`) is that lattice
    (:func:`_lattice_view`).
    """
    method = view_method(view)
    if method == "clip":
        return lambda ref: reference.colorimetric_view(spec, display, ref)
    if reference.aces_view_of(display, view) is not None:
        return aces_view_function(spec, display, view)
    if method is None:
        return None
    if method in lattice_defined():
        return _lattice_view(spec, display, method)
    to_display = reference.scene_to_display_matrix(spec, display)
    bounds = None if method in ANALYTIC_METHODS else lut_range(display, method)
    params = reference.method_params(spec, method)

    def mapped(ref):
        linear = apply_matrix(to_display, ref)
        return reference.map_display_linear(
            display, method, linear if bounds is None else np.clip(linear, *bounds), params
        )

    return mapped


def is_aces13(view: str) -> bool:
    """Whether ``view`` names an ACES 1.3 studio view (OCIO's builtins run them from 2.1)."""
    found = views.catalogue().get(view)
    return found is not None and found.version == "1.3"


def aces_baked(spec: Spec, display: Display, view: str) -> bool:
    """Whether the config of ``spec`` runs ACES view ``view`` as its baked lattice."""
    return not aces_analytic(reference.aces_view_of(display, view).version, spec.ocio_version)


def aces_stage(spec: Spec, display: Display, view: str) -> tuple[tuple, Evaluate] | None:
    """For an ACES view of ``display``: scene reference to CIE XYZ of the display's light
    (1.0 = 100 cd/m²) as the config runs it, and a key naming that evaluation, the same on
    every display showing the view (only their encodings differ); None for any other view."""
    found = None if view_method(view) == "clip" else reference.aces_view_of(display, view)
    if found is None:
        return None
    aces = reference.to_aces_matrix(spec)
    if not aces_baked(spec, display, view):
        return (found, "analytic"), lambda ref: views.evaluate(found, apply_matrix(aces, ref))
    # baked when first evaluated (verify bakes every view's lattice side by side first)
    return (found, "baked"), lambda ref: aces_lattice.evaluate(aces_lattice.bake(found), apply_matrix(aces, ref))


def aces_view_function(spec: Spec, display: Display, view: str) -> Evaluate:
    """Scene reference to ``display``'s codes through an ACES view as the config runs it
    (:func:`aces_stage`): the float64 output transform where OCIO runs it analytically, else
    its baked lattice evaluated in float64 (the file is then what is held to), then the
    display's encoding."""
    stage = aces_stage(spec, display, view)
    if stage is None:
        raise ValueError(f"{view!r} is not an ACES view of {display.name!r}")
    to_xyz = stage[1]
    return lambda ref: reference.display_xyz_encode(spec, display, to_xyz(ref))


def lattice_defined() -> tuple[str, ...]:
    """The methods whose view is defined by its lattice (:data:`generator.luts.view.LATTICE_DEFINED`)."""
    return LATTICE_DEFINED


def lattice_codes(spec: Spec, display: Display, method: str) -> Evaluate:
    """Display-linear RGB (1.0 = 100 cd/m²) to ``display``'s codes through the file of a view
    defined by its lattice (:data:`generator.luts.view.LATTICE_DEFINED`), as OCIO runs it,
    evaluated in float64 from the lattice rebuilt from the spec (a file that differs from it,
    or an engine that reads it otherwise, fails); a file ending in display light is then
    encoded as the display space does."""

    lat = view_lattice(spec, display, method)

    def codes(linear):
        out = display_file(lat, np.asarray(linear, dtype=np.float64) / display.clip_high)
        return out if lat.light is None else reference.display_encode(display, out * display.clip_high)

    return codes


def _lattice_view(spec: Spec, display: Display, method: str) -> Evaluate:
    """Scene reference to ``display``'s codes through a view defined by its lattice: the
    config's matrix, then :func:`lattice_codes`."""
    to_display, codes = reference.scene_to_display_matrix(spec, display), lattice_codes(spec, display, method)
    return lambda ref: codes(apply_matrix(to_display, ref))


def display_view_spaces(spec: Spec) -> list[Endpoint]:
    """The "<view> - <display>" spaces a config holds when the spec asks for them. Read back
    into the scene, a view the config inverts as Colorimetric (clip, and
    :data:`~generator.ocio.emit.INVERTED_AS_COLORIMETRIC`) decodes as its display does;
    RGC's analytic inverse has no evaluation here (no decode: checked forward only)."""
    if not spec.display_view_spaces:
        return []
    return [
        display_view_endpoint(spec, display, view) for display in spec.displays for view in display.views if view != RAW
    ]


def display_view_endpoint(spec: Spec, display: Display, view: str) -> Endpoint:
    """The "<view> - <display>" space of :func:`display_view_spaces`."""
    shown = _display_endpoint(spec, display)
    colorimetric = view_method(view) in ("clip", *INVERTED_AS_COLORIMETRIC)
    return Endpoint(
        display_view_space(view, display.name),
        shown.decode if colorimetric else None,
        view_function(spec, display, view),
        (0.0, 1.0),
        DISPLAY,
        display,
        matrix=shown.matrix,
        linear=shown.linear if colorimetric else None,
        view=view,
    )


def endpoints(spec: Spec) -> dict[str, Endpoint]:
    """Every colour space of the config built from ``spec``, by name, in config order."""
    out = [_scene_endpoint(spec, s) for s in spec.colour_spaces]
    out.append(_xyz_endpoint(spec))
    out += [_display_endpoint(spec, d) for d in spec.displays]
    out += display_view_spaces(spec)
    return {e.name: e for e in out}


class LazyEndpoints(dict[str, Endpoint]):
    """:func:`endpoints`, each built when first looked up: a conversion needs two or three of them,
    and building every view's lattice takes seconds."""

    def __init__(self, spec: Spec):
        super().__init__()
        self.spec = spec
        self.makers: dict[str, Callable[[], Endpoint]] = {
            s.name: partial(_scene_endpoint, spec, s) for s in spec.colour_spaces
        }
        self.makers[DISPLAY_REFERENCE] = partial(_xyz_endpoint, spec)
        self.makers.update({d.name: partial(_display_endpoint, spec, d) for d in spec.displays})
        if spec.display_view_spaces:
            self.makers.update(
                {
                    display_view_space(v, d.name): partial(display_view_endpoint, spec, d, v)
                    for d in spec.displays
                    for v in d.views
                    if v != RAW
                }
            )

    def __missing__(self, name: str) -> Endpoint:
        if name not in self.makers:
            raise KeyError(name)
        self[name] = self.makers[name]()
        return self[name]

    def __contains__(self, name) -> bool:
        return name in self.makers

    def get(self, name, default=None):
        """The endpoint called ``name`` (built now if not yet), or ``default``."""
        return self[name] if name in self.makers else default
