"""Looks in a built config: the look list, the views that apply them, the context variables'
defaults, and the shots' files copied into the build so it stays relocatable."""

from __future__ import annotations

import copy
import shutil
import subprocess
import sys

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.colorimetry.cdl import read_cdl
from tests.looks_cases import SHOTS, write_show


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    folder = tmp_path_factory.mktemp("looks")
    spec = write_show(folder)
    out = folder / "build"
    result = subprocess.run(
        [sys.executable, "-m", "generator", "build", str(spec), "-o", str(out)], capture_output=True, text=True
    )
    assert result.returncode == 0, result.stderr
    return out


def shot_processor(config, shot):
    context = copy.deepcopy(config.getCurrentContext())
    context["SHOT"] = shot
    return config.getProcessor(context, "ACES2065-1", "sRGB - Display", "Colorimetric", ocio.TRANSFORM_DIR_FORWARD)


def test_the_config_declares_its_looks_and_the_shot_default(built):
    config = ocio.Config.CreateFromFile(str(built / "config.ocio"))
    config.validate()
    assert [look.getName() for look in config.getLooks()] == ["Show Look", "Shot Grade"]
    assert config.getEnvironmentVarDefault("SHOT") == "sh010"
    assert list(config.getSearchPaths()) == ["luts", "looks"]
    assert config.getDisplayViewLooks("sRGB - Display", "Colorimetric") == "Show Look, Shot Grade"


def test_every_shot_file_is_copied_into_the_build(built):
    for shot in SHOTS:
        copied = built / "looks" / "shots" / f"{shot}.cc"
        assert read_cdl(copied, shot) == read_cdl(built.parent / "shots" / f"{shot}.cc", shot)


def test_the_shot_variable_picks_the_shot_grade_in_a_moved_build(built, tmp_path):
    moved = tmp_path / "elsewhere"
    shutil.copytree(built, moved)
    config = ocio.Config.CreateFromFile(str(moved / "config.ocio"))
    colour = [0.18, 0.12, 0.05]
    first = shot_processor(config, "sh010").getDefaultCPUProcessor().applyRGB(list(colour))
    second = shot_processor(config, "sh020").getDefaultCPUProcessor().applyRGB(list(colour))
    assert not np.allclose(first, second, atol=1e-4)
    (moved / "looks" / "shots" / "sh020.cc").unlink()
    ocio.ClearAllCaches()  # OCIO keeps a file it has read, and a config its processors
    with pytest.raises(ocio.ExceptionMissingFile, match="elsewhere/looks/shots/sh020.cc"):
        shot_processor(ocio.Config.CreateFromFile(str(moved / "config.ocio")), "sh020")
