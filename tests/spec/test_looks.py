"""A spec's looks and context variables: what loads, and bad input as one error line, exit 2,
nothing written."""

from __future__ import annotations

import subprocess
import sys

import pytest

from generator.spec.load import load
from tests.looks_cases import SPEC, correction, write_show


def build(spec, out):
    return subprocess.run(
        [sys.executable, "-m", "generator", "build", str(spec), "-o", str(out)], capture_output=True, text=True
    )


def test_the_looks_load_with_their_process_spaces_and_defaults(tmp_path):
    spec = load(write_show(tmp_path))
    looks = {look.name: look for look in spec.looks}
    assert set(looks) == {"Show Look", "Shot Grade"}
    assert looks["Show Look"].process_space == "ACEScct"
    assert dict(spec.environment) == {"SHOT": "sh010"}


@pytest.mark.parametrize(
    ("edit", "words"),
    [
        (('looks = "+Show Look, +Shot Grade"', 'looks = "+Show Look, +Night Look"'), "Night Look"),
        (('file = "shots/$SHOT.cc"', 'file = "shots/$SHOT.ccc"'), "sh010.ccc"),
        (('file = "shots/$SHOT.cc"', 'file = "shots/$SHOT.cc"\ncccid = "sh999"'), "sh999"),
        (('[environment]\nSHOT = "sh010"\n', ""), "SHOT"),
        (("saturation = 0.9", "saturation = -1"), "saturation"),
    ],
    ids=["unknown look", "missing CDL file", "CCC id not in the file", "variable without default", "bad value"],
)
def test_bad_looks_are_one_error_line_exit_2_and_nothing_written(tmp_path, edit, words):
    spec = write_show(tmp_path, SPEC.replace(*edit))
    assert SPEC.replace(*edit) != SPEC
    out = tmp_path / "build"
    result = build(spec, out)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error:") and words in lines[0], result.stderr
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["shots", "spec.toml"]


def test_a_ccc_file_is_read_by_its_id(tmp_path):
    spec = write_show(tmp_path, SPEC.replace('file = "shots/$SHOT.cc"', 'file = "grades.ccc"\ncccid = "$SHOT"'))
    body = "".join(correction(s).split("\n", 1)[1] for s in ("sh010", "sh020"))
    (tmp_path / "grades.ccc").write_text(
        f'<?xml version="1.0" encoding="UTF-8"?>\n<ColorCorrectionCollection xmlns="urn:ASC:CDL:v1.01">\n'
        f"{body}</ColorCorrectionCollection>\n"
    )
    looks = {look.name: look for look in load(spec).looks}
    assert looks["Shot Grade"].cccid == "$SHOT"
