"""Pack speed: `ocioforge pack` (the default pack, every file of luts/) against `ociobakelut`
baking the same files in a loop, whole wall time.

ociobakelut -- the one PyOpenColorIO's wheel installs beside this Python (its OCIO), else the one on
PATH (Debian's opencolorio-tools, OCIO 2.1) -- reads a config that `ocioforge build` makes
(untimed) for that OCIO, with the pack's sources and displays and their Scale and ACES 2.0 views
as "<view> - <display>" colour spaces: from OCIO 2.4 the ACES 2.0 views are OCIO's builtins, an
analytic config. It is called once per file of the pack, with the file's --format and
--cubesize. Formats it lacks are skipped and counted. ocioforge bakes the same
files as one process, in parallel over the cores, and measures each through OCIO for its
README (ociobakelut measures nothing). Printed, for each of several rounds (each timing both,
in turn first): both wall times and the ratio ours / theirs, and their CPU times (children's
user + system); then the median round's ratio.

Run: .venv/bin/python bench/pack.py [ROUNDS]
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

#: `ocioforge` as a fresh process of this Python (the environment's entry point, without PATH).
OCIOFORGE = "import sys, generator.cli as c; c.main(sys.argv[1:])"

#: ociobakelut's name of each format the pack writes, and the OCIO version that first bakes it. Its
#: short name "clf" is refused ("File format clf does not support baking"); the long one bakes.
THEIR_FORMATS = {
    "resolve_cube": ("resolve_cube", (2, 1)),
    "iridas_cube": ("iridas_cube", (2, 1)),
    "clf": ("Academy/ASC Common LUT Format", (2, 1)),
    "spi3d": ("spi3d", (2, 2)),
}


def their_tool() -> tuple[str, tuple[int, int]]:
    """The ociobakelut to run and its OCIO version: PyOpenColorIO's beside this Python, else PATH's
    (Debian's, OCIO 2.1)."""
    import PyOpenColorIO as ocio

    beside = Path(sys.executable).parent / "ociobakelut"
    if beside.exists():
        major, minor = ocio.__version__.split(".")[:2]
        return str(beside), (int(major), int(minor))
    found = shutil.which("ociobakelut")
    if found is None:
        sys.exit("ociobakelut is not installed")
    return found, (2, 1)


def bench_spec(items, version: tuple[int, int]) -> str:
    """A spec for OCIO ``version`` with the pack's sources and displays, each display offering the
    views the pack bakes for it (Scale for the gamut mapping)."""
    from generator.spec.load import DEFAULT_ROLES

    sources = list(dict.fromkeys(item.req.source.name for item in items))
    roles = [n for n in DEFAULT_ROLES.values() if n not in ("CIE XYZ-D65 - Display-referred",)]
    spaces = list(dict.fromkeys([*sources, "ACES2065-1", *roles]))
    views: dict[str, list[str]] = {}
    for item in items:
        view = item.req.view.name if item.req.view is not None else "Scale"
        views.setdefault(item.req.display.name, [])
        if view not in views[item.req.display.name]:
            views[item.req.display.name].append(view)
    text = f'name = "pack-bench"\nocio_version = "{version[0]}.{version[1]}"\ncolour_spaces = [' + ", ".join(
        f'"{s}"' for s in spaces
    )
    text += "]\n"
    for display, names in views.items():
        text += f'\n[[display]]\nname = "{display}"\nviews = [' + ", ".join(f'"{v}"' for v in names) + "]\n"
    return text


def their_commands(items, config: Path, out: Path, tool: str, version) -> tuple[list[list[str]], int]:
    """An ociobakelut command per file ``tool`` (of OCIO ``version``) can write, and how many it cannot."""
    commands, skipped = [], 0
    for item in items:
        fmt, since = THEIR_FORMATS[item.req.fmt]
        if version < since:
            skipped += 1
            continue
        view = item.req.view.name if item.req.view is not None else "Scale"
        commands.append(
            [
                tool,
                "--iconfig",
                str(config / "config.ocio"),
                "--inputspace",
                item.req.source.name,
                "--outputspace",
                f"{view} - {item.req.display.name}",
                "--format",
                fmt,
                "--cubesize",
                str(item.req.size),
                str(out / item.name),
            ]
        )
    return commands, skipped


def _children_cpu() -> float:
    """User and system CPU seconds of the finished child processes (a pack's workers included)."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


#: Rounds of both timings: the machine's speed drifts by tens of percent within a minute, so
#: each round times both, in turn first, and the median round's ratio is the figure.
ROUNDS = 3


def _timed(commands: list[list[str]]) -> tuple[float, float]:
    """Wall and CPU seconds of running ``commands`` one after another."""
    started, cpu = time.perf_counter(), _children_cpu()
    for command in commands:
        subprocess.run(command, check=True, capture_output=True)
    return time.perf_counter() - started, _children_cpu() - cpu


def _rounds(text: str) -> int:
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"{text!r}; allowed: a whole number of rounds, 1 or more")
    return int(text)


def main(argv=None) -> None:
    from generator.luts import pack
    from generator.spec import load

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rounds", nargs="?", type=_rounds, default=ROUNDS, metavar="ROUNDS")
    rounds = parser.parse_args(argv).rounds
    tool, version = their_tool()
    items = pack.plan(load.load())
    print(f"default pack: {len(items)} files on {os.cpu_count()} cores, each measured for its README")
    ratios = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        (folder / "spec.toml").write_text(bench_spec(items, version), encoding="utf-8")
        ocioforge = [sys.executable, "-c", OCIOFORGE]
        subprocess.run([*ocioforge, "build", str(folder / "spec.toml"), "-o", str(folder / "pack-bench")], check=True)
        for n in range(rounds):
            theirs_out, ours_out = folder / f"theirs{n}", folder / f"ours{n}"
            theirs_out.mkdir()
            commands, skipped = their_commands(items, folder / "pack-bench", theirs_out, tool, version)
            pack_command = [[*ocioforge, "pack", "-o", str(ours_out)]]
            if n % 2:
                (ours, our_cpu), (theirs, their_cpu) = _timed(pack_command), _timed(commands)
            else:
                (theirs, their_cpu), (ours, our_cpu) = _timed(commands), _timed(pack_command)
            ratios.append(ours / theirs)
            print(f"round {n + 1} ({'ours' if n % 2 else 'theirs'} first)")
            print(f"  ocioforge pack       {ours:8.2f} s wall  {our_cpu:8.2f} s CPU")
            print(
                f"  ociobakelut loop     {theirs:8.2f} s wall  {their_cpu:8.2f} s CPU  "
                f"({len(commands)} files; {skipped} in formats it lacks skipped; OCIO {version[0]}.{version[1]}, {tool})"
            )
            print(f"  ratio ours/theirs    {ours / theirs:8.2f} wall  {our_cpu / their_cpu:8.2f} CPU")
    print(
        f"median ratio ours/theirs over {rounds} rounds: {statistics.median(ratios):.2f} wall "
        f"(rounds {', '.join(f'{r:.2f}' for r in ratios)}; target <= 1.0)"
    )
    print(f"load average at the end: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores (others' work slows both)")


if __name__ == "__main__":
    main()
