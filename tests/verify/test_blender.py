"""Blender as a verify host: which views it can show (none from an inactive space, Raw only from
scene_linear), the OpenColorIO it runs, and its renders judged as every engine's output."""

from __future__ import annotations

import json
import re
from pathlib import Path

from generator.spec import load
from generator.verify import checks, paths
from generator.verify.blender import BlenderEngine
from generator.verify.judge import FAIL, PASS, judge
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


def test_blenders_renders_pass_their_views_checks(blender_run):
    asked, outputs, _ = blender_run
    outcomes = {(c.src, c.display, c.view): judge(c, "blender", out[0]) for c, out in zip(asked, outputs)}
    for key in (
        ("ACEScg", "sRGB - Display", "Colorimetric"),
        ("ACEScct", "Rec.1886 Rec.709 - Display", "Colorimetric"),
    ):
        assert outcomes[key].verdict == PASS and outcomes[key].engine == "blender (PNG uint16)", outcomes[key].worst


def test_blenders_raw_view_shows_scene_linear_so_raw_is_checked_from_scene_linear_alone(spec, blender_run):
    """Blender converts an image to scene_linear (ACEScg) when it loads it: Raw from ACEScg shows
    the file's values, Raw from ACEScct does not (which is why it is not asked for)."""
    asked, outputs, _ = blender_run
    raw = {c.src: (c, judge(c, "blender", out[0]).verdict) for c, out in zip(asked, outputs) if c.view == paths.RAW}
    assert {src: verdict for src, (_, verdict) in raw.items()} == {"ACEScg": PASS, "ACEScct": FAIL}
    assert {src: BlenderEngine().supports(check, spec) for src, (check, _) in raw.items()} == {
        "ACEScg": True,
        "ACEScct": False,
    }


def test_a_view_blender_lacks_fails_with_blenders_words(blender_run):
    asked, outputs, _ = blender_run
    lost = next(judge(c, "blender", out[0]) for c, out in zip(asked, outputs) if c.view == "No Such View")
    assert lost.verdict == FAIL and 'enum "No Such View" not found' in lost.note


def test_one_probe_image_is_written_per_source_space(blender_run):
    asked, _, workdir = blender_run
    jobs = json.loads((workdir / "blender-jobs.json").read_text(encoding="utf-8"))["jobs"]
    by_source = {job["src"]: job["input"] for job in jobs}
    assert [job["input"] for job in jobs] == [by_source[c.src] for c in asked]
    assert len(set(by_source.values())) == 2
