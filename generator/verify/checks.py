"""The checks a verify run makes: what goes in, what the reference says comes out, how it is judged.

Coverage, from the resolved spec (never from the config): every colour space
to the scene reference and back; every display/view from the scene_linear
role, from the compositing_log role and from a display-referred space; every
baked LUT file on its own (:mod:`generator.verify.lut_checks`). Each check names the item a failure points at: the
colour space, "display / view", or the LUT file.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from generator import reference, tolerances
from generator.spec.schema import Display, Spec
from generator.verify import paths, probes
from generator.verify.allowance import determinate, float32_allowance, view_allowance, with_encoding
from generator.verify.probes import Family, Probes, Sizes

TO_REFERENCE, FROM_REFERENCE, VIEW, LUT = "to reference", "from reference", "view", "LUT file"
KINDS = (TO_REFERENCE, FROM_REFERENCE, VIEW, LUT)
#: Metrics: largest per-channel relative error; colour relative error (over the largest
#: component, the float32 limit after a matrix); ΔE ITP for HDR displays.
RELATIVE, COLOUR, ITP, CODES = "relative", "colour relative", "ΔE ITP", "10-bit codes"


#: Methods whose config view is an exact lattice (scale's log lattice, desaturate's HSV
#: lattice): held to the issue's every-set bound for exact mappings.
def view_lut_tolerance(display: Display) -> float:
    """The bound for a config's baked view LUT, in 10-bit codes (ΔE ITP for HDR displays,
    DELTA_E_ITP_PER_PQ_CODE each): the LUT issue's in-gamut target, on every probe set.
    Scale and Desaturate are exact lattices, Perceptual is held to its own lattice: all
    three are exact but for float32, which each sample's allowance carries (measured 0.026
    codes and 0.003 ΔE ITP on the default config lossless). The issue's every-set bound of
    a code let a Scale file whose output was scaled by 0.9991 pass (0.92 codes)."""
    return tolerances.LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP if display.is_hdr else tolerances.LUT_CLF_IN_GAMUT_CODES


@dataclass(frozen=True, eq=False)
class Check:
    """One conversion an engine runs and the verifier judges.

    ``expected`` is None when the reference evaluation has nothing for the item
    (``problem`` says why): such a check fails. ``scale`` divides the colour
    error (a baked curve's error grows by its matrix's largest row sum); ``keep``
    marks the samples compared (a discontinuity band is left out);
    ``allowance`` is the float32 limit (:func:`float32_allowance`), an absolute
    difference per sample and channel taken off before the metric; ``encode``, a
    float64 function the engine's output goes through first (a view file ending in
    display light is encoded as its display space does).
    """

    kind: str
    item: str
    src: str
    dst: str = ""
    display: str = ""
    view: str = ""
    lut: str = ""
    interpolation: str = "linear"
    probes: Probes = field(default_factory=lambda: Probes(()), repr=False)
    expected: np.ndarray | None = field(default=None, repr=False)
    output: str = paths.CODE
    metric: str = RELATIVE
    tolerance: float = tolerances.ANALYTIC_RELATIVE
    target: Display | None = field(default=None, repr=False)
    scale: float = 1.0
    keep: np.ndarray | None = field(default=None, repr=False)
    allowance: np.ndarray | None = field(default=None, repr=False)
    problem: str = ""
    encode: object | None = field(default=None, repr=False)

    @property
    def title(self) -> str:
        if self.kind == VIEW:
            return f"{self.display} / {self.view} from {self.src}"
        if self.kind == LUT:
            return self.lut
        return f"{self.src} -> {self.dst}"


def _evaluate(fn, values: np.ndarray) -> np.ndarray:
    with np.errstate(all="ignore"):
        return np.asarray(fn(values), dtype=np.float64)


@lru_cache(maxsize=64)
def baked_lut(name: str, curve):
    """The LUT the build writes for ``curve`` (deterministic: the bake is re-run from the spec)."""
    from generator.luts.curve1d import bake_curve

    return bake_curve(name, curve, curve.domain)


def input_probes(end: paths.Endpoint, scene: tuple[Family, ...], sizes: Sizes) -> Probes:
    """Probes in ``end``'s encoding: its code families and the scene families encoded into it."""
    lut = None
    if end.baked:
        baked = baked_lut(end.baked, end.curve)
        lut = (len(baked.values), baked.shaper)
    families = probes.code_families(*end.code_range, sizes, lut)
    for family in scene:
        values = family.values if family.name == probes.NON_FINITE else _evaluate(end.encode, family.values)
        families.append(Family(family.name, values, family.notes))
    return Probes(tuple(families))


