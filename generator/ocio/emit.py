"""The only code that turns a :class:`Spec` into PyOpenColorIO objects.

Matrices come from :mod:`generator.reference` (the same functions
the reference evaluation uses), curves from :mod:`generator.ocio.curves`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import PyOpenColorIO as ocio

from generator import reference
from generator.luts import aces_lattice, hsv
from generator.luts.curve1d import BakedCurve
from generator.luts.names import add_file
from generator.luts.pool import Pool
from generator.luts.transforms import matrix_transform
from generator.luts.view import bake_view_lut_cached
from generator.ocio import curves
from generator.ocio import looks as ocio_looks
from generator.ocio.capabilities import HLG_DISPLAY_BUILTIN, SPACE_BUILTINS
from generator.spec.allowed import COLORIMETRIC_ALIASES, VIEW_METHODS
from generator.spec.namespace import DISPLAY_REFERENCE, DISPLAY_REFERENCE_ALIASES, display_view_space
from generator.spec.schema import ColourSpace, Display, Spec

SCENE = ocio.REFERENCE_SPACE_SCENE
DISPLAY = ocio.REFERENCE_SPACE_DISPLAY
LUT_FOLDER = "luts"
COLORIMETRIC = "Colorimetric"
CATEGORIES = {
    "scene-linear": ["file-io", "working-space"],
    "log": ["file-io", "working-space"],
    "sdr-video": ["file-io", "texture"],
    "data": ["file-io", "working-space", "texture"],
}


def space_categories(space) -> list[str]:
    """A scene colour space's menu categories: a library space's as OCIO's ACES studio config
    gives them (:data:`~generator.colorimetry.library.STUDIO_CATEGORIES`, else file-io), a custom
    space's by its encoding (:data:`CATEGORIES`)."""
    from generator.colorimetry import library

    if space.name in library.STUDIO_CATEGORIES:
        return list(library.STUDIO_CATEGORIES[space.name])
    if any(space.name == known.name for known in library.SPACES):
        return ["file-io"]
    return list(CATEGORIES.get(space.encoding, ["file-io"]))


@dataclass(frozen=True)
class Emitted:
    """A config, the 1D curve LUTs it references, and the view LUT files (name -> bytes)."""

    config: ocio.Config
    luts: dict[str, BakedCurve]
    view_luts: dict[str, bytes]


def lut_steps(matrix, path: str, hsv_folder: str | None = None) -> list:
    """The OCIO transforms of a view LUT: MatrixTransform then FileTransform (tetrahedral);
    for an HSV view (:mod:`generator.luts.hsv`), the file between OCIO's RGB_TO_HSV and
    HSV_TO_RGB after the shared table (in ``hsv_folder``), all trilinear."""
    if hsv_folder is None:
        return [matrix_transform(np.asarray(matrix)), ocio.FileTransform(path, interpolation=ocio.INTERP_TETRAHEDRAL)]
    shared = f"{hsv_folder}/{hsv.SHARED_FILE}" if hsv_folder else hsv.SHARED_FILE
    return [
        matrix_transform(np.asarray(matrix)),
        ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_RGB_TO_HSV),
        ocio.FileTransform(shared, interpolation=ocio.INTERP_LINEAR),
        ocio.FileTransform(path, interpolation=ocio.INTERP_LINEAR),
        ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_RGB_TO_HSV, direction=ocio.TRANSFORM_DIR_INVERSE),
    ]


def _matrix_unless_identity(matrix: np.ndarray) -> list:
    return [] if np.allclose(matrix, np.eye(3), rtol=0, atol=1e-12) else [matrix_transform(matrix)]


def _to_reference(spec: Spec, space: ColourSpace, bakes: dict) -> list:
    if space.is_data:
        return []
    if space.special:
        ap0_to_ref = reference.adx_reference_matrix(spec)
        return [ocio.BuiltinTransform(SPACE_BUILTINS[space.special]), *_matrix_unless_identity(ap0_to_ref)]
    label = curves.curve_label(spec, space.name, space.curve_name)
    decode = curves.decode_transforms(label, space.curve, spec.ocio_version, bakes)
    clamp = curves.code_clamp(space.curve_name, spec.ocio_version)
    return clamp + decode + _matrix_unless_identity(reference.space_matrix(spec, space))


