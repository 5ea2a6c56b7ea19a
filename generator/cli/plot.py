"""ocioforge plot: the CIE 1931 chromaticity diagram of a built config's colour spaces."""

from __future__ import annotations

from pathlib import Path

import click

from generator.cli import NAME, Command, ConfigPath, GivenPath, printable, say
from generator.files import check_file_output, target, write_atomic
from generator.spec.schema import SpecError
from generator.verify.figures import chromaticity, png
from generator.verify.run import load

FORMATS = ("png", "svg", "pdf")


@click.command(
    cls=Command,
    help="Draw the CIE 1931 xy diagram of CONFIG's colour spaces and displays (from the spec "
    "stored beside it): the spectral locus and every gamut triangle. With --mapping, the "
    "verifier's probe colours and where each gamut-mapping method sends them on a display "
    "(--display, by default the first).",
)
@click.argument("config", type=ConfigPath(dir_okay=False))
@click.option("-o", "--output", required=True, type=GivenPath(), help="Image to write: .png, .svg or .pdf.")
@click.option("--mapping", is_flag=True, help="Add the probe colours and each gamut mapping's result.")
@click.option(
    "--display",
    "display_name",
    type=NAME,
    default=None,
    help="With --mapping: the display (name or alias; default: the spec's first).",
)
@click.option("--force", is_flag=True, help="Replace an existing image (through a link, the file it points to).")
def command(config, output, mapping, display_name, force):
    if display_name is not None and not mapping:
        raise SpecError("ocioforge plot", "--display", "chooses the display --mapping draws; allowed: with --mapping")
    check_file_output(output)
    target(output, force)  # refused before the drawing, not after (a folder, a device: named as such)
    fmt = Path(output).suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise SpecError(output, "-o", f"unknown image format {fmt!r}; allowed: {', '.join(FORMATS)}")
    _, spec = load(config)
    display = _display(spec, display_name) if mapping else None
    write_atomic(Path(output), png(chromaticity(spec, display, spaces=True), fmt), force)
    say(f"wrote {printable(output)}")


def _display(spec, name: str | None):
    """The display called ``name`` or one of its aliases (case-insensitive), the first without one."""
    if name is None:
        return spec.displays[0]
    for display in spec.displays:
        if name.lower() in (n.lower() for n in (display.name, *display.aliases)):
            return display
    raise SpecError(
        "ocioforge plot", "--display", f"unknown display {name!r}; allowed: {', '.join(d.name for d in spec.displays)}"
    )
