"""Writing files and whole folders so that they are never seen half-written."""

from __future__ import annotations

import errno
import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path


class CannotWrite(Exception):
    """An output the user named could not be written: the path and the operating system's
    reason (read-only file system, no permission, a file where a folder should be, disk full)."""

    def __init__(self, path: str | Path, error: OSError):
        super().__init__(f"{path}: cannot write: {error.strerror or error}")
        self.path, self.error = Path(path), error


@contextmanager
def _writing(path: Path) -> Iterator[None]:
    """Any OSError in the block becomes :class:`CannotWrite` naming ``path``."""
    try:
        yield
    except OSError as error:
        raise CannotWrite(path, error) from error


def _make_folder(folder: Path) -> None:
    """``mkdir -p``; a file in the way reads as the OS says it for a path under a file
    ("Not a directory"), not as "File exists"."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except FileExistsError as error:
        raise NotADirectoryError(errno.ENOTDIR, os.strerror(errno.ENOTDIR), error.filename) from error


#: Errors of writing that Python reports without a file name (a full disk on close).
WRITE_ERRNOS = (errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EIO, errno.EROFS)


def _inside(filename, folder: Path) -> bool:
    """Whether an OSError's ``filename`` (str, bytes or None) lies in ``folder``."""
    return filename is not None and Path(os.fsdecode(filename)).is_relative_to(folder)


@contextmanager
def staged_folder(folder: Path) -> Iterator[Path]:
    """Yield an empty temporary sibling of ``folder``; when the block succeeds, it replaces
    ``folder`` (renamed into place); when it fails, it is removed and ``folder`` is untouched.
    Failing to create, fill (an OSError on a path inside it) or rename it raises
    :class:`CannotWrite` naming ``folder``."""
    missing = [p for p in (folder.parent, *folder.parent.parents) if not p.exists()]
    done = False
    try:
        with _writing(folder):
            _make_folder(folder.parent)
            staging = Path(tempfile.mkdtemp(prefix=f".{folder.name}.", dir=folder.parent))
        try:
            try:
                yield staging
            except OSError as error:
                if _inside(error.filename, staging) or (error.filename is None and error.errno in WRITE_ERRNOS):
                    raise CannotWrite(folder, error) from error
                raise
            with _writing(folder):
                _replace_folder(staging, folder)
            done = True
        finally:
            if staging.exists():
                shutil.rmtree(staging)
    finally:
        if not done:
            _remove_empty(missing)


def _remove_empty(folders: list[Path]) -> None:
    """Remove ``folders`` (innermost first) a failed write created, while they are empty."""
    for created in folders:
        try:
            created.rmdir()
        except OSError:
            return


def _replace_folder(staging: Path, folder: Path) -> None:
    """Rename the complete ``staging`` to ``folder``, moving a previous ``folder`` aside first."""
    os.chmod(staging, _plain_mode(0o777))
    if folder.exists():
        old = Path(tempfile.mkdtemp(prefix=f".{folder.name}.old.", dir=folder.parent))
        folder.rename(old / "x")
        staging.rename(folder)
        shutil.rmtree(old)
    else:
        staging.rename(folder)


def _plain_mode(full: int = 0o666) -> int:
    """The permissions a plain creation gives: ``full`` (0666 for a file, 0777 for a folder)
    less the umask."""
    umask = os.umask(0)
    os.umask(umask)
    return full & ~umask


def write_files(files: dict[Path, bytes]) -> None:
    """Write every file or none: each goes to a private temporary sibling first, gets a
    plain write's permissions, and only once all are complete are they renamed into place.
    A file that cannot be written raises :class:`CannotWrite` naming it."""
    staged: list[tuple[str, Path]] = []
    mode = _plain_mode()
    try:
        for path, data in files.items():
            with _writing(path):
                _make_folder(path.parent)
                handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
                staged.append((temporary, path))
                with os.fdopen(handle, "wb") as stream:
                    stream.write(data)
                os.chmod(temporary, mode)
        for temporary, path in staged:
            with _writing(path):
                os.replace(temporary, path)
    finally:
        for temporary, _ in staged:
            if os.path.exists(temporary):
                os.unlink(temporary)


def write_atomic(path: Path, data: bytes) -> None:
    """One file through :func:`write_files`."""
    write_files({Path(path): data})