def _scene_space(spec: Spec, space: ColourSpace, bakes: dict) -> ocio.ColorSpace:
    cs = ocio.ColorSpace(
        SCENE,
        name=space.name,
        aliases=list(space.aliases),
        family=space.family,
        encoding=space.encoding,
        description=space.description,
        isData=space.is_data,
        categories=space_categories(space),
    )
    transform = curves.group(_to_reference(spec, space, bakes))
    if transform is not None:
        cs.setTransform(transform, ocio.COLORSPACE_DIR_TO_REFERENCE)
    return cs


def _display_space(spec: Spec, display: Display, bakes: dict) -> ocio.ColorSpace:
    """Display-referred space: XYZ-D65 -> display RGB -> clip to [0, peak] -> inverse EOTF."""
    steps = display_steps(spec, display, bakes)
    cs = ocio.ColorSpace(
        DISPLAY,
        name=display.name,
        aliases=list(display.aliases),
        family="Display",
        encoding=display.encoding,
        description=display.description,
        categories=["file-io"],
    )
    cs.setTransform(ocio.GroupTransform(steps), ocio.COLORSPACE_DIR_FROM_REFERENCE)
    return cs


def _display_reference_space() -> ocio.ColorSpace:
    return ocio.ColorSpace(
        DISPLAY,
        name=DISPLAY_REFERENCE,
        aliases=list(DISPLAY_REFERENCE_ALIASES),
        family="",
        encoding="display-linear",
        description="CIE XYZ relative to D65, 1.0 = 100 cd/m²",
        categories=["file-io"],
    )


def display_steps(spec: Spec, display: Display, bakes: dict) -> list:
    """CIE XYZ-D65 -> display RGB -> clip to [0, peak] (divided by the light of code 1 for an
    absolute display) -> display code values."""
    to_rgb = reference.display_matrix(spec, display)
    # An absolute display's range maps onto its codes' [0, 1]: the division by the light of
    # code 1 and the clip are one operator.
    steps = [
        matrix_transform(to_rgb),
        ocio.RangeTransform(
            minInValue=0.0,
            maxInValue=display.clip_high,
            minOutValue=0.0,
            maxOutValue=display.clip_high / display.code_one,
        ),
    ]
    if display.eotf_name == "HLG":
        # The signal ends at code 1 (OCIO 2.1's builtin clamps there, later versions do not).
        return [
            *steps,
            matrix_transform(np.linalg.inv(to_rgb)),
            ocio.BuiltinTransform(HLG_DISPLAY_BUILTIN),
            ocio.RangeTransform(minInValue=0.0, maxInValue=1.0, minOutValue=0.0, maxOutValue=1.0),
        ]
    label = curves.curve_label(spec, display.name, display.eotf_name)
    decode = curves.decode_transforms(label, display.eotf, spec.ocio_version, bakes)
    # Codes beyond the signal range, read back, are clamped to it as a scene space's are (the
    # encoded light never leaves it): OCIO's PQ builtin decodes PQ code 2 as black from 2.2 on.
    return (
        steps
        + ([ocio.GroupTransform(decode, direction=ocio.TRANSFORM_DIR_INVERSE)] if decode else [])
        + curves.code_clamp(label, spec.ocio_version)
    )


#: Methods whose view read backwards (a display-referred file into the scene, through its
#: "<view> - <display>" space) is the Colorimetric view's inverse: the colours the display
#: shows, exactly, for every code. Scale and desaturate leave the display's gamut alone, so
#: that is their inverse; OCIO's inverse of their many-to-one lattice picks one of the
#: colours that map to a code (display white read through Scale came back as scene 2.65, the
#: over-range grey the lattice's inversion landed on). Perceptual moves displayable colours
#: too, and OCIO's inversion of its 33³ file depends on the host's flags (random sRGB codes
#: read back and shown again were off by a median of 23 to 48 ten-bit codes with hosts'
#: default flags); the colours shown are what a file rendered through it holds.
INVERTED_AS_COLORIMETRIC = ("scale", "desaturate", "perceptual")


