"""glibc's malloc told to keep freed memory for reuse: numpy's temporaries of a few MB then
come from the heap instead of fresh pages the kernel must zero.

By default glibc returns a freed block above 128 KB (or above the largest block freed so far,
up to 32 MB) to the kernel, and trims the heap's top once 2× that is free: every array of a
bake's hundred thousand colours was mapped, faulted in page by page and unmapped again. Kept,
the pack's serial bake took 0.13 s of system time instead of 1.9 s, and 15% less wall time
(docs/luts.md). Memory freed stays with the process until it exits; its peak did not grow
(the serial bake: 284 MB either way).
"""

from __future__ import annotations

import ctypes
import sys

#: glibc's mallopt parameters (malloc.h).
M_TRIM_THRESHOLD, M_TOP_PAD, M_MMAP_THRESHOLD = -1, -2, -3

#: Blocks below this are taken from the heap (glibc's largest allowed threshold on 64-bit).
MMAP_THRESHOLD = 32 * 1024 * 1024

#: Free memory at the heap's top kept, not trimmed; and the padding each growth asks for.
TRIM_THRESHOLD, TOP_PAD = 1 << 30, 64 * 1024 * 1024


def keep_freed_memory() -> bool:
    """Set this process's (and the workers it forks later) malloc to keep freed memory; whether
    it could (False off glibc's Linux: nothing changes)."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):  # another C library (musl): leave its malloc as it is
        return False
    settings = ((M_MMAP_THRESHOLD, MMAP_THRESHOLD), (M_TRIM_THRESHOLD, TRIM_THRESHOLD), (M_TOP_PAD, TOP_PAD))
    return all(mallopt(parameter, value) == 1 for parameter, value in settings)
