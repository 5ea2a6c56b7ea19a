"""ocioforge bake: one transform, scene colour space to display, as a LUT file."""

from __future__ import annotations

import time

import click

from generator.cli import NAME, Command, GivenPath, printable, say
from generator.files import check_file_output, target
from generator.luts import bake
from generator.spec import load
from generator.spec.schema import SpecError


@click.command(
    cls=Command, help="Bake the transform from scene colour space SRC (--from) to display DST (--to) into a LUT file."
)
@click.option("--from", "source", type=NAME, required=True, help="Source colour space (name or alias).")
@click.option("--to", "display", type=NAME, required=True, help="Destination display (name or alias).")
@click.option(
    "--gamut-map",
    "method",
    type=NAME,
    default=None,
    help="clip, desaturate, scale, rgc or perceptual (default: scale).",
)
@click.option(
    "--view",
    type=NAME,
    default=None,
    help='An ACES view the display can show (e.g. "ACES 2.0 - SDR 100 nits (Rec.709)"), instead of --gamut-map.',
)
@click.option(
    "--size",
    type=int,
    default=None,
    help="Lattice nodes a side (default: 33, 65 for --view; up to 129, at least the few its shaper needs: "
    "2 to 4 for library spaces).",
)
@click.option(
    "--format",
    "fmt",
    type=NAME,
    default=None,
    help="resolve_cube, iridas_cube, spi3d or clf (default: from the suffix).",
)
@click.option(
    "--shaper",
    type=NAME,
    default="auto",
    show_default=True,
    help="auto, none, or a colour space whose curve spaces the nodes.",
)
@click.option(
    "--spec",
    "spec_path",
    type=GivenPath(),
    default=None,
    help="Spec file, or a build (its folder or config.ocio; default: the embedded spec).",
)
@click.option(
    "-o",
    "--output",
    type=GivenPath(),
    default=None,
    help="File to write, required (a .spi3d's shaper goes beside it as .spi1d).",
)
@click.option("--force", is_flag=True, help="Replace existing files (through a link, the file it points to).")
def command(source, display, method, view, size, fmt, shaper, spec_path, output, force):
    """Bake one LUT file (the ``ocioforge bake`` command)."""
    started = time.perf_counter()
    if view is not None and method is not None:
        raise SpecError(
            bake.WHERE,
            "--view",
            "--view and --gamut-map exclude each other (an ACES view maps its own gamut); allowed: one of them",
        )
    if not output:
        raise SpecError(bake.WHERE, "-o", "give the file to write")
    check_file_output(output)
    target(output, force)  # refused before the bake, not after
    fmt = bake.format_for(fmt, output)
    default_size = bake.DEFAULT_SIZE if view is None else bake.ACES_SIZE
    req = bake.request(
        load.load(spec_path, keep=(source, shaper)),
        source,
        display,
        bake.DEFAULT_METHOD if method is None else method.lower(),
        fmt,
        default_size if size is None else size,
        shaper,
        view,
    )
    files = bake.paths(bake.bake(req), output)
    stale = bake.stale(files, output, fmt)
    bake.write({target(path, force): data for path, data in files.items()}, force, stale)  # every one checked first
    written = ", ".join(printable(path) for path in files)
    order = "; apply the .spi1d, then the .spi3d" if len(files) > 1 else ""
    say(f"{written}: {fmt}, {bake.describe(req)}{order} ({time.perf_counter() - started:.2f} s)")
