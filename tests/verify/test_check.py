"""One check's record and how each output kind is judged: metric, tolerance and target by kind,
the samples left out beside a baked curve's jumps, the largest code a display is sent."""

from __future__ import annotations

from generator.verify.check import LUT, VIEW
from tests.verify.conftest import dim_output_table, newly_failing


def test_a_scale_file_dimmed_by_half_a_code_is_named(config_copy):
    """The exact lattices (Scale, Desaturate) are held to the in-gamut target on every set, as
    Perceptual is to its lattice: the sRGB Scale file's output table scaled by 0.9995 (half a
    ten-bit code at white) fails its view and file; under the issue's every-set bound of a
    code, a file scaled by 0.9991 had passed."""

    def dim(path):
        dim_output_table(path.parent / "luts" / "view_srgb_display_scale_17.clf", 0.9995)

    failing = newly_failing(config_copy, dim, (VIEW, LUT))
    assert failing == {"luts/view_srgb_display_scale_17.clf", "sRGB - Display / Scale"}
