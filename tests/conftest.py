"""Shared fixtures: the default spec, configs built once per session, host programs."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from generator.spec import load
from generator.spec.load import newest_ocio_version

ON_CI = os.environ.get("CI") == "true"
NEWEST = newest_ocio_version()
VERSIONS = [(2, minor) for minor in range(1, NEWEST[1] + 1)]


def host_missing(message: str) -> None:
    """A host the test needs is absent: under CI=true that fails the test, elsewhere it is skipped
    with ``message`` (reported as not run, never as passed)."""
    message = f"{message} (CI installs it: see .ci/run)"
    if ON_CI:
        pytest.fail(message)
    pytest.skip(message)


def require_program(name: str) -> str:
    """The path of a host program (see :func:`host_missing` when it is absent)."""
    path = shutil.which(name)
    if path is None:
        host_missing(f"{name} is not installed")
    return path


@pytest.fixture(scope="session")
def default_spec():
    return load.load()


@pytest.fixture(scope="session")
def build_config(tmp_path_factory, default_spec):
    """Build the default spec for a version (once per session); returns the config path."""
    from generator.ocio.write import build, for_folder

    built: dict[tuple[int, int], Path] = {}

    def _build(version=(2, 1)) -> Path:
        if version not in built:
            folder = tmp_path_factory.mktemp(f"v{version[0]}{version[1]}") / "ocioforge-test"
            build(for_folder(load.load(), folder, version), folder)
            built[version] = folder / "config.ocio"
        return built[version]

    return _build
