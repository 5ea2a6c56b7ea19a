"""ocioforge init: write the embedded default spec."""

from __future__ import annotations

from pathlib import Path

import click


@click.command(help="Write the embedded default spec, commented, to FILE.")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--force", is_flag=True, help="Overwrite an existing FILE.")
def command(file, force):
    from generator.files import write_atomic
    from generator.spec.load import default_text
    from generator.spec.schema import SpecError

    path = Path(file)
    try:
        there = path.is_symlink() or path.exists()
        regular = path.is_file() and not path.is_symlink()
    except OSError as error:
        raise SpecError(str(path), "-", f"cannot write: {error.strerror}") from None
    if there and not regular:
        raise SpecError(str(path), "-", "exists and is not a regular file (a link, device or pipe); allowed: a new "
                        "file's path, or with --force a regular file's")
    if there and not force:
        raise SpecError(str(path), "-", "exists; pass --force to overwrite it")
    write_atomic(path, default_text().encode("utf-8"))
    click.echo(f"{path}: default spec written; edit it, then: ocioforge build {path} -o configs/NAME")
