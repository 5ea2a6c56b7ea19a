"""Staging folders a build killed outright (SIGKILL, a power cut) left beside its output, which
the next build into the same folder removes: only those provably its own, named as
:func:`generator.files.staged_folder` names them, holding the marker it writes inside, owned by
this user, and whose process is gone (on this host: no process of that number started when it
did, or the machine rebooted since). Anything else, or anything unreadable, is left alone.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import socket
import stat
from pathlib import Path

#: The marker a staging folder holds while it is filled, removed before the folder is renamed.
MARKER = ".ocioforge-staging"
#: A staging folder's name: tempfile.mkdtemp(prefix=".<name>.") adds eight of [a-z0-9_].
STAGING_NAME = re.compile(r"\..+\.[a-z0-9_]{8}")
_PROC = Path("/proc")


def _boot_id() -> str:
    """This boot's identity (Linux), or "" where there is none to read."""
    try:
        return (_PROC / "sys/kernel/random/boot_id").read_text(encoding="ascii").strip()
    except OSError:
        return ""


def _start_time(pid: int) -> str:
    """When process ``pid`` started, in clock ticks since boot (field 22 of /proc/PID/stat), or ""."""
    try:
        text = (_PROC / str(pid) / "stat").read_text(encoding="ascii", errors="replace")
    except OSError:
        return ""
    fields = text.rsplit(")", 1)[-1].split()  # after the command's name, which may hold spaces
    return fields[19] if len(fields) > 19 else ""


def mark(folder: Path) -> None:
    """Write the marker into the new staging ``folder``: this process, when it started, on which
    boot and host."""
    pid = os.getpid()
    record = {"pid": pid, "start": _start_time(pid), "boot": _boot_id(), "host": socket.gethostname()}
    (folder / MARKER).write_text(json.dumps(record, sort_keys=True) + "\n", encoding="utf-8")


def unmark(folder: Path) -> None:
    """Remove the marker from the filled staging ``folder`` before it takes its name."""
    (folder / MARKER).unlink(missing_ok=True)


def gone(record: dict) -> bool:
    """Whether the process a marker names is provably gone: it ran on this host, and the machine
    rebooted since, or no process of its number started when it did."""
    pid, start, boot = record.get("pid"), record.get("start"), _boot_id()
    if record.get("host") != socket.gethostname() or not boot or not record.get("boot"):
        return False
    if record["boot"] != boot:
        return True
    if not isinstance(pid, int) or pid <= 0 or not isinstance(start, str) or not start:
        return False
    if not (_PROC / str(pid)).exists():
        return True
    now = _start_time(pid)
    return bool(now) and now != start


def _record(folder: str) -> dict | None:
    """The marker ``folder`` holds when it is a real folder of this user's holding a regular
    marker file; None otherwise (a link, someone else's, unreadable, malformed)."""
    try:
        info = os.lstat(folder)
        if not stat.S_ISDIR(info.st_mode) or info.st_uid != os.getuid():
            return None
        marker = os.path.join(folder, MARKER)
        if not stat.S_ISREG(os.lstat(marker).st_mode):
            return None
        with open(marker, encoding="utf-8") as handle:
            record = json.loads(handle.read(4096))
    except (OSError, ValueError):
        return None
    return record if isinstance(record, dict) else None


def remove_stale(parent: Path) -> list[Path]:
    """Remove the staging folders in ``parent`` that stopped builds left (see the module); the
    paths removed."""
    try:
        names = sorted(entry.name for entry in os.scandir(parent))
    except OSError:
        return []
    removed = []
    for name in names:
        path = os.path.join(parent, name)
        if STAGING_NAME.fullmatch(name) and (record := _record(path)) is not None and gone(record):
            shutil.rmtree(path, ignore_errors=True)
            removed.append(Path(path))
    return removed
