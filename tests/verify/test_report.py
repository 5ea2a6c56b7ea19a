"""Writing verify's report (and the plots, which share the writer)."""

from __future__ import annotations

import os
import stat

from generator.verify.report import write_atomic


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
