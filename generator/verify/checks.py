"""The checks a verify run makes: what goes in, what the reference says comes out, how it is judged.

Coverage, from the resolved spec (never from the config): every colour space
to the scene reference and back; every display/view from the scene_linear
role, from the compositing_log role and from a display-referred space; every
baked LUT file on its own (:mod:`generator.verify.lut_checks`). Each check names
the item a failure points at: the colour space, "display / view", or the LUT file.
The record itself, its kinds and metrics are :mod:`generator.verify.check`'s.
"""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable
from functools import partial
from typing import Any, TypeVar

import numpy as np

from generator import reference, tolerances
from generator.luts import aces_lattice
from generator.luts.pool import Pool
from generator.metrics import colour_relative_error
from generator.ocio.emit import baked_aces_views
from generator.spec.schema import Display, Spec
from generator.verify import lut_checks, paths, probes
from generator.verify.allowance import (
    determinate,
    float32_allowance,
    float32_shift,
    view_allowance,
    with_encoding,
)
from generator.verify.check import (
    CODES,
    COLOUR,
    FROM_REFERENCE,
    ITP,
    KINDS,
    LUT,
    RELATIVE,
    TO_REFERENCE,
    VIEW,
    Check,
    baked_lut,
    discontinuity_band,
    evaluate,
    judging,
)
from generator.verify.probes import Family, Probes, Sizes

R = TypeVar("R")

#: Every endpoint of a spec by name (:func:`generator.verify.paths.endpoints`).
Ends = dict[str, paths.Endpoint]

#: The record's names, from :mod:`generator.verify.check`, where callers have long found them.
__all__ = [
    "CODES",
    "COLOUR",
    "FROM_REFERENCE",
    "ITP",
    "KINDS",
    "LUT",
    "RELATIVE",
    "TO_REFERENCE",
    "VIEW",
    "Check",
    "build_checks",
    "conversion_check",
    "input_probes",
    "space_checks",
    "view_checks",
    "view_sources",
]


def input_probes(end: paths.Endpoint, scene: tuple[Family, ...], sizes: Sizes) -> Probes:
    """Probes in ``end``'s encoding: its code families and the scene families encoded into it."""
    lut = None
    if end.baked:
        baked = baked_lut(end.baked, end.curve)
        lut = (len(baked.values), baked.shaper)
    families = probes.code_families(*end.code_range, sizes, lut)
    for family in scene:
        values = family.values if family.name == probes.NON_FINITE else evaluate(end.encode, family.values)
        families.append(Family(family.name, values, family.notes))
    return Probes(tuple(families))


def _expected(fn, values: np.ndarray, what: str) -> tuple[np.ndarray | None, str]:
    if fn is None:
        return None, f"the reference evaluation has no {what}"
    return evaluate(fn, values), ""


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
    back = evaluate(end.decode, codes)
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
    masks: list[np.ndarray | None] = []
    if src is not None:
        masks.append(discontinuity_band(src, inputs))
        if src.valid is not None:
            masks.append(_inside(inputs, src.code_range) & src.valid(inputs))
        if src.display is not None and src.display.eotf_name == "HLG":
            masks.append(~_hlg_dark(src.display, inputs))
    if dst is not None and expected is not None:
        masks.append(discontinuity_band(dst, expected))
        if dst.valid is not None:
            masks.append(_representable(dst, inputs, expected) & dst.valid(expected))
    if display is not None and display.eotf_name == "HLG" and expected is not None:
        masks.append(~_hlg_dark(display, expected))
    kept = [m for m in masks if m is not None]
    return np.logical_and.reduce(kept) if kept else None


def space_checks(spec: Spec, ends: Ends, scene: tuple[Family, ...], sizes: Sizes) -> list[Check]:
    """Every colour space to the scene reference and back."""
    ref = ends[spec.reference.name]
    to_ref = ref.encode
    assert to_ref is not None  # the scene reference always encodes
    out = []
    for end in ends.values():
        if (decode := end.decode) is not None:
            inputs = input_probes(end, scene, sizes)
            expected: np.ndarray | None = evaluate(lambda v: to_ref(decode(v)), inputs.values)
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
                    **judging(ref, None, end),
                )
            )
        decoded = (
            []
            if end.decode is None
            else [
                Family(f.name, evaluate(end.decode, f.values), f.notes)
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
                **judging(end, end.display, None, end.view),
            )
        )
    return out


