"""A convert run: every frame, in this process, in a pool of processes, or as tasks on a Dask
cluster, each result handed to ``report`` as it comes.

Frames are independent and each is written whole or not at all, so the order they finish in
changes nothing written: the same bytes whatever ``jobs`` or cluster ran them. On a cluster
the workers read and write the paths given (a file system they share); a worker that dies
has its frames run again elsewhere by the scheduler, and what it had staged is never renamed.
"""

from __future__ import annotations

import multiprocessing
import os
from collections.abc import Callable
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

from generator.convert.frame import FAILED, FrameResult, Plan, convert_frame
from generator.convert.frames import Source
from generator.files import uninterrupted

Report = Callable[[FrameResult], None]

#: Seconds to wait for a Dask scheduler to answer.
CONNECT_SECONDS = 5


class SchedulerError(Exception):
    """The Dask scheduler named cannot be reached (or Dask is not installed): one line."""


def run(
    plan: Plan, sources: list[Source], report: Report, jobs: int = 1, scheduler: str = "", fail_fast: bool = False
) -> list[FrameResult]:
    """Convert every source; ``report`` sees each result as it comes. With ``fail_fast`` the
    first failure stops the run: frames not begun are not converted (those running finish)."""
    if scheduler:
        return _on_cluster(plan, sources, report, scheduler, fail_fast)
    if jobs <= 1 or len(sources) <= 1:
        return _here(plan, sources, report, fail_fast)
    return _in_pool(plan, sources, report, jobs, fail_fast)


def _stops(result: FrameResult, fail_fast: bool) -> bool:
    return fail_fast and not result.ok


def _here(plan, sources, report, fail_fast) -> list[FrameResult]:
    out = []
    for source in sources:
        out.append(convert_frame(plan, source))
        report(out[-1])
        if _stops(out[-1], fail_fast):
            break
    return out


def _pool_start(threads: int) -> None:
    """A pool process's OpenImageIO threads: the machine's cores shared among the processes."""
    import OpenImageIO as oiio

    oiio.attribute("threads", threads)
    oiio.attribute("exr_threads", threads)


def _in_pool(plan, sources, report, jobs, fail_fast) -> list[FrameResult]:
    threads = max(1, (os.cpu_count() or 1) // jobs)
    # forkserver: forking this process, whose libraries may hold threads (OIIO's), can deadlock or crash
    # the children; the server forks them from a clean process that has loaded the modules once
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload(["generator.convert.frame"])
    pool = ProcessPoolExecutor(
        max_workers=min(jobs, len(sources)), mp_context=context, initializer=_pool_start, initargs=(threads,)
    )
    out, stopped = [], False
    try:
        with uninterrupted():  # a stop inside the pool's start or locks left it unable to shut down
            pending = {pool.submit(convert_frame, plan, s): s for s in sources}
        while pending:
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for future in done:
                source = pending.pop(future)
                result = _result(future, source)
                out.append(result)
                report(result)
                if _stops(result, fail_fast) and not stopped:
                    stopped = True
                    for other in list(pending):
                        if other.cancel():
                            pending.pop(other)
    except BaseException:  # Ctrl-C, SIGTERM: the processes stop too, removing what they staged
        for process in list(getattr(pool, "_processes", {}).values()):  # (no public way before 3.14)
            process.terminate()
        pool.shutdown(wait=True, cancel_futures=True)
        raise
    pool.shutdown(wait=True)
    return out


def _result(future, source: Source) -> FrameResult:
    """A finished task's result; a task that died (its process or worker lost for good) failed."""
    try:
        return future.result()
    except Exception as error:  # BrokenProcessPool, distributed's KilledWorker, ...
        return FrameResult(source.path, source.output, FAILED, f"{type(error).__name__}: {error}".strip())


def _on_cluster(plan, sources, report, scheduler, fail_fast) -> list[FrameResult]:
    try:  # only here: a local run never imports Dask
        from distributed import Client, as_completed
    except ImportError:
        raise SchedulerError("it needs Dask: pip install 'ocioforge[dask]'") from None
    try:
        client = Client(scheduler, timeout=CONNECT_SECONDS)
    except (OSError, TimeoutError, ValueError) as error:
        raise SchedulerError(
            f"cannot reach it ({error}); allowed: the address of a running Dask scheduler, such as tcp://host:8786"
        ) from None
    out = []
    with client:
        futures = {client.submit(convert_frame, plan, s, pure=False): s for s in sources}
        for future in as_completed(list(futures)):
            result = _result(future, futures[future])
            out.append(result)
            report(result)
            if _stops(result, fail_fast):
                client.cancel([f for f in futures if not f.done()])
                break
    return out
