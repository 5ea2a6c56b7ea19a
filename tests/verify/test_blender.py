"""Blender as a verify host: which views it can show (none from an inactive space, Raw only from
scene_linear), the OpenColorIO it runs, and its renders judged as every engine's output."""

from __future__ import annotations

import re
from pathlib import Path

from generator.spec import load
from generator.verify import checks, paths
from generator.verify.blender import BlenderEngine
from tests.conftest import require_program


def test_blender_checks_no_view_from_an_inactive_space():
    """Blender offers no inactive space: a view is not checked there from an inactive
    compositing_log role's space (verify had failed such a config with "enum 'ACEScct' not
    found"), and still is in every other engine."""
    spec = load.parse(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        'inactive = ["acescct_ap1"]\n',
        "show.toml",
        Path("."),
    )
    views = [c for c in checks.build_checks(spec, "quick", kinds=(checks.VIEW,)) if c.view != paths.RAW]
    assert {c.src for c in views} == {"ACEScg", "ACEScct", spec.displays[0].name}
    assert {c.src for c in views if BlenderEngine().supports(c, spec)} == {"ACEScg", spec.displays[0].name}


def test_blender_says_which_ocio_it_runs():
    require_program("blender")
    assert re.search(r"^Blender \d.*, OCIO (\d+\.\d+\.\d+|unknown)", BlenderEngine().version())
