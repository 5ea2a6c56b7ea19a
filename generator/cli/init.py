"""ocioforge init: write the embedded default spec."""

from __future__ import annotations

import os
from pathlib import Path

import click


@click.command(help="Write the embedded default spec, commented, to FILE.")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--force", is_flag=True, help="Overwrite an existing FILE.")
def command(file, force):
    from generator.spec.load import default_text
    from generator.spec.schema import SpecError

    path = Path(file)
    if path.exists() and not force:
        raise SpecError(str(path), "-", "exists; pass --force to overwrite it")
    temporary = path.with_name(f".{path.name}.tmp")
    temporary.write_text(default_text(), encoding="utf-8")
    os.replace(temporary, path)
    click.echo(f"{path}: default spec written; edit it, then: ocioforge build {path} -o configs/NAME")
