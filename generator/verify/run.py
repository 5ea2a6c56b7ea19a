"""A verify run: the spec beside a config, its checks, each engine, the verdicts.

The reference is the resolved spec stored beside the config by the build
(:func:`generator.spec.resolved.read_beside`), evaluated in float64; the config
is only ever run, never read to decide what it should do.
"""

from __future__ import annotations

import os
import shutil
import tempfile
import time
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from functools import partial
from pathlib import Path

import numpy as np
import PyOpenColorIO as ocio

from generator.files import not_readable
from generator.ocio.environment import set_aside
from generator.spec import resolved
from generator.spec.schema import Spec, SpecError
from generator.verify import looks
from generator.verify.blender import BlenderEngine
from generator.verify.check import KINDS, Check
from generator.verify.checks import build_and_run
from generator.verify.declarations import differences
from generator.verify.engines import (
    IN_PROCESS,
    apply,
    clear_caches,
    explain_default_flags,
    load_config,
    processor,
    run_config,
)
from generator.verify.gpu import GpuEngine
from generator.verify.hosts import NotRunnable, OcioconvertEngine, oiiotool_engines
from generator.verify.judge import APPROX, FAIL, NOT_RUN, PASS, Outcome, judge, judged_output, sample_errors
from generator.verify.paths import LazyEndpoints

#: Whether this runs on CI: ``CI`` set as CI services set it (true, 1 or yes, in any case).
ON_CI = os.environ.get("CI", "").strip().lower() in ("true", "1", "yes")


@dataclass(frozen=True)
class EngineRun:
    """How one engine fared: its version, the time it took, or why it did not run."""

    name: str
    version: str = ""
    seconds: float = 0.0
    skipped: str = ""
    #: Run beside its family's own engine (Debian's oiiotool beside pip's): not running fails nothing.
    extra: bool = False


@dataclass(frozen=True, eq=False)
class Verification:
    """A verify run's result: the config, its spec, the checks, every engine's outcomes and timings."""

    config: Path
    spec: Spec = field(repr=False)
    checks: tuple[Check, ...] = field(repr=False)
    outcomes: tuple[Outcome, ...] = field(repr=False)
    engines: tuple[EngineRun, ...] = ()
    seconds: float = 0.0
    timings: dict = field(default_factory=dict)
    strict: bool = False  # every engine asked for must run (the user named them), as on CI

    @property
    def failures(self) -> list[Outcome]:
        """The outcomes that failed."""
        return [o for o in self.outcomes if o.verdict == FAIL]

    @property
    def compared(self) -> bool:
        """Whether any engine produced anything to judge (a run where every engine was
        skipped, or no check was left, proves nothing)."""
        return any(o.verdict != NOT_RUN for o in self.outcomes)

    @property
    def passed(self) -> bool:
        """Whether something was compared, nothing failed, and (on CI or strict) every engine ran."""
        return self.compared and not self.failures and not ((ON_CI or self.strict) and self.missing)

    @property
    def missing(self) -> list[str]:
        """The engines that did not run (an extra one, which fails nothing, aside)."""
        return [e.name for e in self.engines if e.skipped and not e.extra]


def engine_registry() -> dict:
    """Engine family name -> engines, in table order."""
    return {
        "ocio": IN_PROCESS,
        "oiiotool": oiiotool_engines(),  # Debian's too, beside pip's: each runs its own OCIO
        "ocioconvert": (OcioconvertEngine(),),
        "blender": (BlenderEngine(),),
        "gpu": (GpuEngine(),),
    }


def load(config_path: str | Path) -> tuple[Path, Spec]:
    """The config path and the spec it was built from; SpecError when either is missing or unreadable."""
    if str(config_path).startswith("ocio://"):  # Path() would fold the URI's slashes
        raise SpecError(
            str(config_path),
            "-",
            "is one of OpenColorIO's builtin configs, which no spec built; "
            "allowed: a build's folder or its config.ocio, beside its ocioforge-spec.json",
        )
    path = Path(config_path)
    why = not_readable(path)
    if why is not None:
        raise SpecError(str(path), "-", f"no such config file (it {why}); allowed: a build's folder or its config.ocio")
    spec = resolved.read_beside(path)
    try:
        cfg = load_config(path)
    except Exception as error:  # PyOpenColorIO.Exception and friends
        raise SpecError(str(path), "-", f"OpenColorIO cannot load it: {str(error).splitlines()[0]}") from None
    _same_inventory(path, cfg, spec)
    _same_declarations(path, cfg, spec)
    return path.absolute(), spec


