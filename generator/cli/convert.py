"""ocioforge convert: image sequences through a config, in parallel or on a Dask cluster, verified."""

from __future__ import annotations

import os
import sys
import time

import click

from generator.cli import NAME, Command, ConfigPath, GivenPath, printable, say
from generator.spec.schema import SpecError

FORMAT_NAMES = ("exr", "tiff", "png", "jpeg", "dpx")


@click.command(
    cls=Command,
    help="Convert INPUTS (files, folders of images, frame patterns such as shot.####.exr or shot.%04d.exr) "
    "through a config into the folder -o. Exit status 1 if any frame failed or departs from the "
    "reference (--verify), 2 for bad arguments.",
)
@click.argument("inputs", nargs=-1, required=True, type=GivenPath())
@click.option("-o", "--output", type=GivenPath(file_okay=False), required=True, help="Folder to write the frames in.")
@click.option(
    "--config",
    type=ConfigPath(dir_okay=False),
    help="Config file or a build's folder (default: $OCIO, else the default spec's config, built once).",
)
@click.option(
    "--from", "src", type=NAME, help="Colour space read (default: each file's metadata, else the config's file rules)."
)
@click.option("--to", "dst", type=NAME, help="Colour space written.")
@click.option("--display", type=NAME, help="Display written, through --view (instead of --to).")
@click.option("--view", type=NAME, help="View of --display (default: the display's first).")
@click.option(
    "--frames", type=NAME, help="Frames of the patterns: 1001-1100, 1-99x2, 1001,1005 (default: those on disk)."
)
@click.option(
    "--format",
    "fmt",
    type=click.Choice(FORMAT_NAMES, case_sensitive=False),
    help="Output format (default: the first input's, else exr).",
)
@click.option(
    "--depth",
    type=click.Choice(("half", "float", "uint8", "uint10", "uint16"), case_sensitive=False),
    help="Sample type written (default: the input's where the format holds it, else the format's).",
)
@click.option("--compression", type=NAME, help="EXR or TIFF compression (default: the input's, else zip).")
@click.option(
    "--verify",
    is_flag=True,
    help="Read every written frame back and compare it with the reference "
    "evaluation of the spec that built the config.",
)
@click.option(
    "--sample",
    type=NAME,
    default="65536",
    show_default=True,
    help="Pixels per frame --verify compares (evenly spaced whole rows), or 'all'.",
)
@click.option("--jobs", type=click.IntRange(min=1), default=None, help="Frames at once (default: the core count).")
@click.option("--scheduler", type=NAME, help="Run the frames on this Dask scheduler (tcp://host:8786).")
@click.option("--skip-existing", is_flag=True, help="Leave frames whose output exists (to resume a run).")
@click.option("--force", is_flag=True, help="Replace existing outputs (through a link, the file it points to).")
@click.option("--fail-fast", is_flag=True, help="Stop at the first frame that fails.")
@click.option(
    "--memory",
    type=click.IntRange(min=1),
    default=256,
    show_default=True,
    help="MiB of pixels a frame is converted in at once (larger frames go in bands of rows).",
)
def command(
    inputs,
    output,
    config,
    src,
    dst,
    display,
    view,
    frames,
    fmt,
    depth,
    compression,
    verify,
    sample,
    jobs,
    scheduler,
    skip_existing,
    force,
    fail_fast,
    memory,
):
    """Convert image sequences through a config (the ``ocioforge convert`` command)."""
    started = time.perf_counter()
    # Here, not at the top: `convert --help` starts without OpenColorIO, colour-science or Dask.
    from generator.convert import run as runner
    from generator.convert.plan import plan_run

    plan, sources = plan_run(
        inputs,
        output,
        config,
        src,
        dst,
        display,
        view,
        frames,
        fmt,
        depth,
        compression,
        verify,
        sample,
        skip_existing,
        force,
        memory << 20,
        announce=lambda text: click.echo(text, err=True),
    )
    made = not os.path.isdir(output)
    os.makedirs(output, exist_ok=True)
    with _progress(len(sources)) as advance:

        def report(result):
            advance()
            line = _line(result)
            if line:
                say(line)

        try:
            results = runner.run(plan, sources, report, jobs or os.cpu_count() or 1, scheduler or "", fail_fast)
        except runner.SchedulerError as error:
            if made:  # the folder this run made, still empty
                os.rmdir(output)
            raise SpecError("--scheduler", scheduler, str(error)) from None
    say(_summary(results, len(sources), time.perf_counter() - started, verify))
    if not all(r.ok for r in results) or len(results) < len(sources):
        sys.exit(1)


def _line(result) -> str:
    """A frame worth a line: failed (its reason) or departing from the reference (its worst pixel)."""
    if result.status == "failed":
        return f"FAILED {printable(result.source)}: {printable(result.reason)}"
    if result.verdict is not None and not result.verdict.passed:
        return f"DEPARTS {printable(result.output)} (read as {result.src}): {printable(result.verdict.describe())}"
    return ""


def _summary(results, total: int, seconds: float, verify: bool) -> str:
    counts = {s: sum(r.status == s for r in results) for s in ("written", "skipped", "failed")}
    done = counts["written"] + counts["skipped"]
    text = (
        f"{counts['written']} written, {counts['skipped']} skipped, {counts['failed']} failed"
        f"{'' if len(results) == total else f', {total - len(results)} not run'} of {total} frames "
        f"({seconds:.2f} s, {done / seconds if seconds else 0:.2f} frames/s)"
    )
    if verify:
        judged = [r.verdict for r in results if r.verdict is not None]
        departing = sum(not v.passed for v in judged)
        worst = max(judged, key=lambda v: v.worst / v.tolerance if v.compared else float("inf"), default=None)
        text += f"; verified {len(judged)}: {departing} depart" + (f", worst {worst.describe()}" if worst else "")
    return text


class _progress:
    """A progress bar on stderr (frames done of all, rate, time left) where stderr is a terminal,
    redrawn as each frame ends."""

    def __init__(self, total: int):
        self.total = total
        self.bar = None

    def __enter__(self):
        from rich.console import Console

        console = Console(stderr=True)
        if not console.is_terminal:
            return lambda: None
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            Progress,
            ProgressColumn,
            TextColumn,
            TimeRemainingColumn,
        )
        from rich.text import Text

        class Rate(ProgressColumn):
            def render(self, task):
                return Text(f"{task.speed:.2f} frames/s" if task.speed else "- frames/s")

        self.bar = Progress(
            TextColumn("convert"),
            BarColumn(),
            MofNCompleteColumn(),
            TextColumn("frames"),
            Rate(),
            TimeRemainingColumn(),
            console=console,
            transient=True,
            auto_refresh=False,
        )
        task = self.bar.add_task("convert", total=self.total)
        self.bar.start()

        def advance():
            self.bar.advance(task)
            self.bar.refresh()

        return advance

    def __exit__(self, *exc):
        if self.bar is not None:
            self.bar.stop()
        return False
