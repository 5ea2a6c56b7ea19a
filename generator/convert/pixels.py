"""Reading and writing a frame's pixels through OpenImageIO, a band of rows at a time.

A band is as many whole rows (whole rows of tiles in a tiled file) as a memory budget holds,
so a frame of any size is converted in bounded memory. Every part of a multi-part EXR is read;
channels are found by name (R, G, B; alpha as OIIO names it).
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from generator.convert import formats

if TYPE_CHECKING:
    import OpenImageIO as oiio

#: Bytes of float32 working buffers one band may take, by default (a 4K RGBA frame is 133 MB
#: whole): a frame larger than this is converted in bands of rows.
MEMORY_BUDGET = 256 * 2**20

#: Float32 copies of a band alive at once: the band read, its colour channels, the samples written.
BAND_COPIES = 3


#: The metadata naming a frame's colour space as the config spells it (EXR keeps it; OIIO's
#: ``oiio:ColorSpace`` is kept as a format can, an EXR's as an interop ID only for names OIIO knows).
COLOUR_SPACE = "ocioforge:ColorSpace"


class FrameError(Exception):
    """A frame that cannot be converted as asked: the reason, one line."""


@dataclass(frozen=True)
class Part:
    """One part (subimage) of a source frame: its index, spec, and colour channels (indices of
    R, G, B; () when it has none, so it passes unchanged)."""

    index: int
    spec: oiio.ImageSpec
    rgb: tuple[int, ...]

    @property
    def rows(self) -> range:
        """The part's data window rows, top to bottom."""
        return range(self.spec.y, self.spec.y + self.spec.height)


def rgb_channels(names) -> tuple[int, ...]:
    """The indices of the R, G and B channels (as named, in any case; a layer's ``diffuse.R`` is
    not the image's); () when one is missing."""
    upper = [n.upper() for n in names]
    found = tuple(upper.index(c) for c in "RGB" if c in upper)
    return found if len(found) == 3 else ()


def open_input(path: str):
    """An ImageInput on ``path``; FrameError with OIIO's reason when it cannot be read."""
    import OpenImageIO as oiio

    hints = oiio.ImageSpec()
    hints.attribute("oiio:UnassociatedAlpha", 1)  # colours as stored: not multiplied by an unassociated alpha
    inp = oiio.ImageInput.open(path, hints)
    if inp is None:
        raise FrameError(_first_line(oiio.geterror()) or "cannot be read as an image")
    return inp


def parts(inp, every: bool) -> list[Part]:
    """The frame's parts (the first alone unless ``every``)."""
    out, index = [], 0
    while True:
        spec = inp.spec()
        if spec.depth > 1:
            raise FrameError("is a volume (depth above 1); allowed: 2D images")
        out.append(Part(index, spec, rgb_channels(spec.channelnames)))
        index += 1
        if not every or not inp.seek_subimage(index, 0):
            break
    inp.seek_subimage(0, 0)
    return out