def _input_rounding(end: paths.Endpoint, ref: paths.Endpoint, codes: np.ndarray) -> np.ndarray | None:
    """For a baked curve decoded to the reference: what float32 evaluation alone may move the
    reference values by (:func:`~generator.verify.allowance.float32_shift`), the rounding of its
    codes times the curve's slope among it. A table may rise steeply between two rows (a clip
    flag: 80 to 100 over one 10-bit step, 8e4 per code, where a code's rounding is 1e-4 of the
    value); no float32 engine can do better there."""
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


def _endpoint(spec: Spec, ends: Ends, name: str | None) -> paths.Endpoint | None:
    if name is None:
        return None
    if name in ends:
        return ends[name]
    try:
        return ends[spec.space(name).name]
    except KeyError:
        return None


def view_sources(spec: Spec, ends: Ends) -> list[paths.Endpoint]:
    """The inputs every display/view is checked from: the scene_linear role, the
    compositing_log role and the first display's (display-referred) space."""
    roles = dict(spec.roles)
    names = [roles.get("scene_linear"), roles.get("compositing_log"), spec.displays[0].name if spec.displays else None]
    found = [_endpoint(spec, ends, n) for n in names]
    return list({e.name: e for e in found if e is not None}.values())


def view_checks(spec: Spec, ends: Ends, scene: tuple[Family, ...], sizes: Sizes) -> list[Check]:
    """Every display/view from each of :func:`view_sources` (:func:`one_view_checks` of each unit)."""
    sources, kept = view_inputs(spec, ends, scene, sizes), dict[tuple, np.ndarray]()
    return [c for display, view in view_units(spec) for c in one_view_checks(spec, ends, sources, display, view, kept)]


def view_units(spec: Spec) -> list[tuple[Display, str]]:
    """Every (display, view) of ``spec``, in config order: the unit view checks are built in."""
    return [(display, view) for display in spec.displays for view in display.views]


def view_inputs(spec: Spec, ends: Ends, scene: tuple[Family, ...], sizes: Sizes) -> list[tuple]:
    """Each of :func:`view_sources` with its probes and their decoding (None where it has none),
    decoded once for every display."""
    out = []
    for src in view_sources(spec, ends):
        inputs = input_probes(src, scene, sizes)
        out.append((src, inputs, None if src.decode is None else _read_only(evaluate(src.decode, inputs.values))))
    return out


def one_view_checks(
    spec: Spec, ends: Ends, sources: list[tuple], display: Display, view: str, kept: dict
) -> list[Check]:
    """``display``'s ``view`` from each of ``sources`` (:func:`view_inputs`). An ACES view's
    rendering (:func:`paths.aces_stage`) is evaluated once per source, and the float32 shift of
    a display's linear values once per display and source: both are kept in ``kept`` for the
    other views and displays sharing them."""
    out = []
    back, clip = ends[display.name].matrix, ends[display.name].encode
    stage = None if view == paths.RAW else paths.aces_stage(spec, display, view)
    fn = None if view == paths.RAW or stage is not None else paths.view_function(spec, display, view)
    for src, inputs, decoded in sources:
        title = f"{display.name} / {view}"
        common: dict[str, Any] = dict(probes=inputs, display=display.name, view=view)
        if view == paths.RAW:
            out.append(Check(VIEW, title, src.name, output=paths.DATA, expected=inputs.values.copy(), **common))
            continue
        if decoded is None or (stage is None and fn is None):
            expected, problem = None, f"the reference evaluation has no evaluation of the view {view!r}"
        elif stage is not None:
            key = ("rendered", stage[0], src.name)
            if key not in kept:
                kept[key] = _read_only(evaluate(stage[1], decoded))
            expected, problem = (
                evaluate(partial(reference.display_xyz_encode, spec, display), kept[key]),
                "",
            )
        else:
            expected, problem = evaluate(fn, decoded), ""
        shifted = None
        if expected is not None and src.matrix is not None and src.linear is not None:
            shift_key = ("shift", display.name, src.name)
            if shift_key not in kept:
                kept[shift_key] = float32_shift(src, back, inputs.values)
            shifted = kept[shift_key]
        allowance = with_encoding(
            view_allowance(spec, src, back, display, view, inputs.values, expected, clip, shifted),
            spec,
            display,
            expected,
        )
        out.append(
            Check(
                VIEW,
                title,
                src.name,
                output=paths.DISPLAY,
                expected=expected,
                problem=problem,
                allowance=allowance,
                keep=_keep(src, None, display, inputs.values, expected),
                **common,
                **judging(None, display, None, view),
            )
        )
    return out


def _read_only(values: np.ndarray) -> np.ndarray:
    """``values``, marked read-only: an array several checks' evaluations share."""
    values.flags.writeable = False
    return values


