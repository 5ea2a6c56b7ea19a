"""The CLI through its entry point: in-process for speed, one subprocess for start-up."""

import json
import subprocess
import sys

import numpy as np
import pytest

from generator.cli import main


def run(capsys, *argv):
    try:
        main(list(argv))
        code = 0
    except SystemExit as exit_:
        code = exit_.code
    out, err = capsys.readouterr()
    return code, out, err


def test_help_starts_without_heavy_imports():
    probe = (
        "import sys\nfrom generator.cli import main\n"
        "try:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
        "print(sorted(m for m in ('colour', 'scipy', 'matplotlib', 'PyOpenColorIO', 'OpenImageIO') if m in sys.modules))"
    )
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=60)
    assert "Commands" in result.stdout or "build" in result.stdout
    assert result.stdout.strip().splitlines()[-1] == "[]"


def test_console_script_runs():
    result = subprocess.run(
        [sys.executable, "-m", "generator", "--version"], capture_output=True, text=True, timeout=60
    )
    assert result.returncode == 0 and "ocioforge" in result.stdout


def test_build_writes_a_named_config_and_refuses_to_overwrite(tmp_path, capsys):
    out = tmp_path / "my-show"
    code, stdout, _ = run(capsys, "build", "-o", str(out), "--ocio-version", "2.3")
    assert code == 0 and "OCIO 2.3" in stdout
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(out / "config.ocio"))
    assert cfg.getName() == "my-show" and cfg.getMinorVersion() == 3
    before = sorted(p.name for p in out.iterdir())
    code, _, err = run(capsys, "build", "-o", str(out))
    assert code == 2 and err.count("\n") == 1 and "--force" in err
    assert sorted(p.name for p in out.iterdir()) == before
    assert run(capsys, "build", "-o", str(out), "--force")[0] == 0


def test_build_counts_the_inactive_colour_spaces_it_writes(tmp_path, capsys):
    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "ARRI LogC4", '
        '"sRGB Encoded Rec.709 (sRGB)", "Raw"]\ninactive = ["ARRI LogC4"]\n'
    )
    code, stdout, err = run(capsys, "build", str(tmp_path / "show.toml"), "-o", str(tmp_path / "show"))
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(tmp_path / "show" / "config.ocio"))
    written = cfg.getColorSpaceNames(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL)
    assert code == 0 and f" {len(written)} colour spaces," in stdout, err
    assert len(written) == len(cfg.getColorSpaceNames()) + 1


@pytest.mark.parametrize("foreign", ("footage/shot.exr", "config.ocio"))
def test_force_replaces_only_a_previous_build(tmp_path, capsys, foreign):
    """A folder holding anything a build does not write (footage), or not holding the resolved
    spec a build writes (a hand-made config alone), is never replaced, --force or not."""
    out = tmp_path / "show"
    (out / foreign).parent.mkdir(parents=True, exist_ok=True)
    (out / foreign).write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and "previous build" in err
    assert (out / foreign).read_bytes() == b"keep"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["show"]


def test_force_keeps_what_is_not_a_build_inside_its_lut_folder(tmp_path, capsys):
    """A previous build whose luts/ also holds a file no build writes is not replaced."""
    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    (out / "luts" / "shot.exr").write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and "luts/shot.exr, which no build writes" in err
    assert (out / "luts" / "shot.exr").read_bytes() == b"keep"


@pytest.mark.parametrize("name", ("grade.clf", "show_curve.spi1d"))
def test_force_keeps_a_lut_of_its_own_in_the_lut_folder(tmp_path, capsys, name):
    """A file of a build's suffixes that its config does not read is not the build's: --force
    had deleted a TD's own CLF or .spi1d put in luts/, judging by suffix alone."""
    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    (out / "luts" / name).write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and f"luts/{name}, which its config.ocio does not read" in err, err
    assert (out / "luts" / name).read_bytes() == b"keep"


