"""The AVX upper halves cleared in this thread (generator/avx_state.py)."""

from __future__ import annotations

import pytest

from generator import avx_state

#: VPCMPEQD YMM0, YMM0, YMM0; RET: sets every bit of YMM0, its upper half included.
DIRTY = b"\xc5\xfd\x76\xc0\xc3"


def dirty_upper() -> None:
    """Leave YMM0's upper half in use, as a library without VZEROUPPER does."""
    avx_state._function(DIRTY, "avx", None)()


needs_xinuse = pytest.mark.skipif(avx_state.upper_in_use() is None, reason="XGETBV 1 needs x86-64 with xgetbv1")


@needs_xinuse
def test_clear_upper_marks_the_upper_halves_unused():
    dirty_upper()
    assert avx_state.upper_in_use() is True
    avx_state.clear_upper()
    assert avx_state.upper_in_use() is False
