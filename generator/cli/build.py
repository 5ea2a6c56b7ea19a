"""ocioforge build: spec -> config folder."""

from __future__ import annotations

import time
from pathlib import Path

import click

from generator.cli import NAME, Command, GivenPath, printable, say
from generator.ocio.host_versions import not_loading
from generator.ocio.write import build, for_folder, target
from generator.spec import labels, load


def counted(number: int, noun: str) -> str:
    """``number`` and ``noun``, plural unless one ("1 display", "3 displays")."""
    return f"{number} {noun}{'' if number == 1 else 's'}"


@click.command(cls=Command, help="Build an OCIO config from SPEC (default: the embedded spec) into a folder.")
@click.argument("spec", required=False, type=GivenPath(dir_okay=False))
@click.option("-o", "--output", type=GivenPath(file_okay=False), help="Folder to write (default: configs/<name>).")
@click.option("--ocio-version", type=NAME, help="Config version to write, e.g. 2.1 (overrides the spec).")
@click.option("--force", is_flag=True, help="Replace the output folder if it holds a previous build.")
def command(spec, output, ocio_version, force):
    """Build a config from a spec (the ``ocioforge build`` command)."""
    started = time.perf_counter()
    parsed = load.load(spec)
    version = load.parse_version(ocio_version, "--ocio-version") if ocio_version else None
    out_dir = Path(output) if output else Path("configs") / labels.folder_name(parsed.name, parsed.source)
    result = build(for_folder(parsed, target(out_dir), version), out_dir, force=force)
    say(
        f"{printable(result.path / 'config.ocio')}: OCIO {'.'.join(map(str, version or parsed.ocio_version))}, "
        f"{counted(result.colour_spaces, 'colour space')}, {counted(result.displays, 'display')}, "
        f"{counted(result.views, 'view')}, {counted(result.files, 'file')} ({time.perf_counter() - started:.2f} s)"
    )
    refusing = not_loading(version or parsed.ocio_version)
    if refusing:  # said, not refused: the spec asked for this version
        written = ".".join(map(str, version or parsed.ocio_version))
        click.echo(
            f"note: an OCIO {written} config does not load in {refusing}; --ocio-version 2.1 writes one they load",
            err=True,
        )
