"""Probe images on disk, through OpenImageIO: (n, 3) samples as a near-square image and back."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from generator import tolerances

#: Image width; the last row is padded by repeating the last sample.
WIDTH = 128


def write(path: str | Path, values: np.ndarray) -> None:
    """Write (n, 3) values as an uncompressed float32 OpenEXR image."""
    import OpenImageIO as oiio  # optional: only the host engines read and write images

    values = np.asarray(values, dtype=np.float32).reshape(-1, 3)
    rows = max(1, -(-len(values) // WIDTH))
    pixels = np.concatenate([values, np.repeat(values[-1:], rows * WIDTH - len(values), axis=0)])
    spec = oiio.ImageSpec(WIDTH, rows, 3, oiio.FLOAT)
    spec.attribute("compression", "none")
    out = oiio.ImageOutput.create(str(path))
    if out is None or not out.open(str(path), spec):
        raise OSError(f"{path}: cannot write: {oiio.geterror()}")
    ok = out.write_image(pixels.reshape(rows, WIDTH, 3))
    out.close()
    if not ok:
        raise OSError(f"{path}: cannot write: {out.geterror()}")


def read(path: str | Path, count: int) -> tuple[np.ndarray, float]:
    """The first ``count`` RGB samples of an image as float64, and its quantisation step
    (0 for float files, :data:`tolerances.UINT16_STEP` for 16-bit integer ones)."""
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(str(path))
    if buf.has_error:
        raise OSError(f"{path}: cannot read: {buf.geterror()}")
    spec = buf.spec()
    pixels = np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64)[..., :3].reshape(-1, 3)
    if len(pixels) < count:
        raise OSError(f"{path}: holds {len(pixels)} pixels, {count} expected")
    base = spec.format.basetype
    if base not in (oiio.FLOAT, oiio.HALF, oiio.DOUBLE, oiio.UINT16):
        raise OSError(f"{path}: stored as {spec.format}; the verifier reads float or 16-bit files")
    return pixels[:count], tolerances.UINT16_STEP if base == oiio.UINT16 else 0.0
