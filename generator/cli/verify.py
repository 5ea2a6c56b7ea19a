"""ocioforge verify: a built config through real OCIO engines against the spec's own evaluation."""

from __future__ import annotations

import sys
from pathlib import Path

import click

ENGINES = "ocio,oiiotool,ocioconvert,blender"


@click.command(help="Verify CONFIG (a built config.ocio): probe images through OCIO engines against the "
                    "float64 evaluation of the spec stored beside it. Exit status 1 if any check fails.")
@click.argument("config", type=click.Path(dir_okay=False))
@click.option("--engines", default=ENGINES, show_default=True,
              help="Comma-separated: ocio (PyOpenColorIO, default and lossless flags), oiiotool, ocioconvert, blender.")
@click.option("--report", "report_dir", type=click.Path(file_okay=False),
              help="Folder to write report.html (self-contained) and summary.json into.")
@click.option("--quick", is_flag=True, help="Small probe sets: every check, far fewer samples.")
@click.option("--only", default="", help="Run only the checks whose title contains this text (e.g. HLG); an error if none does.")
@click.option("--summary", "summary_only", is_flag=True, help="Print the summary, not every row.")
def command(config, engines, report_dir, quick, only, summary_only):
    from generator.cli import fail
    from generator.spec.schema import SpecError
    from generator.verify import report
    from generator.verify.run import verify

    if report_dir:
        _check_report_folder(Path(report_dir), fail)
    names = tuple(dict.fromkeys(e.strip() for e in engines.split(",") if e.strip()))  # each engine once
    if not names:
        fail(f"--engines names none; allowed: a comma-separated list of {ENGINES}")
    try:
        result = verify(config, names, density="quick" if quick else "full", only=only)
    except SpecError as error:
        fail(str(error))
    if not summary_only:
        click.echo(report.table(result))
    click.echo(report.summary(result))
    if report_dir:
        from generator.verify.figures import report_figures

        for path in report.write_report(result, report_dir, report_figures(result)):
            click.echo(f"wrote {path}")
    if not result.passed:
        sys.exit(1)


def _check_report_folder(folder: Path, fail) -> None:
    """The report's folder can be written, checked before the run (it used to fail after it):
    a folder or a new path whose nearest existing parent is a writable folder."""
    import errno
    import os

    existing = next(p for p in (folder, *folder.parents) if p.exists())
    if not existing.is_dir():
        fail(f"{folder}: cannot write: {os.strerror(errno.ENOTDIR)}")
    if not os.access(existing, os.W_OK | os.X_OK):
        fail(f"{folder}: cannot write: {os.strerror(errno.EACCES)}")
