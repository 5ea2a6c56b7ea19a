"""A small show with looks, shared by the looks tests: an inline CDL show look and a per-shot
CDL by ``$SHOT``, in ACEScct, on an OCIO 2.1 config every host engine loads."""

from __future__ import annotations

from pathlib import Path

SPEC = """
name = "looks"
ocio_version = "2.1"
colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]

[environment]
SHOT = "sh010"

[[look]]
name = "Show Look"
process_space = "ACEScct"
slope = [1.1, 1.0, 0.9]
offset = [0.01, 0.0, -0.01]
power = [1.0, 1.05, 1.0]
saturation = 0.9

[[look]]
name = "Shot Grade"
process_space = "ACEScct"
file = "shots/$SHOT.cc"

[[display]]
name = "sRGB - Display"
views = [{ view = "Colorimetric", looks = "+Show Look, +Shot Grade" }, "Raw"]
"""

#: Each shot's grade: slope, offset, power, saturation.
SHOTS = {
    "sh010": ("1.05 1.0 1.0", "0.02 0.0 0.0", "1.0 1.0 1.1", "1.1"),
    "sh020": ("0.95 1.0 1.0", "-0.02 0.0 0.0", "1.0 1.0 1.1", "1.1"),
}


def correction(shot: str) -> str:
    """The .cc file of ``shot``'s grade."""
    slope, offset, power, sat = SHOTS[shot]
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        f'<ColorCorrection id="{shot}" xmlns="urn:ASC:CDL:v1.01">\n'
        f"  <SOPNode><Slope>{slope}</Slope><Offset>{offset}</Offset><Power>{power}</Power></SOPNode>\n"
        f"  <SatNode><Saturation>{sat}</Saturation></SatNode>\n"
        "</ColorCorrection>\n"
    )


def write_show(folder: Path, spec: str = SPEC) -> Path:
    """Write the show's spec and shot files into ``folder``; the spec's path."""
    (folder / "shots").mkdir(parents=True, exist_ok=True)
    for shot in SHOTS:
        (folder / "shots" / f"{shot}.cc").write_text(correction(shot))
    path = folder / "spec.toml"
    path.write_text(spec)
    return path
