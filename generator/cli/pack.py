"""ocioforge pack: a show's LUT pack, its spec's [[lut_pack]] tables, baked into a folder."""

from __future__ import annotations

import sys
import time

import click
from rich.console import Console
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

from generator.cli import Command, GivenPath, printable, say
from generator.luts import pack
from generator.spec import load
from generator.spec.schema import SpecError


@click.command(
    cls=Command,
    help="Bake the LUT pack that SPEC's [[lut_pack]] tables declare (default: the embedded spec's, "
    "the repository's luts/) into a folder, with README.md listing each file's measured error.",
)
@click.argument("spec_path", metavar="[SPEC]", required=False, type=GivenPath(dir_okay=False))
@click.option(
    "-o",
    "--output",
    type=GivenPath(),
    default=None,
    help="Folder to write, required; made if missing. Its other files are left alone.",
)
@click.option(
    "--force",
    is_flag=True,
    help="Replace files of the pack's names that an earlier pack did not write.",
)
@click.option("--jobs", type=click.IntRange(1, 256), default=None, help="Worker processes (default: one per core).")
def command(spec_path, output, force, jobs):
    """Bake a spec's LUT pack into a folder (the ``ocioforge pack`` command)."""
    started = time.perf_counter()
    if not output:
        raise SpecError("ocioforge pack", "-o", "give the folder to write")
    if output.startswith("-"):  # `-o --help` had made a folder called --help
        raise SpecError(
            "ocioforge pack",
            "-o",
            f"{printable(output)!r} looks like an option, not a folder; allowed: a folder's path "
            "(./-name for a name starting with '-')",
        )
    spec = load.load(spec_path)
    bar = _Progress()
    try:
        folder = pack.build_pack(output, spec, force, bar.advance, jobs, None if spec_path is None else str(spec_path))
    finally:
        bar.stop()
    say(f"{printable(folder)}: {bar.total} LUTs and README.md ({time.perf_counter() - started:.1f} s)")


class _Progress:
    """A progress bar on standard error when it is a terminal (nothing otherwise), started
    when the pack knows how many files it bakes."""

    def __init__(self):
        self.total, self.bar, self.task = 0, None, None

    def advance(self, done: int, total: int) -> None:
        """Show ``done`` of ``total`` files baked (a bar on a terminal only)."""
        self.total = total
        if self.bar is None and sys.stderr.isatty():
            columns = (TextColumn("baking"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn())
            self.bar = Progress(*columns, console=Console(stderr=True), transient=True)
            self.bar.start()
            self.task = self.bar.add_task("pack", total=total)
        if self.bar is not None:
            self.bar.update(self.task, completed=done)

    def stop(self) -> None:
        """Remove the bar, if one is shown."""
        if self.bar is not None:
            self.bar.stop()
