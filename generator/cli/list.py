"""ocioforge list: the library's colour spaces, displays, curves and ACES views, or a spec's own."""

from __future__ import annotations

import sys

import click

from generator.cli import Command, GivenPath, say
from generator.colorimetry import library
from generator.colorimetry.curves import CURVES
from generator.rendering.views import catalogue
from generator.spec.load import load
from generator.spec.schema import SpecError


def _rows(what: str) -> tuple[tuple[str, ...], list[tuple[str, ...]]]:
    """The header and rows of the listing of ``what``."""
    if what == "displays":
        return (
            ("display", "gamut", "EOTF", "peak cd/m²", "aliases"),
            [(d.name, d.gamut, d.eotf, f"{d.peak:g}", ", ".join(d.aliases)) for d in library.DISPLAYS],
        )
    if what == "views":
        return (
            ("ACES view", "ACES", "peak cd/m²", "OCIO builtin"),
            [(v.name, v.version, f"{v.peak:g}", v.style.rsplit(" - ", 1)[-1]) for v in catalogue().values()],
        )
    if what == "curves":
        return ("curve", "family"), [(name, type(curve).__name__) for name, curve in CURVES.items()]
    return (
        ("colour space", "family", "gamut", "curve", "aliases"),
        [(s.name, s.family, s.gamut or "-", s.curve, ", ".join(s.aliases)) for s in library.SPACES],
    )


def _spec_rows(spec, what: str) -> tuple[tuple[str, ...], list[tuple[str, ...]]]:
    """The header and rows of the listing of ``what`` defined by ``spec`` (its colour spaces,
    its displays, or each display's views in menu order)."""
    if what == "displays":
        return (
            ("display", "gamut", "EOTF", "peak cd/m²", "aliases", "views"),
            [
                (d.name, d.gamut.name, d.eotf_name, f"{d.peak:g}", ", ".join(d.aliases), ", ".join(d.views))
                for d in spec.displays
            ],
        )
    if what == "views":
        return ("display", "view"), [(d.name, v) for d in spec.displays for v in d.views]
    return (
        ("colour space", "family", "gamut", "curve", "aliases"),
        [
            (s.name, s.family, s.gamut.name if s.gamut else "-", s.curve_name, ", ".join(s.aliases))
            for s in spec.colour_spaces
        ],
    )


@click.command(
    cls=Command,
    help="List the library's colour spaces (default), displays, curves or ACES views, or with --spec a "
    "spec's own colour spaces, displays or views; piped, one tab-separated line per row.",
)
@click.option("--displays", is_flag=True, help="List displays.")
@click.option("--curves", is_flag=True, help="List transfer functions.")
@click.option("--views", is_flag=True, help="List the ACES views a display's views may name.")
@click.option("--spaces", is_flag=True, help="List colour spaces (the default).")
@click.option(
    "--spec",
    "spec_path",
    type=GivenPath(),
    default=None,
    help="List what a spec or a build (its folder or config.ocio) defines: its colour spaces, its displays "
    "with their views, or (--views) each display's views.",
)
def command(displays, curves, views, spaces, spec_path):
    """List colour spaces, displays, curves or views (the ``ocioforge list`` command)."""
    given = (("spaces", spaces), ("displays", displays), ("curves", curves), ("views", views))
    chosen = [name for name, flag in given if flag]
    if len(chosen) > 1:
        raise SpecError(
            "ocioforge list",
            f"--{chosen[1]}",
            f"given with --{chosen[0]}; allowed: one of --spaces, --displays, --curves, --views",
        )
    if spec_path is None:
        header, rows = _rows(chosen[0] if chosen else "spaces")
    elif chosen and chosen[0] == "curves":
        raise SpecError(
            "ocioforge list",
            "--curves",
            "lists the library's curves, not a spec's; allowed with --spec: --spaces, --displays, --views",
        )
    else:
        header, rows = _spec_rows(load(spec_path), chosen[0] if chosen else "spaces")
    if not sys.stdout.isatty():  # piped (grep, a script): never wrapped
        for row in (header, *rows):
            say("\t".join(row))
        return
    from rich.console import Console
    from rich.table import Table

    table = Table(box=None, pad_edge=False)
    for column in header:
        table.add_column(column)
    for row in rows:
        table.add_row(*row)
    Console(width=200).print(table)
