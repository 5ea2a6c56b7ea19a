"""verify on a config with looks: every look and view with looks checked in each shot's context,
through every host engine; a corrupted CDL value or a swapped shot file fails, naming them."""

from __future__ import annotations

import shutil
import subprocess
import sys

import pytest

from tests.conftest import require_program
from tests.looks_cases import correction, write_show


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    folder = tmp_path_factory.mktemp("looks")
    out = folder / "build"
    result = subprocess.run(
        [sys.executable, "-m", "generator", "build", str(write_show(folder)), "-o", str(out)],
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stderr
    return out


def verify(config, *args):
    return subprocess.run(
        [sys.executable, "-m", "generator", "verify", str(config), "--quick", *args], capture_output=True, text=True
    )


def test_every_engine_passes_in_each_shot(built):
    for program in ("oiiotool", "ocioconvert", "blender"):
        require_program(program)
    for shot in ("sh010", "sh020"):
        result = verify(built, "--engines", "ocio,oiiotool,ocioconvert,blender", "--context", f"SHOT={shot}")
        assert result.returncode == 0, result.stdout + result.stderr
        assert "Show Look" in result.stdout and f"SHOT={shot}" in result.stdout


def test_a_corrupted_cdl_value_fails_naming_the_look(built, tmp_path):
    broken = tmp_path / "broken"
    shutil.copytree(built, broken)
    config = broken / "config.ocio"
    text = config.read_text()
    assert "slope: [1.1, 1, 0.9]" in text
    config.write_text(text.replace("slope: [1.1, 1, 0.9]", "slope: [1.1, 1, 0.95]"))
    result = verify(broken, "--engines", "ocio")
    assert result.returncode == 1
    failing = [line for line in result.stdout.splitlines() if "FAIL" in line.upper()]
    assert any("Show Look" in line for line in failing), result.stdout


def test_a_swapped_shot_file_fails_naming_the_look_and_the_shot(built, tmp_path):
    swapped = tmp_path / "swapped"
    shutil.copytree(built, swapped)
    (swapped / "looks" / "shots" / "sh010.cc").write_text(correction("sh020").replace('id="sh020"', 'id="sh010"'))
    result = verify(swapped, "--engines", "ocio", "--context", "SHOT=sh010")
    assert result.returncode == 1
    out = result.stdout + result.stderr
    assert "Shot Grade" in out and "sh010" in out, out


def test_an_unknown_context_value_is_one_error_line(built):
    result = verify(built, "--engines", "ocio", "--context", "SHOT=sh999")
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error:") and "sh999" in lines[0], result.stderr
