"""Writing files so that they are never seen half-written (bake, verify's report, plots, init)."""

from __future__ import annotations

import os
import stat

import pytest

from generator.files import write_atomic, write_files


def test_a_written_file_is_readable_as_a_plain_write_would_leave_it(tmp_path):
    old = os.umask(0o022)
    try:
        write_atomic(tmp_path / "sub" / "report.html", b"<html></html>")
    finally:
        os.umask(old)
    path = tmp_path / "sub" / "report.html"
    assert path.read_bytes() == b"<html></html>"
    assert stat.S_IMODE(path.stat().st_mode) == 0o644
    assert [p.name for p in path.parent.iterdir()] == ["report.html"]  # no temporary left


def test_files_are_written_all_or_none(tmp_path):
    """The second file cannot be written (its folder is a file): the first, though complete,
    is not renamed into place, the existing one is kept, and no temporary is left."""
    (tmp_path / "lut.cube").write_bytes(b"old")
    (tmp_path / "blocked").write_bytes(b"")
    with pytest.raises(OSError):
        write_files({tmp_path / "lut.cube": b"new", tmp_path / "blocked" / "lut.spi1d": b"shaper"})
    assert (tmp_path / "lut.cube").read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocked", "lut.cube"]
