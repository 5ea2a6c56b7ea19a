"""The config the convert tests run frames through."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="module")
def config(build_config):
    """The default spec's 2.1 config, built once per session."""
    return build_config((2, 1))