def _same_declarations(path: Path, cfg, spec: Spec) -> None:
    """The config declares the roles, file rules, inactive spaces, views and aliases its stored
    spec builds (:mod:`generator.verify.declarations`): no check's numbers would show an edit."""
    found = differences(cfg, spec)
    if found:
        more = f" (and {len(found) - 1} more)" if len(found) > 1 else ""
        raise SpecError(
            str(path),
            "-",
            f"it declares what its stored spec does not build: {found[0]}{more}; allowed: "
            "a config as ocioforge build wrote it, beside its ocioforge-spec.json (rebuild it)",
        )


def _same_inventory(path: Path, cfg, spec: Spec) -> None:
    """The config holds exactly the colour spaces, displays and views its stored spec builds:
    verify checks what the spec defines, so anything added or removed since the build (a space
    pasted in, a display dropped from the stored spec) would go unchecked."""
    held = {
        "colour spaces": set(cfg.getColorSpaceNames(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL)),
        # every display and view it defines, whatever OCIO_ACTIVE_DISPLAYS / _VIEWS narrow them to
        "displays/views": {
            f"{d} / {v}" for d in cfg.getDisplaysAll() for v in cfg.getViews(ocio.VIEW_DISPLAY_DEFINED, d)
        },
    }
    built = {
        "colour spaces": set(LazyEndpoints(spec).makers),  # names only: no endpoint is evaluated
        "displays/views": {f"{d.name} / {v}" for d in spec.displays for v in d.views},
    }
    for what in held:
        extra, missing = sorted(held[what] - built[what]), sorted(built[what] - held[what])
        if extra or missing:
            names = "; ".join(
                part
                for part in (
                    f"holds {', '.join(map(repr, extra[:3]))}" if extra else "",
                    f"lacks {', '.join(map(repr, missing[:3]))}" if missing else "",
                )
                if part
            )
            raise SpecError(
                str(path),
                "-",
                f"its {what} are not what its stored spec builds ({names}); allowed: a "
                "config as ocioforge build wrote it, beside its ocioforge-spec.json (rebuild it)",
            )


def _worst(check: Check, values: np.ndarray, step: float = 0.0) -> float:
    errors, _ = sample_errors(check, values, step)
    return float(np.nanmax(errors)) if not np.all(np.isnan(errors)) else 0.0


def _approx(outcome: Outcome, why: str) -> Outcome:
    return replace(outcome, verdict=APPROX, note=why, values=None)


def _explain(config: Path, outcome: Outcome) -> Outcome:
    """A default-flags failure the flags explain becomes APPROX, with the flag and operator named."""
    if outcome.violations or outcome.errors is None:
        return outcome
    why = explain_default_flags(
        config, outcome.check, lambda values: _worst(outcome.check, judged_output(outcome.check, values))
    )
    return _approx(outcome, why) if why else outcome


def _inherit(config: Path, outcome: Outcome, explained: dict) -> Outcome:
    """A host's failure on a check the in-process default flags explain becomes APPROX when
    the host computed what those flags compute (hosts run OCIO with its default flags):
    its output judged against the in-process default-flags output meets the tolerance."""
    default = explained.get(id(outcome.check))
    if outcome.verdict != FAIL or default is None or outcome.values is None or outcome.violations:
        return outcome
    cfg = run_config(config)
    proc = processor(cfg, outcome.check, config.parent)
    ours = judged_output(
        outcome.check, apply(proc.getOptimizedCPUProcessor(ocio.OPTIMIZATION_DEFAULT), outcome.check.probes.values)
    )
    against = replace(outcome.check, expected=ours)
    gap = _worst(against, outcome.values, outcome.step)
    if gap > outcome.check.tolerance:
        return outcome
    return _approx(outcome, f"as in-process default flags (within {gap:.2g}): {default.note.split(': ', 1)[-1]}")


