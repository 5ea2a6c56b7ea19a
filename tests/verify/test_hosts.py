"""The command-line hosts (oiiotool, Debian's ocioconvert): which OpenColorIO each runs, said
beside its result; Debian's oiiotool beside pip's; a host whose OCIO cannot read the config
reported not run, found at once; a check a host refuses failed alone with its words; names
oiiotool would read as wildcards; a hung host stopped."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys

import pytest

from generator.verify import checks, hosts, paths, probes
from generator.verify.checks import FROM_REFERENCE, LUT, TO_REFERENCE, Check
from generator.verify.hosts import (
    TOO_NEW,
    NotRunnable,
    OcioconvertEngine,
    OiiotoolEngine,
    installed,
    linked_ocio,
    ocio_in,
    oiiotool_engines,
    read_output,
)
from generator.verify.judge import APPROX, FAIL, NOT_RUN, PASS, judge
from generator.verify.report import summary
from generator.verify.run import verify
from tests.conftest import NEWEST, host_missing, require_program
from tests.verify.conftest import verified_on

VERSION = re.compile(r"OCIO \d+\.\d+\.\d+")


@pytest.mark.parametrize(
    "text, version",
    [
        ("OpenColorIO 2.1.2, color config: built-in", "2.1.2"),  # oiiotool 2.4's --help
        ("Dependencies: expat 2.6.3, OpenColorIO 2.5.1, OpenEXR 3.5.2", "2.5.1"),  # oiiotool 3.x
        ("no colour management", ""),
    ],
)
def test_the_ocio_a_host_names_is_read_from_its_words(text, version):
    assert ocio_in(text) == version


def test_the_ocio_a_program_loads_is_read_from_its_library():
    program = require_program("ocioconvert")
    assert re.fullmatch(r"2\.\d+\.\d+", linked_ocio(program)), linked_ocio(program)
    assert linked_ocio(shutil.which("ldd") or program) == ""  # no OCIO linked: no version


def test_debians_oiiotool_is_an_engine_of_its_own_beside_pips():
    system = shutil.which("oiiotool", path="/usr/bin")
    engines = oiiotool_engines()
    if system is None or len(engines) == 1:
        host_missing("one oiiotool only: a second engine needs pip's and Debian's")
    assert [e.name for e in engines] == ["oiiotool", "oiiotool system"]
    assert os.path.realpath(engines[1].executable()) == os.path.realpath(system)
    assert all(VERSION.search(e.version()) for e in engines)
    assert "OCIO 2.1" in engines[1].version() and f"({system})" in engines[1].version()


def test_verify_says_which_ocio_each_host_runs(build_config, tmp_path):
    """Each engine's line names the OpenColorIO it runs: oiiotool's from its help, ocioconvert's
    and Blender's from the library they load (they print none)."""
    require_program("ocioconvert")
    require_program("oiiotool")
    engines = ("--engines", "oiiotool,ocioconvert")
    only = ("--only", "ACEScct -> ACES2065-1")
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "generator",
            "verify",
            str(build_config((2, 1))),
            *engines,
            "--quick",
            *only,
            "--summary",
        ],
        capture_output=True,
        text=True,
    )
    lines = [line for line in result.stdout.splitlines() if re.match(r"  engine [^:]+: ", line)]
    names = [e.name for e in oiiotool_engines()] + ["ocioconvert"]
    assert [line.split(":")[0].removeprefix("  engine ") for line in lines] == names, result.stdout + result.stderr
    assert all(VERSION.search(line) for line in lines), lines
    assert result.returncode == 0, result.stdout + result.stderr


def test_a_host_that_cannot_load_the_config_says_which_ocio_refused_it(build_config):
    """Debian's ocioconvert and oiiotool (OCIO 2.1) cannot load a 2.5 config: each is reported not
    run with the OCIO it runs; Debian's oiiotool, run beside pip's (which loads it), fails nothing."""

    require_program("ocioconvert")
    assert NEWEST >= (2, 5), "the pinned PyOpenColorIO writes 2.5 configs"
    only = "ACEScct -> ACES2065-1"
    result = verify(build_config((2, 5)), ("oiiotool", "ocioconvert"), density="quick", only=only, strict=True)
    runs = {e.name: e for e in result.engines}
    assert runs["ocioconvert"].skipped, f"Debian's ocioconvert loaded a 2.5 config ({runs['ocioconvert'].version})"
    assert runs["ocioconvert"].version == OcioconvertEngine().version() and VERSION.search(runs["ocioconvert"].version)
    lines = summary(result).splitlines()
    assert f"  engine ocioconvert: not run ({runs['ocioconvert'].version}): " in "\n".join(lines)
    assert result.missing == ["ocioconvert"] and not result.passed  # named, it must run
    system = runs.get("oiiotool system")
    if system is not None:
        assert system.skipped and "OCIO 2.1" in system.version and not runs["oiiotool"].skipped
        assert any(line.startswith("  engine oiiotool system: not run (OpenImageIO") for line in lines)
        alone = verify(build_config((2, 5)), ("oiiotool",), density="quick", only=only, strict=True)
        assert alone.passed and [e.name for e in alone.engines if e.skipped] == ["oiiotool system"]


