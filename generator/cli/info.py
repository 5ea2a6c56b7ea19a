"""ocioforge info: everything about one colour space or display, of the library or of a spec."""

from __future__ import annotations

import click
import numpy as np

from generator import reference
from generator.cli import NAME, Command, GivenPath, say
from generator.colorimetry import transfer
from generator.colorimetry.gamuts import D65, STUDIO_CONFIG_ADAPTATION
from generator.ocio.curves import is_baked
from generator.spec.allowed import newest_ocio_version
from generator.spec.load import load, named_display, named_space
from generator.spec.namespace import DISPLAY_REFERENCE


def _curve(name: str, curve) -> str:
    """A curve by name and parameters; a published formula (no parameters) by its code domain."""
    if isinstance(curve, transfer.Function):
        lo, hi = curve.domain
        return f"{name}: the published formula, codes {lo:g} to {hi:g}"
    return f"{name}: {curve!r}"


def _lines(space, spec, target: tuple[int, int] | None = None) -> list[str]:
    """What ``info`` prints; ``target``, the OCIO version a given spec builds, is marked."""
    out = [
        f"name:      {space.name}",
        f"aliases:   {', '.join(space.aliases) or '-'}",
        f"family:    {space.family}",
        f"encoding:  {space.encoding}",
    ]
    if space.description:
        out.append(f"about:     {space.description}")
    if space.gamut is not None:
        g = space.gamut
        out += [
            f"gamut:     {g.name}  ({g.citation})",
            "primaries: " + "  ".join(f"{c} ({x:.5f}, {y:.5f})" for c, (x, y) in zip("RGB", g.primaries)),
            f"white:     ({g.white[0]:.5f}, {g.white[1]:.5f})",
            f"curve:     {_curve(space.curve_name, space.curve)}",
        ]
        out.append(f"18% grey:  code {float(space.curve.encode(np.float64(0.18))):.6f}")
        out.append(f"to {spec.scene_reference} ({_adaptation(spec, g)}):")
        out += ["  " + " ".join(f"{v: .10f}" for v in row) for row in reference.space_matrix(spec, space)]
    newest = newest_ocio_version()
    for minor in range(1, newest[1] + 1):
        how = _expression(space, (2, minor))
        out.append(f"OCIO 2.{minor}: {how}{'  (the spec builds this version)' if target == (2, minor) else ''}")
    return out


def _display_lines(display, spec) -> list[str]:
    """What ``info`` prints for a display: its gamut, EOTF, peak and views, and its linear RGB
    (1.0 = 100 cd/m²) to the display reference and from the scene reference, as the config converts."""
    g = display.gamut
    same = np.allclose(g.white, D65, rtol=0, atol=1e-12)
    absolute = "  (absolute: code 1 emits the peak)" if display.absolute else ""
    out = [
        f"name:      {display.name}  (a display)",
        f"aliases:   {', '.join(display.aliases) or '-'}",
        f"encoding:  {display.encoding}",
        *([f"about:     {display.description}"] if display.description else []),
        f"gamut:     {g.name}  ({g.citation})",
        "primaries: " + "  ".join(f"{c} ({x:.5f}, {y:.5f})" for c, (x, y) in zip("RGB", g.primaries)),
        f"white:     ({g.white[0]:.5f}, {g.white[1]:.5f})",
        f"eotf:      {_curve(display.eotf_name, display.eotf)}",
        f"peak:      {display.peak:g} cd/m²{absolute}",
        f"views:     {', '.join(display.views)}",
        f"to {DISPLAY_REFERENCE} ({'the same white: no adaptation' if same else spec.chromatic_adaptation}):",
    ]
    out += [
        "  " + " ".join(f"{v: .10f}" for v in row) for row in np.linalg.inv(reference.display_matrix(spec, display))
    ]
    out.append(f"from {spec.scene_reference} (display-linear, 1.0 = 100 cd/m²):")
    out += ["  " + " ".join(f"{v: .10f}" for v in row) for row in reference.scene_to_display_matrix(spec, display)]
    return out


def _adaptation(spec, gamut) -> str:
    """How ``gamut`` adapts to the spec's scene reference, and on whose authority."""
    if np.allclose(gamut.white, spec.reference.gamut.white, rtol=0, atol=1e-12):
        return "the same white: no adaptation"
    cat = reference.adaptation_for(spec, gamut)
    if not gamut.adaptation:
        return cat
    return f"{cat}, as the ACES studio config" if gamut.name in STUDIO_CONFIG_ADAPTATION else f"{cat}, as its publisher"


def _expression(space, version) -> str:
    if space.is_data:
        return "data (no transform)"
    if space.special:
        return "analytic (BuiltinTransform)"
    if is_baked(space.curve_name, space.curve, version):
        return "baked 1D LUT"
    if isinstance(space.curve, transfer.Function):
        return "analytic (BuiltinTransform)"
    return f"analytic ({type(space.curve).__name__})"


@click.command(
    cls=Command,
    help="Describe a colour space (gamut, white, curve, matrix, how OCIO expresses it) or a display "
    "(gamut, white, EOTF, peak, views, matrices).",
)
@click.argument("name", type=NAME)
@click.option(
    "--spec",
    "spec_path",
    type=GivenPath(),
    default=None,
    help="Take NAME from a spec or a build (its folder or config.ocio), with its scene reference and "
    "adaptation (default: the library's spaces, the default spec's displays).",
)
def command(name, spec_path):
    """Describe a colour space or display (the ``ocioforge info`` command)."""
    spec = load(spec_path)
    display = named_display(spec, name)
    if display is not None:
        say("\n".join(_display_lines(display, spec)))
        return
    space = named_space(None if spec_path is None else spec, name, "ocioforge info", "NAME")
    say("\n".join(_lines(space, spec, None if spec_path is None else spec.ocio_version)))
