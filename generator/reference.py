"""The reference evaluation: float64 numpy, the single source of truth.

Every colour transform a config expresses is evaluated here directly from the
resolved spec: the emitter writes the same maths as OCIO transforms, the baker
samples these functions, the verifier compares OCIO's output with them.

Conventions: scene-linear values are relative to the scene reference (by
default ACES2065-1); display-linear values are CIE XYZ relative to D65 with
1.0 = 100 cd/m²; views clip each display channel to [0, peak / 100 cd/m²].

Layer: above spec, gamut and rendering (it evaluates a spec's paths with them), below
luts, ocio and verify (which sample it, emit it and compare with it).
"""

from __future__ import annotations

import numpy as np

from generator.colorimetry.adx import aces_to_adx, adx_to_aces
from generator.colorimetry.gamuts import D65, gamuts
from generator.colorimetry.matrices import Gamut, adaptation_matrix, apply_matrix, rgb_to_rgb, rgb_to_xyz_adapted
from generator.gamut import METHODS, DisplayGamut, PerceptualParams
from generator.gamut.display import matrix_tuple
from generator.rendering import views
from generator.spec.schema import ColourSpace, Display, Spec


def adaptation_between(gamut: Gamut, reference_gamut: Gamut, chosen: str) -> str:
    """The chromatic adaptation between ``gamut`` and a reference gamut: the one behind the
    published matrices of either (:data:`generator.colorimetry.gamuts.PUBLISHED_ADAPTATION`),
    else ``chosen`` (the spec's)."""
    return gamut.adaptation or reference_gamut.adaptation or chosen


def reference_gamut(spec: Spec) -> Gamut:
    """The gamut of the spec's scene reference (never a data space)."""
    gamut = spec.reference.gamut
    if gamut is None:
        raise ValueError(f"the scene reference {spec.scene_reference!r} has no gamut")
    return gamut


def adaptation_for(spec: Spec, gamut: Gamut) -> str:
    """:func:`adaptation_between` ``gamut`` and the spec's scene reference."""
    return adaptation_between(gamut, reference_gamut(spec), spec.chromatic_adaptation)


def gamut_matrix(spec: Spec, gamut: Gamut) -> np.ndarray:
    """Linear RGB of ``gamut`` to the scene reference."""
    return rgb_to_rgb(gamut, reference_gamut(spec), adaptation_for(spec, gamut))


def space_matrix(spec: Spec, space: ColourSpace) -> np.ndarray:
    """Linear RGB of ``space`` to the scene reference."""
    if space.gamut is None:
        raise ValueError(f"{space.name!r} is a data space: it has no gamut")
    return gamut_matrix(spec, space.gamut)


def adx_reference_matrix(spec: Spec) -> np.ndarray:
    """ACES2065-1 (AP0, ADX's linear) to the scene reference."""
    return rgb_to_rgb(gamuts()["AP0"], reference_gamut(spec), spec.chromatic_adaptation)


def to_reference(spec: Spec, space: ColourSpace, rgb) -> np.ndarray:
    """Encoded values of ``space`` (..., 3) to scene-reference linear RGB."""
    rgb = np.asarray(rgb, dtype=np.float64)
    if space.is_data:
        return rgb.copy()
    if space.special:
        return apply_matrix(adx_reference_matrix(spec), adx_to_aces(rgb, int(space.special[3:])))
    return apply_matrix(space_matrix(spec, space), space.curve.decode(rgb))


def from_reference(spec: Spec, space: ColourSpace, ref) -> np.ndarray:
    """Scene-reference linear RGB (..., 3) to encoded values of ``space``."""
    ref = np.asarray(ref, dtype=np.float64)
    if space.is_data:
        return ref.copy()
    if space.special:
        return aces_to_adx(apply_matrix(np.linalg.inv(adx_reference_matrix(spec)), ref), int(space.special[3:]))
    return space.curve.encode(apply_matrix(np.linalg.inv(space_matrix(spec, space)), ref))


