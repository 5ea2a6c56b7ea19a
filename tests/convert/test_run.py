"""A convert run: every frame here, in a pool of processes, or as tasks on a real Dask
LocalCluster on 127.0.0.1 (generator/convert/run.py). The same bytes however it runs; a frame
that fails fails alone, and a worker killed mid-run has its frames run elsewhere with nothing
half-written."""

from __future__ import annotations

import os
import signal

import numpy as np
import pytest

from tests.conftest import host_missing
from tests.convert import images
from tests.convert.images import convert


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


def test_corrupt_and_truncated_frames_fail_alone(tmp_path, capsys, config):
    frames = images.sequence(tmp_path / "in", "s", range(1, 5))
    frames[1].write_bytes(frames[1].read_bytes()[: len(frames[1].read_bytes()) // 2])  # truncated
    frames[2].write_bytes(b"not an image at all" * 10)  # corrupt
    code, out, _ = convert(
        capsys,
        *images.cg_to_cct(tmp_path / "in" / "s.####.exr", config, tmp_path / "out", 2),
    )
    assert code == 1
    assert "FAILED" in out and "s.0002.exr" in out and "s.0003.exr" in out and "2 written" in out and "2 failed" in out
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["s.0001.exr", "s.0004.exr"]
    code, out, _ = convert(
        capsys,
        *images.cg_to_cct(tmp_path / "in" / "s.####.exr", config, tmp_path / "out2", 1),
        "--fail-fast",
    )
    assert code == 1 and "1 written" in out and "1 failed" in out and "2 not run" in out


def test_a_pool_writes_the_bytes_of_a_run_here_and_reports_every_frame(tmp_path, config):
    from generator.convert.frame import WRITTEN, Plan
    from generator.convert.run import run

    listed = _frames(tmp_path, 3)
    plan = Plan(str(config), "ACEScg", "ACEScct")
    reported = {}
    for jobs in (1, 2):
        (tmp_path / f"jobs{jobs}").mkdir()
        seen = []
        results = run(plan, listed(tmp_path / f"jobs{jobs}"), seen.append, jobs=jobs)
        assert sorted(r.output for r in seen) == sorted(r.output for r in results)
        assert [r.status for r in results] == [WRITTEN] * 3
        reported[jobs] = {os.path.basename(r.output) for r in seen}
    assert reported[1] == reported[2] == {"s.0001.exr", "s.0002.exr", "s.0003.exr"}
    for name in reported[1]:
        assert (tmp_path / "jobs1" / name).read_bytes() == (tmp_path / "jobs2" / name).read_bytes()


def test_a_frame_that_fails_stops_a_fail_fast_run_before_the_next(tmp_path, config):
    from generator.convert.frame import FAILED, Plan
    from generator.convert.run import run

    listed = _frames(tmp_path, 3)
    (tmp_path / "in" / "s.0002.exr").write_bytes(b"no image")
    (tmp_path / "out").mkdir()
    results = run(Plan(str(config), "ACEScg", "ACEScct"), listed(tmp_path / "out"), lambda r: None, fail_fast=True)
    assert [r.status for r in results] == ["written", FAILED] and results[1].reason
    assert sorted(os.listdir(tmp_path / "out")) == ["s.0001.exr"]
