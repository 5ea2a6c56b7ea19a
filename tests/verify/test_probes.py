"""The probe colours verify feeds every engine: each family what its name says, in float32,
named sample by sample, and the same on every run."""

from __future__ import annotations

import numpy as np
import pytest

from generator import reference
from generator.verify import probes


def test_probe_families_are_float32_and_named(spec):
    families = probes.scene_families(spec, probes.SIZES["quick"])
    names = [f.name for f in families]
    assert names == [
        "ColorChecker D65",
        "ColorChecker A",
        "monochromatic",
        "camera gamut",
        "display faces",
        "negative",
        "near black",
        "over-range",
        probes.NON_FINITE,
    ]
    for family in families:
        assert np.array_equal(family.values, family.values.astype(np.float32).astype(np.float64), equal_nan=True)
    assert np.nanmax(families[7].values) == 65504.0
    special = families[-1].values
    assert np.isnan(special).any() and np.isposinf(special).any() and np.isneginf(special).any()


def test_display_faces_lie_on_every_displays_faces(spec):
    """Each display's share of the family has one channel at 0 or at the peak (to the float32
    rounding of the reference values) and the others inside."""
    count = 8
    faces = probes.display_faces(spec, count)
    assert len(faces.values) == count * len(spec.displays)
    for k, display in enumerate(spec.displays):
        light = (
            reference.apply_matrix(
                reference.scene_to_display_matrix(spec, display), faces.values[k * count : (k + 1) * count]
            )
            / display.clip_high
        )
        on_face = np.minimum(np.abs(light).min(axis=-1), np.abs(light - 1.0).min(axis=-1))
        assert on_face.max() <= 1e-6 and light.min() >= -1e-6 and light.max() <= 1.0 + 1e-6, display.name


def test_the_tungsten_lit_chart_is_warmer(spec):
    to_xyz = reference.scene_to_display_reference(spec)
    white = [probes.colorchecker(spec, light).values[18] @ to_xyz.T for light in ("D65", "A")]
    x = [w[0] / w.sum() for w in white]
    assert x[1] > x[0]


#: ITU-R BT.2020's primaries are monochromatic light of 630 and 532 nm (and 467 nm); the
#: published xy, rounded to three decimals, sit a hair outside the spectral locus.
ON_PRIMARIES = {"Rec.2020": {"532 nm", "630 nm"}}


def test_monochromatic_light_is_outside_every_display(spec):
    family = probes.monochromatic(spec, 1.0)
    for display in spec.displays:
        rgb = family.values @ (reference.display_matrix(spec, display) @ reference.scene_to_display_reference(spec)).T
        inside = {family.notes[i] for i in np.flatnonzero(rgb.min(axis=1) > 0.0)}
        assert inside <= ON_PRIMARIES.get(display.gamut.name, set()), display.name


def test_a_probe_describes_itself(spec):
    family = probes.monochromatic(spec, 100.0)
    assert probes.Probes((family,)).describe(1).startswith("monochromatic[1] 480 nm (")


def test_a_run_is_repeatable():
    """Every random family has a fixed seed: two makings are equal to the bit."""
    sizes = probes.SIZES["quick"]
    first, second = (probes.code_families(-0.1, 1.2, sizes, (9, 2.0)) for _ in range(2))
    assert [f.name for f in first] == ["ramp", "lattice", "random", "LUT nodes and midpoints"]
    for a, b in zip(first, second):
        np.testing.assert_array_equal(a.values, b.values)
    np.testing.assert_array_equal(probes.negatives(64).values, probes.negatives(64).values)
    np.testing.assert_array_equal(probes.near_black(64).values, probes.near_black(64).values)


def test_code_families_cover_the_code_range_and_a_baked_luts_nodes():
    """Ramps run from end to end of the range (grey and each channel alone), the random codes
    stay inside it, and a baked curve's LUT of 9 nodes with a square shaper has each node's code
    ((k / 8) ** 2 of the range) and the codes between (odd halves)."""
    lo, hi = -0.1, 1.2
    ramp, lattice, random, nodes = probes.code_families(lo, hi, probes.SIZES["quick"], (9, 2.0))
    assert ramp.values.min() == pytest.approx(lo) and ramp.values.max() == pytest.approx(hi)
    for channel in range(3):
        alone = ramp.values[np.all(np.delete(ramp.values, channel, axis=1) == 0.0, axis=1)][:, channel]
        assert alone.max() == pytest.approx(hi)
    for family in (lattice, random):
        assert family.values.min() > lo and family.values.max() < hi
    assert len(np.unique(lattice.values, axis=0)) == probes.SIZES["quick"].lattice ** 3
    u = np.sqrt(np.clip((nodes.values[:, 0] - lo) / (hi - lo), 0.0, None)) * 16.0  # lo is float32-rounded
    np.testing.assert_allclose(u, np.arange(17), atol=1e-4)


