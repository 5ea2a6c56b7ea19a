"""Shared fixtures: the default spec, configs built once per session, host programs."""

from __future__ import annotations

import os
import shutil
import socket
import stat
from pathlib import Path

import pytest

from generator.spec import load
from generator.spec.allowed import newest_ocio_version
from generator.verify.run import ON_CI

NEWEST = newest_ocio_version()
VERSIONS = [(2, minor) for minor in range(1, NEWEST[1] + 1)]


def host_missing(message: str, remedy: str = "CI installs it: see .ci/run") -> None:
    """A host the test needs is absent: under CI=true that fails the test, elsewhere it is skipped
    with ``message`` (reported as not run, never as passed)."""
    message = f"{message} ({remedy})"
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


CURVE_A = "code,linear\n0,0\n0.25,0.02\n0.5,0.12\n0.75,0.45\n1,1\n"
CURVE_B = "code,linear\n0,0\n0.5,0.4\n1,1.5\n"
#: Custom spaces whose names slug alike, one of them as a library curve's name does.
SLUGGING_ALIKE = (("Tab Log", "a.csv"), ("Tab-Log", "b.csv"), ("Canon Log 2", "b.csv"))


@pytest.fixture(scope="session")
def slugging_alike(tmp_path_factory):
    """A 2.1 config of custom tabulated spaces whose names slug alike, one as the library's
    Canon Log 2 (whose space the config has too): the spec and the config's folder."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    folder = tmp_path_factory.mktemp("alike")
    (folder / "a.csv").write_text(CURVE_A)
    (folder / "b.csv").write_text(CURVE_B)
    text = (
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", '
        '"CanonLog2 CinemaGamut D55"]\n'
    )
    for name, csv in SLUGGING_ALIKE:
        text += (
            f'[[custom_space]]\nname = "{name}"\ngamut = "P3-D65"\n'
            f'transfer = {{ family = "tabulated", file = "{csv}" }}\n'
        )
    (folder / "alike.toml").write_text(text + '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n')
    spec = for_folder(load.load(folder / "alike.toml"), folder / "config", (2, 1))
    build(spec, folder / "config")
    return spec, folder / "config"


def special_file(path: Path, kind: str) -> Path:
    """A file at ``path`` that is not a regular one: a FIFO, a socket, or a character device like
    /dev/null (which needs root, as CI runs: see :func:`host_missing` elsewhere)."""
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "socket":
        with socket.socket(socket.AF_UNIX) as listener:
            listener.bind(str(path))
    else:
        try:
            os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, 3))
        except PermissionError:
            host_missing("making a device needs root", "CI runs as root")
    return path
