"""Baking a build's view files in worker processes (generator/luts/pool.py)."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from generator.luts.pool import Pool


def _where(value):
    """``value`` and the process that computed it."""
    return value, os.getpid()


def _slow(seconds: float) -> int:
    time.sleep(seconds)
    return os.getpid()


def _fails():
    raise ValueError("a bake failed")


def test_a_submitted_bake_runs_in_a_worker_and_one_never_submitted_runs_here():
    with Pool(2) as pool:
        pool.submit("a", _where, 1)
        value, pid = pool.result("a", _where, 1)
        assert value == 1 and pid != os.getpid()
        assert pool.result("b", _where, 2) == (2, os.getpid())


def test_a_key_is_baked_once_whatever_is_submitted_under_it_again():
    with Pool(1) as pool:
        pool.submit("a", _where, 1)
        pool.submit("a", _where, 99)  # the same key: the first bake stands
        assert pool.result("a", _where, 5)[0] == 1


def test_bakes_run_side_by_side_in_their_workers():
    """While one worker sleeps through its bake, the other takes the next."""
    with Pool(2) as pool:
        for key in ("a", "b"):
            pool.submit(key, _slow, 0.5)
        pids = {pool.result(key, _slow, 0.0) for key in ("a", "b")}
        assert len(pids) == 2 and os.getpid() not in pids


def test_a_failed_bake_raises_where_its_result_is_asked():
    with Pool(1) as pool:
        pool.submit("a", _fails)
        with pytest.raises(ValueError, match="a bake failed"):
            pool.result("a", _fails)


def test_a_pool_never_used_starts_no_worker_and_a_closed_one_starts_anew():
    pool = Pool(1)
    pool.close()  # nothing to stop
    assert pool._executor is None
    pool.submit("a", _where, 1)
    pool.close()
    assert pool._executor is None
    pool.submit("b", _where, 2)
    try:
        assert pool.result("b", _where, 2)[0] == 2
    finally:
        pool.close()


#: A process that forks a worker, has it write its pid and wait, then waits itself.
ORPHANING = """
import os, sys, time
from generator.luts.pool import Pool

def wait(path):
    with open(path, "w") as handle:
        handle.write(str(os.getpid()))
    time.sleep(600)

pool = Pool(1)
pool.submit("w", wait, sys.argv[1])
time.sleep(600)
"""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the parent's death reaches a worker on Linux")
def test_a_worker_ends_when_the_process_that_forked_it_is_killed(tmp_path):
    """A build killed outright (SIGKILL) runs no clean-up: its workers must not wait forever."""
    marker = tmp_path / "worker.pid"
    parent = subprocess.Popen([sys.executable, "-c", ORPHANING, str(marker)])
    deadline = time.monotonic() + 60
    while not (marker.is_file() and marker.read_text()) and time.monotonic() < deadline:
        time.sleep(0.02)
    worker = int(marker.read_text())
    parent.send_signal(signal.SIGKILL)
    parent.wait()
    deadline = time.monotonic() + 10
    while Path(f"/proc/{worker}").exists() and time.monotonic() < deadline:
        time.sleep(0.02)
        with contextlib.suppress(ChildProcessError):
            os.waitpid(worker, os.WNOHANG)  # not ours to reap: init reaps it
    status = Path(f"/proc/{worker}/stat")
    assert not status.exists() or status.read_text().split()[2] == "Z", "the worker outlived its parent"
