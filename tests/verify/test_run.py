"""A verify run: the config and its stored spec loaded (or refused, naming why), every engine
asked for run and judged, hosts' default-flag departures explained, the working folder removed,
and the verdict (CI counts an engine that did not run as a failure)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import PyOpenColorIO as ocio
import pytest

from generator.spec.schema import SpecError
from generator.verify.check import TO_REFERENCE, Check
from generator.verify.judge import APPROX, FAIL, NOT_RUN, PASS, Outcome
from generator.verify.run import EngineRun, Verification, engine_registry, load, verify
from tests.conftest import require_program


def test_the_default_config_passes(config_copy):
    result = verify(config_copy, ("ocio",), density="quick")
    assert result.passed, [(o.check.title, o.engine, o.worst, o.note) for o in result.failures]


@pytest.mark.parametrize("missing", ["config.ocio", "ocioforge-spec.json"])
def test_a_missing_file_is_a_clear_error(config_copy, missing):
    (config_copy.parent / missing).unlink()
    with pytest.raises(SpecError, match="no such config file|no resolved spec here"):
        verify(config_copy, ("ocio",), density="quick")


def test_a_host_verified_alone_has_its_default_flag_departures_explained(build_config):
    """oiiotool runs OCIO with its default flags; verified without the in-process engines, its
    departures the flags explain are named so (APPROX) from in-process runs made for that alone,
    not failures (they failed when the ocio engine was not asked for). Samsung Log's checks: its
    inverse 1D table departs under the default flags (OPTIMIZATION_LUT_INV_FAST)."""
    require_program("oiiotool")
    result = verify(build_config((2, 1)), ("oiiotool",), density="quick", only="Samsung")
    names = {e.name for e in engine_registry()["oiiotool"]}  # Debian's too, where it is installed
    assert {run.name for run in result.engines} == names
    assert {o.engine for o in result.outcomes} <= {f"{n} ({v})" for n in names for v in ("EXR float", "TIFF uint16")}
    assert any(o.verdict == APPROX and "in-process default flags" in o.note for o in result.outcomes)
    assert result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]


def test_a_stopped_run_leaves_no_working_folder(build_config, tmp_path, monkeypatch):
    """SIGTERM ends a run as SystemExit; its working folder goes even while a host's output is
    still being written there (a run stopped under oiiotool left it, with a traceback)."""
    from generator.verify import run as runner

    def stopped(engine, config, spec, checks, workdir):
        (workdir / "host-0000-out.exr").write_bytes(b"partial")
        raise SystemExit(143)

    monkeypatch.setattr(runner, "run_engine", stopped)
    with pytest.raises(SystemExit):
        verify(build_config((2, 1)), ("ocio",), density="quick", workdir=tmp_path)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "value, expected", [("true", True), ("1", True), ("YES", True), ("false", False), ("0", False), ("", False)]
)
def test_ci_is_told_as_ci_services_set_it(value, expected):
    """CI=1 had counted as not CI, so engines a CI run lacks passed as not run."""
    env = {**os.environ, "CI": value}
    done = subprocess.run(
        [sys.executable, "-c", "import generator.verify.run as r; print(r.ON_CI)"],
        capture_output=True,
        text=True,
        check=True,
        env=env,
    )
    assert done.stdout.strip() == str(expected)


def test_a_builtin_config_is_refused_as_no_build():
    with pytest.raises(SpecError, match="is one of OpenColorIO's builtin configs, which no spec built"):
        load("ocio://default")


@pytest.mark.parametrize(
    "edit, words",
    [
        ("paste", "its colour spaces are not what its stored spec builds (holds 'Pasted Space')"),
        ("drop", "its displays/views are not what its stored spec builds (lacks 'sRGB - Display / Scale')"),
    ],
)
def test_a_config_holding_what_its_spec_does_not_build_is_refused(config_copy, edit, words):
    """A space pasted in would go unchecked, a view removed would be missed: both named."""
    cfg = ocio.Config.CreateFromFile(str(config_copy))
    if edit == "paste":
        cfg.addColorSpace(ocio.ColorSpace(name="Pasted Space"))
    else:
        cfg.removeDisplayView("sRGB - Display", "Scale")
    config_copy.write_text(cfg.serialize(), encoding="utf-8")
    with pytest.raises(SpecError) as raised:
        load(config_copy)
    assert words in str(raised.value)


def _verification(outcomes, engines=(), strict=False) -> Verification:
    return Verification(Path("config.ocio"), None, (), tuple(outcomes), tuple(engines), strict=strict)


def test_a_run_passes_when_something_was_compared_nothing_failed_and_strict_every_engine_ran():
    """An engine that did not run fails a strict run (and every run on CI); one run beside its
    family's own engine (Debian's oiiotool beside pip's) fails nothing; a run that compared
    nothing proves nothing."""
    check = Check(TO_REFERENCE, "ACEScct", "ACEScct", "ACES2065-1")
    passed, failed = Outcome(check, "ocio default", PASS), Outcome(check, "ocio default", FAIL)
    not_run = Outcome(check, "ocioconvert", NOT_RUN, note="ocioconvert is not installed")
    ran = EngineRun("ocio default", "PyOpenColorIO")
    absent = EngineRun("ocioconvert", skipped="ocioconvert is not installed")
    extra = EngineRun("oiiotool system", skipped="its OCIO cannot load the config", extra=True)
    assert _verification([passed], [ran]).passed
    assert not _verification([passed, failed], [ran]).passed
    assert not _verification([not_run], [absent]).passed  # nothing compared
    assert _verification([passed, not_run], [ran, absent, extra]).missing == ["ocioconvert"]
    assert not _verification([passed, not_run], [ran, absent], strict=True).passed
    assert _verification([passed], [ran, extra], strict=True).passed


def test_an_engine_of_the_default_list_not_installed_is_reported_as_not_run(build_config, monkeypatch):
    """Blender absent (and not on CI, where any engine missing fails the run): not run by
    default, a failure when named (strict)."""
    from generator.verify import run as verify_run
    from generator.verify.blender import BlenderEngine

    monkeypatch.setattr(BlenderEngine, "missing", lambda self, config: "blender is not installed")
    monkeypatch.setattr(verify_run, "ON_CI", False)
    config = build_config((2, 1))
    default = verify_run.verify(config, ("ocio", "blender"), density="quick", only="ACEScct -> ACES2065-1")
    named = verify_run.verify(config, ("ocio", "blender"), density="quick", only="ACEScct -> ACES2065-1", strict=True)
    assert default.passed and default.missing == ["blender"]
    assert not named.passed


def test_the_in_process_engines_run_beside_the_checks_as_a_serial_run_would(config_copy, tmp_path):
    """Each in-process engine's outcomes, gathered from the forked worker's part and this
    process's, hold the run's very checks, in their order, once each; their verdicts and
    figures are those of one serial run of the engines on the same checks."""
    from generator.verify.run import IN_PROCESS, in_process

    result = verify(config_copy, ("ocio",), density="quick")
    for engine in IN_PROCESS:
        checks = [o.check for o in result.outcomes if o.engine == engine.name]
        assert len(checks) == len(result.checks) and all(a is b for a, b in zip(checks, result.checks))
    config, spec = load(config_copy)
    serial = [o for _, found in in_process(config, spec, list(result.checks), tmp_path) for o in found]

    def rows(outcomes):
        return [(o.engine, o.check.title, o.verdict, o.worst, o.p99, o.note) for o in outcomes]

    assert rows(serial) == rows(result.outcomes)
