"""ocioforge list: the library's colour spaces, displays and curves."""

from __future__ import annotations

import click


@click.command(help="List the library's colour spaces (default), displays or curves.")
@click.option("--displays", "what", flag_value="displays", help="List displays.")
@click.option("--curves", "what", flag_value="curves", help="List transfer functions.")
@click.option("--spaces", "what", flag_value="spaces", default=True, help="List colour spaces.")
def command(what):
    from rich.console import Console
    from rich.table import Table

    from generator.colorimetry import library

    table = Table(box=None, pad_edge=False)
    if what == "displays":
        for column in ("display", "gamut", "EOTF", "peak cd/m²", "aliases"):
            table.add_column(column)
        for d in library.DISPLAYS:
            table.add_row(d.name, d.gamut, d.eotf, f"{d.peak:g}", ", ".join(d.aliases))
    elif what == "curves":
        from generator.colorimetry.curves import CURVES

        table.add_column("curve")
        table.add_column("family")
        for name, curve in CURVES.items():
            table.add_row(name, type(curve).__name__)
    else:
        for column in ("colour space", "family", "gamut", "curve", "aliases"):
            table.add_column(column)
        for s in library.SPACES:
            table.add_row(s.name, s.family, s.gamut or "-", s.curve, ", ".join(s.aliases))
    Console(width=200).print(table)
