"""Views defined by their lattice (Perceptual) on displays beyond the defaults verify."""

from __future__ import annotations

from generator.verify.run import verify


def test_perceptual_on_hdr_and_extended_range_displays_verifies(tmp_path):
    """Display P3 HDR's file ends in light through the sRGB curve's inverse, PQ's through a
    power: near black a lattice coordinate's float32 rounding times the lattice's slope is a
    large share of the light (it had failed Display P3 HDR from sRGB codes by 0.05 ΔE ITP),
    and hosts' fast powers there are named as such, not failed."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    views = 'views = ["Colorimetric", "Perceptual", "Raw"]\n'
    text = load.default_text().split("[[display]]")[0] + "".join(
        f'[[display]]\nname = "{name}"\n{views}'
        for name in ("sRGB - Display", "Display P3 HDR - Display", "Rec.2100-PQ - Display")
    )
    folder = tmp_path / "hdr"
    build(for_folder(load.parse(text, "hdr.toml", tmp_path), folder), folder)
    result = verify(folder / "config.ocio", ("ocio",), density="quick")
    assert result.passed, [(o.check.title, o.engine, o.worst, o.note) for o in result.failures]
