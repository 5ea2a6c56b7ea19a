"""ocioforge pack through its entry point: a small pack, the folder's other files, bad input."""

from __future__ import annotations

import pytest

from generator.luts import aces_probes, pack_folder, probes
from tests.cli.conftest import run

SPEC = """
colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]
[[display]]
name = "sRGB - Display"
[[lut_pack]]
sources = ["ACEScct"]
displays = ["sRGB - Display"]
formats = ["clf"]
size = 5
file_name = "{source}_{display}_{gamut_map}_{size}"
"""


NAME = "acescct_srgb_display_scale_5.clf"


@pytest.fixture
def spec(tmp_path, monkeypatch):
    monkeypatch.setattr(probes, "COUNT", 256)
    monkeypatch.setattr(aces_probes, "PROBE_COUNT", 256)
    path = tmp_path / "show.toml"
    path.write_text(SPEC)
    return path


def test_help_prints_help_and_writes_nothing(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, _ = run(capsys, "pack", "--help")
    assert code == 0 and "[[lut_pack]]" in out and "--force" in out
    assert list(tmp_path.iterdir()) == []
    code, out, err = run(capsys, "pack", "-o", "--help")  # taken for -o's value: refused, not a folder
    assert code == 2 and "'--help' looks like an option" in err and list(tmp_path.iterdir()) == []


def test_pack_writes_its_files_beside_the_folders_own_and_reruns(capsys, spec, tmp_path):
    folder = tmp_path / "out"
    folder.mkdir()
    (folder / "plate.exr").write_bytes(b"a plate")
    code, out, err = run(capsys, "pack", spec, "-o", folder, "--jobs", "1")
    assert code == 0, err
    assert f"{folder}: 1 LUTs and README.md" in out
    assert sorted(p.name for p in folder.iterdir()) == [pack_folder.MANIFEST, "README.md", NAME, "plate.exr"]
    readme = (folder / "README.md").read_text()
    assert f"| {NAME} | ACEScct | sRGB - Display | scale | 5³ |" in readme
    first = (folder / NAME).read_bytes()
    (folder / NAME).write_bytes(b"")  # no longer the pack's: a rerun refuses to replace it
    code, _, err = run(capsys, "pack", spec, "-o", folder)
    assert code == 2 and err.count("\n") == 1 and f"{NAME}: exists and is not a file ocioforge pack wrote" in err
    assert (folder / NAME).read_bytes() == b""
    code, _, err = run(capsys, "pack", spec, "-o", folder, "--force")
    assert code == 0, err
    assert (folder / NAME).read_bytes() == first and (folder / "plate.exr").read_bytes() == b"a plate"
    code, _, err = run(capsys, "pack", spec, "-o", folder)  # its own files: replaced without --force
    assert code == 0, err and (folder / NAME).read_bytes() == first


@pytest.mark.parametrize(
    "line, field",
    [
        ('formats = ["png"]', "lut_pack[0].formats[0]"),
        ("size = 1", "lut_pack[0].size"),
        ('colour = "red"', "lut_pack[0].colour"),
        ('gamut_maps = ["clip", "clip"]', "lut_pack[0].gamut_maps[1]"),
        ('shaper = "ACEScg"', "lut_pack[0].shaper"),
    ],
)
def test_bad_lut_pack_keys_are_one_line_and_write_nothing(capsys, tmp_path, line, field):
    key = line.split(" ")[0]
    text = "\n".join(row for row in SPEC.splitlines() if not row.startswith(key + " ")) + "\n" + line + "\n"
    path = tmp_path / "bad.toml"
    path.write_text(text)
    code, out, err = run(capsys, "pack", path, "-o", tmp_path / "out")
    assert code == 2 and out == "" and err.count("\n") == 1
    assert err.startswith(f"error: {path}:{field}: ") and "allowed" in err
    assert not (tmp_path / "out").exists()


def test_a_spec_without_a_pack_and_a_missing_output_are_refused(capsys, tmp_path):
    path = tmp_path / "plain.toml"
    path.write_text(SPEC.split("[[lut_pack]]")[0])
    code, _, err = run(capsys, "pack", path, "-o", tmp_path / "out")
    assert code == 2 and "lut_pack: the spec declares no LUT pack" in err and not (tmp_path / "out").exists()
    code, _, err = run(capsys, "pack", path)
    assert code == 2 and "-o: give the folder to write" in err


def test_a_file_in_place_of_the_folder_is_refused(capsys, spec, tmp_path):
    (tmp_path / "out").write_text("a file")
    code, _, err = run(capsys, "pack", spec, "-o", tmp_path / "out")
    assert code == 2 and "is not a folder" in err and (tmp_path / "out").read_text() == "a file"