def _engine_explained(config: Path, outcome: Outcome, explainers: dict) -> Outcome:
    """A failure of an engine that explains its own departures (``explainers``: engine name to
    its ``explain(config, check, error_of)``, e.g. the GPU's, naming the operator of OCIO's GPU
    path), still a failure, with that explanation as its note; a non-finite policy violation is
    named already."""
    explain = explainers.get(outcome.engine.split(" (")[0])
    if explain is None or outcome.verdict != FAIL or outcome.violations or outcome.values is None:
        return outcome
    why = explain(config, outcome.check, lambda values: _worst(outcome.check, judged_output(outcome.check, values)))
    return replace(outcome, note=why)


def run_engine(engine, config: Path, spec: Spec, checks: list[Check], workdir: Path) -> tuple[EngineRun, list[Outcome]]:
    """Run ``engine`` on the checks it supports and judge every output."""
    supports = getattr(engine, "supports", lambda check, spec: True)
    supported = [c for c in checks if c.kind in engine.kinds and supports(c, spec)]
    started = time.perf_counter()
    reason = engine.missing(config)
    installed = not reason
    if not reason:
        try:
            outputs = engine.run(config, supported, workdir)
        except NotRunnable as error:
            reason = str(error)
    if reason:  # an installed host that cannot load the config says which OCIO it runs
        version = engine.version() if installed else ""
        return EngineRun(engine.name, version, skipped=reason, extra=getattr(engine, "extra", False)), [
            Outcome(c, engine.name, NOT_RUN, note=reason) for c in supported
        ]
    outcomes = [judge(check, engine.name, out) for check, outs in zip(supported, outputs) for out in outs]
    return EngineRun(engine.name, engine.version(), time.perf_counter() - started), outcomes


def in_process(config: Path, spec: Spec, checks: list[Check], workdir: Path) -> list[tuple[EngineRun, list[Outcome]]]:
    """:func:`run_engine` of each in-process engine on ``checks``, in turn (they share OCIO's file
    cache and each check's reference), the default-flags failures the flags explain named so."""
    runs = [run_engine(engine, config, spec, checks, workdir) for engine in IN_PROCESS]
    explained = iter(_explained(config, [o for _, found in runs for o in found]))
    return [(run, [next(explained) for _ in found]) for run, found in runs]


def _in_process_on(
    config: Path, spec: Spec, only: str, workdir: Path, part: list[Check]
) -> list[tuple[EngineRun, list[Outcome]]]:
    """:func:`in_process` on the checks of ``part`` a verification keeps: those whose title holds
    ``only``, but a view's plain check where the view applies looks (a look-aware one replaces it)."""
    return in_process(config, spec, [c for c in part if only in c.title and looks.plain_kept(spec, c)], workdir)


def _merged(parts: list[list[tuple[EngineRun, list[Outcome]]]], checks: list[Check]) -> list[tuple[EngineRun, list]]:
    """Each in-process engine's runs on parts of ``checks`` as one: the time summed, the
    outcomes in the order of ``checks``."""
    order = {id(check): i for i, check in enumerate(checks)}
    merged = []
    for position in range(len(IN_PROCESS)):
        runs = [part[position][0] for part in parts]
        outcomes = sorted((o for part in parts for o in part[position][1]), key=lambda o: order[id(o.check)])
        merged.append((replace(runs[0], seconds=sum(r.seconds for r in runs)), outcomes))
    return merged


def _in_process_for_hosts(config: Path, spec: Spec, outcomes: list[Outcome], workdir: Path) -> list[Outcome]:
    """When hosts ran without the in-process engines, those engines' outcomes on the checks a
    host failed, so that the failures OCIO's default flags explain are named as such (they
    are not reported themselves); none otherwise."""
    names = {o.engine for o in outcomes}
    failed = {id(o.check): o.check for o in outcomes if o.verdict == FAIL}
    if any(e.name in names for e in IN_PROCESS) or not failed:
        return []
    return [o for engine in IN_PROCESS for o in run_engine(engine, config, spec, list(failed.values()), workdir)[1]]


def _explained(config: Path, outcomes: list[Outcome], extra: Sequence[Outcome] = ()) -> list[Outcome]:
    """Default-flags failures on checks the lossless engine passes, explained (APPROX) when
    one default flag accounts for them; then hosts' failures that match those (``extra``:
    in-process outcomes run only for these explanations, not returned)."""
    default, lossless = (e.name for e in IN_PROCESS)
    everything = [*outcomes, *extra]
    exact = {id(o.check) for o in everything if o.engine == lossless and o.verdict == PASS}
    everything = [
        _explain(config, o) if o.engine == default and o.verdict == FAIL and id(o.check) in exact else o
        for o in everything
    ]
    explained = {id(o.check): o for o in everything if o.engine == default and o.verdict == APPROX}
    return [
        _inherit(config, o, explained) if o.engine not in (default, lossless) else o
        for o in everything[: len(outcomes)]
    ]


