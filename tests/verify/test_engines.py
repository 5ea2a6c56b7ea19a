"""The default config through every engine, once: PyOpenColorIO (default and lossless
flags), oiiotool, Debian's ocioconvert and Blender. Under CI=true a missing host fails.

ocioconvert converts one image per process (a third of a second each, mostly its
start-up), so here it covers every view from the scene_linear role; ``ocioforge
verify`` runs it on every check.
"""

from __future__ import annotations

import os
from dataclasses import replace

import pytest

from generator.verify.checks import KINDS, VIEW
from generator.verify.judge import APPROX, NOT_RUN, PASS
from generator.verify.run import engine_registry, verify
from tests.conftest import host_missing


@pytest.fixture(scope="module")
def everywhere(build_config):
    config = build_config((2, 1))
    missing = [
        f"{e.name}: {reason}" for family in engine_registry().values() for e in family if (reason := e.missing(config))
    ]
    if missing:
        host_missing("; ".join(missing))
    hosts = verify(config, ("ocio", "oiiotool", "blender"), density="quick", kinds=KINDS)
    convert = verify(config, ("ocio", "ocioconvert"), density="quick", kinds=(VIEW,), only=" from ACEScg")
    extra = [o for o in convert.outcomes if o.engine.startswith("ocioconvert")]
    return replace(hosts, outcomes=hosts.outcomes + tuple(extra), engines=hosts.engines + convert.engines[2:])


def test_every_engine_on_the_default_config(everywhere):
    """One test, so that the module's one verification runs once under pytest-xdist."""
    assert not [e for e in everywhere.engines if e.skipped]
    assert {e.name for e in everywhere.engines} == {
        "ocio default",
        "ocio lossless",
        *(e.name for e in engine_registry()["oiiotool"]),  # Debian's too, where it is installed
        "ocioconvert",
        "blender",
    }
    assert all(o.verdict != NOT_RUN for o in everywhere.outcomes)
    views = {o.engine for o in everywhere.outcomes if o.check.kind == "view"}
    assert {
        "oiiotool (EXR float)",
        "oiiotool (TIFF uint16)",
        "ocioconvert (EXR float)",
        "blender (PNG uint16)",
    } <= views
    approx = [o.note for o in everywhere.outcomes if o.verdict == APPROX]
    assert all("OPTIMIZATION_" in note and "Transform" in note for note in approx), approx
    inexact = [
        (o.check.title, f"{o.worst:.3g}")
        for o in everywhere.outcomes
        if o.engine == "ocio lossless" and o.verdict != PASS
    ]
    assert not inexact, f"the lossless engine misses its tolerance: {inexact}"
    failing = [(o.check.title, o.engine, f"{o.worst:.3g}", o.worst_input, o.note) for o in everywhere.failures]
    assert not failing, failing


def test_a_config_newer_than_a_hosts_ocio_is_not_run_there(build_config):
    """Debian's ocioconvert (OCIO 2.1) cannot read a 2.3 config: verify reports it not run, with
    OCIO's reason, rather than failing every check; the LUT files it reads without the config
    do not change that."""
    from generator.verify.checks import FROM_REFERENCE, LUT
    from generator.verify.hosts import TOO_NEW
    from tests.conftest import require_program

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
        from generator.verify.report import summary

        rows = [line for line in summary(result).splitlines() if line.strip().startswith("ocioconvert ")]
        assert rows and all(line.endswith("not run") for line in rows)  # no figures of 0 for what never ran


