"""Writing files and whole folders so that they are never seen half-written, and never in
place of anything the user did not ask to replace."""

from __future__ import annotations

import contextlib
import errno
import os
import shutil
import stat
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from generator.leftovers import mark, remove_stale, unmark


class CannotWrite(Exception):
    """An output the user named could not be written: the path and the operating system's
    reason (read-only file system, no permission, a file where a folder should be, disk full)."""

    def __init__(self, path: str | Path, error: OSError):
        super().__init__(f"{path}: cannot write: {error.strerror or error}")
        self.path, self.error = Path(path), error


class Refused(Exception):
    """An output the user named is something a command may not replace: the path, what is
    there and what is allowed."""

    def __init__(self, path: str | Path, reason: str):
        super().__init__(f"{path}: {reason}")
        self.path = Path(path)


class Stopped(BaseException):
    """A signal asked the process to stop: raised instead of renaming anything into place."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


#: The signal that asked the process to stop (0: none). Recorded by the signal handler, so
#: that an exception the handler raised and something swallowed (a weakref callback) can
#: never lead to files renamed into place.
_stop_signal = 0


def stop(signum: int) -> None:
    """Record that signal ``signum`` asked the process to stop."""
    global _stop_signal
    _stop_signal = signum


def stop_signal() -> int:
    """The signal recorded by :func:`stop` (0: none)."""
    return _stop_signal


def _unless_stopped() -> None:
    if _stop_signal:
        raise Stopped(_stop_signal)


#: What ``--force`` allows, said in refusals.
ALLOWED = "allowed: a new file's path, or with --force a regular file or a link to one"


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


def _mode(path: Path) -> int | None:
    """``path``'s own file type and mode (a link's, not its target's); None when nothing is there."""
    with _writing(path):
        try:
            return os.lstat(path).st_mode
        except (FileNotFoundError, NotADirectoryError):  # a folder on the way missing, or a file: written, it fails
            return None


def named(path: Path, what: str = "file") -> Path:
    """``path``, whose last component names a file or folder (not ``.``, ``..`` or ``/``)."""
    if path.name in ("", ".", ".."):
        raise Refused(path, f"names no {what} of its own; allowed: a path ending in the {what}'s name")
    return path


def check_file_output(path: str | Path) -> None:
    """:class:`Refused` where ``path`` names a file in a folder that does not exist (a command
    writing one file, init, plot or bake, makes no folder: a failed write had left the folders
    it made), or ends in a slash, naming a folder, not the file it would have written."""
    text = str(path)
    if text.endswith(("/", os.sep)) and Path(text).name:
        raise Refused(path, "ends in a slash, so it names a folder; allowed: a file's name")
    parent = Path(path).parent
    try:
        os.stat(parent)
    except FileNotFoundError:
        raise Refused(
            path, f"its folder {str(parent)!r} does not exist; allowed: a file in an existing folder"
        ) from None
    except OSError:
        pass  # a file or a loop of links where the folder should be: the write names the OS's reason


