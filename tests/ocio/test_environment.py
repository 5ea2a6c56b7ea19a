"""A shell's OpenColorIO overrides (OCIO_ACTIVE_DISPLAYS and the like) reach neither a build
nor verify, and are put back after."""

from __future__ import annotations

import os

import PyOpenColorIO as ocio

from generator.ocio.write import build, for_folder
from generator.spec import load
from generator.verify.checks import VIEW
from generator.verify.judge import APPROX
from generator.verify.run import engine_registry, verify
from tests.conftest import host_missing

#: A show's settings, none of which the default config defines.
SHOW = {
    "OCIO_ACTIVE_DISPLAYS": "ACES",
    "OCIO_ACTIVE_VIEWS": "Film",
    "OCIO_INACTIVE_COLORSPACES": "ACEScg,ACEScct",
    "OCIO_USER_CATEGORIES": "show",
}


def test_a_build_sees_the_config_as_written(tmp_path, monkeypatch):
    """OCIO validates a build with the shell's active displays applied: a display the spec does not
    define had failed the build with OCIO's traceback."""
    for key, value in SHOW.items():
        monkeypatch.setenv(key, value)
    result = build(for_folder(load.load(), tmp_path / "show"), tmp_path / "show")
    for key, value in SHOW.items():
        assert os.environ[key] == value
    monkeypatch.delenv("OCIO_ACTIVE_DISPLAYS")
    monkeypatch.delenv("OCIO_ACTIVE_VIEWS")
    cfg = ocio.Config.CreateFromFile(str(result.path / "config.ocio"))
    assert len(list(cfg.getDisplaysAll())) == len(load.load().displays)


def test_verify_runs_its_flags_and_every_host_on_the_config_as_written(build_config, monkeypatch):
    """OCIO_OPTIMIZATION_FLAGS set to lossless had replaced the default flags verify names (none of
    their departures left to explain), and Blender, handed the shell's active views and inactive
    spaces, failed every view it was asked for that they hide."""
    config = build_config((2, 1))
    for key, value in {
        **SHOW,
        "OCIO_ACTIVE_VIEWS": "Colorimetric",
        "OCIO_OPTIMIZATION_FLAGS": str(int(ocio.OPTIMIZATION_LOSSLESS)),
    }.items():
        monkeypatch.setenv(key, value)
    flags = verify(config, ("ocio",), density="quick", kinds=(VIEW,))
    assert not flags.failures and any(o.verdict == APPROX for o in flags.outcomes)
    if reason := engine_registry()["blender"][0].missing(config):
        host_missing(f"blender: {reason}")
    hosts = verify(config, ("blender",), density="quick", kinds=(VIEW,), only=" from ACEScg")
    assert [e for e in hosts.engines if e.name == "blender" and not e.skipped]
    assert not [(o.check.title, o.note) for o in hosts.failures]