def scene_to_display_reference(spec: Spec) -> np.ndarray:
    """Scene-reference linear RGB to CIE XYZ-D65 (the display reference)."""
    return rgb_to_xyz_adapted(reference_gamut(spec), D65, spec.chromatic_adaptation)


def display_matrix(spec: Spec, display: Display) -> np.ndarray:
    """CIE XYZ-D65 to the display's linear RGB (adapted to the display's white)."""
    return display.gamut.xyz_to_rgb @ adaptation_matrix(D65, display.gamut.white, spec.chromatic_adaptation)


def display_encode(display: Display, rgb) -> np.ndarray:
    """Display-linear RGB (1.0 = 100 cd/m², already inside [0, peak/100]) to code values
    (the EOTF's code 1 is :attr:`~generator.spec.schema.Display.code_one`)."""
    rgb = np.asarray(rgb, dtype=np.float64)
    if display.eotf_name == "HLG":
        from colour.models import eotf_inverse_BT2100_HLG

        # A display signal ends at code 1: saturated colours near the peak would need more.
        # colour-science's inverse OOTF and OETF divide by and take logarithms of dark values,
        # where numpy warns though the codes are right (black is code 0).
        with np.errstate(divide="ignore", invalid="ignore"):
            code = np.asarray(eotf_inverse_BT2100_HLG(rgb * 100.0, L_B=0.0, L_W=display.peak), dtype=np.float64)
        return np.clip(code, 0.0, 1.0)
    return display.eotf.encode(rgb / display.code_one)


def display_decode(display: Display, code) -> np.ndarray:
    """Display code values to display-linear RGB (1.0 = 100 cd/m²)."""
    code = np.asarray(code, dtype=np.float64)
    if display.eotf_name == "HLG":
        from colour.models import eotf_BT2100_HLG

        return np.asarray(eotf_BT2100_HLG(code, L_B=0.0, L_W=display.peak), dtype=np.float64) / 100.0
    return display.eotf.decode(code) * display.code_one


def colorimetric_view(spec: Spec, display: Display, ref) -> np.ndarray:
    """Scene-reference linear RGB through the Colorimetric view of ``display``:
    to display RGB, clip each channel to [0, peak], encode."""
    matrix = display_matrix(spec, display) @ scene_to_display_reference(spec)
    linear = np.clip(apply_matrix(matrix, ref), 0.0, display.clip_high)
    return display_encode(display, linear)


def display_gamut(display: Display):
    """The :class:`~generator.gamut.DisplayGamut` of ``display``: its linear RGB to XYZ
    matrix (SMPTE RP 177) and white, as the gamut-mapping methods need them."""
    return DisplayGamut(matrix_tuple(display.gamut.rgb_to_xyz), display.gamut.whitepoint)


def scene_to_display_matrix(spec: Spec, display: Display) -> np.ndarray:
    """Scene-reference linear RGB to the display's linear RGB (1.0 = 100 cd/m²)."""
    return display_matrix(spec, display) @ scene_to_display_reference(spec)


def normalised_display_matrix(spec: Spec, display: Display) -> np.ndarray:
    """Scene-reference linear RGB to normalised display-linear RGB (1 = the display's peak):
    the input of a view's baked LUT."""
    return scene_to_display_matrix(spec, display) / display.clip_high


def normalised_display_to_xyz(spec: Spec, display: Display) -> np.ndarray:
    """Normalised display-linear RGB (1 = the display's peak) to CIE XYZ-D65 (1.0 = 100 cd/m²):
    where a view's baked LUT ending in display light hands over to the display space."""
    return np.linalg.inv(display_matrix(spec, display)) * display.clip_high


def map_display_linear(display: Display, method: str, linear, params=None) -> np.ndarray:
    """Display-linear RGB (1.0 = 100 cd/m², any values) gamut mapped and encoded.

    The methods of :data:`generator.gamut.METHODS` bring colours into the unit
    cube; the cube is the display's range [0, peak], so display-linear values
    are divided by ``display.clip_high`` before mapping and multiplied after.

    Parameters
    ----------
    display : Display
    method : str
        A key of :data:`generator.gamut.METHODS` (clip, desaturate, scale, rgc, perceptual).
    linear : array_like, shape (..., 3)
    params : optional
        The method's parameters (e.g. :class:`~generator.gamut.RGCParams`), or None for its defaults.

    Returns
    -------
    numpy.ndarray, shape (..., 3), float64: code values.
    """
    return display_encode(display, gamut_map(display, method, linear, params) * display.clip_high)