@pytest.mark.parametrize("src", ("/mnt/show/grades/grade.clf", "grade.clf"))
def test_force_keeps_a_lut_only_a_look_of_its_own_reads(tmp_path, capsys, src):
    """A TD's look reading their grade (from luts/, or another file of the same name) does not
    make it the build's: files_read had gone by file name over every transform, looks too."""
    import PyOpenColorIO as ocio

    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    cfg = ocio.Config.CreateFromFile(str(out / "config.ocio"))
    cfg.addLook(ocio.Look(name="Grade", processSpace="ACEScct", transform=ocio.FileTransform(src=src)))
    (out / "config.ocio").write_text(cfg.serialize(), encoding="utf-8")
    (out / "luts" / "grade.clf").write_bytes(b"keep")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and "luts/grade.clf, which its config.ocio does not read" in err, err
    assert (out / "luts" / "grade.clf").read_bytes() == b"keep"


@pytest.mark.parametrize("force", (True, False))
def test_a_previous_build_without_its_config_is_refused_in_one_line(tmp_path, capsys, force):
    """A build whose config.ocio is gone had ended the next build in a traceback, --force or not."""
    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    (out / "config.ocio").unlink()
    code, _, err = run(capsys, "build", "-o", str(out), *(["--force"] if force else []))
    assert code == 2 and err.count("\n") == 1 and "has no config.ocio" in err, err
    assert (out / "luts").is_dir()


def test_force_refuses_a_build_whose_config_does_not_load(tmp_path, capsys):
    """Which of luts/ a build wrote is told by the config that reads them: without one that
    loads, nothing is replaced."""
    out = tmp_path / "show"
    assert run(capsys, "build", "-o", str(out))[0] == 0
    (out / "config.ocio").write_text("not a config")
    code, _, err = run(capsys, "build", "-o", str(out), "--force")
    assert code == 2 and err.count("\n") == 1 and "config.ocio OpenColorIO cannot load" in err, err
    assert (out / "config.ocio").read_text() == "not a config"


def test_force_through_a_link_replaces_the_build_it_points_to(tmp_path, capsys):
    """A show's ``current`` link to a versioned build stays a link; the build is replaced."""
    build = tmp_path / "v001"
    assert run(capsys, "build", "-o", str(build))[0] == 0
    (tmp_path / "current").symlink_to("v001")
    with (build / "config.ocio").open("a") as config:
        config.write("# stale\n")
    assert run(capsys, "build", "-o", str(tmp_path / "current"), "--force")[0] == 0
    assert (tmp_path / "current").is_symlink() and not (build / "config.ocio").read_text().endswith("# stale\n")
    import PyOpenColorIO as ocio

    assert ocio.Config.CreateFromFile(str(build / "config.ocio")).getName() == "v001"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["current", "v001"]


def test_a_link_to_nothing_is_named(tmp_path, capsys):
    (tmp_path / "current").symlink_to("v002")
    code, _, err = run(capsys, "build", "-o", str(tmp_path / "current"))
    assert code == 2 and err.count("\n") == 1 and "is a link to 'v002', which does not exist" in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["current"] and not (tmp_path / "current").exists()


def test_a_spec_not_in_utf8_is_one_line(tmp_path, capsys):
    spec = tmp_path / "show.toml"
    spec.write_bytes('name = "show"\n'.encode("utf-16"))
    code, _, err = run(capsys, "build", str(spec), "-o", str(tmp_path / "out"))
    assert code == 2 and err.count("\n") == 1 and "not UTF-8 text" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["show.toml"]


