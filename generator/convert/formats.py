"""Output formats: what each holds (channels, sample types, compressions) and how a written
value is quantised, which the verifier undoes in the written format's precision.

Integer samples are quantised here, not by OpenImageIO: ``round(clip(v, 0, 1) * (2**bits - 1))``,
so every format's codes are that one rounding (OIIO's 10-bit DPX goes through 16 bits and
truncates: up to a whole code off).
"""

from __future__ import annotations

import os
from dataclasses import dataclass

import numpy as np

#: Sample types: name -> (bits, is_float).
DEPTHS = {"uint8": (8, False), "uint10": (10, False), "uint16": (16, False), "half": (16, True), "float": (32, True)}

#: Compressions no writer undoes exactly (lossy): a frame written with one cannot be verified.
LOSSY = ("b44", "b44a", "dwaa", "dwab", "jpeg", "pxr24")

#: The largest finite half float: a half file holds no larger value.
HALF_MAX = 65504.0


@dataclass(frozen=True)
class Format:
    """An output format: its name, suffix, the sample types it writes (the first the default),
    its compressions (the first the default; () for none), how many channels it holds (0:
    any), whether it holds tiles, and whether it is lossy itself (JPEG)."""

    name: str
    suffix: str
    depths: tuple[str, ...]
    compressions: tuple[str, ...] = ()
    channels: int = 0
    tiles: bool = False
    lossy: bool = False


FORMATS = {
    "exr": Format(
        "exr",
        ".exr",
        ("half", "float"),
        ("zip", "none", "rle", "zips", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"),
        tiles=True,
    ),
    "tiff": Format("tiff", ".tif", ("uint16", "uint8", "float"), ("zip", "none", "lzw"), tiles=True),
    "png": Format("png", ".png", ("uint8", "uint16"), channels=4),
    "jpeg": Format("jpeg", ".jpg", ("uint8",), channels=3, lossy=True),
    "dpx": Format("dpx", ".dpx", ("uint10", "uint16"), channels=4),
}

#: File suffixes that name a format (``-o`` of a single file is not offered: the format is ``--format``).
SUFFIXES = {
    ".exr": "exr",
    ".tif": "tiff",
    ".tiff": "tiff",
    ".png": "png",
    ".jpg": "jpeg",
    ".jpeg": "jpeg",
    ".dpx": "dpx",
}

#: OpenImageIO's names of its sample types, for the ones a source may hold.
_OIIO_DEPTH = {"half": "half", "float": "float", "uint8": "uint8", "uint16": "uint16", "double": "float"}


def format_of(path: str) -> str | None:
    """The format a file's suffix names, or None."""
    return SUFFIXES.get(os.path.splitext(path)[1].lower())


def choose_depth(fmt: Format, asked: str | None, source_type: str, source_bits: int) -> str:
    """The sample type written: ``asked``, else the source's where the format holds it (a half
    EXR stays half, a 10-bit DPX 10-bit), else the format's default."""
    if asked:
        return asked
    kept = "uint10" if source_bits == 10 else _OIIO_DEPTH.get(source_type, "")
    return kept if kept in fmt.depths else fmt.depths[0]


def choose_compression(fmt: Format, asked: str | None, source_format: str, source_compression: str) -> str:
    """The compression written: ``asked``, else the source's where the format takes it (a
    ``dwaa:45`` keeps its level), else the format's default ("" for a format without)."""
    if asked:
        return asked
    if not fmt.compressions:
        return ""
    if source_format == fmt.name and source_compression.split(":")[0].lower() in fmt.compressions:
        return source_compression
    return fmt.compressions[0]


def is_lossy(fmt: Format, compression: str, depth: str) -> bool:
    """Whether the written samples may differ from the values given beyond their quantisation:
    JPEG, and the lossy EXR compressions (pxr24 is lossless on half samples)."""
    method = compression.split(":")[0].lower()
    return fmt.lossy or (method in LOSSY and not (method == "pxr24" and depth == "half"))


def integer_bits(depth: str) -> int:
    """The bits of an integer sample type; 0 for a float one."""
    bits, is_float = DEPTHS[depth]
    return 0 if is_float else bits


def quantised(values: np.ndarray, depth: str) -> np.ndarray:
    """Float samples as the integers written for ``depth`` (uint8 or uint16 arrays; a 10-bit
    code in the top bits of a uint16, as OIIO's DPX writer takes it); floats unchanged."""
    bits = integer_bits(depth)
    if not bits:
        return values
    codes = np.rint(np.clip(np.nan_to_num(values, nan=0.0), 0.0, 1.0) * float(2**bits - 1))
    if bits == 8:
        return codes.astype(np.uint8)
    return (codes.astype(np.uint16) << (16 - bits)).astype(np.uint16)


def dequantised(stored: np.ndarray, depth: str) -> np.ndarray:
    """Samples read back in their stored type (see :func:`read_type`) as float64 values."""
    bits = integer_bits(depth)
    if not bits:
        return stored.astype(np.float64)
    codes = stored.astype(np.uint32) >> (16 - bits) if bits != 8 else stored.astype(np.uint32)
    return codes.astype(np.float64) / float(2**bits - 1)


def read_type(depth: str) -> str:
    """The OpenImageIO type to read a written file back in, exactly: its own sample type."""
    return {"uint8": "uint8", "uint10": "uint16", "uint16": "uint16", "half": "half", "float": "float"}[depth]


def written_type(depth: str) -> str:
    """The OpenImageIO type of the buffers given to the writer for ``depth``."""
    return {"uint8": "uint8", "uint10": "uint16", "uint16": "uint16", "half": "float", "float": "float"}[depth]


def step(written: np.ndarray, expected: np.ndarray, depth: str) -> np.ndarray | float:
    """The quantisation step of the written samples: an integer format's code, or for half
    floats the gap from each written value to the next half toward ``expected`` (a value the
    engine computed there rounds to it from at most half that gap)."""
    bits = integer_bits(depth)
    if bits:
        return 1.0 / float(2**bits - 1)
    if depth == "float":
        return 0.0
    halves = written.astype(np.float16)
    with np.errstate(all="ignore"):
        direction = np.where(expected > written, np.inf, -np.inf).astype(np.float16)
        toward = np.nextafter(halves, direction)
        gap = np.abs(toward.astype(np.float64) - halves.astype(np.float64))
    return np.where(np.isfinite(gap), gap, 0.0)
