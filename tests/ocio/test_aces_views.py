"""ACES views in a built config: each OCIO version's emission, verified against the reference."""

import subprocess
import sys

import PyOpenColorIO as ocio
import pytest

from generator.verify.run import verify

SPEC = """
name = "aces-views"
colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "Raw", "sRGB Encoded Rec.709 (sRGB)"]
[[display]]
name = "sRGB - Display"
views = ["ACES 2.0", "Un-tone-mapped", "Raw"]
[[display]]
name = "Rec.2100-PQ - Display"
views = ["ACES 2.0 - HDR 1000 nits (P3 D65)", "Raw"]
[[display]]
name = "LED Wall"
primaries = [[0.70, 0.29], [0.17, 0.75], [0.135, 0.045]]
white = "D65"
eotf = "ST 2084"
peak_luminance = 1500
views = ["ACES 2.0", "Raw"]
"""


@pytest.fixture(scope="module", params=["2.1", "2.6"])
def aces_build(request, tmp_path_factory):
    folder = tmp_path_factory.mktemp("aces") / f"aces-{request.param}"
    spec = folder.parent / "aces.toml"
    spec.write_text(SPEC)
    subprocess.run(
        [sys.executable, "-m", "generator", "build", str(spec), "-o", str(folder), "--ocio-version", request.param],
        check=True,
        capture_output=True,
    )
    return request.param, folder


def test_each_version_runs_aces_2_as_it_can(aces_build):
    """2.6: the studio preset as OCIO's builtin, the LED wall's own as the fixed function with
    its parameters; 2.1: one baked file per view."""
    version, folder = aces_build
    cfg = ocio.Config.CreateFromFile(str(folder / "config.ocio"))
    wall = cfg.getViewTransform("ACES 2.0 - HDR 1500 nits (LED Wall)").getTransform(
        ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE
    )
    files = sorted(p.name for p in (folder / "luts").glob("*.ctf")) if (folder / "luts").exists() else []
    if version == "2.6":
        assert files == []
        assert any(isinstance(t, ocio.FixedFunctionTransform) and next(iter(t.getParams())) == 1500.0 for t in wall)
    else:
        assert files == [
            "aces_2_0_hdr_1000_nits_p3_d65_81.ctf",
            "aces_2_0_hdr_1500_nits_led_wall_93.ctf",
            "aces_2_0_sdr_100_nits_rec_709_117.ctf",
        ]
    assert next(iter(cfg.getViews("sRGB - Display"))) == "ACES 2.0 - SDR 100 nits (Rec.709)"


def test_verify_holds_every_aces_view_to_the_reference(aces_build):
    _, folder = aces_build
    result = verify(folder / "config.ocio", engines=("ocio",), density="quick", only="ACES")
    assert result.compared and result.passed, [str(f) for f in result.failures][:5]
