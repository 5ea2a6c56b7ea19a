"""ocioforge plot: the CIE 1931 chromaticity diagram of a built config's displays and the spaces
asked for, where each gamut mapping moves the probe colours on a display, or what each view of
a display does to highlights."""

from __future__ import annotations

from pathlib import Path

import click

from generator.cli import NAME, Command, ConfigPath, GivenPath, printable, say
from generator.files import check_file_output, target, write_atomic
from generator.spec.fields import suggest
from generator.spec.schema import ColourSpace, SpecError
from generator.verify import figures
from generator.verify.run import load

FORMATS = ("png", "svg", "pdf")


@click.command(
    cls=Command,
    help="Draw the CIE 1931 xy diagram of CONFIG's displays (from the spec stored beside it): "
    "the spectral locus and each display's gamut triangle, and those of the colour spaces "
    "--spaces names. With --mapping, one panel per gamut-mapping method (and ACES view) of a "
    "display (--display, by default the first): a line from each of the verifier's probe "
    "colours to where the method puts it. With --highlights, one panel per view of that display: "
    "a grey and six hues ramped up to 16 times scene white.",
)
@click.argument("config", type=ConfigPath(dir_okay=False))
@click.option("-o", "--output", required=True, type=GivenPath(), help="Image to write: .png, .svg or .pdf.")
@click.option(
    "--spaces",
    "space_names",
    type=NAME,
    multiple=True,
    help="Colour spaces whose gamuts to draw too (names or aliases; repeat it or separate them with commas).",
)
@click.option("--mapping", is_flag=True, help="Draw each gamut mapping's moves, a panel per method.")
@click.option("--highlights", is_flag=True, help="Draw exposure ramps to 16 through each view, a panel per view.")
@click.option(
    "--display",
    "display_name",
    type=NAME,
    default=None,
    help="With --mapping or --highlights: the display (name or alias; default: the spec's first).",
)
@click.option("--force", is_flag=True, help="Replace an existing image (through a link, the file it points to).")
def command(config, output, space_names, mapping, highlights, display_name, force):
    """Draw gamuts on the chromaticity diagram (the ``ocioforge plot`` command)."""
    if mapping and highlights:
        raise SpecError("ocioforge plot", "--highlights", "draws another figure than --mapping; allowed: one of them")
    if display_name is not None and not (mapping or highlights):
        raise SpecError(
            "ocioforge plot",
            "--display",
            "chooses the display --mapping or --highlights draws; allowed: with one of them",
        )
    if highlights and space_names:
        raise SpecError("ocioforge plot", "--spaces", "draws gamuts, which --highlights does not; allowed: without it")
    check_file_output(output)
    target(output, force)  # refused before the drawing, not after (a folder, a device: named as such)
    fmt = Path(output).suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise SpecError(output, "-o", f"unknown image format {fmt!r}; allowed: {', '.join(FORMATS)}")
    _, spec = load(config)
    spaces = _spaces(spec, space_names)
    if mapping:
        figure = figures.mapping(spec, _display(spec, display_name), spaces)
    elif highlights:
        display = _display(spec, display_name)
        if not figures.highlight_views(spec, display):
            raise SpecError(
                "ocioforge plot", "--display", f"{display.name!r} offers no view but Raw; allowed: a display with one"
            )
        figure = figures.highlights(spec, display)
    else:
        figure = figures.chromaticity(spec, spaces)
    write_atomic(Path(output), figures.png(figure, fmt), force)
    say(f"wrote {printable(output)}")


def _spaces(spec, given: tuple[str, ...]) -> list:
    """The colour spaces ``given`` names (each value one name or several, comma separated;
    names or aliases, case-insensitive), in order, each once; SpecError for one the config lacks
    or one without a gamut (Raw, ADX)."""
    names = [n.strip() for value in given for n in value.split(",")]
    if any(not n for n in names):
        raise SpecError("ocioforge plot", "--spaces", f"{','.join(given)!r} holds an empty name; allowed: names")
    found: dict[str, ColourSpace] = {}
    for name in names:
        space = next((s for s in spec.colour_spaces if name.lower() in (n.lower() for n in s.all_names)), None)
        if space is None:
            known = [n for s in spec.colour_spaces if s.gamut is not None for n in s.all_names]
            raise SpecError(
                "ocioforge plot",
                "--spaces",
                f"unknown colour space {name!r}{suggest(name, known)}; allowed: a colour space of the config "
                "with a gamut (ocioforge list --spec CONFIG lists them)",
            )
        if space.gamut is None:
            raise SpecError("ocioforge plot", "--spaces", f"{space.name!r} has no gamut to draw; allowed: RGB spaces")
        found.setdefault(space.name, space)
    return list(found.values())


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
