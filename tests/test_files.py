"""Writing files so that they are never seen half-written (bake, verify's report, plots, init)."""

from __future__ import annotations

import os
import stat

import pytest

from generator.files import CannotWrite, staged_folder, write_atomic, write_files


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
    with pytest.raises(CannotWrite, match="lut.spi1d: cannot write: Not a directory"):
        write_files({tmp_path / "lut.cube": b"new", tmp_path / "blocked" / "lut.spi1d": b"shaper"})
    assert (tmp_path / "lut.cube").read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocked", "lut.cube"]


def test_a_folder_that_cannot_be_staged_names_the_folder(tmp_path):
    (tmp_path / "blocked").write_bytes(b"")
    with pytest.raises(CannotWrite, match=r"show: cannot write: Not a directory$"):
        with staged_folder(tmp_path / "blocked" / "show"):
            pass


def test_an_error_filling_the_staged_folder_names_the_folder_and_removes_it(tmp_path):
    """An OSError on a path inside the staging folder is a write failure of the folder; any other
    (reading an input) passes through unchanged. Either way nothing is left behind."""
    with pytest.raises(CannotWrite, match=r"show: cannot write: No space left on device$"):
        with staged_folder(tmp_path / "show") as staging:
            raise OSError(28, os.strerror(28), str(staging / "config.ocio"))
    with pytest.raises(FileNotFoundError):
        with staged_folder(tmp_path / "show"):
            open(tmp_path / "missing.csv")
    assert list(tmp_path.iterdir()) == []


def test_a_full_disk_reported_without_a_file_name_is_a_write_failure(tmp_path):
    """Python reports a full disk on closing a file with no file name: still a write failure of
    the folder (it was a traceback), and nothing is left behind."""
    with pytest.raises(CannotWrite, match=r"show: cannot write: No space left on device$"):
        with staged_folder(tmp_path / "show"):
            raise OSError(28, os.strerror(28))
    assert list(tmp_path.iterdir()) == []
