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


def dim_output_table(clf, factor: float) -> None:
    """Scale the output table (the first LUT1D) of the CLF at ``clf`` by ``factor``."""
    lines = clf.read_text(encoding="utf-8").splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if line.startswith("<LUT1D")) + 2
    end = next(i for i in range(start, len(lines)) if lines[i].startswith("</Array>"))
    lines[start:end] = [f"{float(line) * factor!r}\n" for line in lines[start:end]]
    clf.write_text("".join(lines), encoding="utf-8")
