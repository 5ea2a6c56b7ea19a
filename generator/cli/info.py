"""ocioforge info: everything about one library colour space."""

from __future__ import annotations

import click


def _lines(space, spec) -> list[str]:
    import numpy as np

    from generator.colorimetry import reference
    from generator.ocio.capabilities import curve_chain
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
        out.append(f"to {spec.scene_reference} ({spec.chromatic_adaptation}):")
        out += ["  " + " ".join(f"{v: .10f}" for v in row) for row in reference.space_matrix(spec, space)]
    newest = newest_ocio_version()
    for minor in range(1, newest[1] + 1):
        how = _expression(space, (2, minor), curve_chain)
        out.append(f"OCIO 2.{minor}: {how}")
    return out


def _expression(space, version, curve_chain) -> str:
    from generator.colorimetry import transfer

    if space.is_data:
        return "data (no transform)"
    if space.special:
        return "BuiltinTransform"
    curve = space.curve
    if isinstance(curve, (transfer.Linear, transfer.Power, transfer.PiecewisePower, transfer.LogCamera)):
        return f"analytic ({type(curve).__name__})"
    if isinstance(curve, transfer.Function) and curve_chain(space.curve_name, version):
        return "analytic (BuiltinTransform)"
    return "baked 1D LUT"


@click.command(help="Describe a library colour space: gamut, white, curve, matrix, how OCIO expresses it.")
@click.argument("name")
def command(name):
    from generator.spec.load import library_space, load

    space = library_space(name, "ocioforge info", "NAME")
    click.echo("\n".join(_lines(space, load())))