def conversion_check(
    spec: Spec, ends: Ends, inputs: Probes, src: str, dst: str = "", display: str = "", view: str = ""
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
        if target.view:
            assert target.display is not None  # a display-view space shows its display
            allowance = view_allowance(
                spec,
                source,
                target.matrix,
                target.display,
                target.view,
                values,
                expected,
                ends[target.display.name].encode,
            )
        else:
            allowance = float32_allowance(source, target.matrix, target.encode, values)
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
        **judging(target, target.display, source, target.view),
    )


def _view_conversion(spec: Spec, ends: Ends, source, inputs: Probes, display: str, view: str) -> Check:
    """:func:`conversion_check` through a display's view."""
    common: dict[str, Any] = dict(probes=inputs, display=display, view=view)
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
    if source.output == paths.DATA:
        return Check(
            VIEW, f"{display} / {view}", source.name, output=paths.DATA, expected=inputs.values.copy(), **common
        )
    decoded = None if source.decode is None else evaluate(source.decode, inputs.values)
    return one_view_checks(spec, ends, [(source, inputs, decoded)], target, view, {})[0]


#: What :func:`build_and_run` hands its forked worker: (spec, endpoints, scene families, sizes,
#: then, claims). Endpoints hold closures, which do not pickle: the worker finds them here, as
#: they were when forked.
_BUILDING: list[tuple] = []


def _claim(claims, first: bool) -> int | None:
    """The next view unit (:func:`view_units`) not yet claimed, from the first (the worker) or the last (this process)
    of the shared range ``claims`` [next first, end); None when they have met."""
    with claims.get_lock():
        start, end = claims[0], claims[1]
        if start >= end:
            return None
        claims[0 if first else 1] = start + 1 if first else end - 1
        return start if first else end - 1


def _claimed_views(index: int, first: bool) -> tuple[dict[int, list[Check]], list]:
    """The view checks of each view unit (:func:`view_units`) claimed in turn (:func:`_claim`), by
    unit, and what ``then`` made of each unit's as soon as it was built."""
    spec, ends, scene, sizes, then, claims = _BUILDING[index]
    units, sources, kept, views, made = view_units(spec), None, dict[tuple, Any](), dict[int, list[Check]](), []
    while (u := _claim(claims, first)) is not None:
        sources = sources or view_inputs(spec, ends, scene, sizes)
        views[u] = one_view_checks(spec, ends, sources, *units[u], kept)
        if then is not None:
            made.append(then(views[u]))
    return views, made


def build_checks(spec: Spec, density: str = "full", kinds=KINDS) -> list[Check]:
    """All checks for the config built from ``spec``, of the given ``kinds`` (:func:`build_and_run`)."""
    return build_and_run(spec, density, kinds)[0]


def build_and_run(
    spec: Spec, density: str = "full", kinds=KINDS, then: Callable[[list[Check]], R] | None = None
) -> tuple[list[Check], list[R]]:
    """All checks for the config built from ``spec``, of the given ``kinds``, and ``then`` of each
    part as soon as it is built, where it was built (no result without ``then``). A forked worker
    builds the view checks view by view (:func:`view_units`) from the first, while this process builds the
    others, then takes units from the last until they meet: both cores stay busy to the end."""
    sizes = probes.SIZES[density]
    ends, scene = aces_lattice.bake_all(
        baked_aces_views(spec), lambda: (paths.endpoints(spec), probes.scene_families(spec, sizes))
    )
    claims = multiprocessing.get_context("fork").Array("i", [0, len(view_units(spec)) if VIEW in kinds else 0])
    job = (spec, ends, scene, sizes, then, claims)
    _BUILDING.append(job)
    index = len(_BUILDING) - 1
    try:
        with Pool(1) as pool:
            pool.submit("views", _claimed_views, index, True)
            out = []
            if TO_REFERENCE in kinds or FROM_REFERENCE in kinds:
                out += [c for c in space_checks(spec, ends, scene, sizes) if c.kind in kinds]
            luts = (
                lut_checks.lut_checks(spec, sizes)
                + lut_checks.view_lut_checks(spec, scene, sizes)
                + lut_checks.aces_lut_checks(spec, sizes)
                if LUT in kinds
                else []
            )
            results = [] if then is None else [then(out + luts)]
            here, made_here = _claimed_views(index, False)
            there, made_there = pool.result("views", _claimed_views, index, True)
            views = {**here, **there}
            return out + [c for u in sorted(views) for c in views[u]] + luts, results + made_here + made_there
    finally:
        _BUILDING[:] = [j for j in _BUILDING if j is not job]
