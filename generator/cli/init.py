"""ocioforge init: write the embedded default spec."""

from __future__ import annotations

import click

from generator.cli import Command, GivenPath, printable, say
from generator.files import check_file_output, write_atomic
from generator.spec.load import default_text


@click.command(cls=Command, help="Write the embedded default spec, commented, to FILE.")
@click.argument("file", type=GivenPath())
@click.option("--force", is_flag=True, help="Overwrite an existing FILE (through a link, the file it points to).")
def command(file, force):
    """Write the default spec (the ``ocioforge init`` command)."""
    check_file_output(file)
    write_atomic(file, default_text().encode("utf-8"), force)
    say(f"{printable(file)}: default spec written; edit it, then: ocioforge build {printable(file)} -o configs/NAME")