def band_rows(spec, budget: int, align: int) -> int:
    """How many rows a band holds within ``budget`` bytes: whole multiples of ``align`` (a tile's
    height), at least one."""
    per_row = max(1, spec.width * spec.nchannels * 4 * BAND_COPIES)
    rows = max(1, budget // per_row)
    return max(align, rows // align * align) if align > 1 else rows


def bands(part: Part, budget: int) -> list[tuple[int, int]]:
    """The bands ``(y0, y1)`` that cover ``part``, aligned to its tiles."""
    spec = part.spec
    step = band_rows(spec, budget, max(1, spec.tile_height))
    return [(y, min(y + step, spec.y + spec.height)) for y in range(spec.y, spec.y + spec.height, step)]


def read_rows(inp, part: Part, y0: int, y1: int, kind: str = "float") -> np.ndarray:
    """Rows ``y0`` to ``y1`` of ``part``, every channel, as an array (rows, width, channels) of
    OIIO type ``kind``; a tiled part is read by whole rows of tiles. FrameError on a read error
    (a truncated or corrupt file)."""
    import OpenImageIO as oiio

    spec = part.spec
    if spec.tile_width:
        th = spec.tile_height
        a0 = spec.y + (y0 - spec.y) // th * th
        a1 = min(spec.y + spec.height, spec.y + -(-(y1 - spec.y) // th) * th)
        data = inp.read_tiles(
            part.index,
            0,
            spec.x,
            spec.x + spec.width,
            a0,
            a1,
            spec.z,
            spec.z + 1,
            0,
            spec.nchannels,
            oiio.TypeDesc(kind),
        )
        data = (
            None if data is None else np.asarray(data).reshape(a1 - a0, spec.width, spec.nchannels)[y0 - a0 : y1 - a0]
        )
    else:
        data = inp.read_scanlines(part.index, 0, y0, y1, spec.z, 0, spec.nchannels, oiio.TypeDesc(kind))
    if data is None or (hasattr(data, "size") and data.size == 0):
        raise FrameError(f"rows {y0} to {y1 - 1}: {_first_line(inp.geterror()) or 'cannot be read'}")
    return np.asarray(data).reshape(y1 - y0, spec.width, spec.nchannels)


def _first_line(text: str) -> str:
    return (text or "").strip().splitlines()[0] if (text or "").strip() else ""


def kept_channels(part: Part, fmt: formats.Format) -> tuple[int, ...]:
    """The source channels a format holds, in the order written: every one for EXR and TIFF;
    R, G, B and alpha (where the format holds four) for PNG, DPX and JPEG."""
    if not fmt.channels:
        return tuple(range(part.spec.nchannels))
    if not part.rgb:
        raise FrameError(f"has no R, G, B channels ({', '.join(part.spec.channelnames)}); allowed: RGB images")
    alpha = part.spec.alpha_channel
    extra = (alpha,) if fmt.channels >= 4 and alpha >= 0 and alpha not in part.rgb else ()
    return part.rgb + extra


def output_spec(
    part: Part,
    fmt: formats.Format,
    depth: str,
    compression: str,
    colour_space: str,
    channels: tuple[int, ...],
    stamp: str,
):
    """The written part's spec: the source's (windows, metadata) with the channels kept, the
    sample type, compression, tiles where the format holds them, the colour space written
    (``oiio:ColorSpace``) and a DateTime (the source's, else ``stamp``: the same bytes on every run)."""
    import OpenImageIO as oiio

    spec = oiio.ImageSpec(part.spec)
    names = [part.spec.channelnames[c] for c in channels]
    spec.nchannels = len(channels)
    spec.channelnames = tuple(names)
    spec.alpha_channel = channels.index(part.spec.alpha_channel) if part.spec.alpha_channel in channels else -1
    spec.z_channel = channels.index(part.spec.z_channel) if part.spec.z_channel in channels else -1
    spec.set_format(oiio.TypeDesc({"uint10": "uint16"}.get(depth, depth)))
    spec.channelformats = ()
    for name in (
        "oiio:BitsPerSample",
        "compression",
        "oiio:ColorSpace",
        "oiio:Gamma",
        "oiio:subimages",
        "oiio:UnassociatedAlpha",
    ):
        spec.erase_attribute(name)
    if formats.integer_bits(depth):
        spec.attribute("oiio:BitsPerSample", formats.integer_bits(depth))
    if compression:
        spec.attribute("compression", compression)
    if not (fmt.tiles and part.spec.tile_width):
        spec.tile_width = spec.tile_height = spec.tile_depth = 0
    spec.attribute("oiio:ColorSpace", colour_space)  # OIIO keeps what each format can (EXR: an interop ID)
    spec.attribute(COLOUR_SPACE, colour_space)  # the config's own name, where the format keeps any text
    if spec.alpha_channel >= 0 and fmt.name != "exr":
        spec.attribute("oiio:UnassociatedAlpha", 1)  # colours written as given, not divided by alpha
    if not part.spec.getattribute("DateTime"):
        spec.attribute("DateTime", stamp)
    return spec


def write_rows(out, spec, y0: int, y1: int, data: np.ndarray) -> None:
    """Rows ``y0`` to ``y1`` of the open part ``spec`` of ``out``; FrameError on a write error."""
    if spec.tile_width:
        done = out.write_tiles(spec.x, spec.x + spec.width, y0, y1, spec.z, spec.z + 1, data)
    else:
        done = out.write_scanlines(y0, y1, spec.z, data)
    if not done:
        raise FrameError(f"writing rows {y0} to {y1 - 1}: {_first_line(out.geterror()) or 'failed'}")


def stamp_of(path: str) -> str:
    """A DateTime for an output whose source has none: the source file's modification time
    (UTC), the same on every machine and every run."""
    return time.strftime("%Y:%m:%d %H:%M:%S", time.gmtime(os.stat(path).st_mtime))