def _band(end: paths.Endpoint | None, codes: np.ndarray, curve=None) -> np.ndarray | None:
    """Samples away from a baked curve's published discontinuities (None: keep all)."""
    curve = curve if end is None else end.curve if end.baked else None
    jumps = getattr(curve, "discontinuities", ())
    if not jumps:
        return None
    keep = np.ones(len(codes), dtype=bool)
    for jump in jumps:
        keep &= np.all(np.abs(codes - jump) > tolerances.DISCONTINUITY_BAND, axis=-1)
    return keep


def _judging(
    out: paths.Endpoint | None, display: Display | None, baked_src: paths.Endpoint | None, view: str = ""
) -> dict:
    """Metric, tolerance, scale and target for an output kind (a baked source, a view)."""
    method = paths.view_method(view) if view else None
    if view and paths.is_aces13(view):
        # OCIO's ACES 1.x builtins depart from the CTL (black's offset, the red modifier's
        # saturation, rescaled tone-curve slopes): held to what was measured against them.
        return dict(
            metric=ITP if display.is_hdr else CODES,
            target=display,
            tolerance=tolerances.ACES13_OCIO_RED_DARK_DELTA_E_ITP if display.is_hdr else tolerances.ACES13_OCIO_CODES,
        )
    if method is not None and method not in paths.ANALYTIC_METHODS:
        return dict(metric=ITP if display.is_hdr else CODES, tolerance=view_lut_tolerance(display), target=display)
    if baked_src is not None and baked_src.baked and (out is None or out.output == paths.LINEAR):
        gain = float(np.abs(baked_src.matrix).sum(1).max())
        return dict(metric=COLOUR, tolerance=tolerances.BAKED_CURVE_RELATIVE, scale=gain)
    if display is not None and display.is_hdr:
        return dict(metric=ITP, tolerance=tolerances.ANALYTIC_DELTA_E_ITP, target=display)
    if out is not None and out.output == paths.LINEAR:
        return dict(metric=COLOUR)
    tolerance = tolerances.BAKED_CURVE_RELATIVE if out is not None and out.baked else tolerances.ANALYTIC_RELATIVE
    return dict(metric=RELATIVE, tolerance=tolerance, target=display)


def _expected(fn, values: np.ndarray, what: str) -> tuple[np.ndarray | None, str]:
    if fn is None:
        return None, f"the reference evaluation has no {what}"
    return _evaluate(fn, values), ""


def _hlg_dark(display: Display, codes: np.ndarray) -> np.ndarray:
    """Samples an HLG display shows below HLG_BUILTIN_BLACK cd/m² (OCIO's builtin departs there)."""
    with np.errstate(all="ignore"):
        light = reference.display_decode(display, codes) @ display.gamut.rgb_to_xyz[1] * 100.0
    return light < tolerances.HLG_BUILTIN_BLACK


def _inside(values: np.ndarray, bounds: tuple[float, float]) -> np.ndarray:
    with np.errstate(invalid="ignore"):
        return np.all((values >= bounds[0]) & (values <= bounds[1]), axis=-1)


def _representable(end: paths.Endpoint, ref: np.ndarray, codes: np.ndarray) -> np.ndarray:
    """Samples of a bounded encoding inside its code range whose codes decode back to ``ref``."""
    from generator.metrics import colour_relative_error

    back = _evaluate(end.decode, codes)
    with np.errstate(invalid="ignore"):
        return _inside(codes, end.code_range) & (colour_relative_error(back, ref) <= tolerances.REPRESENTABLE_RELATIVE)


