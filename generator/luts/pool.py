"""Baking a build's view files in worker processes while the build goes on.

A config's view files (gamut-mapping lattices, ACES 2.0 lattices) are pure functions of the
spec: a build submits them all first, emits its colour spaces meanwhile and collects each
file where it writes it. Workers are forked, so they inherit numpy's pinned settings and
the modules already loaded: their bytes are those of a bake in the build's own process.
"""

from __future__ import annotations

import contextlib
import ctypes
import multiprocessing
import os
import signal
import sys
from collections.abc import Callable, Hashable
from concurrent.futures import Future, ProcessPoolExecutor

from generator.files import uninterrupted

#: Linux's prctl option making a process receive a signal when its parent dies.
_PR_SET_PDEATHSIG = 1


def _die_with_parent(parent: int) -> None:
    """A worker's initializer: on Linux, kill the worker when ``parent``, which forked it, dies (a
    build killed outright left its workers waiting for work forever); elsewhere nothing. A
    worker holds its results in memory only, so nothing is left half-written."""
    if sys.platform.startswith("linux"):
        with contextlib.suppress(OSError, AttributeError):  # no prctl: as before
            ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
        if os.getppid() != parent:  # it died before the request took effect
            os._exit(1)


class Pool:
    """Pure bakes by key: :meth:`submit` hands one to a worker, :meth:`result` waits for it
    (or, for a key never submitted, calls the function here)."""

    def __init__(self, workers: int | None = None) -> None:
        self._workers = workers or os.cpu_count() or 1
        self._executor: ProcessPoolExecutor | None = None
        self._futures: dict[Hashable, Future] = {}

    def submit(self, key: Hashable, fn: Callable, *args) -> None:
        """Start ``fn(*args)`` in a worker, once per ``key``. A stop signal waits until the
        submission is done: raised inside the executor's start (its thread made, not started)
        or its locks, it left a pool that could not shut down (a traceback, or a hung build)."""
        if key in self._futures:
            return
        with uninterrupted():
            if self._executor is None:
                self._executor = ProcessPoolExecutor(
                    self._workers,
                    mp_context=multiprocessing.get_context("fork"),
                    initializer=_die_with_parent,
                    initargs=(os.getpid(),),
                )
            self._futures[key] = self._executor.submit(fn, *args)

    def result(self, key: Hashable, fn: Callable, *args):
        """The result of the bake submitted as ``key``, else ``fn(*args)`` computed here."""
        future = self._futures.get(key)
        return future.result() if future is not None else fn(*args)

    def close(self) -> None:
        """Stop the workers (a bake still running is cancelled)."""
        if self._executor is not None:
            self._executor.shutdown(cancel_futures=True)
            self._executor = None

    def __enter__(self) -> Pool:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
