"""Verifying a config's looks and the views that apply them, in one context (the values of the
context variables that choose each shot's file), against :mod:`generator.looks`.

Each look is checked alone, on its process space's values (PyOpenColorIO's LookTransform); each
view that applies looks from every source the view checks use, through engines that run views
(hosts given the context in their environment). A check's title names the looks and the context,
so a corrupted CDL value or a swapped shot file is named by look and shot.
"""

from __future__ import annotations

import os
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from generator import tolerances
from generator.looks import context_of, look_function, looks_in_reference
from generator.ocio.looks import search_path
from generator.spec import looks as spec_looks
from generator.spec.schema import Look, Spec, SpecError, with_context
from generator.verify import paths, probes
from generator.verify.check import ITP, RELATIVE, VIEW, Check, evaluate, judging
from generator.verify.checks import input_probes, view_sources
from generator.verify.probes import Family, Probes

LOOK = "look"
#: A look's probes: a lattice over its process space's codes (a little past 0 and 1) and random colours.
LATTICE_NODES = {"full": 17, "quick": 7}
RANDOM_SAMPLES = {"full": 2000, "quick": 200}
CODE_RANGE = (-0.05, 1.1)


@dataclass(frozen=True, eq=False)
class LookCheck(Check):
    """A check of a look alone (``kind`` :data:`LOOK`) or of a view applying looks (VIEW), titled
    with the looks and the context it ran in."""

    looks: str = ""
    context: str = ""

    @property
    def title(self) -> str:
        """The check's name in reports: the display and view, the looks and their context."""
        where = f"{self.display} / {self.view} from {self.src}, " if self.kind == VIEW else ""
        return f"{where}look {self.looks} ({self.context or 'no context'})"


def parse_context(spec: Spec, given: tuple[str, ...], source: str = "--context") -> dict[str, str]:
    """``NAME=value`` assignments over the spec's defaults; each name one the config's environment
    declares, each look's file (and CCC id) there in the build for the values."""
    context = context_of(spec)
    for item in given:
        name, sep, value = item.partition("=")
        if not sep or not name:
            raise SpecError(source, item, "expected NAME=value; allowed: e.g. SHOT=sh010")
        if name not in context:
            allowed = ", ".join(context) or "none (the config declares no context variables)"
            raise SpecError(source, item, f"unknown context variable {name!r}; allowed: {allowed}")
        if not value or "/" in value or "\\" in value or value in (".", ".."):
            raise SpecError(source, item, "a value a file name may hold; allowed: a non-empty name without /")
        context[name] = value
    for look in spec.looks:
        if look.file:
            spec_looks.check_file(look, Path(spec.look_folder), context, source, f"look {look.name!r}")
    return context


def describe(context: dict[str, str]) -> str:
    """The context as a check names it: ``SHOT=sh010, SEQ=sq01``."""
    return ", ".join(f"{k}={v}" for k, v in context.items())


@contextmanager
def in_environment(context: dict[str, str], environ=os.environ):
    """The context variables set in ``environ`` (OpenColorIO, and every host verify starts, read
    them there) while the block runs; the previous values put back after."""
    kept = {k: environ.get(k) for k in context}
    environ.update(context)
    try:
        yield
    finally:
        for key, value in kept.items():
            if value is None:
                environ.pop(key, None)
            else:
                environ[key] = value


def _changed_file(spec: Spec, look: Look, context: dict[str, str]) -> str:
    """Why the build's copy of the file ``look`` reads in ``context`` is not the one it copied ("")."""
    name = with_context(look.file, context)
    recorded = dict(look.files).get(name)
    path = Path(spec.look_folder) / name
    if recorded is None:
        return f"{spec_looks.LOOK_FOLDER}/{name} is no file the build copied"
    if not path.is_file():
        return f"{spec_looks.LOOK_FOLDER}/{name} is missing"
    if spec_looks.digest(path) != recorded:
        return f"{spec_looks.LOOK_FOLDER}/{name} is not the file the build copied (its SHA-256 differs)"
    return ""


def _look_probes(density: str) -> Probes:
    n = LATTICE_NODES[density]
    axis = np.linspace(*CODE_RANGE, n)
    lattice = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), -1).reshape(-1, 3)
    random = np.random.default_rng(23).uniform(*CODE_RANGE, (RANDOM_SAMPLES[density], 3))
    return Probes((Family("look lattice", lattice), Family("look random", random)))


def _problem(spec: Spec, names: tuple[str, ...], context: dict[str, str]) -> str:
    for look in (k for k in spec.looks if k.name in names and k.file):
        why = _changed_file(spec, look, context)
        if why:
            return f"look {look.name!r} ({describe({v: context[v] for v in look.variables}) or 'no context'}): {why}"
    return ""


def look_checks(spec: Spec, context: dict[str, str], density: str = "full") -> list[Check]:
    """Each look of ``spec`` alone, on its process space's values, in ``context``."""
    inputs = _look_probes(density)
    out: list[Check] = []
    for look in spec.looks:
        shown = describe({v: context[v] for v in look.variables})
        problem = _problem(spec, (look.name,), context)
        expected = None if problem else evaluate(look_function(spec, look, context), inputs.values)
        out.append(
            LookCheck(
                LOOK,
                f"look {look.name}",
                look.process_space,
                look.process_space,
                probes=inputs,
                expected=expected,
                problem=problem,
                output=paths.CODE,
                metric=RELATIVE,
                looks=repr(look.name),
                context=shown,
            )
        )
    return out


