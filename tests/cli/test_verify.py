"""ocioforge verify: a built config's checks, their table, summary and report; bad input one line
and exit status 2 before any check."""

from __future__ import annotations

import json

import pytest

from generator.cli import main
from tests.cli.conftest import LONG, invoke, one_line, run


def test_verify_prints_a_row_per_check_and_a_summary(config, tmp_path):
    result = invoke(
        "verify", config, "--engines", "ocio", "--quick", "--only", " -> ACES2065-1", "--report", tmp_path / "report"
    )
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0].split() == ["check", "item", "engine", "max", "p99", "tolerance", "verdict"]
    assert any("to reference" in line and "ACEScct" in line and "ocio lossless" in line for line in lines)
    assert "verify passed" in result.output
    summary = json.loads((tmp_path / "report" / "summary.json").read_text())
    assert summary["passed"] and {e["name"] for e in summary["engines"]} == {"ocio default", "ocio lossless"}
    page = (tmp_path / "report" / "report.html").read_text()
    assert page.count("data:image/png;base64,") == 4 and "<script src" not in page  # inline only
    assert not [p for p in (tmp_path / "report").iterdir() if p.name.startswith(".")]


def test_verify_fails_and_names_the_broken_lut(config):
    (config.parent / "luts" / "n_log_to_linear.spi1d").write_text(
        "Version 1\nFrom 0 1\nLength 2\nComponents 1\n{\n 0\n 1\n}\n"
    )
    result = invoke("verify", config, "--engines", "ocio", "--quick", "--summary")
    assert result.exit_code == 1
    assert "FAIL: LUT file luts/n_log_to_linear.spi1d" in result.output
    assert "worst input" in result.output


@pytest.mark.parametrize(
    "args, message",
    [
        (["missing/config.ocio"], "no such config file"),
        (["{config}", "--engines", "ocio,nuke"], "unknown engine"),
        (["{config}", "--engines", "ocio", "--quick", "--only", "zzz"], "--only:zzz: matches no check title"),
        (["{config}", "--engines", ","], "--engines names none"),
    ],
)
def test_verify_bad_input_is_one_line_and_exit_2(config, args, message):
    result = invoke("verify", *[a.format(config=config) for a in args])
    assert result.exit_code == 2
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("error: ") and message in result.stderr


def test_verify_without_the_stored_spec_is_a_clear_error(config):
    (config.parent / "ocioforge-spec.json").unlink()
    result = invoke("verify", config, "--engines", "ocio", "--quick")
    assert result.exit_code == 2 and "no resolved spec here" in result.stderr


@pytest.mark.parametrize("only", ("", "  "))
def test_verify_refuses_an_empty_only(capsys, build_config, only):
    """An empty --only had run every check, as if not given."""
    code, out, err = run(capsys, "verify", str(build_config((2, 1))), "--quick", "--only", only)
    assert code == 2 and err.count("\n") == 1 and "--only" in err and "is empty" in err and out == "", err


def test_an_unwritable_report_is_one_line_and_exit_2_before_the_run(config, tmp_path, capsys):
    """The path and the OS's reason, exit status 2 (not verify's 1 for failed checks)."""
    blocked = tmp_path / "blocked"
    blocked.write_bytes(b"")
    argv = ["verify", config, "--engines", "ocio", "--quick", "--only", " -> ACES2065-1", "--summary"]
    code, out, err = run(capsys, *argv, "--report", f"{blocked}/report")
    assert code == 2 and err.count("\n") == 1, err
    assert err.startswith(f"error: {blocked}/") and err.endswith(": cannot write: Not a directory\n")
    assert "verify passed" not in out  # the report's folder is checked before the run


VERIFY = ("verify", "{config}", "--engines", "ocio", "--quick", "--only", "ACEScct -> ACES2065-1", "--summary")


def test_a_report_is_replaced_only_with_force_and_refused_before_the_run(config, tmp_path, capsys):
    report = tmp_path / "report"
    argv = [a.format(config=config) for a in VERIFY]
    assert run(capsys, *argv, "--report", report)[0] == 0
    (report / "summary.json").write_text("keep")
    code, out, err = run(capsys, *argv, "--report", report)
    assert one_line(code, err, "summary.json: exists; pass --force"), err
    assert out == "" and (report / "summary.json").read_text() == "keep"
    assert run(capsys, *argv, "--report", report, "--force")[0] == 0
    assert (report / "summary.json").read_text().startswith("{")


