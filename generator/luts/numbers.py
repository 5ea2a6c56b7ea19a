"""Fast, deterministic text for LUT tables: fixed decimals, trailing zeros dropped.

Writing a 65³ lattice through Python's string formatting takes longer than
sampling it; these helpers build the ASCII digits with numpy instead. The same
values always give the same bytes, and every written value parses back to
:func:`rounded` of the input (what the baker uses to place nodes exactly).
"""

from __future__ import annotations

import numpy as np


def rounded(values, decimals: int) -> np.ndarray:
    """``values`` rounded to ``decimals`` decimals, as the text will hold them."""
    scale = 10.0**decimals
    return np.rint(np.asarray(values, dtype=np.float64) * scale) / scale


def table(values, decimals: int) -> bytes:
    """Rows of ``values`` (shape (rows, columns), each within (-10, 10)) as text lines.

    Columns are separated by one space, rows end with a newline; each value
    has at most ``decimals`` decimals with trailing zeros (and a bare point)
    removed, so 0.5 is written ``0.5``, 1.0 ``1`` and -0.25 ``-0.25``.

    Raises
    ------
    ValueError
        If a value lies outside (-10, 10) once rounded (or is not finite).
    """
    values = np.asarray(values, dtype=np.float64)
    rows, columns = values.shape
    scale = 10**decimals
    q = np.rint(values * scale)
    if not np.all(np.abs(q) < 10 * scale):
        raise ValueError("table values must lie within (-10, 10)")
    rest = np.abs(q).astype(np.int64)
    width = decimals + 4  # sign, digit, point, decimals, separator
    chars = np.empty((rows, columns, width), dtype=np.uint8)
    keep = np.ones((rows, columns, width), dtype=bool)
    significant = np.zeros(rest.shape, dtype=bool)  # a nonzero decimal at or right of this place
    for place in range(decimals, 0, -1):
        rest, digit = np.divmod(rest, 10)
        chars[..., place + 2] = digit + ord("0")
        significant |= digit != 0
        keep[..., place + 2] = significant
    chars[..., 0] = ord("-")
    keep[..., 0] = q < 0
    chars[..., 1] = rest + ord("0")
    chars[..., 2] = ord(".")
    keep[..., 2] = significant
    chars[..., -1] = ord(" ")
    chars[:, -1, -1] = ord("\n")
    return chars[keep].tobytes()


def number(value: float) -> str:
    """One float as the shortest text that reads back to the same float64."""
    value = float(value)
    return "0" if value == 0 else repr(value)