def _keep(
    src: paths.Endpoint | None,
    dst: paths.Endpoint | None,
    display: Display | None,
    inputs: np.ndarray,
    expected: np.ndarray | None,
) -> np.ndarray | None:
    """The samples compared: away from baked discontinuities; for bounded encodings (ADX)
    valid inputs inside the code range and colours it represents; above
    HLG_BUILTIN_BLACK for HLG displays."""
    masks = []
    if src is not None:
        masks.append(_band(src, inputs))
        if src.valid is not None:
            masks.append(_inside(inputs, src.code_range) & src.valid(inputs))
        if src.display is not None and src.display.eotf_name == "HLG":
            masks.append(~_hlg_dark(src.display, inputs))
    if dst is not None and expected is not None:
        masks.append(_band(dst, expected))
        if dst.valid is not None:
            masks.append(_representable(dst, inputs, expected) & dst.valid(expected))
    if display is not None and display.eotf_name == "HLG" and expected is not None:
        masks.append(~_hlg_dark(display, expected))
    masks = [m for m in masks if m is not None]
    return np.logical_and.reduce(masks) if masks else None


def space_checks(spec: Spec, ends: dict, scene: tuple[Family, ...], sizes: Sizes) -> list[Check]:
    """Every colour space to the scene reference and back."""
    ref = ends[spec.reference.name]
    out = []
    for end in ends.values():
        if end.decode is not None:
            inputs = input_probes(end, scene, sizes)
            expected = _evaluate(lambda v: ref.encode(end.decode(v)), inputs.values)  # noqa: B023 (called at once)
            out.append(
                Check(
                    TO_REFERENCE,
                    end.name,
                    end.name,
                    ref.name,
                    probes=inputs,
                    expected=expected,
                    output=ref.output,
                    keep=_keep(end, None, None, inputs.values, expected),
                    allowance=_input_rounding(end, ref, inputs.values),
                    **_judging(ref, None, end),
                )
            )
        decoded = (
            []
            if end.decode is None
            else [
                Family(f.name, _evaluate(end.decode, f.values), f.notes)
                for f in probes.code_families(*end.code_range, sizes)
            ]
        )
        inputs = Probes(tuple(decoded) + scene)
        expected, problem = _expected(end.encode, inputs.values, f"evaluation of {end.name!r}")
        allowance = None
        if expected is not None and end.output in (paths.CODE, paths.DISPLAY):
            if end.view:
                allowance = view_allowance(
                    spec, ref, end.matrix, end.display, end.view, inputs.values, expected, end.encode
                )
            else:
                allowance = float32_allowance(ref, end.matrix, end.encode, inputs.values)
            allowance = with_encoding(allowance, spec, end.display, expected, _scene_space(spec, end))
        keep = _keep(None, end, end.display, inputs.values, expected)
        if end.valid is not None and keep is not None:
            keep &= determinate(ref, end, inputs.values)
        out.append(
            Check(
                FROM_REFERENCE,
                end.name,
                ref.name,
                end.name,
                probes=inputs,
                expected=expected,
                output=end.output,
                problem=problem,
                allowance=allowance,
                keep=keep,
                **_judging(end, end.display, None, end.view),
            )
        )
    return out


def _input_rounding(end: paths.Endpoint, ref: paths.Endpoint, codes: np.ndarray) -> np.ndarray | None:
    """For a baked curve decoded to the reference: what float32 evaluation alone may move the
    reference values by (:func:`~generator.verify.allowance.float32_shift`), the rounding of its
    codes times the curve's slope among it. A table may rise steeply between two rows (a clip
    flag: 80 to 100 over one 10-bit step, 8e4 per code, where a code's rounding is 1e-4 of the
    value); no float32 engine can do better there."""
    from generator.verify.allowance import float32_shift

    if not end.baked or end.matrix is None or end.linear is None or ref.matrix is None:
        return None
    with np.errstate(all="ignore"):
        return np.nan_to_num(float32_shift(end, ref.matrix, codes)[1], nan=0.0, posinf=0.0)