def _remove(folder: Path, attempts: int = 5) -> None:
    """Remove the working folder, also when the run was stopped (SIGTERM, Ctrl-C) while a host
    was still writing into it: retried briefly rather than raising "Directory not empty" over
    the stop itself."""
    for _ in range(attempts):
        shutil.rmtree(folder, ignore_errors=True)
        if not folder.exists():
            return
        time.sleep(0.1)


def verify(
    config_path: str | Path,
    engines=("ocio",),
    density: str = "full",
    kinds=KINDS,
    workdir: str | Path | None = None,
    only: str = "",
    strict: bool = False,
    context: tuple[str, ...] = (),
) -> Verification:
    """Verify the config at ``config_path`` through the named engine families: the checks
    of the given ``kinds`` whose title contains ``only`` (every one when empty; SpecError when
    it matches none). ``strict``: an engine that cannot run fails the verification (one the user
    named), as every one does on CI; otherwise it is reported as not run. ``context``: NAME=value
    assignments of the config's context variables (its environment's defaults for the rest)."""
    with set_aside():  # the shell's OCIO overrides: verify checks the config as written
        return _verify(config_path, engines, density, kinds, workdir, only, strict, context)


def _verify(config_path, engines, density, kinds, workdir, only, strict, context=()) -> Verification:
    started = time.perf_counter()
    clear_caches()
    try:
        return _verify_files(config_path, engines, density, kinds, workdir, only, strict, started, context)
    finally:
        clear_caches()  # the configs it loaded go with it


def _verify_files(
    config_path, engines, density, kinds, workdir, only, strict, started: float, context=()
) -> Verification:
    """:func:`verify` once OCIO's caches are cleared: the checks, each engine, the explanations,
    with the context variables set in the environment OCIO and the hosts read."""
    config, spec = load(config_path)
    values = looks.parse_context(spec, tuple(context))
    with looks.in_environment(values):
        return _verify_in_context(config, spec, engines, density, kinds, workdir, only, strict, started, values)


def _verify_in_context(
    config, spec, engines, density, kinds, workdir, only, strict, started: float, values
) -> Verification:
    registry = engine_registry()
    unknown = [e for e in engines if e not in registry]
    if unknown:
        raise SpecError("--engines", ",".join(unknown), f"unknown engine; allowed: {', '.join(registry)}")
    tmp = Path(tempfile.mkdtemp(prefix="ocioforge-verify-", dir=workdir))
    try:
        # The in-process engines run on each part of the checks where it is built, as soon as it is.
        run_on = partial(_in_process_on, config, spec, only, tmp)
        built, parts = build_and_run(
            spec, density, kinds, run_on if any(registry[f] == IN_PROCESS for f in engines) else None
        )
        checks = [c for c in looks.with_looks(spec, built, values, density, kinds) if only in c.title]
        if only and not checks:
            raise SpecError(
                "--only",
                only,
                "matches no check title (titles are 'SPACE -> SPACE', "
                "'DISPLAY / VIEW from SPACE' and LUT file paths such as 'luts/NAME.clf')",
            )
        timings = {"checks": time.perf_counter() - started}
        runs: list[EngineRun] = []
        outcomes: list[Outcome] = []
        for family in engines:
            if registry[family] == IN_PROCESS:
                ran = {id(c) for c in built}
                parts.append(in_process(config, spec, [c for c in checks if id(c) not in ran], tmp))  # the looks'
                family_runs = _merged(parts, checks)
            else:
                family_runs = [run_engine(engine, config, spec, checks, tmp) for engine in registry[family]]
            for run, found in family_runs:
                runs.append(run)
                outcomes += found
        extra = _in_process_for_hosts(config, spec, outcomes, tmp)
    finally:
        _remove(tmp)
    explainers = {e.name: e.explain for family in engines for e in registry[family] if hasattr(e, "explain")}
    outcomes = [_engine_explained(config, o, explainers) for o in _explained(config, outcomes, extra)]
    return Verification(
        config, spec, tuple(checks), tuple(outcomes), tuple(runs), time.perf_counter() - started, timings, strict
    )
