"""Frames as tasks on a real Dask LocalCluster on 127.0.0.1: the same bytes as a local run, and a
worker killed mid-run has its frames run elsewhere with nothing half-written."""

from __future__ import annotations

import os
import signal

import numpy as np
import pytest

from tests.conftest import host_missing
from tests.convert import images


@pytest.fixture(scope="module")
def cluster():
    try:
        from distributed import LocalCluster
    except ImportError:
        host_missing("Dask distributed is not installed", "pip install -e '.[test,dask]', as make test does")
    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None
    ) as local:
        yield local


def _plan(config, folder):
    from generator.convert.frame import Plan

    return Plan(str(config), "ACEScg", "ACEScct", verify=4096), folder


def _frames(tmp_path, count):
    from generator.convert.frames import sources

    folder = tmp_path / "in"
    for f in range(1, count + 1):
        images.write(
            folder / f"s.{f:04d}.exr" if folder.mkdir(exist_ok=True) is None else None,
            np.tile(images.pixels(f), (4, 4, 1)),
            "half",
            compression="zip",
        )
    return lambda out: sources((str(folder / "s.####.exr"),), None, str(out), ".exr")


def test_a_cluster_writes_the_bytes_a_local_run_writes(tmp_path, build_config, cluster):
    from generator.convert.run import run

    config = build_config((2, 1))
    listed = _frames(tmp_path, 4)
    plan, _ = _plan(config, None)
    local = (
        run(plan, listed(tmp_path / "local"), lambda r: None, jobs=1) if (tmp_path / "local").mkdir() is None else None
    )
    (tmp_path / "cluster").mkdir()
    remote = run(plan, listed(tmp_path / "cluster"), lambda r: None, scheduler=cluster.scheduler_address)
    assert all(r.ok for r in local + remote) and len(remote) == 4
    assert all(r.verdict is not None and r.verdict.passed for r in remote)
    for name in sorted(os.listdir(tmp_path / "local")):
        assert (tmp_path / "local" / name).read_bytes() == (tmp_path / "cluster" / name).read_bytes()


def test_a_worker_killed_mid_run_has_its_frames_run_elsewhere(tmp_path, build_config, cluster):
    from distributed import Client

    from generator.convert.run import run

    config = build_config((2, 1))
    listed = _frames(tmp_path, 12)
    plan, _ = _plan(config, None)
    (tmp_path / "local").mkdir()
    run(plan, listed(tmp_path / "local"), lambda r: None, jobs=1)
    with Client(cluster.scheduler_address) as client:
        pids = list(client.run(os.getpid).values())
    killed = []

    def report(result):  # the first frame back: one worker dies with frames still queued or running
        if not killed:
            os.kill(pids[0], signal.SIGKILL)
            killed.append(pids[0])

    (tmp_path / "cluster").mkdir()
    results = run(plan, listed(tmp_path / "cluster"), report, scheduler=cluster.scheduler_address)
    assert killed and len(results) == 12 and all(r.ok for r in results), [r.reason for r in results if not r.ok]
    finals = sorted(p.name for p in (tmp_path / "cluster").iterdir() if not p.name.startswith("."))
    assert finals == sorted(os.listdir(tmp_path / "local"))
    for name in finals:  # every frame whole: the bytes of the local run
        assert (tmp_path / "local" / name).read_bytes() == (tmp_path / "cluster" / name).read_bytes()
