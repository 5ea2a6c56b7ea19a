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


def significant(values, digits: int) -> np.ndarray:
    """``values`` rounded to ``digits`` significant digits, as Python's ``float(f"{v:.{digits}g}")``
    rounds each: scaled to ``digits`` integer digits and rounded there; the few the scaling's own
    rounding could tip (within 1e-6 of a half, or off a power of ten) through that text instead.
    At most 9 digits: the scaling's error (2^-53 of 10^9) stays far below that margin."""
    if not 1 <= digits <= 9:
        raise ValueError(f"{digits} significant digits; allowed: 1 to 9")
    values = np.asarray(values, dtype=np.float64)
    flat = values.ravel()
    with np.errstate(all="ignore"):
        exponent = np.floor(np.log10(np.abs(flat)))
        power = np.clip(digits - 1 - exponent, -22, 22)  # 10 ** power is exact in float64
        scaled = flat * 10.0**power
        whole = np.rint(scaled)
        out = np.where(power >= 0, whole / 10.0**power, whole * 10.0**-power)
        doubtful = ~np.isfinite(out) | (flat == 0.0) | (np.abs(np.abs(scaled - np.floor(scaled)) - 0.5) < 1e-6)
        doubtful |= (np.abs(scaled) < 10.0 ** (digits - 1)) | (np.abs(scaled) >= 10.0**digits)
        doubtful |= power != digits - 1 - exponent
    for i in np.flatnonzero(doubtful):
        out[i] = float(f"{flat[i]:.{digits}g}")
    return out.reshape(values.shape)


#: Digits are made three at a time: for each number below 1000, its hundreds, tens and
#: units as ASCII, and how many trailing zeros it has (3 for 0).
_GROUP = np.arange(1000)
_GROUP_DIGITS = tuple(((_GROUP // place) % 10 + ord("0")).astype(np.uint8) for place in (100, 10, 1))
_GROUP_TRAILING = (_GROUP % 10 == 0).astype(np.int64) + (_GROUP % 100 == 0) + (_GROUP == 0)


def _digits(rest: np.ndarray, count: int) -> tuple[list[np.ndarray], np.ndarray]:
    """The last ``count`` decimal digits of non-negative integers ``rest`` (n,), most
    significant first, each as ASCII (n,), and how many trailing zeros ``rest`` has
    (``count`` or more for 0)."""
    groups = []
    for _ in range(-(-count // 3)):
        above = rest // 1000  # floor division by a constant is much faster than divmod
        groups.append(rest - above * 1000)
        rest = above
    digits = [np.take(table, group) for group in reversed(groups) for table in _GROUP_DIGITS]
    trailing = np.take(_GROUP_TRAILING, groups[0])
    zero = groups[0] == 0
    for group in groups[1:]:
        trailing += zero * np.take(_GROUP_TRAILING, group)
        zero &= group == 0
    return digits[-count:], trailing


#: Rows formatted at a time: small blocks reuse the same memory (and stay in cache).
TABLE_BLOCK = 8192


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
    scale = 10**decimals
    q = np.rint(values * scale)
    if not np.all(np.abs(q) < 10 * scale):
        raise ValueError("table values must lie within (-10, 10)")
    return b"".join(_block(q[start : start + TABLE_BLOCK], decimals) for start in range(0, len(q), TABLE_BLOCK))


def _block(q: np.ndarray, decimals: int) -> bytes:
    """Text of rows of integers ``q`` (rows, columns), each ``10**decimals`` times a value."""
    rows, columns = q.shape
    q = q.ravel()
    digits, trailing = _digits(np.abs(q).astype(np.int64), decimals + 1)
    places = decimals - np.minimum(trailing, decimals)  # decimals written
    width = decimals + 4  # sign, digit, point, decimals, separator
    chars = np.empty((q.size, width), dtype=np.uint8)
    keep = np.ones((q.size, width), dtype=bool)
    chars[:, 0], keep[:, 0] = ord("-"), q < 0
    chars[:, 1] = digits[0]
    chars[:, 2], keep[:, 2] = ord("."), places > 0
    for place in range(1, decimals + 1):
        chars[:, place + 2], keep[:, place + 2] = digits[place], places >= place
    return _lines(chars, keep, rows, columns)


def _lines(chars: np.ndarray, keep: np.ndarray, rows: int, columns: int) -> bytes:
    """The kept characters of numbers ``chars`` (rows·columns, width; ASCII, the last column
    the separator), columns one space apart, each row ending with a newline."""
    chars[:, -1] = ord(" ")
    chars.reshape(rows, columns, -1)[:, -1, -1] = ord("\n")
    return chars.ravel()[keep.ravel()].tobytes()  # boolean indexing: a third of np.compress's time


def integer_table(values) -> bytes:
    """Rows of integers ``values`` (shape (rows, columns)) as text lines, each as ``str`` writes it:
    columns one space apart, each row ending with a newline."""
    q = np.asarray(values, dtype=np.int64)
    return b"".join(_integer_block(q[start : start + TABLE_BLOCK]) for start in range(0, len(q), TABLE_BLOCK))


def _integer_block(q: np.ndarray) -> bytes:
    rows, columns = q.shape
    q = q.ravel()
    magnitude = np.abs(q)
    count = len(str(int(magnitude.max(initial=0))))
    digits, _ = _digits(magnitude, count)
    chars = np.empty((q.size, count + 2), dtype=np.uint8)
    keep = np.ones((q.size, count + 2), dtype=bool)
    chars[:, 0], keep[:, 0] = ord("-"), q < 0
    for place in range(count):  # a leading zero is dropped; the units digit is always written
        chars[:, place + 1] = digits[place]
        if place < count - 1:
            keep[:, place + 1] = magnitude >= 10 ** (count - 1 - place)
    return _lines(chars, keep, rows, columns)


def number(value: float) -> str:
    """One float as the shortest text that reads back to the same float64."""
    value = float(value)
    return "0" if value == 0 else repr(value)