def _mapped_view_transform(
    spec: Spec, display: Display, view: str, bakes: dict, view_luts: dict, pool: Pool | None = None
) -> ocio.ViewTransform:
    """Scene reference -> display RGB (1 = peak) -> gamut mapping -> CIE XYZ-D65.

    RGC is analytic (OCIO's FixedFunction ACES_GAMUT_COMP_13, in the display's RGB);
    the other methods are a CLF lattice in the display's code values whose output
    the display's own encoding is undone from, so the display space re-encodes it
    exactly; for an HDR display (PQ, HLG, extended range) the file ends in display
    light and the display space encodes it."""
    method = VIEW_METHODS[view]
    to_display = reference.normalised_display_matrix(spec, display)
    to_xyz = reference.normalised_display_to_xyz(spec, display)
    if method == "rgc":
        steps = [
            matrix_transform(to_display),
            ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_ACES_GAMUT_COMP_13, spec.rgc.as_ocio_params()),
            matrix_transform(to_xyz),
        ]
    else:
        lut = _baked(pool, ("view", spec, display, method), _view_file, spec, display, method)
        add_file(view_luts, lut.filename, lut.data)
        if lut.hsv:
            add_file(view_luts, hsv.SHARED_FILE, hsv.shared_clf())
        back = (
            matrix_transform(to_xyz)
            if lut.light
            else ocio.GroupTransform(display_steps(spec, display, bakes), direction=ocio.TRANSFORM_DIR_INVERSE)
        )
        steps = [*lut_steps(lut.matrix, lut.filename, "" if lut.hsv else None), back]
    vt = ocio.ViewTransform(
        SCENE,
        name=f"{view} ({display.name})",
        family="Gamut mapped",
        description=f"{view} gamut mapping into {display.name}",
    )
    vt.setTransform(ocio.GroupTransform(steps), ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
    if method in INVERTED_AS_COLORIMETRIC:
        vt.setTransform(
            matrix_transform(np.linalg.inv(reference.scene_to_display_reference(spec))),
            ocio.VIEWTRANSFORM_DIR_TO_REFERENCE,
        )
    return vt


def aces_view_transform(spec: Spec, view) -> ocio.ViewTransform:
    """The view transform of an ACES view (scene reference -> CIE XYZ-D65, as the studio
    configs'): OCIO's builtin where the target version has it, FixedFunction
    ACES_OUTPUT_TRANSFORM_20 for a custom display's own ACES 2.0 view, else its baked
    lattice (:mod:`generator.luts.aces_lattice`), whose file the build adds at its end
    (its workers bake it meanwhile)."""
    from generator.ocio.capabilities import aces_analytic
    from generator.rendering import views

    steps = _matrix_unless_identity(reference.to_aces_matrix(spec))
    if aces_analytic(view.version, spec.ocio_version):
        steps += [ocio.BuiltinTransform(view.style)] if view.style else _aces2_fixed_function(view)
    else:
        name, upper = aces_lattice.file_name(view), aces_lattice.upper(view)
        steps += [
            matrix_transform(views.tables(view).ap0_to_ap1),
            ocio.RangeTransform(minInValue=0.0, maxInValue=upper, minOutValue=0.0, maxOutValue=upper),
            ocio.FileTransform(name, interpolation=ocio.INTERP_TETRAHEDRAL),
            ocio.RangeTransform(minInValue=0.0, maxInValue=1.0, minOutValue=0.0, maxOutValue=1.0),
            matrix_transform(aces_lattice.to_xyz(view)),
        ]
    family = f"ACES {view.version}"
    vt = ocio.ViewTransform(
        SCENE,
        name=view.name,
        family=family,
        description=f"{view.name}: the Academy's output transform to CIE XYZ-D65 display light",
    )
    vt.setTransform(curves.group(steps), ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
    return vt


def _aces2_fixed_function(view) -> list:
    """A custom ACES 2.0 view as OCIO's builtins run one: AP0 -> AP1, clamp to the tone
    scale's forward limit, back, the output transform (peak and limiting primaries and white),
    clamp to the peak, limiting RGB -> CIE XYZ (with the white scaling)."""
    from generator.rendering import views

    t = views.tables(view)
    upper, peak = float(t.tone.forward_limit), view.render_peak / 100.0
    params = [view.render_peak, *np.ravel(view.limiting), *view.white]
    return [
        matrix_transform(t.ap0_to_ap1),
        ocio.RangeTransform(minInValue=0.0, maxInValue=upper, minOutValue=0.0, maxOutValue=upper),
        matrix_transform(t.ap1_to_ap0),
        ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_ACES_OUTPUT_TRANSFORM_20, [float(v) for v in params]),
        ocio.RangeTransform(minInValue=0.0, maxInValue=peak, minOutValue=0.0, maxOutValue=peak),
        matrix_transform(t.limit_to_xyz * t.display_scale),
    ]


def baked_aces_views(spec: Spec) -> list:
    """The ACES views ``spec``'s target version runs as baked lattices, each once, in order."""
    from generator.ocio.capabilities import aces_analytic

    found = (reference.aces_view_of(d, v) for d in spec.displays for v in d.views)
    return list(dict.fromkeys(a for a in found if a is not None and not aces_analytic(a.version, spec.ocio_version)))


def _views(spec: Spec, cfg: ocio.Config, bakes: dict, view_luts: dict, pool: Pool | None = None) -> None:
    vt = ocio.ViewTransform(
        SCENE,
        name=COLORIMETRIC,
        family="Colorimetric",
        description="Scene reference to CIE XYZ-D65, no tone or gamut mapping; displays clip per channel",
    )
    vt.setTransform(matrix_transform(reference.scene_to_display_reference(spec)), ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
    cfg.addViewTransform(vt)
    raw = next((s.name for s in spec.colour_spaces if s.is_data), None)
    aces_added: set[str] = set()
    for display in spec.displays:
        for view in display.views:
            looks = ocio_looks.view_looks(display, view)
            if view == "Raw":
                cfg.addDisplayView(display.name, view, raw)
            elif view == COLORIMETRIC or view in COLORIMETRIC_ALIASES:
                cfg.addDisplayView(display.name, view, COLORIMETRIC, display.name, looks, "", "")
            elif reference.aces_view_of(display, view) is not None:
                if view not in aces_added:
                    cfg.addViewTransform(aces_view_transform(spec, reference.aces_view_of(display, view)))
                    aces_added.add(view)
                cfg.addDisplayView(display.name, view, view, display.name, looks, "", "")
            else:
                mapped = _mapped_view_transform(spec, display, view, bakes, view_luts, pool)
                cfg.addViewTransform(mapped)
                cfg.addDisplayView(display.name, view, mapped.getName(), display.name, looks, "", "")
    cfg.setActiveDisplays(", ".join(d.name for d in spec.displays))
    # No active views: OCIO would order every display's views by that one list, and a display
    # listing Raw first would default to another display's first view.


def _display_view_spaces(spec: Spec) -> list[ocio.ColorSpace]:
    """A colour space per display view but Raw, for writing display-ready files."""
    out = []
    for display in spec.displays:
        for view in display.views:
            if view == "Raw":
                continue
            cs = ocio.ColorSpace(
                SCENE,
                name=display_view_space(view, display.name),
                family="Display-View",
                encoding=display.encoding,
                categories=["file-io"],
                description=f"The {view} view of {display.name}, for writing display-ready files",
            )
            # The view alone, its looks bypassed: a look (a LUT file's, a shot's) has no inverse.
            dvt = ocio.DisplayViewTransform(
                src=spec.scene_reference, display=display.name, view=view, looksBypass=bool(display.view_looks(view))
            )
            cs.setTransform(dvt, ocio.COLORSPACE_DIR_FROM_REFERENCE)
            out.append(cs)
    return out


def generated_spaces(spec: Spec) -> list[ocio.ColorSpace]:
    """The colour spaces a build writes beside the spec's and its displays': the display
    reference and, where the spec asks for them, the display views'."""
    return [_display_reference_space(), *(_display_view_spaces(spec) if spec.display_view_spaces else ())]


def _file_rules(spec: Spec) -> ocio.FileRules:
    rules = ocio.FileRules()
    for index, rule in enumerate(r for r in spec.file_rules if r.name != "Default"):
        if rule.regex:
            rules.insertRule(index, rule.name, rule.colour_space, rule.regex)
        else:
            rules.insertRule(index, rule.name, rule.colour_space, rule.pattern, rule.extension)
    rules.setDefaultRuleColorSpace(spec.file_rules[-1].colour_space)
    return rules


def emit(spec: Spec) -> Emitted:
    """The OCIO config for ``spec`` (validated) and the 1D LUTs it references."""
    with Pool() as pool:
        _submit_bakes(spec, pool)  # the view files, in workers while the spaces are emitted
        try:
            return _emit(spec, pool)
        finally:
            _BUILDING.remove(spec)


def _baked_methods(spec: Spec) -> list[tuple[Display, str]]:
    """Each display and gamut-mapping method whose view is a baked file, in config order."""
    return [
        (d, VIEW_METHODS[v]) for d in spec.displays for v in d.views if VIEW_METHODS.get(v) not in (None, "clip", "rgc")
    ]


#: The spec a build's forked workers bake from (a spec holds functions, which do not pickle:
#: the workers find it here, as it was when they were forked).
_BUILDING: list[Spec] = []


@dataclass(frozen=True)
class _ViewFile:
    """What the config needs of a gamut-mapping view's baked file."""

    filename: str
    data: bytes
    matrix: tuple
    light: bool
    hsv: bool


def _view_file(spec: Spec, display: Display, method: str) -> _ViewFile:
    lut = bake_view_lut_cached(spec, display, method)
    return _ViewFile(lut.filename, lut.data, lut.matrix, lut.light, lut.hsv)


def _worker_view_file(index: int, method: str) -> _ViewFile:
    spec = _BUILDING[-1]
    return _view_file(spec, spec.displays[index], method)


def _submit_bakes(spec: Spec, pool: Pool) -> None:
    """Hand every view file of ``spec``'s config to ``pool``: the ACES 2.0 lattices first, largest
    first, so that none starts last."""
    _BUILDING.append(spec)
    for view in sorted(baked_aces_views(spec), key=lambda v: -aces_lattice.lattice_size(v)):
        if ("aces", view) not in _DONE:
            pool.submit(("aces", view), aces_lattice.baked_file, view)
    for display, method in _baked_methods(spec):
        if ("view", spec, display, method) not in _DONE:
            pool.submit(("view", spec, display, method), _worker_view_file, spec.displays.index(display), method)


#: View files already baked in this process, by key: a process building one spec again (tests,
#: an API user) takes them rather than baking them anew. Bounded: the oldest go first.
_DONE: dict = {}
_DONE_MAX = 64


def _baked(pool: Pool | None, key, fn, *args):
    """The view file ``key``: baked before in this process, else from ``pool``'s worker (or here)."""
    if key not in _DONE:
        _DONE[key] = (pool or Pool()).result(key, fn, *args)
        while len(_DONE) > _DONE_MAX:
            _DONE.pop(next(iter(_DONE)))
    return _DONE[key]


def _emit(spec: Spec, pool: Pool) -> Emitted:
    cfg = ocio.Config()
    cfg.setMajorVersion(spec.ocio_version[0])
    cfg.setMinorVersion(spec.ocio_version[1])
    cfg.setName(spec.name)
    cfg.setDescription(spec.description)
    cfg.setSearchPath(LUT_FOLDER)
    bakes: dict[str, BakedCurve] = {}
    for space in spec.colour_spaces:
        cfg.addColorSpace(_scene_space(spec, space, bakes))
    cfg.addColorSpace(_display_reference_space())
    for display in spec.displays:
        cfg.addColorSpace(_display_space(spec, display, bakes))
    view_luts: dict[str, bytes] = {}
    _views(spec, cfg, bakes, view_luts, pool)
    if spec.display_view_spaces:
        for space in _display_view_spaces(spec):
            cfg.addColorSpace(space)
    for role, target in spec.roles:
        cfg.setRole(role, target)
    cfg.setFileRules(_file_rules(spec))
    if spec.inactive:
        cfg.setInactiveColorSpaces(", ".join(spec.inactive))
    ocio_looks.add_looks(spec, cfg, LUT_FOLDER)
    cfg.validate()
    for view in baked_aces_views(spec):
        add_file(view_luts, aces_lattice.file_name(view), _baked(pool, ("aces", view), aces_lattice.baked_file, view))
    return Emitted(cfg, dict(sorted(bakes.items())), dict(sorted(view_luts.items())))
