"""ocioforge verify: a built config through real OCIO engines against the spec's own evaluation."""

from __future__ import annotations

import errno
import os
import sys
import tempfile
from pathlib import Path

import click

from generator.cli import NAME, Command, ConfigPath, GivenPath, fail, printable, say
from generator.files import CannotWrite, target
from generator.verify import report
from generator.verify.figures import report_figures
from generator.verify.report import report_paths
from generator.verify.run import verify

ENGINES = "ocio,oiiotool,ocioconvert,blender"


@click.command(
    cls=Command,
    help="Verify CONFIG (a build's folder, or its config.ocio): probe images through OCIO engines against the "
    "float64 evaluation of the spec stored beside it. Exit status 1 if any check fails, or if an "
    "engine --engines names cannot run.",
)
@click.argument("config", type=ConfigPath(dir_okay=False))
@click.option(
    "--engines",
    type=NAME,
    default=ENGINES,
    show_default=True,
    help="Comma-separated: ocio (PyOpenColorIO, default and lossless flags), oiiotool, ocioconvert, blender, "
    "gpu (OCIO's GLSL shaders drawn on an OpenGL device, as hosts' viewers draw; named only). Of the "
    "default list, those not installed are reported as not run; named, they must run.",
)
@click.option(
    "--report",
    "report_dir",
    type=GivenPath(file_okay=False),
    help="Folder to write report.html (self-contained) and summary.json into.",
)
@click.option("--force", is_flag=True, help="Replace the report's files in --report's folder.")
@click.option("--quick", is_flag=True, help="Small probe sets: every check, far fewer samples.")
@click.option(
    "--only",
    type=NAME,
    default=None,
    help="Run only the checks whose title contains this text (e.g. HLG); an error if none does.",
)
@click.option(
    "--summary",
    "summary_only",
    is_flag=True,
    help="Print the summary alone: not every row, nor each departure OCIO's default flags explain "
    "(--report's files name them).",
)
@click.option(
    "--context",
    "context",
    multiple=True,
    metavar="NAME=VALUE",
    help="A context variable's value (repeatable), e.g. SHOT=sh010: the looks read that shot's files. "
    "Default: the config's environment defaults.",
)
@click.pass_context
def command(ctx, config, engines, report_dir, force, quick, only, summary_only, context):
    """Verify a config against the reference (the ``ocioforge verify`` command)."""
    if report_dir:
        _check_report_folder(Path(report_dir), force)
    names = tuple(dict.fromkeys(e.strip().lower() for e in engines.split(",") if e.strip()))  # each engine once
    if not names:
        fail(f"--engines names none; allowed: a comma-separated list of {ENGINES},gpu")
    named = ctx.get_parameter_source("engines") is not click.core.ParameterSource.DEFAULT
    result = verify(config, names, density="quick" if quick else "full", only=only or "", strict=named, context=context)
    written = []
    if report_dir:  # first: a verdict printed to a full device is lost, the report's is not
        written = report.write_report(result, report_dir, report_figures(result), force)
    if not summary_only:
        say(report.table(result))
    say(report.summary(result, explained=not summary_only))  # the report names each explained row
    for path in written:
        say(f"wrote {printable(path)}")
    if not result.passed:
        sys.exit(1)


def _check_report_folder(folder: Path, force: bool) -> None:
    """The report's folder can be written, checked before the run (it used to fail after it):
    a folder or a new path whose nearest existing parent is a writable folder, its report files
    absent or (with ``force``) regular files."""
    existing = next(p for p in (folder, *folder.parents) if p.exists())
    for code, broken in (
        (errno.ENOTDIR, not existing.is_dir()),
        (errno.EACCES, not os.access(existing, os.W_OK | os.X_OK)),
    ):
        if broken:
            raise CannotWrite(folder, OSError(code, os.strerror(code)))
    if existing != folder:  # a folder to make: try there (os.access passes root everywhere, /proc too)
        try:
            os.rmdir(tempfile.mkdtemp(prefix=".ocioforge-check.", dir=existing))
        except OSError as error:
            raise CannotWrite(folder, error) from None
    for path in report_paths(folder):
        target(path, force)
