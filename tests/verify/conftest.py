"""A copy of the default config that a test may break."""

from __future__ import annotations

import shutil

import pytest


@pytest.fixture
def config_copy(build_config, tmp_path):
    """A fresh copy of the default config folder (OCIO 2.1); returns its config path."""
    source = build_config((2, 1)).parent
    target = tmp_path / source.name
    shutil.copytree(source, target)
    return target / "config.ocio"