def test_a_config_newer_than_a_hosts_ocio_is_not_run_there(build_config):
    """Debian's ocioconvert (OCIO 2.1) cannot read a 2.3 config: verify reports it not run, with
    OCIO's reason, rather than failing every check; the LUT files it reads without the config
    do not change that."""

    require_program("ocioconvert")
    config = build_config((2, 3))
    # "cale": the Scale display-view spaces (which load the config) and the Scale view LUTs (which do not)
    result = verify(config, ("ocioconvert",), density="quick", kinds=(FROM_REFERENCE, LUT), only="cale")
    outcomes = [o for o in result.outcomes if o.engine.startswith("ocioconvert")]
    assert {o.check.kind for o in outcomes} == {FROM_REFERENCE, LUT}
    assert outcomes and not [o for o in outcomes if o.verdict not in (PASS, APPROX, NOT_RUN)]
    run = next(e for e in result.engines if e.name == "ocioconvert")
    if run.skipped:  # a host whose OCIO predates 2.3
        assert TOO_NEW in run.skipped and all(o.verdict == NOT_RUN for o in outcomes)
        rows = [line for line in summary(result).splitlines() if line.strip().startswith("ocioconvert ")]
        assert rows and all(line.endswith("not run") for line in rows)  # no figures of 0 for what never ran


def test_oiiotool_reads_names_holding_its_wildcards(tmp_path):
    """'#' is oiiotool's frame wildcard: a colour space whose name reads as a path with one
    ('Cam #1/A') made every check of the batch fail ("No filenames found matching pattern")."""
    result = verified_on(
        tmp_path,
        "oiiotool",
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = \'Cam #1/A\'\ngamut = "P3-D65"\ntransfer = { family = "gamma", exponent = 2.2 }\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n',
        density="quick",
        only="Cam #1/A",
    )
    assert result.passed, [(o.check.title, o.engine, o.note) for o in result.failures]


def test_a_host_that_cannot_read_the_config_is_found_at_once_and_proves_nothing(build_config):
    """OCIO 2.1's ocioconvert cannot read a 2.6 config: one process finds that out (it had
    started one per check, minutes of them), and a run in which no engine compared anything
    does not pass."""

    require_program("ocioconvert")
    result = verify(build_config((2, 6)), ("ocioconvert",), density="quick")
    assert [run.name for run in result.engines if run.skipped] == ["ocioconvert"]
    assert {o.verdict for o in result.outcomes} == {NOT_RUN}
    assert not result.compared and not result.passed
    assert "nothing compared" in summary(result).splitlines()[-1]


@pytest.fixture(scope="module")
def three_checks(spec):
    """Two conversions of the default config and, between them, one from a space it lacks."""
    ends = paths.LazyEndpoints(spec)
    inputs = probes.Probes((*probes.code_families(0.0, 1.0, probes.SIZES["quick"]), probes.non_finite()))
    good = [
        checks.conversion_check(spec, ends, inputs, src, dst)
        for src, dst in (("ACEScct", "ACEScg"), ("ACEScg", "ACEScct"))
    ]
    lost = Check(TO_REFERENCE, "No Such Space", "No Such Space", "ACEScg", probes=inputs, expected=inputs.values)
    return [good[0], lost, good[1]]


@pytest.mark.parametrize("engine", [OiiotoolEngine(), OcioconvertEngine()], ids=lambda e: e.name)
def test_a_check_a_host_refuses_fails_alone_with_the_hosts_words(build_config, tmp_path, three_checks, engine):
    """oiiotool runs a batch in one command: the check it stops at is failed with its message and
    the rest of the batch is run again after it; ocioconvert runs a process per check."""
    require_program(engine.name)
    outputs = engine.run(build_config((2, 1)), three_checks, tmp_path)
    assert [len(o) for o in outputs] == [1, 1, 1]
    first, lost, last = (judge(check, engine.name, out[0]) for check, out in zip(three_checks, outputs))
    assert first.verdict == last.verdict == PASS, (first.worst, last.worst)
    assert lost.verdict == FAIL and "No Such Space" in lost.note, lost.note
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.endswith("-in.exr")) == [
        f"{engine.name}-{i:04d}-in.exr" for i in range(3)
    ]


def test_an_output_a_host_did_not_write_carries_its_words(tmp_path, three_checks):
    check = three_checks[0]
    said = read_output(tmp_path / "none.exr", check, "EXR float", "oiiotool ERROR: unknown color space")
    assert said.values is None and said.error == "oiiotool ERROR: unknown color space"
    assert read_output(tmp_path / "none.exr", check, "EXR float", "").error == "no output written (none.exr)"


def test_a_host_that_hangs_is_stopped_and_its_run_reported_failed(monkeypatch):
    monkeypatch.setattr(hosts, "HOST_TIMEOUT", 1)
    result = hosts.run_host([require_program("sleep"), "30"])
    assert result.returncode == -1 and result.stderr == "timed out after 1 s"


def test_a_host_not_installed_cannot_run():
    with pytest.raises(NotRunnable, match="^ocioconvert is not installed$"):
        installed(None, "ocioconvert")
