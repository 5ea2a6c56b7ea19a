"""ocioforge matrix: the 3x3 from one colour space's linear RGB to another's."""

from __future__ import annotations

import json
from dataclasses import dataclass

import click
import numpy as np

from generator import reference
from generator.cli import NAME, Command, GivenPath, say
from generator.colorimetry import library
from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import CATS, Gamut, rgb_to_rgb, settled
from generator.luts.names import slug
from generator.ocio.emit import matrix_transform
from generator.reference import adaptation_between
from generator.spec import load
from generator.spec.load import DEFAULT_ADAPTATION
from generator.spec.namespace import DISPLAY_REFERENCE, DISPLAY_REFERENCE_ALIASES
from generator.spec.schema import ColourSpace, Display, SpecError

FORMATS = ("plain", "json", "nuke", "ocio")


def _ocio_snippet(matrix) -> str:
    """The matrix as an OCIO config line, serialised by OCIO itself."""
    import PyOpenColorIO as ocio

    cfg = ocio.Config()
    cs = ocio.ColorSpace(name="matrix")
    cs.setTransform(matrix_transform(matrix), ocio.COLORSPACE_DIR_TO_REFERENCE)
    cfg.addColorSpace(cs)
    return next(
        line.split("to_scene_reference:")[1].strip()
        for line in cfg.serialize().splitlines()
        if "MatrixTransform" in line
    )


def _node_name(space) -> str:
    """The space's (or display's) first alias usable in a Nuke node name (ASCII letters, digits and
    underscores, not starting with a digit), else its name's slug, an underscore before a digit."""
    name = next((a for a in space.aliases if a.isascii() and a.isidentifier()), slug(space.name))
    return f"_{name}" if name[:1].isdigit() else name


@dataclass(frozen=True)
class Endpoint:
    """SRC or DST: a colour space, a display or the display reference; ``kind`` says which."""

    name: str
    aliases: tuple[str, ...]
    gamut: Gamut
    kind: str
    record: ColourSpace | Display | None = None


def _is_display(name: str) -> bool:
    """Whether ``name`` is a library display's or the display reference's name or alias."""
    names = [n for d in library.DISPLAYS for n in (d.name, *d.aliases)] + [DISPLAY_REFERENCE]
    return name.lower() in {n.lower() for n in (*names, *DISPLAY_REFERENCE_ALIASES)}


def endpoint(spec, name: str, which: str) -> Endpoint:
    """SRC or DST by name or alias: a display of ``spec``, the display reference (CIE XYZ-D65),
    or a colour space (the library's when ``spec`` is None)."""
    if spec is not None:
        display = load.named_display(spec, name)
        if display is not None:
            return Endpoint(display.name, display.aliases, display.gamut, "display", display)
        if name.lower() in {n.lower() for n in (DISPLAY_REFERENCE, *DISPLAY_REFERENCE_ALIASES)}:
            return Endpoint(DISPLAY_REFERENCE, DISPLAY_REFERENCE_ALIASES, gamuts()["CIE XYZ-D65"], "reference")
    space = load.named_space(spec, name, "ocioforge matrix", which)
    if space.gamut is None:
        raise SpecError("ocioforge matrix", which, f"{space.name!r} has no RGB primaries (data or density)")
    return Endpoint(space.name, space.aliases, space.gamut, "space", space)


def to_reference(spec, end: Endpoint) -> np.ndarray:
    """``end``'s linear RGB (a display's: 1.0 = 100 cd/m²) to ``spec``'s scene reference, as its config converts."""
    if end.kind == "display" and isinstance(end.record, Display):
        return np.linalg.inv(reference.scene_to_display_matrix(spec, end.record))
    if end.kind == "reference":
        return np.linalg.inv(reference.scene_to_display_reference(spec))
    return reference.gamut_matrix(spec, end.gamut)


def published_matrix(source, target):
    """``source`` to ``target`` linear RGB as a config of the default spec converts: each to
    ACES2065-1 with the adaptation behind its published matrices, else the default one."""
    aces = gamuts()["AP0"]
    to_aces = [rgb_to_rgb(g, aces, adaptation_between(g, aces, DEFAULT_ADAPTATION)) for g in (source, target)]
    return np.linalg.solve(to_aces[1], to_aces[0])


def render(matrix, fmt: str, label: str) -> str:
    """``matrix`` as text: plain rows, json, a Nuke ColorMatrix node named ``label``, or an OCIO snippet."""
    matrix = settled(matrix)
    rows = [[float(v) for v in row] for row in matrix]
    if fmt == "json":
        return json.dumps({"matrix": rows})
    if fmt == "nuke":
        body = "\n".join("     {" + " ".join(f"{v:.10g}" for v in row) + "}" for row in rows)
        return f"ColorMatrix {{\n matrix {{\n{body}\n   }}\n name {label}\n}}"
    if fmt == "ocio":
        return _ocio_snippet(matrix)
    return "\n".join(" ".join(f"{v: .10f}" for v in row) for row in rows)


@click.command(cls=Command, help="Print the 3x3 matrix taking linear SRC RGB to linear DST RGB (column vectors).")
@click.argument("src", type=NAME)
@click.argument("dst", type=NAME)
@click.option(
    "--cat",
    type=NAME,
    default=None,
    help="Chromatic adaptation: Bradford, CAT02, CAT16, von Kries, XYZ scaling, none (default: the one "
    "behind each camera gamut's published matrices, else Bradford, through ACES2065-1 as a config "
    "with the default spec converts).",
)
@click.option("--format", "fmt", type=click.Choice(FORMATS, case_sensitive=False), default="plain", show_default=True)
@click.option(
    "--spec",
    "spec_path",
    type=GivenPath(),
    default=None,
    help="Take SRC and DST from a spec or a build (its folder or config.ocio), converted as its config "
    "does (default: the library's spaces).",
)
def command(src, dst, cat, fmt, spec_path):
    """Print the matrix between two colour spaces (the ``ocioforge matrix`` command)."""
    if cat is not None:
        chosen = next((c for c in CATS if c.lower() == cat.lower()), None)
        if chosen is None:
            raise SpecError(
                "ocioforge matrix", "--cat", f"unknown chromatic adaptation {cat!r}; allowed: {', '.join(CATS)}"
            )
        cat = chosen

    spec = None if spec_path is None else load.load(spec_path)
    if spec is None and (_is_display(src) or _is_display(dst)):  # the library's displays: the default spec's
        spec = load.load(None, keep=(src, dst))
    ends = [endpoint(spec, name, which) for name, which in ((src, "SRC"), (dst, "DST"))]
    if ends[0].gamut == ends[1].gamut and ends[0].kind == ends[1].kind:  # exactly the identity
        matrix = np.eye(3)
    elif cat:
        matrix = rgb_to_rgb(ends[0].gamut, ends[1].gamut, cat)
    elif spec is not None:
        matrix = np.linalg.solve(to_reference(spec, ends[1]), to_reference(spec, ends[0]))
    else:
        matrix = published_matrix(*(e.gamut for e in ends))
    label = f"{_node_name(ends[0])}_to_{_node_name(ends[1])}"
    say(render(matrix, fmt, label))
