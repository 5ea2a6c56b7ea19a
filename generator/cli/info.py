"""ocioforge info: everything about one library colour space."""

from __future__ import annotations

import click

from generator.cli import NAME, Command


def _lines(space, spec) -> list[str]:
    import numpy as np

    from generator.colorimetry import reference
    from generator.spec.load import newest_ocio_version

    out = [f"name:      {space.name}", f"aliases:   {', '.join(space.aliases)}",
           f"family:    {space.family}", f"encoding:  {space.encoding}"]
    if space.description:
        out.append(f"about:     {space.description}")
    if space.gamut is not None:
        g = space.gamut
        out += [f"gamut:     {g.name}  ({g.citation})",
                "primaries: " + "  ".join(f"{c} ({x:.5f}, {y:.5f})" for c, (x, y) in zip("RGB", g.primaries)),
                f"white:     ({g.white[0]:.5f}, {g.white[1]:.5f})", f"curve:     {space.curve_name}: {space.curve!r}"]
        out.append(f"18% grey:  code {float(space.curve.encode(np.float64(0.18))):.6f}")
        out.append(f"to {spec.scene_reference} ({reference.adaptation_for(spec, g)}"
                   f"{', as its publisher' if g.adaptation else ''}):")
        out += ["  " + " ".join(f"{v: .10f}" for v in row) for row in reference.space_matrix(spec, space)]
    newest = newest_ocio_version()
    for minor in range(1, newest[1] + 1):
        how = _expression(space, (2, minor))
        out.append(f"OCIO 2.{minor}: {how}")
    return out


def _expression(space, version) -> str:
    from generator.colorimetry import transfer
    from generator.ocio.curves import is_baked

    if space.is_data:
        return "data (no transform)"
    if space.special:
        return "analytic (BuiltinTransform)"
    if is_baked(space.curve_name, space.curve, version):
        return "baked 1D LUT"
    if isinstance(space.curve, transfer.Function):
        return "analytic (BuiltinTransform)"
    return f"analytic ({type(space.curve).__name__})"


@click.command(cls=Command, help="Describe a library colour space: gamut, white, curve, matrix, how OCIO expresses it.")
@click.argument("name", type=NAME)
def command(name):
    from generator.spec.load import library_space, load

    space = library_space(name, "ocioforge info", "NAME")
    click.echo("\n".join(_lines(space, load())))
