"""ocioforge matrix: the 3x3 from one colour space's linear RGB to another's."""

from __future__ import annotations

import json

import click
import numpy as np

from generator.cli import NAME, Command, GivenPath, say

FORMATS = ("plain", "json", "nuke", "ocio")


def _ocio_snippet(matrix) -> str:
    """The matrix as an OCIO config line, serialised by OCIO itself."""
    import PyOpenColorIO as ocio

    from generator.ocio.emit import matrix_transform

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
    """The space's first alias usable as a node name (letters, digits, underscores)."""
    from generator.luts.names import slug

    return next((a for a in space.aliases if a.replace("_", "").isalnum()), slug(space.name))


def published_matrix(source, target):
    """``source`` to ``target`` linear RGB as a config of the default spec converts: each to
    ACES2065-1 with the adaptation behind its published matrices, else the default one."""
    from generator.colorimetry.gamuts import gamuts
    from generator.colorimetry.matrices import rgb_to_rgb
    from generator.reference import adaptation_between
    from generator.spec.load import DEFAULT_ADAPTATION

    aces = gamuts()["AP0"]
    to_aces = [rgb_to_rgb(g, aces, adaptation_between(g, aces, DEFAULT_ADAPTATION)) for g in (source, target)]
    return np.linalg.solve(to_aces[1], to_aces[0])


def render(matrix, fmt: str, label: str) -> str:
    from generator.colorimetry.matrices import settled

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
    from generator.colorimetry.matrices import CATS, rgb_to_rgb
    from generator.spec.schema import SpecError

    if cat is not None:
        chosen = next((c for c in CATS if c.lower() == cat.lower()), None)
        if chosen is None:
            raise SpecError(
                "ocioforge matrix", "--cat", f"unknown chromatic adaptation {cat!r}; allowed: {', '.join(CATS)}"
            )
        cat = chosen
    from generator.spec import load

    spec = None if spec_path is None else load.load(spec_path)
    spaces = [load.named_space(spec, name, "ocioforge matrix", which) for name, which in ((src, "SRC"), (dst, "DST"))]
    for space, which in zip(spaces, ("SRC", "DST")):
        if space.gamut is None:
            raise SpecError("ocioforge matrix", which, f"{space.name!r} has no RGB primaries (data or density)")
    if spaces[0].gamut == spaces[1].gamut:  # one gamut: exactly the identity, not a product with its inverse
        matrix = np.eye(3)
    elif cat:
        matrix = rgb_to_rgb(spaces[0].gamut, spaces[1].gamut, cat)
    elif spec is not None:
        from generator.reference import space_matrix

        matrix = np.linalg.solve(space_matrix(spec, spaces[1]), space_matrix(spec, spaces[0]))
    else:
        matrix = published_matrix(*(s.gamut for s in spaces))
    label = f"{_node_name(spaces[0])}_to_{_node_name(spaces[1])}"
    say(render(matrix, fmt, label))