def not_readable(path: str | Path) -> str | None:
    """Why ``path`` is not a file to read, or None for a regular file (through links): a
    device or pipe would be read without end (/dev/zero) or wait for a writer forever."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return "does not exist"
    except OSError as error:
        return f"cannot be read: {error.strerror}"
    if stat.S_ISDIR(mode):
        return "is a folder"
    if not stat.S_ISREG(mode):
        return "is not a regular file (a device, pipe or socket)"
    return None


def target(path: str | Path, force: bool) -> Path:
    """Where writing the file ``path`` goes: ``path`` when nothing is there; with ``force``, a
    regular file there, or the regular file a link there points to (written, the link kept, as
    a build through a show's ``current`` link does). :class:`Refused` otherwise: an existing
    file or link without ``force``, and anything else (a folder, device, pipe, a link to nothing
    or in a loop) even with it."""
    path = named(Path(path))
    mode = _mode(path)
    if mode is None:
        return path
    if stat.S_ISLNK(mode):
        linked = _linked_file(path)  # a link to nothing is refused as such, --force or not
        if not force:
            raise Refused(path, f"is a link; pass --force to write the file it points to; {ALLOWED}")
        return linked
    if stat.S_ISDIR(mode):
        raise Refused(path, f"is a folder; {ALLOWED}")
    if not stat.S_ISREG(mode):
        raise Refused(path, f"exists and is not a regular file (a device, pipe or socket); {ALLOWED}")
    if not force:
        raise Refused(path, "exists; pass --force to replace it")
    return path


def _linked_file(link: Path) -> Path:
    """The regular file ``link`` points to; :class:`Refused` when it points to nothing, to itself
    through a loop, or to anything but a regular file."""
    real = Path(os.path.realpath(link))
    mode = _mode(real)
    if mode is None or stat.S_ISLNK(mode):
        raise Refused(link, f"is a link to nothing (a missing file, or a loop of links); {ALLOWED}")
    if not stat.S_ISREG(mode):
        raise Refused(link, f"is a link to something that is not a regular file; {ALLOWED}")
    return real


#: Errors of writing that Python reports without a file name (a full disk on close).
WRITE_ERRNOS = (errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EIO, errno.EROFS)


def _inside(filename, folder: Path) -> bool:
    """Whether an OSError's ``filename`` (str, bytes or None) lies in ``folder``."""
    return filename is not None and Path(os.fsdecode(filename)).is_relative_to(folder)


def _no_check(folder: Path) -> None:
    """Any folder may be replaced."""


@contextmanager
def staged_folder(folder: Path, check: Callable[[Path], None] = _no_check) -> Iterator[Path]:
    """Yield a temporary sibling of ``folder``, empty but for the marker that tells a build
    killed outright left it (:mod:`generator.leftovers`: the next one here removes it); when the
    block succeeds, it replaces ``folder`` (renamed into place, the marker removed first); when
    it fails, it is removed and ``folder`` is untouched.
    ``check(path)`` raises when what is at ``path`` may not be replaced: it is run again on
    what is there right before the rename (another process may have written there meanwhile).
    Failing to create, fill (an OSError on a path inside it) or rename it raises
    :class:`CannotWrite` naming ``folder``."""
    named(folder, "folder")
    missing = [p for p in (folder.parent, *folder.parent.parents) if not p.exists()]
    done, staging = False, None
    try:
        with _writing(folder):
            _make_folder(folder.parent)
            remove_stale(folder.parent)  # what builds killed outright (SIGKILL) left here
            with uninterrupted():  # a stop waits until the folder made has its name, to be removed
                staging = Path(tempfile.mkdtemp(prefix=f".{folder.name}.", dir=folder.parent))
            mark(staging)
        try:
            yield staging
        except OSError as error:
            if _inside(error.filename, staging) or (error.filename is None and error.errno in WRITE_ERRNOS):
                raise CannotWrite(folder, error) from error
            raise
        with _writing(folder):
            unmark(staging)
            _replace_folder(staging, folder, check)
        done = True
    finally:
        if staging is not None and staging.exists():
            shutil.rmtree(staging)
        if not done:
            _remove_empty(missing)


def _remove_empty(folders: list[Path]) -> None:
    """Remove ``folders`` (innermost first) a failed write created, while they are empty."""
    for created in folders:
        try:
            created.rmdir()
        except OSError:
            return


#: What renaming a folder onto an existing path says when that path holds something.
_OCCUPIED = (errno.ENOTEMPTY, errno.EEXIST, errno.ENOTDIR, errno.EISDIR)


def _replace_folder(staging: Path, folder: Path, check: Callable[[Path], None]) -> None:
    """Rename the complete ``staging`` to ``folder``, after ``check`` allows what is there: in
    one step when nothing (or an empty folder) is there, as the rename itself refuses anything
    else; otherwise what is there is moved aside, checked again there (what it held when
    moved is what is deleted), and deleted only then; moved back when the check refuses it.
    Signals wait until it is done (:func:`uninterrupted`)."""
    _take_modes(staging, folder)
    _unless_stopped()
    with uninterrupted():
        check(folder)
        try:
            staging.rename(folder)
            return
        except OSError as error:
            if error.errno not in _OCCUPIED:
                raise
        holder = Path(tempfile.mkdtemp(prefix=f".{folder.name}.old.", dir=folder.parent))
        aside = holder / "previous"
        try:
            folder.rename(aside)
        except BaseException:
            holder.rmdir()
            raise
        try:
            check(aside)
            staging.rename(folder)
        except BaseException:
            _move_back(aside, folder)
            raise
        shutil.rmtree(holder)


def _kept_mode(path: Path, folder: bool) -> int | None:
    """The permissions of what ``path`` holds, when it is what will be replaced (a folder, or a
    regular file: links are followed, as a replacement writes through them); None otherwise."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return None
    return stat.S_IMODE(mode) if (stat.S_ISDIR(mode) if folder else stat.S_ISREG(mode)) else None


def _take_modes(staging: Path, folder: Path) -> None:
    """The staged folder's permissions: those of the folder it replaces, entry for entry where
    the old one held an entry of the same name and kind (a show's build rebuilt under a stricter
    umask stays readable to the show), a plain creation's otherwise; a shared parent's setgid
    bit, which the staged folder took, kept on a new folder."""
    old = _kept_mode(folder, True)
    if old is None:
        os.chmod(staging, _plain_mode(0o777) | (staging.stat().st_mode & stat.S_ISGID))
        return
    for path in sorted(staging.rglob("*"), reverse=True):  # a folder after what it holds, the staged one last
        mode = _kept_mode(folder / path.relative_to(staging), path.is_dir())
        if mode is not None and not path.is_symlink():
            os.chmod(path, mode)
    os.chmod(staging, old)


def _move_back(aside: Path, folder: Path) -> None:
    """Put what was at ``folder`` back from ``aside``; should that fail, say where it is (it is
    never deleted)."""
    try:
        aside.rename(folder)
        aside.parent.rmdir()
    except OSError as error:
        raise CannotWrite(
            folder, OSError(error.errno, f"{error.strerror}; what was there is kept in {aside}")
        ) from error


@contextmanager
def uninterrupted() -> Iterator[None]:
    """A stop signal arriving while the block runs waits until it is done (:func:`deferring`
    tells the handler to record it and return), then stops the command: renames into place and
    the removal of what they replaced are done whole or not begun, never cut between two files
    or two folders; a process pool's start and submissions are never cut inside its locks.
    (Blocking the signals would not do: the kernel hands a signal to any thread that does not
    block it, and Python then runs the handler at once.)"""
    global _deferring
    _deferring += 1
    try:
        yield
    finally:
        _deferring -= 1
    if not _deferring:
        _unless_stopped()


#: How many :func:`uninterrupted` blocks are running.
_deferring = 0


def deferring() -> bool:
    """Whether a stop signal must wait (recorded by :func:`stop`) until the files are in place."""
    return _deferring > 0


def _plain_mode(full: int = 0o666) -> int:
    """The permissions a plain creation gives: ``full`` (0666 for a file, 0777 for a folder)
    less the umask."""
    umask = os.umask(0)
    os.umask(umask)
    return full & ~umask


def write_files(files: dict[Path, bytes], force: bool) -> list[Path]:
    """Write every file or none: each target is checked (:func:`target`: without ``force`` no
    file may be there) before any is written, each goes to a private temporary sibling first
    and gets a plain write's permissions (a file replaced, its own), and only once all are complete, and every target is
    checked again, are they renamed into place, signals held back until all are
    (:func:`uninterrupted`). Returns the paths written (a link's file where a link was). A file
    that cannot be written raises :class:`CannotWrite`."""
    targets = {target(path, force): data for path, data in files.items()}
    staged: list[tuple[str, Path]] = []
    mode = _plain_mode()
    try:
        for path, data in targets.items():
            with _writing(path):
                _make_folder(path.parent)
                with uninterrupted():  # a stop waits until the file made is listed, to be removed
                    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
                    staged.append((temporary, path))
                with os.fdopen(handle, "wb") as stream:
                    stream.write(data)
                kept = _kept_mode(path, False)  # a file replaced keeps its permissions
                os.chmod(temporary, mode if kept is None else kept)
        _unless_stopped()
        with uninterrupted():
            for _, path in staged:
                target(path, force)
            _replace_all(staged)
    finally:
        for temporary, _ in staged:
            if os.path.exists(temporary):
                os.unlink(temporary)
    return list(targets)


def _replace_all(staged: list[tuple[str, Path]]) -> None:
    """Rename each staged temporary onto its path, all or none: with more than one, each file
    there is first moved aside, and if any rename fails, the files placed are taken back and
    the old ones restored (a .spi3d must not be left new beside its old .spi1d)."""
    if len(staged) == 1:
        temporary, path = staged[0]
        with _writing(path):
            os.replace(temporary, path)
        return
    aside: dict[Path, str] = {}  # a path whose old file was moved, to where
    placed: list[Path] = []
    try:
        for _, path in staged:
            if os.path.lexists(path):
                with _writing(path):
                    handle, old = tempfile.mkstemp(prefix=f".{path.name}.old.", dir=path.parent)
                    os.close(handle)
                    try:
                        os.replace(path, old)
                    except OSError:
                        os.unlink(old)
                        raise
                aside[path] = old
        for temporary, path in staged:
            with _writing(path):
                os.replace(temporary, path)
            placed.append(path)
    except BaseException:
        for path in placed:
            if path not in aside:
                with contextlib.suppress(OSError):
                    os.unlink(path)
        for path, old in aside.items():
            with contextlib.suppress(OSError):
                os.replace(old, path)
        raise
    for old in aside.values():
        with contextlib.suppress(OSError):
            os.unlink(old)


def write_atomic(path: Path, data: bytes, force: bool) -> Path:
    """One file through :func:`write_files`; returns the path written."""
    return write_files({Path(path): data}, force)[0]
