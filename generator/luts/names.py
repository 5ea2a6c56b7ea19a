"""File names of written LUTs: a slug of a name, unique among the files of one folder."""

from __future__ import annotations

import hashlib
import re
from collections import Counter
from collections.abc import Iterable

#: Hex digits of a name's SHA-256 that tell apart names slugging alike.
DIGEST_DIGITS = 8


def _unaccented(text: str) -> str:
    """``text`` with accents taken off its letters (``Caméra`` as ``Camera``)."""
    import unicodedata

    return "".join(c for c in unicodedata.normalize("NFKD", text) if not unicodedata.combining(c))


def ascii_text(text: str) -> str:
    """``text`` in ASCII, for files whose formats are: accents taken off, anything else as
    Python escapes it (``\\u30ab``)."""
    return _unaccented(text).encode("ascii", "backslashreplace").decode("ascii")


def slug(name: str) -> str:
    """Lower-case ASCII letters and digits of ``name`` (accents taken off), runs of anything
    else as one ``_``."""
    return re.sub(r"[^a-z0-9]+", "_", _unaccented(name).lower()).strip("_")


def _digest(name: str) -> str:
    return hashlib.sha256(name.encode("utf-8")).hexdigest()[:DIGEST_DIGITS]


def file_stems(names: Iterable[str], taken: Iterable[str] = ()) -> dict[str, str]:
    """A file-name stem for each of ``names``, distinct for distinct names: the name's slug,
    or, where the slug is empty, another name's too or one of the stems ``taken``, the slug
    and the first digits of the SHA-256 of the exact name. A stem depends on the names
    alone, not on their order, so a spec names its files the same way every build."""
    names = list(dict.fromkeys(names))
    shared = Counter(slug(n) for n in names)
    taken = set(taken)
    stems = {}
    for name in names:
        s = slug(name)
        stems[name] = s if s and shared[s] == 1 and s not in taken else "_".join(filter(None, (s, _digest(name))))
    clashes = Counter(stems.values())
    clash = sorted(n for n, s in stems.items() if clashes[s] > 1 or s in taken)
    if clash:
        raise ValueError(f"names {clash} give the same file name")
    return stems


def add_file(files: dict, name: str, content) -> None:
    """Record ``content`` to be written as ``name``; a different content already under that name
    is an error (one file would overwrite the other)."""
    if files.setdefault(name, content) != content:
        raise ValueError(f"two different LUTs would be written to the one file {name}")
