"""The ocioforge command group and entry point (generator.cli): commands looked up by name, the
options every command parses alike (empty values, options given twice, names with blanks),
bad input as one error line and exit status 2, signals, the environment and standard output."""

import subprocess
import sys

import pytest

from generator.cli import main
from tests.cli.conftest import BAKE, one_line, run


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


def test_an_unknown_command_lists_the_commands(capsys):
    code, _, err = run(capsys, "bogus")
    assert (
        code == 2
        and "allowed: build, init, matrix, bake, pack, verify, plot, info, list, convert" in err
        and err.count("\n") == 1
    )


def _interrupted(*args, **kwargs):
    raise KeyboardInterrupt


def click_command_raising(fn):
    import click

    @click.command()
    @click.argument("file")
    def command(file):
        fn()

    return command


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


def test_terminated_build_leaves_nothing(tmp_path):
    """SIGTERM while the folder is being written removes the staging folder."""
    import signal
    import time

    build = subprocess.Popen(
        [sys.executable, "-m", "generator", "build", "-o", str(tmp_path / "show")],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        deadline = time.monotonic() + 60
        while not any(tmp_path.iterdir()) and build.poll() is None and time.monotonic() < deadline:
            time.sleep(0.01)
        assert build.poll() is None, "the build ended before it could be terminated"
        build.send_signal(signal.SIGTERM)
        assert build.wait(timeout=60) == 128 + signal.SIGTERM
    finally:  # a build that hangs is killed, not left running after the tests
        build.kill()
        build.wait()
    assert list(tmp_path.iterdir()) == []


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


#: A build stopped as its worker pool starts: SIGTERM's handler runs inside the pool's manager
#: thread's start, as a signal arriving there does.
STOPPED_AS_THE_POOL_STARTS = """
import concurrent.futures.process as process, signal, sys
import generator.cli
start = process._ExecutorManagerThread.start
def terminated_meanwhile(thread):
    generator.cli._stop(signal.SIGTERM, None)
    start(thread)
process._ExecutorManagerThread.start = terminated_meanwhile
generator.cli.main(["build", "-o", sys.argv[1]])
"""


def test_a_stop_while_the_worker_pool_starts_ends_the_build_cleanly(tmp_path):
    """SIGTERM arriving as the build's process pool starts its manager thread (made, not yet
    started) left a pool that could not shut down: the build never ended (and, a moment later
    in the start, a traceback "cannot join thread before it is started", exit 1). The stop now
    waits for the submission: exit 128 + SIGTERM, nothing left."""
    import signal

    build = subprocess.run(
        [sys.executable, "-c", STOPPED_AS_THE_POOL_STARTS, str(tmp_path / "cfg")],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert build.returncode == 128 + signal.SIGTERM, build.stderr
    assert list(tmp_path.iterdir()) == []


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


def test_a_config_that_is_a_device_is_refused_unread(capsys):
    """plot and verify read CONFIG through OpenColorIO: a device or pipe is refused first."""
    code, _, err = run(capsys, "plot", "/dev/zero", "-o", "never.png")
    assert code == 2 and err.count("\n") == 1 and "not a regular file" in err, err


@pytest.mark.parametrize("argv", (["build", "-o", "show"], ["info", "acescg"], [*BAKE, "-o", "a.clf"]))
def test_a_deleted_working_directory_is_one_line(tmp_path, capsys, monkeypatch, argv):
    gone = tmp_path / "gone"
    gone.mkdir()
    monkeypatch.chdir(gone)
    gone.rmdir()
    code, _, err = run(capsys, *argv)
    assert one_line(code, err, "the working directory: No such file or directory"), err


@pytest.mark.parametrize(
    "argv, words",
    [
        (["verify", "a\nb.ocio"], "a\\nb.ocio"),
        (["build", "no\npe.toml"], "no\\npe.toml"),
        (["build", "-o", "afile/x\ny"], "afile/x\\ny"),
    ],
)
def test_a_path_holding_a_newline_is_one_line(tmp_path, capsys, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "afile").write_bytes(b"")
    code, _, err = run(capsys, *argv)
    assert one_line(code, err, words), err


def test_a_path_not_in_utf8_is_said_byte_for_byte(tmp_path, capsys):
    """A bake to a path of bytes that are not UTF-8 is fine, and says where, byte for byte."""
    import os

    lut = os.fsdecode(os.fsencode(tmp_path) + b"/x\xff.cube")
    code, stdout, _ = run(capsys, "bake", "--from", "ACEScg", "--to", "sRGB - Display", "--size", "9", "-o", lut)
    assert code == 0 and stdout.startswith(f"{tmp_path}/x\\xff.cube: ")


def test_standard_output_closed_is_one_line(capsys, monkeypatch):
    """``ocioforge list >&-``: Python's sys.stdout is None (an AttributeError on isatty)."""
    import sys

    monkeypatch.setattr(sys, "stdout", None)
    with pytest.raises(SystemExit) as exited:
        main(["list"])
    err = capsys.readouterr().err
    assert exited.value.code == 2 and err.count("\n") == 1 and "standard output is closed" in err


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
        # one check: the report and the verdict are printed whatever the checks
        checked = ocioforge(
            "verify", "show", "--quick", "--engines", "ocio", "--only", "ACES2065-1 -> ACEScg", "--report", "report"
        )
    for done in (built, checked):
        assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
        assert done.stderr.startswith("error: standard output: No space left on device (files the command wrote")
    assert sorted(p.name for p in (tmp_path / "show").iterdir()) == ["config.ocio", "luts", "ocioforge-spec.json"]
    assert sorted(p.name for p in (tmp_path / "report").iterdir()) == ["report.html", "summary.json"]


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


#: The commands, in the order the help lists them.
COMMANDS = ("build", "init", "matrix", "bake", "pack", "verify", "plot", "info", "list", "convert")


def test_no_command_prints_the_help_listing_every_command(capsys):
    code, out, err = run(capsys)
    listed = [line.split()[0] for line in out.split("Commands:\n")[1].splitlines() if line[:3].strip()]
    assert code == 0 and err == "" and listed == list(COMMANDS), out


@pytest.mark.parametrize("command", COMMANDS)
def test_each_command_is_found_and_has_its_help(capsys, command):
    code, out, err = run(capsys, command, "--help")
    assert code == 0 and err == "" and out.startswith(f"Usage: ocioforge {command} "), out
    assert "--help" in out


def test_a_flag_given_twice_is_not_refused(tmp_path, capsys):
    """Only an option taking a value is refused twice (the last had silently won); a flag says
    the same thing again."""
    (tmp_path / "show.toml").write_text("old")
    code, _, err = run(capsys, "init", tmp_path / "show.toml", "--force", "--force")
    assert code == 0 and (tmp_path / "show.toml").read_text().startswith("# ocioforge spec"), err
