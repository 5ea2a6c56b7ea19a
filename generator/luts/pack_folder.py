"""Writing a LUT pack into a folder that may hold other things.

The pack knows its own files by a manifest it writes beside them, :data:`MANIFEST`: each
file's name and SHA-256. A rerun replaces the files it wrote before, all or none (staged in
a hidden folder inside, then renamed into place by :func:`generator.files.write_files`),
and deletes those of them it no longer writes, but only while they hold what it wrote.
Anything else there is left alone; a file of the same name as one of the pack's is refused
unless ``force``.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import stat
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from generator.files import CannotWrite, Refused, write_files

README = "README.md"
MANIFEST = ".ocioforge-pack.json"
NOTE = "The files ocioforge pack wrote in this folder; a rerun replaces them and leaves anything else alone."


def digest(data: bytes) -> str:
    """The SHA-256 of ``data``, in hex."""
    return hashlib.sha256(data).hexdigest()


def manifest(files: dict[str, bytes]) -> bytes:
    """The manifest of ``files`` (name to bytes): the same files give the same bytes."""
    record = {"note": NOTE, "files": {name: digest(data) for name, data in sorted(files.items())}}
    return (json.dumps(record, indent=1, sort_keys=True, ensure_ascii=False) + "\n").encode("utf-8")


def _recorded(folder: Path) -> dict[str, str]:
    """Name to SHA-256 of the files an earlier pack wrote in ``folder`` ({} when none, or the
    manifest is not one a pack wrote)."""
    try:
        files = json.loads((folder / MANIFEST).read_text(encoding="utf-8")).get("files", {})
    except (OSError, ValueError, AttributeError):
        return {}
    ok = isinstance(files, dict) and all(isinstance(v, str) and "/" not in k for k, v in files.items())
    return files if ok else {}


def _holds(path: Path, sha: str) -> bool:
    """Whether ``path`` is a regular file (not a link) holding the bytes of SHA-256 ``sha``."""
    try:
        if not stat.S_ISREG(os.lstat(path).st_mode):
            return False
        return digest(path.read_bytes()) == sha
    except OSError:
        return False


def own_files(folder: Path) -> set[str]:
    """The names in ``folder`` that hold what an earlier pack wrote there (the manifest too)."""
    own = {name for name, sha in _recorded(folder).items() if _holds(folder / name, sha)}
    return own | ({MANIFEST} if _recorded(folder) else set())


def check(folder: Path, names: list[str], force: bool) -> None:
    """:class:`Refused` when ``folder`` is not a folder, or, without ``force``, holds a file
    of one of ``names`` that an earlier pack did not write."""
    try:
        mode = os.stat(folder).st_mode
    except FileNotFoundError:
        return
    except OSError as error:
        raise CannotWrite(folder, error) from error
    if not stat.S_ISDIR(mode):
        raise Refused(folder, "exists and is not a folder; allowed: a folder, or a path where one can be made")
    if force:
        return
    own = own_files(folder)
    foreign = next((n for n in (*names, README, MANIFEST) if n not in own and os.path.lexists(folder / n)), None)
    if foreign is not None:
        raise Refused(
            folder / foreign,
            f"exists and is not a file ocioforge pack wrote here (not in {MANIFEST}); allowed: another "
            "folder, or --force to replace it (the folder's other files are left alone)",
        )


@contextmanager
def staged(folder: Path, names: list[str], force: bool) -> Iterator[Path]:
    """Yield an empty hidden folder inside ``folder`` (made, with its parents, if missing) to
    bake into; when the block succeeds, its files and a new manifest replace those of the
    earlier pack, all or none, and the earlier pack's files not written again are deleted.
    ``folder``'s other files are never touched; the hidden folder is always removed."""
    folder = Path(os.path.abspath(folder))
    check(folder, names, force)
    missing = [p for p in (folder, *folder.parents) if not p.exists()]
    staging = None
    done = False
    try:
        try:
            folder.mkdir(parents=True, exist_ok=True)
            staging = Path(tempfile.mkdtemp(prefix=".ocioforge-pack.", dir=folder))
        except OSError as error:
            raise CannotWrite(folder, error) from error
        yield staging
        _commit(folder, staging, force)
        done = True
    finally:
        if staging is not None:
            shutil.rmtree(staging, ignore_errors=True)
        if not done:
            for made in missing:  # innermost first, while empty
                try:
                    made.rmdir()
                except OSError:
                    break


def _commit(folder: Path, staging: Path, force: bool) -> None:
    """Rename the staged files into ``folder`` with their manifest (all or none), then delete
    the earlier pack's files this one does not write, where they still hold what it wrote."""
    files = {p.name: p.read_bytes() for p in sorted(staging.iterdir())}
    earlier = _recorded(folder)
    check(folder, list(files), force)  # again: another process may have written meanwhile
    write_files({folder / name: data for name, data in {**files, MANIFEST: manifest(files)}.items()}, True)
    for name, sha in earlier.items():
        if name not in files and name != MANIFEST and _holds(folder / name, sha):
            (folder / name).unlink()
