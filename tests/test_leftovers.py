"""A build killed outright leaves its staging folder; the next build beside it removes that one,
and only folders provably left so."""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from generator import leftovers
from generator.leftovers import MARKER, gone, mark, remove_stale
from tests.cli.test_cli import run

TINY = (
    'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
    '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
)
LINUX = pytest.mark.skipif(not Path("/proc/self/stat").is_file(), reason="processes are told apart through /proc")


def _ours(**change) -> dict:
    """A marker record of this process, with ``change``."""
    record = {
        "pid": os.getpid(),
        "start": leftovers._start_time(os.getpid()),
        "boot": leftovers._boot_id(),
        "host": socket.gethostname(),
    }
    return {**record, **change}


def _left(parent: Path, name: str, record: dict | None) -> Path:
    folder = parent / name
    folder.mkdir()
    (folder / "config.ocio").write_text("half")
    if record is not None:
        (folder / MARKER).write_text(json.dumps(record))
    return folder


@LINUX
def test_only_a_gone_process_on_this_host_is_gone():
    assert not gone(_ours())  # this process: alive
    assert gone(_ours(start="1"))  # its number, another start: the one that wrote it is gone
    assert gone(_ours(boot="another boot"))
    assert not gone(_ours(start="1", host="another-host"))  # a shared disk: cannot be told
    assert not gone(_ours(start=""))
    assert not gone({"pid": "1", "host": socket.gethostname()})


@LINUX
def test_only_staging_folders_provably_left_by_a_gone_build_are_removed(tmp_path):
    dead = _ours(start="1")
    stale = _left(tmp_path, ".show.abc_1234", dead)
    kept = [
        _left(tmp_path, ".show.abcd1235", _ours()),  # a build running now
        _left(tmp_path, ".show.abcd1236", None),  # no marker: not provably ours
        _left(tmp_path, "show.abcd1237", dead),  # not a staging folder's name
        _left(tmp_path, ".show.abcd12", dead),
        _left(tmp_path, ".show.abcd1238", _ours(start="1", host="elsewhere")),
    ]
    bad = _left(tmp_path, ".show.abcd1239", None)
    (bad / MARKER).write_text("not JSON")
    target = _left(tmp_path, "target", dead)
    (tmp_path / ".show.abcd1240").symlink_to(target)  # a link to such a folder: not one
    (tmp_path / ".file.abcd1241").write_text(json.dumps(dead))
    assert remove_stale(tmp_path) == [stale]
    assert not stale.exists() and all(folder.is_dir() for folder in (*kept, bad, target))
    assert (tmp_path / ".show.abcd1240").is_symlink() and (tmp_path / ".file.abcd1241").is_file()


def test_a_staged_folder_is_marked_while_filled_and_unmarked_in_place(tmp_path):
    from generator.files import staged_folder

    with staged_folder(tmp_path / "show") as staging:
        assert json.loads((staging / MARKER).read_text())["pid"] == os.getpid()
        (staging / "config.ocio").write_text("done")
    assert sorted(p.name for p in (tmp_path / "show").iterdir()) == ["config.ocio"]
    mark(tmp_path)
    assert (tmp_path / MARKER).is_file()


@LINUX
def test_the_next_build_removes_what_a_build_killed_outright_left(tmp_path, capsys):
    (tmp_path / "tiny.toml").write_text(TINY, encoding="utf-8")
    # A baked ACES 2.0 view and a Scale file keep the killed build in its staging folder for seconds.
    slow = TINY.replace('views = ["Colorimetric", "Raw"]', 'views = ["ACES 2.0", "Scale", "Raw"]')
    (tmp_path / "slow.toml").write_text(slow, encoding="utf-8")
    out = tmp_path / "configs"
    build = subprocess.Popen(
        [sys.executable, "-m", "generator", "build", str(tmp_path / "slow.toml"), "-o", str(out / "show")],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    deadline = time.monotonic() + 120
    while not list(out.glob(f".show.*/{MARKER}")) and build.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    build.send_signal(signal.SIGKILL)
    build.wait()
    left = [p.parent for p in out.glob(f".show.*/{MARKER}")]
    assert left, "the build finished before it could be killed"
    foreign = _left(out, ".show.zzzz9999", None)  # named alike, not the build's own
    code, _, err = run(capsys, "build", str(tmp_path / "tiny.toml"), "-o", str(out / "other"))
    assert code == 0, err
    assert not any(p.exists() for p in left) and foreign.is_dir()
    assert sorted(p.name for p in out.iterdir()) == [".show.zzzz9999", "other"]