def _scene_space(spec: Spec, end: paths.Endpoint):
    """The spec's scene colour space ``end`` is, or None (displays, display-view spaces, the XYZ reference)."""
    if end.display is not None or end.view:
        return None
    try:
        return spec.space(end.name)
    except KeyError:
        return None


def _endpoint(spec: Spec, ends: dict, name: str | None) -> paths.Endpoint | None:
    if name is None or name in ends:
        return ends.get(name)
    try:
        return ends[spec.space(name).name]
    except KeyError:
        return None


def view_sources(spec: Spec, ends: dict) -> list[paths.Endpoint]:
    """The inputs every display/view is checked from: the scene_linear role, the
    compositing_log role and the first display's (display-referred) space."""
    roles = dict(spec.roles)
    names = [roles.get("scene_linear"), roles.get("compositing_log"), spec.displays[0].name if spec.displays else None]
    found = [_endpoint(spec, ends, n) for n in names]
    return list({e.name: e for e in found if e is not None}.values())


def view_checks(spec: Spec, ends: dict, scene: tuple[Family, ...], sizes: Sizes) -> list[Check]:
    """Every display/view from each of :func:`view_sources`."""
    out = []
    sources = [(src, input_probes(src, scene, sizes)) for src in view_sources(spec, ends)]
    for display in spec.displays:
        back, clip = ends[display.name].matrix, ends[display.name].encode
        for view in display.views:
            fn = paths.view_function(spec, display, view)
            for src, inputs in sources:
                common = dict(probes=inputs, display=display.name, view=view)
                if view == paths.RAW:
                    out.append(
                        Check(
                            VIEW,
                            f"{display.name} / {view}",
                            src.name,
                            output=paths.DATA,
                            expected=inputs.values.copy(),
                            **common,
                        )
                    )
                    continue
                through = None if fn is None else (lambda v, f=fn, s=src: f(s.decode(v)))
                expected, problem = _expected(through, inputs.values, f"evaluation of the view {view!r}")
                allowance = with_encoding(
                    view_allowance(spec, src, back, display, view, inputs.values, expected, clip),
                    spec,
                    display,
                    expected,
                )
                out.append(
                    Check(
                        VIEW,
                        f"{display.name} / {view}",
                        src.name,
                        output=paths.DISPLAY,
                        expected=expected,
                        problem=problem,
                        allowance=allowance,
                        keep=_keep(src, None, display, inputs.values, expected),
                        **common,
                        **_judging(None, display, None, view),
                    )
                )
    return out


def conversion_check(
    spec: Spec, ends: dict, inputs: Probes, src: str, dst: str = "", display: str = "", view: str = ""
) -> Check:
    """The check of one conversion a config runs on ``inputs`` (``ocioforge convert``'s frames):
    ``src`` to the colour space ``dst``, or to ``display`` through ``view`` (names as the config
    spells them), judged as the space and view checks judge theirs: the same expectation, metric,
    tolerance, float32 allowance and samples kept. ``ends`` is ``paths.endpoints(spec)``. A data
    space at either end, or the same space at both, is no conversion in OCIO, and none here."""
    source, values = _endpoint(spec, ends, src), inputs.values
    if display:
        return _view_conversion(spec, ends, source, inputs, display, view)
    target = _endpoint(spec, ends, dst)
    if source is None or target is None or paths.DATA in (source.output, target.output) or source is target:
        identity = source is not None and target is not None
        return Check(
            TO_REFERENCE,
            f"{src} -> {dst}",
            src,
            dst,
            probes=inputs,
            output=paths.DATA,
            expected=values.copy() if identity else None,
            problem="" if identity else "the stored spec has no such colour space",
        )
    expected, problem = _expected(
        None if source.decode is None or target.encode is None else (lambda v: target.encode(source.decode(v))),
        values,
        f"path {src!r} -> {dst!r}",
    )
    allowance = None
    if expected is not None and target.output in (paths.CODE, paths.DISPLAY):
        allowance = (
            view_allowance(
                spec,
                source,
                target.matrix,
                target.display,
                target.view,
                values,
                expected,
                ends[target.display.name].encode,
            )
            if target.view
            else float32_allowance(source, target.matrix, target.encode, values)
        )
        allowance = with_encoding(allowance, spec, target.display, expected, _scene_space(spec, target))
    elif expected is not None and source.baked:
        allowance = _input_rounding(source, target, values)
    keep = _keep(source, target, target.display, values, expected)
    if target.valid is not None and keep is not None:
        keep &= determinate(source, target, values)
    return Check(
        TO_REFERENCE,
        f"{src} -> {dst}",
        src,
        dst,
        probes=inputs,
        expected=expected,
        output=target.output,
        problem=problem,
        allowance=allowance,
        keep=keep,
        **_judging(target, target.display, source, target.view),
    )