def test_a_report_is_written_whole_or_not_at_all(config, tmp_path, capsys):
    """report.html a folder: refused before the run, and summary.json not written either."""
    report = tmp_path / "report"
    (report / "report.html").mkdir(parents=True)
    code, out, err = run(capsys, *(a.format(config=config) for a in VERIFY), "--report", report, "--force")
    assert one_line(code, err, "report.html: is a folder; allowed: ") and out == "", err
    assert sorted(p.name for p in report.iterdir()) == ["report.html"]


@pytest.mark.parametrize(
    "argv, words",
    [
        (["verify", "{tmp}/" + LONG + "/config.ocio"], "File name too long"),
        (["verify", "{config}", "--report", "{tmp}/" + LONG], "File name too long"),
    ],
)
def test_a_path_too_long_is_one_line(config, looped_links, capsys, argv, words):
    code, _, err = run(capsys, *(a.format(config=config, tmp=looped_links) for a in argv))
    assert one_line(code, err, words), err
    assert sorted(p.name for p in looped_links.iterdir()) == ["l1", "l2"]


def test_verify_refuses_a_config_holding_what_its_spec_does_not(config):
    """A space pasted into config.ocio after the build would go unchecked (verify checks what the
    stored spec defines): it is named, exit 2, nothing run."""
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(config))
    pasted = ocio.ColorSpace(name="Bogus Space")
    pasted.setTransform(
        ocio.MatrixTransform([2, 0, 0, 0, 0, 0.1, 0, 0, 0, 0, 5, 0, 0, 0, 0, 1]), ocio.COLORSPACE_DIR_TO_REFERENCE
    )
    cfg.addColorSpace(pasted)
    config.write_text(cfg.serialize())
    result = invoke("verify", config, "--engines", "ocio", "--quick")
    assert result.exit_code == 2 and "holds 'Bogus Space'" in result.stderr and result.stderr.count("\n") == 1


@pytest.mark.parametrize(
    "edit, words",
    [
        (lambda d: d.update(chromatic_adaptation="foo"), "unknown chromatic adaptation 'foo'"),
        (lambda d: d.update(scene_reference="Nope"), ":scene_reference: 'Nope' names nothing the spec defines"),
        (lambda d: d.update(ocio_version=["9", "9"]), ":ocio_version[0]: expected an integer, got '9'"),
        (lambda d: d["colour_spaces"][1]["gamut"].update(primaries=[[0.7, 0.3]]), "expected 3 entries or more, got 1"),
        (lambda d: d["colour_spaces"][0].update(gamut=None), "has no gamut"),
    ],
)
def test_an_edited_stored_spec_is_one_line_and_exit_2(config, edit, words):
    """What later commands take for granted is checked as the stored spec is read (each of these
    raised a traceback, exit 1, deep inside verify)."""
    path = config.parent / "ocioforge-spec.json"
    data = json.loads(path.read_text())
    edit(data)
    path.write_text(json.dumps(data))
    result = invoke("verify", config, "--engines", "ocio", "--quick")
    assert result.exit_code == 2 and words in result.stderr and result.stderr.count("\n") == 1, result.stderr


def test_verify_reads_every_display_whatever_the_active_ones(config, monkeypatch):
    """Studio shells narrow what hosts show with OCIO_ACTIVE_DISPLAYS / _VIEWS; the config still
    holds every display and view its spec builds, and verify checks them all."""
    monkeypatch.setenv("OCIO_ACTIVE_DISPLAYS", "sRGB - Display")
    monkeypatch.setenv("OCIO_ACTIVE_VIEWS", "Colorimetric,Raw")
    result = invoke(
        "verify", config, "--engines", "ocio", "--quick", "--only", "Display P3 - Display / Scale", "--summary"
    )
    assert result.exit_code == 0, result.output


