"""ocioforge list: the library's colour spaces, displays, curves and ACES views."""

from __future__ import annotations

import sys

import click

from generator.cli import Command, say


def _rows(what: str) -> tuple[tuple[str, ...], list[tuple[str, ...]]]:
    """The header and rows of the listing of ``what``."""
    from generator.colorimetry import library

    if what == "displays":
        return (
            ("display", "gamut", "EOTF", "peak cd/m²", "aliases"),
            [(d.name, d.gamut, d.eotf, f"{d.peak:g}", ", ".join(d.aliases)) for d in library.DISPLAYS],
        )
    if what == "views":
        from generator.rendering.views import catalogue

        return (
            ("ACES view", "ACES", "peak cd/m²", "OCIO builtin"),
            [(v.name, v.version, f"{v.peak:g}", v.style.rsplit(" - ", 1)[-1]) for v in catalogue().values()],
        )
    if what == "curves":
        from generator.colorimetry.curves import CURVES

        return ("curve", "family"), [(name, type(curve).__name__) for name, curve in CURVES.items()]
    return (
        ("colour space", "family", "gamut", "curve", "aliases"),
        [(s.name, s.family, s.gamut or "-", s.curve, ", ".join(s.aliases)) for s in library.SPACES],
    )


@click.command(
    cls=Command,
    help="List the library's colour spaces (default), displays, curves or ACES views; piped, "
    "one tab-separated line per row.",
)
@click.option("--displays", is_flag=True, help="List displays.")
@click.option("--curves", is_flag=True, help="List transfer functions.")
@click.option("--views", is_flag=True, help="List the ACES views a display's views may name.")
@click.option("--spaces", is_flag=True, help="List colour spaces (the default).")
def command(displays, curves, views, spaces):
    from generator.spec.schema import SpecError

    given = (("spaces", spaces), ("displays", displays), ("curves", curves), ("views", views))
    chosen = [name for name, flag in given if flag]
    if len(chosen) > 1:
        raise SpecError(
            "ocioforge list",
            f"--{chosen[1]}",
            f"given with --{chosen[0]}; allowed: one of --spaces, --displays, --curves, --views",
        )
    header, rows = _rows(chosen[0] if chosen else "spaces")
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
