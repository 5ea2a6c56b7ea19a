"""ocioforge list: the library's colour spaces, displays, curves and ACES views, or a spec's own;
piped, a tab-separated line a row."""

import pytest

from tests.cli.conftest import SHOW, run


def test_list_gives_the_librarys_spaces_displays_curves_and_views(capsys):
    _, out, _ = run(capsys, "list")
    assert "S-Log3 S-Gamut3.Cine" in out and "lin_ap1" in out
    _, out, _ = run(capsys, "list", "--displays")
    assert "Rec.2100-PQ - Display" in out
    _, out, _ = run(capsys, "list", "--curves")
    assert "LogCamera" in out and "T-LogE" in out
    _, out, _ = run(capsys, "list", "--views")
    assert "ACES 2.0 - HDR 108 nits (P3 D65)\t2.0\t108\tHDR-108nit-P3-D65_2.0" in out
    assert "ACES 1.1 - HDR Cinema (108 nits & P3 lim)\t1.3\t108" in out


def test_list_takes_one_kind(capsys):
    code, _, err = run(capsys, "list", "--displays", "--curves")
    assert code == 2 and err.count("\n") == 1 and "allowed: one of --spaces, --displays, --curves" in err


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


def test_list_spec_gives_the_shows_own_spaces_displays_and_views(capsys, show):
    code, out, err = run(capsys, "list", "--spec", str(SHOW))
    lines = out.splitlines()
    assert code == 0 and lines[0].split("\t")[0] == "colour space", err
    assert [line.split("\t")[0] for line in lines[1:]] == [s.name for s in show.colour_spaces]
    assert "Linear LED Wall\tStage\tLinear LED Wall\tlinear\tlin_ledwall" in lines
    _, out, _ = run(capsys, "list", "--spec", str(SHOW), "--displays")
    assert "LED Wall\tLED Wall\tST 2084\t1500\tled_wall\tACES 2.0 - HDR 1500 nits (LED Wall), Scale, Raw" in out
    assert len(out.splitlines()) == 3  # the header and the show's two displays, not the library's
    _, out, _ = run(capsys, "list", "--views", "--spec", str(SHOW))
    assert out.splitlines() == ["display\tview"] + [f"{d.name}\t{v}" for d in show.displays for v in d.views]


def test_list_spec_reads_a_build_folder(capsys, tmp_path):
    """A build's folder holds the spec it was built from (ocioforge-spec.json)."""
    from generator.spec import load, resolved

    (tmp_path / "show").mkdir()
    (tmp_path / "show" / resolved.FILENAME).write_text(resolved.dumps(load.load(SHOW)), encoding="utf-8")
    assert (
        run(capsys, "list", "--spec", str(tmp_path / "show"), "--displays")[1]
        == (run(capsys, "list", "--spec", str(SHOW), "--displays")[1])
    )


@pytest.mark.parametrize(
    "argv, words",
    [
        (["list", "--spec", "missing.toml"], "missing.toml: cannot read the spec: it does not exist"),
        (["list", "--spec", ".", "--views"], "no resolved spec here"),
        (["list", "--spec", str(SHOW), "--curves"], "allowed with --spec: --spaces, --displays, --views"),
    ],
)
def test_a_spec_that_is_not_there_is_one_line(capsys, tmp_path, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *argv)
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1 and words in err, err
    assert out == ""


def test_spaces_is_the_default_listing(capsys):
    assert run(capsys, "list", "--spaces") == run(capsys, "list")


def test_on_a_terminal_a_table_of_aligned_columns():
    """On a terminal (not piped), a table: no tabs, each value under its column's header."""
    import os
    import pty
    import re
    import subprocess
    import sys

    from generator.colorimetry import library

    primary, secondary = pty.openpty()
    listing = subprocess.Popen(
        [sys.executable, "-m", "generator", "list", "--displays"], stdout=secondary, stderr=subprocess.PIPE
    )
    os.close(secondary)
    chunks = []
    while True:
        try:
            chunk = os.read(primary, 4096)
        except OSError:  # the terminal's other end closed: all is read
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(primary)
    assert listing.wait(timeout=120) == 0, listing.stderr.read()
    text = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", b"".join(chunks).decode("utf-8"))
    lines = [line.rstrip() for line in text.replace("\r\n", "\n").splitlines() if line.strip()]
    assert "\t" not in text and lines[0].split() == ["display", "gamut", "EOTF", "peak", "cd/m²", "aliases"]
    at = {column: lines[0].index(column) for column in ("gamut", "EOTF")}
    rows = {line[: at["gamut"]].strip(): line for line in lines[1:]}
    assert sorted(rows) == sorted(d.name for d in library.DISPLAYS)
    for display in library.DISPLAYS:
        assert rows[display.name][at["gamut"] :].startswith(display.gamut + " ")
        assert rows[display.name][at["EOTF"] :].startswith(display.eotf + " ")
