"""The AVX registers' upper halves cleared before OCIO's SSE code runs.

A library that leaves 256-bit register halves in use (OpenImageIO's zip EXR reader here)
makes every later SSE instruction in the thread merge with them: PyOpenColorIO's CPU
processor then ran ten times slower (LogC4 to ACEScg, a UHD frame: 7.7 s instead of 0.7 s).
Compiled AVX code ends with VZEROUPPER, which numpy's AVX functions would run, but
backends keeps numpy at its SSE baseline. This module runs that one instruction itself.
"""

from __future__ import annotations

import ctypes
import functools
import mmap
import platform
from collections.abc import Callable
from pathlib import Path

#: VZEROUPPER; RET.
_VZEROUPPER = b"\xc5\xf8\x77\xc3"
#: MOV ECX, 1; XGETBV; RET: the state components in use (XINUSE), bit 2 the upper halves.
_XINUSE = b"\xb9\x01\x00\x00\x00\x0f\x01\xd0\xc3"
#: Bit of XINUSE for the upper halves of YMM0-15.
YMM_UPPER = 1 << 2

_PAGES: list[mmap.mmap] = []


def _cpu_flags() -> set[str]:
    """The processor's flags as Linux reports them (AVX only where the kernel enabled it); none
    elsewhere."""
    try:
        text = Path("/proc/cpuinfo").read_text()
    except OSError:
        return set()
    for line in text.splitlines():
        if line.startswith("flags"):
            return set(line.split(":", 1)[1].split())
    return set()


@functools.cache
def _function(code: bytes, flag: str, restype) -> Callable[[], int] | None:
    """``code`` as a function in a page of its own, or None where the processor lacks ``flag``
    or the system refuses executable memory."""
    if platform.machine().lower() not in ("x86_64", "amd64") or flag not in _cpu_flags():
        return None
    try:
        page = mmap.mmap(-1, mmap.PAGESIZE, prot=mmap.PROT_READ | mmap.PROT_WRITE | mmap.PROT_EXEC)
    except (OSError, AttributeError):  # W^X policies, or no mmap.PROT_EXEC
        return None
    page.write(code)
    _PAGES.append(page)  # kept for the process's life, as the cached function is
    return ctypes.CFUNCTYPE(restype)(ctypes.addressof(ctypes.c_char.from_buffer(page)))


def clear_upper() -> None:
    """Mark the AVX registers' upper halves unused in this thread (nothing without AVX)."""
    function = _function(_VZEROUPPER, "avx", None)
    if function is not None:
        function()


def upper_in_use() -> bool | None:
    """Whether this thread's AVX upper halves are marked in use; None where it cannot be read."""
    function = _function(_XINUSE, "xgetbv1", ctypes.c_uint32)
    return None if function is None else bool(function() & YMM_UPPER)