def _verified_on(tmp_path, program: str, text: str, **options):
    """Build the spec ``text`` (beside files already in ``tmp_path``) for OCIO 2.1 and verify it
    with ``program`` alone, which must have run."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from tests.conftest import require_program

    require_program(program)
    (tmp_path / "show.toml").write_text(text)
    folder = tmp_path / "show"
    build(for_folder(load.load(tmp_path / "show.toml"), folder, (2, 1)), folder)
    result = verify(folder / "config.ocio", (program,), **options)
    assert result.outcomes and not [e for e in result.engines if e.skipped]
    return result


def test_ocio_21s_tabulated_pq_is_carried_near_black(tmp_path):
    """OCIO 2.1 tabulates PQ over 4096 codes, and its default flags tabulate the display's
    inverse again over half-float light: a blue-only code near black from a log space (red at
    5e-6 cd/m² after the matrices) came back 0.0102 ΔE ITP away, over the 0.01 tolerance, which
    no config can change. Verify carries that departure."""
    rows = "".join(f"{c:.6f},{(10.0 ** (5 * c) - 1) * 1e-3:.9g}\n" for c in (i / 256 for i in range(257)))
    (tmp_path / "curve.csv").write_text("code,linear\n" + rows)
    result = _verified_on(
        tmp_path,
        "ocioconvert",
        'chromatic_adaptation = "CAT02"\n'
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Tab Log"\nprimaries = [[0.70, 0.30], [0.17, 0.80], [0.13, 0.04]]\nwhite = 5600\n'
        'transfer = { family = "tabulated", file = "curve.csv" }\nencoding = "log"\n'
        '[[display]]\nname = "Rec.2100-PQ - Display"\nviews = ["Colorimetric", "Raw"]\n'
        '[roles]\ncompositing_log = "Tab Log"\n',
        kinds=(VIEW,),
        only="Colorimetric from Tab Log",
    )
    assert result.passed, [(o.check.title, o.engine, o.worst, o.worst_input) for o in result.failures]


def test_oiiotool_reads_names_holding_its_wildcards(tmp_path):
    """'#' is oiiotool's frame wildcard: a colour space whose name reads as a path with one
    ('Cam #1/A') made every check of the batch fail ("No filenames found matching pattern")."""
    result = _verified_on(
        tmp_path,
        "oiiotool",
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = \'Cam #1/A\'\ngamut = "P3-D65"\ntransfer = { family = "gamma", exponent = 2.2 }\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n',
        density="quick",
        only="Cam #1/A",
    )
    assert result.passed, [(o.check.title, o.engine, o.note) for o in result.failures]


def test_a_host_verified_alone_has_its_default_flag_departures_explained(build_config):
    """oiiotool runs OCIO with its default flags; verified without the in-process engines, its
    departures the flags explain are named so (APPROX) from in-process runs made for that alone,
    not failures (they failed when the ocio engine was not asked for)."""
    from generator.verify.judge import APPROX
    from tests.conftest import require_program

    require_program("oiiotool")
    result = verify(build_config((2, 1)), ("oiiotool",), density="quick")
    names = {e.name for e in engine_registry()["oiiotool"]}  # Debian's too, where it is installed
    assert {run.name for run in result.engines} == names
    assert {o.engine for o in result.outcomes} <= {f"{n} ({v})" for n in names for v in ("EXR float", "TIFF uint16")}
    assert any(o.verdict == APPROX and "in-process default flags" in o.note for o in result.outcomes)
    assert result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]


def test_ocio_21s_tabulated_pq_is_carried_for_a_scene_encoding(tmp_path):
    """A scene space encoded with ST 2084 goes through OCIO's PQ builtin too: OCIO 2.1's
    4096-code table put a near-black code 1.24e-4 relative off, over the 1e-4 tolerance (the
    allowance covered display encodings only)."""
    result = _verified_on(
        tmp_path,
        "ocioconvert",
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "PQ Scene"\ngamut = "Rec.2020"\ntransfer = "ST 2084"\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n',
        only="PQ Scene",
    )
    assert result.passed, [(o.check.title, o.engine, o.worst, o.worst_input) for o in result.failures]


def test_a_host_that_cannot_read_the_config_is_found_at_once_and_proves_nothing(build_config):
    """OCIO 2.1's ocioconvert cannot read a 2.6 config: one process finds that out (it had
    started one per check, minutes of them), and a run in which no engine compared anything
    does not pass."""
    from generator.verify.judge import NOT_RUN
    from generator.verify.report import summary
    from tests.conftest import require_program

    require_program("ocioconvert")
    result = verify(build_config((2, 6)), ("ocioconvert",), density="quick")
    assert [run.name for run in result.engines if run.skipped] == ["ocioconvert"]
    assert {o.verdict for o in result.outcomes} == {NOT_RUN}
    assert not result.compared and not result.passed
    assert "nothing compared" in summary(result).splitlines()[-1]


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


def test_a_desaturate_chains_flag_is_named_with_its_operator(tmp_path):
    """A Desaturate chain (RGB_TO_HSV, half-domain tables, the lattice) run operator by operator
    had departed by itself (650 codes), so no operator was named: OCIO's processor cache had
    given its hue table's inverse the table's own processor (one length, a key without the
    values). Built uncached, the chain holds, and the power the fast flag approximates is named."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from generator.verify.judge import APPROX

    text = (
        '[[display]]\nname = "Odd Wide D50 - Display"\nprimaries = [[0.70, 0.29], [0.12, 0.84], [0.145, 0.035]]\n'
        'white = "D50"\neotf = { family = "gamma", exponent = 2.4 }\n'
        '[[display]]\nname = "Dim 48 - Display"\nprimaries = [[0.68, 0.32], [0.265, 0.69], [0.15, 0.06]]\n'
        'white = "D65"\neotf = { family = "gamma", exponent = 2.6 }\npeak_luminance = 48\n'
        'absolute_luminance = true\nviews = ["Desaturate"]\n'
    )
    folder = tmp_path / "dim"
    build(for_folder(load.parse(text, "dim.toml", tmp_path), folder), folder)
    result = verify(folder / "config.ocio", ("ocio",), only="Dim 48 - Display / Desaturate from Odd Wide")
    explained = [o.note for o in result.outcomes if o.verdict == APPROX]
    assert explained and all("OPTIMIZATION_FAST_LOG_EXP_POW in ExponentTransform" in note for note in explained), (
        explained
    )


@pytest.mark.parametrize(
    "value, expected", [("true", True), ("1", True), ("YES", True), ("false", False), ("0", False), ("", False)]
)
def test_ci_is_told_as_ci_services_set_it(value, expected):
    """CI=1 had counted as not CI, so engines a CI run lacks passed as not run."""
    import subprocess
    import sys

    env = {**os.environ, "CI": value}
    done = subprocess.run(
        [sys.executable, "-c", "import generator.verify.run as r; print(r.ON_CI)"],
        capture_output=True,
        text=True,
        check=True,
        env=env,
    )
    assert done.stdout.strip() == str(expected)