def test_near_black_is_noise_of_either_sign_below_the_smallest_half_floats_and_minus_zero():
    """Channels of either sign, none over 1e-5, many below the smallest subnormal half float
    (2**-24), where a table over half floats reads its first entries; and -0 itself."""
    family = probes.near_black(200)
    noise = family.values[:-2]
    assert (noise > 0).any() and (noise < 0).any()
    assert np.abs(noise).max() <= 1e-5 and np.mean(np.abs(noise) < 2.0**-24) > 0.2
    assert np.all(family.values[-2:] == 0.0) and np.signbit(family.values[-2]).all()


def test_a_quarter_of_the_negatives_are_negative_in_every_channel():
    values = probes.negatives(64).values
    assert np.all(values[:16] < 0.0) and np.all(values < 1.0)
    assert np.any(values[16:] > 0.0, axis=1).mean() > 0.5  # the rest mixed


def test_only_the_non_finite_family_is_left_out_of_the_comparison():
    """Each special value in each channel beside mid grey, and in all three: those samples, and
    only those, are not compared, and each is described by its note."""
    special = probes.non_finite()
    ramp = probes.Family("ramp", np.linspace(0.0, 1.0, 9)[:, None].repeat(3, axis=1))
    inputs = probes.Probes((ramp, special, ramp))
    assert inputs.finite.tolist() == [True] * 9 + [False] * 12 + [True] * 9
    assert np.all(np.isfinite(inputs.values[inputs.finite]))
    assert not np.any(np.all(np.isfinite(inputs.values[~inputs.finite]), axis=1))
    assert inputs.describe(10) == "non-finite[1] NaN in channel 1 (0.180000007, nan, 0.180000007)"
    assert inputs.describe(20).startswith("non-finite[11] -Inf in every channel (-inf, -inf, -inf)")


def test_a_described_sample_gives_back_its_float32_exactly():
    values = np.random.default_rng(3).normal(0.0, 10.0, (500, 3)) * 10.0 ** np.random.default_rng(4).uniform(
        -8, 4, (500, 1)
    )
    inputs = probes.Probes((probes.Family("random", values),))
    for index in range(len(values)):
        text = inputs.describe(index).split("(")[1].rstrip(")")
        back = np.array([float(v) for v in text.split(", ")], dtype=np.float32)
        np.testing.assert_array_equal(back, inputs.values[index].astype(np.float32))


def test_the_colorchecker_is_relative_to_its_illuminant(spec):
    """Under D65 the neutral patches sit near D65's white and the white patch reflects about 89%
    (a perfect white would be Y = 1)."""
    xyz = probes.colorchecker(spec, "D65").values @ reference.scene_to_display_reference(spec).T
    assert 0.85 < xyz[18, 1] < 0.92 and xyz[23, 1] < 0.05
    xy = xyz[18:, :2] / xyz[18:].sum(axis=1, keepdims=True)
    np.testing.assert_allclose(xy, np.broadcast_to([0.3127, 0.3290], xy.shape), atol=0.006)


def test_monochromatic_light_has_the_observers_luminance(spec):
    """Unit radiance at 560 nm has Y = ȳ(560 nm) = 0.995 (CIE 1931 2°)."""
    family = probes.monochromatic(spec, 20.0)
    index = family.notes.index("560 nm")
    xyz = family.values[index] @ reference.scene_to_display_reference(spec).T
    assert xyz[1] == pytest.approx(0.995, abs=1e-5)


#: Published chromaticities of the red, green and blue primaries of gamuts whose white is D65.
PRIMARIES = {
    "Rec.709": ((0.64, 0.33), (0.30, 0.60), (0.15, 0.06)),
    "Rec.2020": ((0.708, 0.292), (0.170, 0.797), (0.131, 0.046)),
    "P3-D65": ((0.680, 0.320), (0.265, 0.690), (0.150, 0.060)),
}


@pytest.mark.parametrize("gamut", sorted(PRIMARIES))
def test_the_camera_gamut_family_holds_each_gamuts_primaries(spec, gamut):
    """A D65 gamut's primaries, at 0.18 and 1, taken to CIE XYZ-D65, lie at their published
    chromaticities."""
    family = probes.camera_gamut(spec)
    xyz = family.values @ reference.scene_to_display_reference(spec).T
    for label, xy in zip(("red", "green", "blue"), PRIMARIES[gamut]):
        for level in ("0.18", "1"):
            found = xyz[family.notes.index(f"{gamut} {label} x{level}")]
            np.testing.assert_allclose(found[:2] / found.sum(), xy, atol=2e-5)