@pytest.fixture
def blender_missing(monkeypatch):
    """Blender not installed, and not on CI (where any engine missing fails the run)."""
    from generator.verify import run as verify_run
    from generator.verify.blender import BlenderEngine

    monkeypatch.setattr(BlenderEngine, "missing", lambda self, config: "blender is not installed")
    monkeypatch.setattr(verify_run, "ON_CI", False)


ONE_CHECK = ("--quick", "--only", "ACEScct -> ACES2065-1", "--summary")


def test_an_engine_named_but_not_installed_fails_the_run(config, blender_missing):
    """Named in --engines, an engine that cannot run is not a pass (it had said "verify passed,
    not run: blender", exit 0); in the default list it is reported as not run."""
    result = invoke("verify", config, "--engines", "ocio,Blender", *ONE_CHECK)
    assert result.exit_code == 1 and "verify FAILED" in result.output
    assert "not run (asked for by --engines): blender" in result.output


def test_verify_takes_a_builds_folder_for_its_config(config, capsys, tmp_path):
    from generator.cli import main

    def code(*argv):
        try:
            main(list(argv))
        except SystemExit as exited:
            return exited.code
        return 0

    assert code("verify", str(config.parent), "--quick", "--engines", "ocio", "--only", "ACEScct") == 0
    assert code("verify", str(tmp_path), "--quick", "--engines", "ocio") == 2
    err = capsys.readouterr().err
    assert "is a folder without config.ocio; allowed: " in err and err.count("\n") == 1, err


@pytest.mark.parametrize(
    "argv, words",
    [
        (["verify", "ocio://default"], "is one of OpenColorIO's builtin configs"),  # said: ocio:/default, no such file
        (["verify", "{config}", "--engines", ","], "ocio,oiiotool,ocioconvert,blender,gpu"),  # gpu was left out
        # root passes os.access everywhere: /proc took the run, then failed making its folder
        (["verify", "{config}", "--engines", "ocio", "--report", "/proc/ocioforge-report"], "cannot write"),
    ],
)
def test_what_verify_cannot_do_is_one_line_before_any_check(config, capsys, argv, words):
    with pytest.raises(SystemExit) as exited:
        main([a.format(config=config) for a in argv])
    out, err = capsys.readouterr()
    assert exited.value.code == 2 and err.count("\n") == 1 and words in err, err
    assert "verify passed" not in out and "FAILED" not in out


def test_verify_summary_leaves_each_explained_row_to_the_report(config, tmp_path):
    """--summary prints the summary alone: the departures OCIO's default flags explain (dozens on
    the default config) are counted, and named in the table's run and in the report."""
    args = ("verify", config, "--engines", "ocio", "--quick", "--only", "-> ADX10")
    full = invoke(*args)
    assert full.exit_code == 0, full.output
    assert "approx: from reference ACES2065-1 -> ADX10 [ocio default]" in full.output
    short = invoke(*args, "--summary", "--report", tmp_path / "report")
    assert short.exit_code == 0, short.output
    assert not [line for line in short.output.splitlines() if line.startswith("approx:")]
    assert "explained by OCIO's default flags (each named without --summary, and in --report's files)" in short.output
    page = (tmp_path / "report" / "report.html").read_text()
    assert "approx: from reference ACES2065-1 -&gt; ADX10 [ocio default]" in page
    results = json.loads((tmp_path / "report" / "summary.json").read_text())["results"]
    assert any(r["verdict"] == "approx" and "OPTIMIZATION_" in r["note"] for r in results)


def test_an_engine_named_twice_in_any_case_runs_once_and_the_report_files_are_named(build_config, tmp_path, capsys):
    report = tmp_path / "report"
    code, out, err = run(
        capsys,
        "verify",
        build_config((2, 1)),
        "--engines",
        " OCIO ,ocio",
        "--quick",
        "--only",
        "ACEScct -> ACES2065-1",
        "--summary",
        "--report",
        report,
    )
    assert code == 0, err
    engines = [engine["name"] for engine in json.loads((report / "summary.json").read_text())["engines"]]
    assert sorted(engines) == ["ocio default", "ocio lossless"]
    assert sorted(out.splitlines()[-2:]) == [f"wrote {report / 'report.html'}", f"wrote {report / 'summary.json'}"]
