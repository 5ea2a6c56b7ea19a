"""Which frames a convert run reads and where each is written: frame patterns, ranges, folders.

A pattern marks the frame number in a file name as the tools of a pipeline do: ``####`` (a run
of ``#``, one digit each, as Nuke), ``#`` alone (four digits, as oiiotool), ``@`` (one digit
each), ``%04d`` or ``%d`` (printf). Without ``--frames``, the frames are the files on disk that
the pattern matches; with it, exactly the frames the range names (``1001-1100``, ``1-100x5``,
``1001,1003,1010-1012``), a missing one failing as a frame.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

#: Suffixes read as images in a folder (OpenImageIO reads them all).
IMAGE_SUFFIXES = (".exr", ".tif", ".tiff", ".png", ".jpg", ".jpeg", ".dpx", ".hdr", ".tga", ".bmp", ".sxr", ".mxr")

#: The largest number of frames a range may name (a typo such as 1-1000000000 is refused, not listed).
MAX_FRAMES = 1_000_000

_MARK = re.compile(r"%0?(\d*)d|#+|@+")


class FramesError(ValueError):
    """A pattern, range or input that names no frames as asked: what is wrong and what is allowed."""


@dataclass(frozen=True)
class Pattern:
    """A file name with its frame number marked: ``prefix``, the number padded to ``padding``
    digits, ``suffix``."""

    prefix: str
    padding: int
    suffix: str

    def path(self, frame: int) -> str:
        """The file name of frame number ``frame``."""
        return f"{self.prefix}{frame:0{self.padding}d}{self.suffix}"

    def regex(self) -> re.Pattern:
        """File names of this pattern: a number of at least ``padding`` digits, no longer
        than ``padding`` unless it needs more (frame 10000 of ``####``)."""
        digits = rf"(?:\d{{{self.padding}}}|[1-9]\d{{{self.padding},}})" if self.padding > 1 else r"(?:0|[1-9]\d*)"
        return re.compile(re.escape(os.path.basename(self.prefix)) + f"({digits})" + re.escape(self.suffix) + r"\Z")


def parse_pattern(text: str) -> Pattern | None:
    """The frame pattern in the file name of ``text``; None when it marks no frame number.
    More than one mark is refused (FramesError)."""
    folder, name = os.path.split(text)
    marks = list(_MARK.finditer(name))
    if not marks:
        return None
    if len(marks) > 1:
        raise FramesError(f"{text!r} marks the frame number {len(marks)} times; allowed: one mark (####, #, @, %04d)")
    mark = marks[0]
    token = mark.group(0)
    if token.startswith("%"):
        padding = int(mark.group(1) or 1)
    elif token == "#":
        padding = 4
    else:
        padding = len(token)
    return Pattern(os.path.join(folder, name[: mark.start()]), padding, name[mark.end() :])


_RANGE = re.compile(r"(\d+)(?:-(\d+)(?:x(\d+))?)?\Z")


def parse_frames(text: str) -> tuple[int, ...]:
    """The frames a range names, in order, each once: ``1001-1100``, ``1-100x5`` (every fifth),
    ``1001,1005,1010-1012``."""
    out: dict[int, None] = {}
    for part in text.replace(" ", "").split(","):
        match = _RANGE.match(part)
        if not match:
            raise FramesError(
                f"--frames {text!r}: {part!r} is not a frame range; allowed: FIRST-LAST, "
                "FIRST-LASTxSTEP or FRAME, comma-separated, frames 0 or more (1001-1100, 1-99x2)"
            )
        first, last, step = int(match.group(1)), int(match.group(2) or match.group(1)), int(match.group(3) or 1)
        if last < first or step < 1:
            raise FramesError(
                f"--frames {text!r}: {part!r} runs backwards or by a step below 1; allowed: "
                "FIRST-LAST with FIRST <= LAST and a step of 1 or more"
            )
        if len(out) + (last - first) // step + 1 > MAX_FRAMES:
            raise FramesError(f"--frames {text!r} names more than {MAX_FRAMES} frames; allowed: fewer")
        out.update(dict.fromkeys(range(first, last + 1, step)))
    return tuple(out)


def on_disk(pattern: Pattern) -> list[tuple[int, str]]:
    """The frames of ``pattern`` present in its folder, by frame number."""
    folder = os.path.dirname(pattern.prefix) or "."
    regex = pattern.regex()
    try:
        names = os.listdir(folder)
    except FileNotFoundError:
        raise FramesError(
            f"{pattern.path(0)!r}: its folder {folder!r} does not exist; allowed: a pattern in an existing folder"
        ) from None
    found: dict[int, str] = {}
    for name in names:
        match = regex.match(name)
        if match:
            found.setdefault(int(match.group(1)), os.path.join(os.path.dirname(pattern.prefix), name))
    return sorted(found.items())


@dataclass(frozen=True)
class Source:
    """One frame to convert: the file read, the file written (in the output folder, the same
    name with the format's suffix)."""

    path: str
    output: str


def _output(path: str, folder: str, suffix: str) -> str:
    return os.path.join(folder, Path(path).stem + suffix)


def _folder_images(folder: str) -> list[str]:
    names = sorted(n for n in os.listdir(folder) if n.lower().endswith(IMAGE_SUFFIXES) and not n.startswith("."))
    return [os.path.join(folder, n) for n in names if os.path.isfile(os.path.join(folder, n))]


def _pattern_sources(text: str, pattern: Pattern, frames: tuple[int, ...] | None) -> list[str]:
    if frames is not None:
        return [pattern.path(f) for f in frames]
    found = on_disk(pattern)
    if not found:
        raise FramesError(
            f"{text!r} matches no file; allowed: a pattern matching frames on disk, or --frames to name them"
        )
    return [path for _, path in found]


def sources(inputs: tuple[str, ...], frames: str | None, folder: str, suffix: str) -> list[Source]:
    """Every frame the ``inputs`` name (files, folders of images, frame patterns; ``frames``
    a range for the patterns), each with its output in ``folder``. Refused (FramesError): an
    input that names nothing, ``frames`` without a pattern, two frames written to one file."""
    wanted = parse_frames(frames) if frames is not None else None
    paths: list[str] = []
    patterned = False
    for text in inputs:
        pattern = None if os.path.exists(text) else parse_pattern(text)
        if pattern is not None:
            patterned = True
            paths += _pattern_sources(text, pattern, wanted)
        elif os.path.isdir(text):
            images = _folder_images(text)
            if not images:
                raise FramesError(
                    f"{text!r} is a folder holding no image file; allowed: a folder of images "
                    f"({', '.join(IMAGE_SUFFIXES)})"
                )
            paths += images
        elif os.path.exists(text):
            paths.append(text)
        else:
            raise FramesError(
                f"{text!r} does not exist and marks no frame number; allowed: a file, a folder "
                "or a frame pattern (####, #, @, %04d)"
            )
    if wanted is not None and not patterned:
        raise FramesError(
            "--frames is given but no input is a frame pattern; allowed: --frames with a pattern such as shot.####.exr"
        )
    return _paired(list(dict.fromkeys(paths)), folder, suffix)


def _paired(paths: list[str], folder: str, suffix: str) -> list[Source]:
    """Each path with its output; FramesError when two write one file, or one would replace its input."""
    out: list[Source] = []
    taken: dict[str, str] = {}
    for path in paths:
        target = _output(path, folder, suffix)
        key = os.path.normcase(os.path.abspath(target))
        if key in taken:
            raise FramesError(
                f"{taken[key]!r} and {path!r} would both be written to {target!r}; allowed: "
                "inputs whose names differ once the suffix is the output format's"
            )
        if os.path.exists(path) and os.path.exists(target) and os.path.samefile(path, target):
            raise FramesError(
                f"{path!r} would be written over itself; allowed: an output folder other than "
                "the input's, or another format"
            )
        taken[key] = path
        out.append(Source(path, target))
    return out