def gamut_map(display: Display, method: str, linear, params=None) -> np.ndarray:
    """Display-linear RGB (1.0 = 100 cd/m², any values) gamut mapped into the display's
    cube, normalised: shape (..., 3), within [0, 1] (1 = the display's peak). The
    methods of :data:`generator.gamut.METHODS` act on ``linear / display.clip_high``."""
    gamut = None if method in ("clip", "scale") else display_gamut(display)
    return METHODS[method](np.asarray(linear, dtype=np.float64) / display.clip_high, gamut, params)


def method_params(
    spec: Spec, method: str, params=None, source: ColourSpace | None = None, display: Display | None = None
):
    """``params`` if given, else the spec's for ``method``: its RGC parameters; for a
    perceptual mapping from a known ``source`` (a bake) to ``display``, the source's gamut,
    so that its boundary lands on the display's (:func:`source_gamut_matrix`); None, the
    method's defaults, otherwise (a view, which every source goes through, compresses up to a
    fixed multiple of the display's boundary)."""
    if params is not None:
        return params
    if method == "rgc":
        return spec.rgc
    if method == "perceptual" and source is not None and display is not None:
        return PerceptualParams(source_to_display=matrix_tuple(source_gamut_matrix(spec, source, display)))
    return None


def source_gamut_matrix(spec: Spec, source: ColourSpace, display: Display) -> np.ndarray:
    """Linear ``source`` RGB to normalised display-linear RGB, scaled so that the source's white
    is the display's (1, 1, 1): the source gamut's solid at the display's size, whose boundary
    a perceptual bake maps onto the display's (on an HDR display the source's scene white,
    1.0, would otherwise be a fraction of the peak)."""
    matrix = normalised_display_matrix(spec, display) @ space_matrix(spec, source)
    return matrix / float(np.mean(matrix.sum(axis=1)))


def mapped_view(spec: Spec, display: Display, method: str, ref, params=None) -> np.ndarray:
    """Scene-reference linear RGB through a gamut-mapped view of ``display``.

    To display-linear RGB (the scene-to-display matrix with chromatic
    adaptation), gamut mapping with ``method`` into [0, peak], display encoding
    (see :func:`map_display_linear`). ``mapped_view(..., "clip")`` is
    :func:`colorimetric_view`. ``params`` None takes the spec's (:func:`method_params`).
    """
    return map_display_linear(
        display, method, apply_matrix(scene_to_display_matrix(spec, display), ref), method_params(spec, method, params)
    )


def aces_view_of(display: Display, view: str):
    """The :class:`~generator.rendering.views.ACESView` called ``view`` on ``display``, or None."""
    return views.resolve(view, display.name, display.peak, display.gamut.primaries, display.gamut.whitepoint)


def to_aces_matrix(spec: Spec) -> np.ndarray:
    """Scene-reference linear RGB to ACES2065-1, the ACES output transforms' input."""
    return np.linalg.inv(gamut_matrix(spec, gamuts()["AP0"]))


def display_xyz_encode(spec: Spec, display: Display, xyz) -> np.ndarray:
    """CIE XYZ-D65 (1.0 = 100 cd/m²) to ``display``'s code values as its display space
    encodes: to display RGB, clip each channel to [0, peak], encode."""
    return display_encode(display, np.clip(apply_matrix(display_matrix(spec, display), xyz), 0.0, display.clip_high))


def aces_view(spec: Spec, display: Display, view: str, ref) -> np.ndarray:
    """Scene-reference linear RGB through the ACES view ``view`` of ``display``: to
    ACES2065-1, the output transform (float64) to CIE XYZ, the display's encoding."""
    xyz = views.evaluate(aces_view_of(display, view), apply_matrix(to_aces_matrix(spec), ref))
    return display_xyz_encode(spec, display, xyz)