def _rounding_allowance(fn, graded: np.ndarray, expected: np.ndarray) -> np.ndarray:
    """Per sample and channel, how far the view's codes move when the looks' output moves by
    their float32 rounding (LOOK_ROUNDING_ULPS of each channel, one at a time, summed): what an
    engine's float32 look chain may put on the view, and no more."""
    step = tolerances.LOOK_ROUNDING_ULPS * np.finfo(np.float32).eps
    out = np.zeros_like(expected)
    with np.errstate(all="ignore"):
        for channel in range(3):
            moved = graded.copy()
            moved[:, channel] *= 1.0 + step
            out += np.abs(evaluate(fn, moved) - expected)
    return np.nan_to_num(out, nan=0.0, posinf=0.0)


def view_look_checks(spec: Spec, context: dict[str, str], density: str = "full") -> list[Check]:
    """Each display view that applies looks, from each of the view checks' sources, in ``context``."""
    sizes = probes.SIZES[density]
    ends = paths.endpoints(spec)
    scene = probes.scene_families(spec, sizes)
    out: list[Check] = []
    for display in spec.displays:
        for view, given in display.looks:
            names = display.view_looks(view)
            fn = paths.view_function(spec, display, view)
            problem = _problem(spec, names, context)
            applied = None if problem else looks_in_reference(spec, names, context)
            used = dict.fromkeys(v for k in spec.looks if k.name in names for v in k.variables)
            for src in view_sources(spec, ends):
                inputs = input_probes(src, scene, sizes)
                graded = (
                    None if applied is None else evaluate(lambda v, s=src, a=applied: a(s.decode(v)), inputs.values)
                )
                expected: np.ndarray | None = None
                allowance: np.ndarray | None = None
                if fn is not None and graded is not None:
                    expected = evaluate(fn, graded)
                    allowance = _rounding_allowance(fn, graded, expected)
                rule = judging(None, display, None, view)
                if rule["metric"] == RELATIVE:  # judged in ΔE ITP: see LOOK_VIEW_DELTA_E_ITP
                    rule.update(metric=ITP, tolerance=tolerances.LOOK_VIEW_DELTA_E_ITP, target=display)
                out.append(
                    LookCheck(
                        VIEW,
                        f"{display.name} / {view}",
                        src.name,
                        display=display.name,
                        view=view,
                        probes=inputs,
                        expected=expected,
                        problem=problem or ("" if fn else f"the reference evaluation has no view {view!r}"),
                        output=paths.DISPLAY,
                        looks=given,
                        context=describe({v: context[v] for v in used}),
                        allowance=allowance,
                        **rule,
                    )
                )
    return out


def with_looks(spec: Spec, checks: list[Check], context: dict[str, str], density: str, kinds) -> list[Check]:
    """``checks`` with each plain check of a view that applies looks replaced by its look-aware
    one, and the looks' own checks added (with the VIEW kind asked for)."""
    if not spec.looks:
        return checks
    kept = [c for c in checks if plain_kept(spec, c)]
    if VIEW not in kinds:
        return kept
    return [*kept, *view_look_checks(spec, context, density), *look_checks(spec, context, density)]


def plain_kept(spec: Spec, check: Check) -> bool:
    """Whether :func:`with_looks` keeps ``check``: all but a view's plain check where the view applies looks."""
    return not (
        check.kind == VIEW and (check.display, check.view) in {(d.name, v) for d in spec.displays for v, _ in d.looks}
    )


def look_differences(cfg, spec: Spec, lut_folder: str) -> list[str]:
    """What ``cfg`` declares of looks, environment and search path that ``spec`` does not build."""
    out = []
    held_env = {n: cfg.getEnvironmentVarDefault(n) for n in cfg.getEnvironmentVarNames()}
    if held_env != dict(spec.environment):
        out.append(f"environment is {held_env}, the spec's {dict(spec.environment)}")
    if cfg.getSearchPath() != search_path(spec, lut_folder):
        out.append(
            f"the search path is {cfg.getSearchPath()!r}, the build's {search_path(spec, lut_folder)!r} (folders "
            "beside the config, wherever it is copied)"
        )
    held = list(cfg.getLookNames())
    if held != [k.name for k in spec.looks]:
        out.append(f"looks are {held}, the spec's {[k.name for k in spec.looks]}")
    for look in spec.looks:
        found = cfg.getLook(look.name)
        if found is not None and found.getProcessSpace() != look.process_space:
            out.append(
                f"look {look.name!r} is applied in {found.getProcessSpace()!r}, the spec's {look.process_space!r}"
            )
    for display in spec.displays:
        for view in display.views:
            held_looks = cfg.getDisplayViewLooks(display.name, view) if view in cfg.getViews(display.name) else ""
            if spec_looks.look_names(held_looks) != display.view_looks(view):
                out.append(
                    f"{display.name} / {view} applies looks {held_looks!r}, the spec's {dict(display.looks).get(view, '')!r}"
                )
    return out


__all__ = ["LOOK", "LookCheck", "look_checks", "look_differences", "parse_context", "with_looks"]