def test_a_build_failing_while_written_leaves_no_folders_it_made(tmp_path, capsys):
    """A table no 1D LUT holds is found while the folder is staged: the folders made for the
    output go too, and the error names the space."""
    codes = sorted([(i / 39) ** 1.7 for i in range(40)] + [0.33331, 0.33333])  # uneven rows, a step between two
    (tmp_path / "rough.csv").write_text(
        "".join(f"{x:.6f},{x * 0.3 + (0.2 if x > 0.33332 else 0.0):.6f}\n" for x in codes)
    )
    (tmp_path / "rough.toml").write_text(
        'colour_spaces = ["*"]\n[[custom_space]]\nname = "Rough"\ngamut = "Rec.709"\n'
        'transfer = { family = "tabulated", file = "rough.csv" }\n'
    )
    code, _, err = run(capsys, "build", str(tmp_path / "rough.toml"), "-o", str(tmp_path / "a" / "b" / "show"))
    assert code == 2 and err.count("\n") == 1 and "custom_space[name = 'Rough'].transfer" in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["rough.csv", "rough.toml"]


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ("../escape", "cannot name a folder"),
        ("", "cannot name a folder"),
        ("..", "cannot name a folder"),
        ("show\nbuild", "control character"),
        ("a/b", "cannot name a folder"),
        ("CON", "keeps it for a device"),
        ("aux.show", "keeps it for a device"),
        ("Com1", "keeps it for a device"),
        ("show.", "drops a final dot"),
        ("show..", "drops a final dot"),
    ],
)
def test_a_spec_name_that_cannot_name_the_default_folder_is_refused(tmp_path, capsys, monkeypatch, name, words):
    """Without -o a build goes to configs/<name>: a name no folder takes is one line, exit 2."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "show.toml").write_text(f"name = {name!r}\n".replace("'", '"').replace('\n"', '\\n"'))
    code, _, err = run(capsys, "build", "show.toml")
    assert code == 2 and err.count("\n") == 1 and words in err, err
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["show.toml"]
    (tmp_path / "show.toml").write_text('name = "Show: A"\n')
    assert run(capsys, "build", "show.toml", "-o", str(tmp_path / "out"))[0] == 0  # -o names the folder


def test_list_takes_one_kind(capsys):
    code, _, err = run(capsys, "list", "--displays", "--curves")
    assert code == 2 and err.count("\n") == 1 and "allowed: one of --spaces, --displays, --curves" in err


@pytest.mark.parametrize("argv", (["build", "-o", "{blocked}/show"], ["init", "{blocked}/show.toml"]))
def test_an_unwritable_output_is_one_line_and_exit_2(tmp_path, capsys, argv):
    """An output under a regular file cannot be written, for any user: the path and the OS's
    reason on one line, exit status 2 (1 is verify's "checks failed"), nothing left behind."""
    blocked = tmp_path / "blocked"
    blocked.write_bytes(b"")
    code, _, err = run(capsys, *(a.format(blocked=blocked) for a in argv))
    assert code == 2 and err.count("\n") == 1, err
    assert err == f"error: {blocked / argv[-1].split('/')[-1]}: cannot write: Not a directory\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocked"]


