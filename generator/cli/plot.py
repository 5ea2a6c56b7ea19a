"""ocioforge plot: the CIE 1931 chromaticity diagram of a built config's colour spaces."""

from __future__ import annotations

from pathlib import Path

import click

FORMATS = ("png", "svg", "pdf")


@click.command(help="Draw the CIE 1931 xy diagram of CONFIG's colour spaces and displays (from the spec "
                    "stored beside it): the spectral locus and every gamut triangle. With --mapping, the "
                    "verifier's probe colours and where each gamut-mapping method sends them on the first display.")
@click.argument("config", type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False),
              help="Image to write: .png, .svg or .pdf.")
@click.option("--mapping", is_flag=True, help="Add the probe colours and each gamut mapping's result.")
def command(config, output, mapping):
    from generator.cli import fail
    from generator.spec import resolved
    from generator.spec.schema import SpecError
    from generator.verify.figures import chromaticity, png
    from generator.files import write_atomic

    fmt = Path(output).suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        fail(f"{output}:-o: unknown image format {fmt!r}; allowed: {', '.join(FORMATS)}")
    if not Path(config).is_file():
        fail(f"{config}:-: no such config file")
    try:
        spec = resolved.read_beside(config)
    except SpecError as error:
        fail(str(error))
    display = spec.displays[0] if spec.displays and mapping else None
    write_atomic(Path(output), png(chromaticity(spec, display, spaces=True), fmt))
    click.echo(f"wrote {output}")
