"""File names of written LUTs: a slug of a name, unique among the files of one folder."""

from __future__ import annotations

import hashlib
import re
import unicodedata
from collections import Counter
from collections.abc import Iterable

#: Hex digits of a name's SHA-256 that tell apart names slugging alike; where those still
#: meet another stem, the next count (the whole digest last).
DIGEST_DIGITS = (8, 16, 64)

#: Longest stem: with the longest affixes a build's file takes (``view_`` and
#: ``_desaturate_hsv19.clf``), a file name of 255 bytes, all file systems allow. A longer
#: slug is cut, and the digest added, within it.
STEM_MAX = 229


def _unaccented(text: str) -> str:
    """``text`` with accents taken off its letters (``Caméra`` as ``Camera``)."""
    return "".join(c for c in unicodedata.normalize("NFKD", text) if not unicodedata.combining(c))


def ascii_text(text: str) -> str:
    """``text`` in ASCII, for files whose formats are: accents taken off, anything else as
    Python escapes it (``\\u30ab``)."""
    return _unaccented(text).encode("ascii", "backslashreplace").decode("ascii")


def slug(name: str) -> str:
    """Lower-case ASCII letters and digits of ``name`` (accents taken off), runs of anything
    else as one ``_``."""
    return re.sub(r"[^a-z0-9]+", "_", _unaccented(name).lower()).strip("_")


def _stem(name: str, level: int) -> str:
    """``name``'s slug at ``level`` 0, then, cut to fit :data:`STEM_MAX`, with the first
    ``DIGEST_DIGITS[level - 1]`` digits of the SHA-256 of the exact name."""
    if level == 0:
        return slug(name)
    digits = DIGEST_DIGITS[level - 1]
    cut = slug(name)[: STEM_MAX - 1 - digits].rstrip("_")
    return "_".join(filter(None, (cut, hashlib.sha256(name.encode("utf-8")).hexdigest()[:digits])))


def file_stems(names: Iterable[str], taken: Iterable[str] = ()) -> dict[str, str]:
    """A file-name stem for each of ``names``, distinct for distinct names and from the stems
    ``taken``: the name's slug, or, where the slug is empty, longer than :data:`STEM_MAX`,
    another name's too or taken, the slug (cut to fit) and the first digits of the SHA-256 of the
    exact name; more digits while a stem still meets another (a name may itself end in
    another's digest). A stem depends on the names alone, not on their order, so a spec
    names its files the same way every build."""
    names = list(dict.fromkeys(names))
    taken = set(taken)
    level = {n: 0 if slug(n) and len(slug(n)) <= STEM_MAX else 1 for n in names}
    while True:
        stems = {n: _stem(n, level[n]) for n in names}
        counts = Counter(stems.values())
        clash = [n for n in names if counts[stems[n]] > 1 or stems[n] in taken]
        if not clash:
            return stems
        if any(level[n] == len(DIGEST_DIGITS) for n in clash):  # the same slug and SHA-256: not met in practice
            raise ValueError(f"names {sorted(clash)} give the same file name")
        for n in clash:
            level[n] += 1


def add_file(files: dict, name: str, content) -> None:
    """Record ``content`` to be written as ``name``; a different content already under that name
    is an error (one file would overwrite the other)."""
    if files.setdefault(name, content) != content:
        raise ValueError(f"two different LUTs would be written to the one file {name}")