def test_terminated_build_leaves_nothing(tmp_path):
    """SIGTERM while the folder is being written removes the staging folder."""
    import signal
    import time

    build = subprocess.Popen(
        [sys.executable, "-m", "generator", "build", "-o", str(tmp_path / "show")],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    deadline = time.monotonic() + 60
    while not any(tmp_path.iterdir()) and build.poll() is None and time.monotonic() < deadline:
        time.sleep(0.01)
    assert build.poll() is None, "the build ended before it could be terminated"
    build.send_signal(signal.SIGTERM)
    assert build.wait(timeout=60) == 128 + signal.SIGTERM
    assert list(tmp_path.iterdir()) == []


def test_bad_spec_gives_one_line_exit_2_and_writes_nothing(tmp_path, capsys):
    spec = tmp_path / "bad.toml"
    spec.write_text('colour_spaces = ["ACEScg", "Linear Rec.709 (sRGB)", "S-Log3 S-Gamut9"]\n')
    code, _, err = run(capsys, "build", str(spec), "-o", str(tmp_path / "out"))
    assert code == 2
    assert err.startswith("error: ") and err.count("\n") == 1
    assert "bad.toml:colour_spaces[2]" in err and "S-Log3 S-Gamut3" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml"]


@pytest.mark.parametrize(
    "argv, words",
    [
        (("build", "--ocio-version", "1.9"), "allowed: 2.1 to"),
        (("build", "nowhere.toml"), "cannot read"),
        (("matrix", "acescg", "lin_rec709", "--cat", "Sharp"), "allowed: Bradford"),
        (("matrix", "acescg", "raw"), "no RGB primaries"),
        (("info", "nothing_like_this"), "unknown colour space"),
        (("matrix", "acescg"), "Missing argument"),
    ],
)
def test_bad_arguments_exit_2_with_one_line(tmp_path, capsys, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err
    assert list(tmp_path.iterdir()) == []


def test_init_writes_the_default_spec_that_builds(tmp_path, capsys):
    path = tmp_path / "my-show.toml"
    assert run(capsys, "init", str(path))[0] == 0
    assert path.read_text().startswith("# ocioforge spec")
    assert run(capsys, "init", str(path))[0] == 2
    assert run(capsys, "build", str(path), "-o", str(tmp_path / "cfg"))[0] == 0


def test_init_replaces_only_a_regular_file(tmp_path, capsys):
    """A pipe, a link (dangling or not) or a name too long is refused in one line, --force or
    not (run as root, --force had turned /dev/null into a text file)."""
    import os

    os.mkfifo(tmp_path / "pipe")
    (tmp_path / "link").symlink_to(tmp_path / "nowhere")
    for name, words in (("pipe", "is not a regular file"), ("link", "is a link to nothing")):
        code, _, err = run(capsys, "init", str(tmp_path / name), "--force")
        assert code == 2 and words in err and err.count("\n") == 1
    assert (tmp_path / "link").is_symlink() and not (tmp_path / "nowhere").exists()
    code, _, err = run(capsys, "init", str(tmp_path / ("x" * 300 + ".toml")))
    assert code == 2 and "cannot write" in err and err.count("\n") == 1


def test_matrix_reads_cat_in_any_case_and_gives_one_gamut_the_identity(capsys):
    _, lower, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--cat", "cat02", "--format", "json")
    _, upper, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--cat", "CAT02", "--format", "json")
    assert lower == upper
    code, out, _ = run(capsys, "matrix", "srgb", "lin_srgb", "--format", "json")
    assert code == 0 and json.loads(out)["matrix"] == np.eye(3).tolist()


def test_matrix_formats_agree(capsys):
    from generator.colorimetry.gamuts import gamuts
    from generator.colorimetry.matrices import rgb_to_rgb

    expected = rgb_to_rgb(gamuts()["AP1"], gamuts()["Rec.709"], "Bradford")
    code, out, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--format", "json")
    assert code == 0 and np.allclose(json.loads(out)["matrix"], expected, rtol=0, atol=1e-15)
    _, plain, _ = run(capsys, "matrix", "ACEScg", "Linear Rec.709 (sRGB)")
    assert np.allclose(np.array(plain.split(), dtype=float).reshape(3, 3), expected, atol=1e-10)
    _, nuke, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--format", "nuke")
    assert nuke.startswith("ColorMatrix {") and "name lin_ap1_to_lin_rec709_srgb" in nuke
    _, snippet, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--format", "ocio")
    assert snippet.startswith("!<MatrixTransform>") and "1.705050992657" in snippet
    _, cat02, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--cat", "CAT02", "--format", "json")
    assert not np.allclose(json.loads(cat02)["matrix"], expected, atol=1e-6)


def test_info_and_list(capsys):
    code, out, _ = run(capsys, "info", "arri_logc4")
    assert code == 0 and "ARRI Wide Gamut 4" in out and "18% grey:  code 0.278396" in out
    assert "OCIO 2.1: analytic (LogCamera)" in out
    _, out, _ = run(capsys, "info", "canonlog3_cinemagamut_d55")
    assert "OCIO 2.1: baked 1D LUT" in out and "OCIO 2.2: analytic (BuiltinTransform)" in out
    _, out, _ = run(capsys, "list")
    assert "S-Log3 S-Gamut3.Cine" in out and "lin_ap1" in out
    _, out, _ = run(capsys, "list", "--displays")
    assert "Rec.2100-PQ - Display" in out
    _, out, _ = run(capsys, "list", "--curves")
    assert "LogCamera" in out and "T-LogE" in out
    _, out, _ = run(capsys, "list", "--views")
    assert "ACES 2.0 - HDR 108 nits (P3 D65)\t2.0\t108\tHDR-108nit-P3-D65_2.0" in out
    assert "ACES 1.1 - HDR Cinema (108 nits & P3 lim)\t1.3\t108" in out


def test_list_piped_gives_one_unwrapped_line_a_row(capsys):
    """Piped (as under pytest), each row is one tab-separated line, so grep finds a name
    whatever its length (the 200-column table wrapped long aliases mid-name)."""
    from generator.colorimetry import library

    _, out, _ = run(capsys, "list")
    lines = out.splitlines()
    assert lines[0].split("\t")[0] == "colour space" and len(lines) == len(library.SPACES) + 1
    assert all(line.count("\t") == 4 for line in lines)
    assert any(
        line.startswith("Gamma 2.4 Encoded Rec.709\t") and "Gamma 2.4 Rec.709 - Texture" in line for line in lines
    )


def test_an_unknown_command_lists_the_commands(capsys):
    code, _, err = run(capsys, "bogus")
    assert (
        code == 2
        and "allowed: build, init, matrix, bake, pack, verify, plot, info, list, convert" in err
        and err.count("\n") == 1
    )


def _interrupted(*args, **kwargs):
    raise KeyboardInterrupt


def test_ctrl_c_exits_130_not_as_bad_input(capsys, monkeypatch):
    """Interrupted is not bad input (exit 2): the shell's 128 + SIGINT, and one line (click had
    printed a blank line before it)."""
    from generator.cli import init

    monkeypatch.setattr(init, "command", click_command_raising(_interrupted))
    code, _, err = run(capsys, "init", "x.toml")
    assert code == 130 and err == "error: interrupted\n"


def test_ctrl_c_before_the_command_runs_is_one_line(capsys, monkeypatch):
    """Ctrl-C during the imports that precede the command (numpy's, 0.2 s in) was a traceback."""
    import generator.colour_science

    monkeypatch.setattr(generator.colour_science, "skip_plotting", _interrupted)
    code, _, err = run(capsys, "list")
    assert code == 130 and err == "error: interrupted\n"


def test_a_swallowed_sigterm_still_stops_the_command_before_it_writes(tmp_path, capsys, monkeypatch):
    """SIGTERM's exception raised inside a weakref callback is only printed: the signal is
    recorded, so the bake renames nothing into place and exits 128 + SIGTERM (it had exited 0)."""
    import signal

    import generator.cli
    from generator.luts import bake

    real_bake = bake.bake

    def terminated_meanwhile(req):
        try:
            generator.cli._stop(signal.SIGTERM, None)
        except SystemExit:
            pass  # as Python does with an exception raised in a weakref callback
        return real_bake(req)

    monkeypatch.setattr(bake, "bake", terminated_meanwhile)
    code, _, _ = run(
        capsys, "bake", "--from", "ACEScg", "--to", "sRGB - Display", "--size", "9", "-o", str(tmp_path / "a.clf")
    )
    assert code == 128 + signal.SIGTERM and list(tmp_path.iterdir()) == []
    assert run(capsys, "list")[0] == 0  # the next command in the process is not stopped


@pytest.mark.parametrize(
    "argv",
    [
        ("build", "-o", ""),
        ("build", "--ocio-version", ""),
        ("build", ""),
        ("verify", ""),
        ("init", ""),
        ("plot", "", "-o", "a.png"),
        ("bake", "--from", " ", "--to", "srgb_display", "-o", "a.clf"),
        ("matrix", "acescg", ""),
    ],
)
def test_an_empty_value_is_refused(tmp_path, capsys, monkeypatch, argv):
    """An empty -o had meant configs/<name>, an empty --ocio-version the spec's, an empty path '.'."""
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.count("\n") == 1 and "is empty" in err, err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("only", ("", "  "))
def test_verify_refuses_an_empty_only(capsys, build_config, only):
    """An empty --only had run every check, as if not given."""
    code, out, err = run(capsys, "verify", str(build_config((2, 1))), "--quick", "--only", only)
    assert code == 2 and err.count("\n") == 1 and "--only" in err and "is empty" in err and out == "", err


@pytest.mark.parametrize(
    "argv, option",
    [
        (("bake", "--from", "acescct", "--from", "acescg", "--to", "srgb_display", "-o", "a.clf"), "--from"),
        (("bake", "--from", "acescg", "--to", "srgb_display", "--size", "5", "--size", "9", "-o", "a.clf"), "--size"),
        (("build", "-o", "a", "--output", "b"), "--output"),
    ],
)
def test_an_option_given_twice_is_refused(tmp_path, capsys, monkeypatch, argv, option):
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.count("\n") == 1 and f"{option} is given more than once" in err, err
    assert list(tmp_path.iterdir()) == []


def test_names_and_keywords_are_read_in_any_case_and_without_surrounding_blanks(tmp_path, capsys):
    out = tmp_path / "a.clf"
    code, printed, err = run(
        capsys,
        "bake",
        "--from",
        " acescg",
        "--to",
        "srgb_display ",
        "--gamut-map",
        "CLIP",
        "--size",
        "9",
        "-o",
        str(out),
    )
    assert code == 0 and "gamut mapping clip" in printed and out.exists(), err
    _, plain, _ = run(capsys, "matrix", "acescg", "lin_rec709", "--format", "json")
    code, padded, err = run(capsys, "matrix", " acescg", "lin_rec709 ", "--format", "JSON")
    assert code == 0 and padded == plain, err


def test_standard_output_closed_is_one_line(capsys, monkeypatch):
    """``ocioforge list >&-``: Python's sys.stdout is None (an AttributeError on isatty)."""
    import sys

    monkeypatch.setattr(sys, "stdout", None)
    with pytest.raises(SystemExit) as exited:
        main(["list"])
    err = capsys.readouterr().err
    assert exited.value.code == 2 and err.count("\n") == 1 and "standard output is closed" in err


def test_an_empty_source_date_epoch_is_unset():
    """CI services export it empty: a command runs as without it (colour-science's f2py, which
    fails on an empty one, imported in a fresh process)."""
    import os

    env = {**os.environ, "SOURCE_DATE_EPOCH": ""}
    done = subprocess.run(
        [sys.executable, "-m", "generator", "info", "acescg"], capture_output=True, text=True, timeout=120, env=env
    )
    assert done.returncode == 0 and done.stderr == "", done.stderr


@pytest.mark.parametrize("value", ("abc", "1.5", "253402300800", "99999999999999999999", " 1"))
def test_a_malformed_source_date_epoch_is_one_line(capsys, monkeypatch, value):
    """numpy's f2py, imported with colour-science, failed on it with a traceback (plot, info,
    bake --gamut-map perceptual); reproducible-builds.org asks for an error. A whole number past
    year 9999 overflowed the time functions of info and plot with a traceback."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", value)
    code, _, err = run(capsys, "info", "acescg")
    assert code == 2 and err.count("\n") == 1 and "SOURCE_DATE_EPOCH" in err, err
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    assert run(capsys, "info", "acescg")[0] == 0


def test_counts_are_singular_for_one():
    from generator.cli.build import counted

    assert (counted(1, "display"), counted(2, "display"), counted(0, "view")) == ("1 display", "2 displays", "0 views")


def click_command_raising(fn):
    import click

    @click.command()
    @click.argument("file")
    def command(file):
        fn()

    return command


def test_plot_maps_onto_the_display_asked_for(build_config, tmp_path, capsys):
    config = build_config((2, 1))
    first, chosen = tmp_path / "first.png", tmp_path / "pq.png"
    assert run(capsys, "plot", str(config), "-o", str(first), "--mapping")[0] == 0
    assert (
        run(capsys, "plot", str(config), "-o", str(chosen), "--mapping", "--display", "rec.2100-pq - display")[0] == 0
    )
    assert first.read_bytes() != chosen.read_bytes()
    code, _, err = run(capsys, "plot", str(config), "-o", str(tmp_path / "x.png"), "--mapping", "--display", "Nope")
    assert code == 2 and err.count("\n") == 1 and "unknown display 'Nope'; allowed: sRGB - Display" in err, err


def test_matrix_takes_a_shows_own_spaces_as_its_config_converts(tmp_path, capsys):
    from generator import reference
    from generator.spec import load

    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "ARRI LogC4", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Caméra B"\nprimaries = [[0.70, 0.29], [0.17, 0.80], [0.13, 0.05]]\nwhite = "D65"\n',
        encoding="utf-8",
    )
    spec = load.load(tmp_path / "show.toml")
    code, out, err = run(
        capsys, "matrix", "Caméra B", "ACEScg", "--spec", str(tmp_path / "show.toml"), "--format", "json"
    )
    expected = np.linalg.solve(
        reference.space_matrix(spec, spec.space("ACEScg")), reference.space_matrix(spec, spec.space("Caméra B"))
    )
    assert code == 0 and np.allclose(json.loads(out)["matrix"], expected, rtol=0, atol=1e-15), err
    library = run(capsys, "matrix", "ARRI LogC4", "ACEScg", "--format", "json")[1]
    assert (
        run(capsys, "matrix", "ARRI LogC4", "ACEScg", "--format", "json", "--spec", str(tmp_path / "show.toml"))[1]
        == library
    )
    code, _, err = run(capsys, "matrix", "Nope", "ACEScg", "--spec", str(tmp_path / "show.toml"))
    assert code == 2 and "no colour space 'Nope' in show.toml" in err and err.count("\n") == 1, err


def test_info_takes_a_shows_own_space_with_its_reference_and_version(tmp_path, capsys):
    from generator import reference
    from generator.spec import load

    (tmp_path / "show.toml").write_text(
        'ocio_version = "2.3"\nscene_reference = "ACEScg"\nchromatic_adaptation = "CAT16"\n'
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Wall"\naliases = ["led_wall"]\nprimaries = [[0.70, 0.29], [0.17, 0.80], [0.13, 0.05]]\n'
        'white = 6000\ntransfer = { family = "gamma", exponent = 2.4 }\n',
        encoding="utf-8",
    )
    spec = load.load(tmp_path / "show.toml")
    code, out, err = run(capsys, "info", "LED_wall", "--spec", str(tmp_path / "show.toml"))
    assert code == 0 and "name:      Wall" in out and "to ACEScg (CAT16):" in out, err
    rows = out.split("to ACEScg (CAT16):\n")[1].splitlines()[:3]
    assert np.allclose(
        [[float(v) for v in row.split()] for row in rows],
        reference.space_matrix(spec, spec.space("Wall")),
        rtol=0,
        atol=5e-11,
    )
    assert "OCIO 2.3: analytic (Power)  (the spec builds this version)" in out and out.count("the spec builds") == 1
    assert "(the spec builds" not in run(capsys, "info", "acescct")[1]
    code, _, err = run(capsys, "info", "arri_logc4", "--spec", str(tmp_path / "show.toml"))
    assert code == 2 and "no colour space 'arri_logc4' in show.toml" in err and err.count("\n") == 1, err


def test_a_config_that_is_a_device_is_refused_unread(capsys):
    """plot and verify read CONFIG through OpenColorIO: a device or pipe is refused first."""
    code, _, err = run(capsys, "plot", "/dev/zero", "-o", "never.png")
    assert code == 2 and err.count("\n") == 1 and "not a regular file" in err, err


@pytest.mark.parametrize(
    "command, name, words",
    [
        ("init", "nd/sub/show.toml", "its folder"),  # made nd/sub, and left it when the write failed
        ("init", "show.toml/", "ends in a slash"),  # wrote show.toml
        ("plot", "nd/sub/gamuts.png", "its folder"),
        ("plot", "gamuts", "is a folder"),  # said: unknown image format ''
    ],
)
def test_a_file_output_in_no_folder_or_naming_one_is_refused_and_makes_nothing(
    capsys, tmp_path, monkeypatch, build_config, command, name, words
):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "gamuts").mkdir()
    args = ["init", name] if command == "init" else ["plot", str(build_config((2, 1))), "-o", name]
    code, _, err = run(capsys, *args)
    assert code == 2 and err.count("\n") == 1 and words in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["gamuts"] and not any((tmp_path / "gamuts").iterdir())


def test_plot_display_without_mapping_is_refused(capsys, tmp_path, build_config):
    """--display chooses the display --mapping draws: alone, any name (a typo too) was ignored."""
    code, _, err = run(capsys, "plot", str(build_config((2, 1))), "-o", str(tmp_path / "g.png"), "--display", "nope")
    assert code == 2 and "with --mapping" in err, err
    assert not any(tmp_path.iterdir())


@pytest.mark.parametrize(
    "name, how",
    [
        ("ARRI LogC4", "(CAT02, as its publisher)"),
        ("DaVinci Intermediate WideGamut", "(CAT02, as the ACES studio config)"),  # said: as its publisher
        ("ACEScg", "(the same white: no adaptation)"),  # said: Bradford, though AP1 and AP0 share ACES white
        ("sRGB Encoded Rec.709 (sRGB)", "(Bradford)"),
    ],
)
def test_info_says_how_and_on_whose_authority_a_gamut_adapts(capsys, name, how):
    code, out, _ = run(capsys, "info", name)
    assert code == 0 and f"to ACES2065-1 {how}:" in out, out


def test_a_folder_name_that_is_not_utf8_is_one_line(tmp_path, capsys):
    """The folder's name names the config, which OCIO writes in UTF-8: a name of other bytes had
    failed inside OCIO with a traceback. A bake to such a path is fine, and says where, byte for byte."""
    import os

    out = os.fsdecode(os.fsencode(tmp_path) + b"/bad\xffname")
    code, _, err = run(capsys, "build", "-o", out)
    assert code == 2 and err.count("\n") == 1 and "bad\\xffname:-o: the folder's name" in err
    assert list(tmp_path.iterdir()) == []
    lut = os.fsdecode(os.fsencode(tmp_path) + b"/x\xff.cube")
    code, stdout, _ = run(capsys, "bake", "--from", "ACEScg", "--to", "sRGB - Display", "--size", "9", "-o", lut)
    assert code == 0 and stdout.startswith(f"{tmp_path}/x\\xff.cube: ")


def test_a_full_standard_output_is_named_and_loses_no_file(tmp_path):
    """A report printed to a full device: the error names standard output (it read as a full disk,
    the build half-written), and verify writes its report folder before printing its verdict."""
    with open("/dev/full", "w") as full:

        def ocioforge(*argv):
            return subprocess.run(
                [sys.executable, "-m", "generator", *argv],
                stdout=full,
                stderr=subprocess.PIPE,
                text=True,
                timeout=300,
                cwd=tmp_path,
            )

        built = ocioforge("build", "-o", "show")
        checked = ocioforge("verify", "show", "--quick", "--engines", "ocio", "--report", "report")
    for done in (built, checked):
        assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
        assert done.stderr.startswith("error: standard output: No space left on device (files the command wrote")
    assert sorted(p.name for p in (tmp_path / "show").iterdir()) == ["config.ocio", "luts", "ocioforge-spec.json"]
    assert sorted(p.name for p in (tmp_path / "report").iterdir()) == ["report.html", "summary.json"]


def test_bake_view_writes_the_displays_aces_view_in_any_case(tmp_path, capsys):
    """``--view ACES 2.0`` is the display's first ACES 2.0 studio view, as in a spec; names are
    matched in any case, and the report says which view was baked."""
    out = tmp_path / "a.cube"
    code, printed, err = run(
        capsys, "bake", "--from", "acescct", "--to", "srgb_display", "--view", "aces 2.0", "--size", "9", "-o", str(out)
    )
    assert code == 0 and "view ACES 2.0 - SDR 100 nits (Rec.709), 9^3" in printed and out.exists(), err
    again = tmp_path / "b.cube"
    code, _, err = run(
        capsys,
        "bake",
        "--from",
        "ACEScct",
        "--to",
        "sRGB - Display",
        "--view",
        "ACES 2.0 - SDR 100 nits (rec.709)",
        "--size",
        "9",
        "-o",
        str(again),
    )
    assert code == 0 and again.read_bytes() == out.read_bytes(), err


@pytest.mark.parametrize(
    "args, words",
    [
        (
            ("--view", "ACES 2.0 - HDR 1000 nits (P3 D65)"),
            "cannot show 'ACES 2.0 - HDR 1000 nits (P3 D65)': it is an HDR view",
        ),
        (("--view", "ACES 3.0"), "unknown ACES view 'ACES 3.0'"),
        (("--view", "ACES 2.0", "--gamut-map", "scale"), "--view and --gamut-map exclude each other"),
    ],
)
def test_bake_view_refuses_in_one_line_and_writes_nothing(tmp_path, capsys, args, words):
    code, out, err = run(
        capsys, "bake", "--from", "ACEScct", "--to", "sRGB - Display", *args, "-o", str(tmp_path / "a.clf")
    )
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err and out == "", err
    assert list(tmp_path.iterdir()) == []