def _view_conversion(spec: Spec, ends: dict, source, inputs: Probes, display: str, view: str) -> Check:
    """:func:`conversion_check` through a display's view."""
    common = dict(probes=inputs, display=display, view=view)
    target = next((d for d in spec.displays if d.name == display), None)
    if source is None or target is None:
        return Check(
            VIEW,
            f"{display} / {view}",
            "" if source is None else source.name,
            output=paths.DISPLAY,
            problem="the stored spec has no such colour space or display",
            **common,
        )
    if view == paths.RAW or source.output == paths.DATA:
        return Check(
            VIEW, f"{display} / {view}", source.name, output=paths.DATA, expected=inputs.values.copy(), **common
        )
    fn = paths.view_function(spec, target, view)
    through = None if fn is None or source.decode is None else (lambda v: fn(source.decode(v)))
    expected, problem = _expected(through, inputs.values, f"evaluation of the view {view!r}")
    back, clip = ends[display].matrix, ends[display].encode
    allowance = with_encoding(
        view_allowance(spec, source, back, target, view, inputs.values, expected, clip), spec, target, expected
    )
    return Check(
        VIEW,
        f"{display} / {view}",
        source.name,
        output=paths.DISPLAY,
        expected=expected,
        problem=problem,
        allowance=allowance,
        keep=_keep(source, None, target, inputs.values, expected),
        **common,
        **_judging(None, target, None, view),
    )


def build_checks(spec: Spec, density: str = "full", kinds=KINDS) -> list[Check]:
    """All checks for the config built from ``spec``, of the given ``kinds``."""
    sizes = probes.SIZES[density]
    ends = paths.endpoints(spec)
    scene = probes.scene_families(spec, sizes)
    out = []
    if TO_REFERENCE in kinds or FROM_REFERENCE in kinds:
        out += [c for c in space_checks(spec, ends, scene, sizes) if c.kind in kinds]
    if VIEW in kinds:
        out += view_checks(spec, ends, scene, sizes)
    if LUT in kinds:
        from generator.verify import lut_checks  # it builds on this module

        out += (
            lut_checks.lut_checks(spec, sizes)
            + lut_checks.view_lut_checks(spec, scene, sizes)
            + lut_checks.aces_lut_checks(spec, sizes)
        )
    return out


@lru_cache(maxsize=32)
def display_code_limit(display: Display) -> float:
    """The largest code value ``display`` is sent: the largest over the corners of its
    light cube [0, peak]^3 (HLG's inverse OOTF lifts a saturated peak above the white's code)."""
    corners = np.array(np.meshgrid([0.0, 1.0], [0.0, 1.0], [0.0, 1.0])).reshape(3, -1).T * display.clip_high
    with np.errstate(all="ignore"):
        return float(np.nanmax(reference.display_encode(display, corners[1:])))
