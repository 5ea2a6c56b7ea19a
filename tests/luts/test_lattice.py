"""Sampling the reference on a lattice: shapers, preimages, node values (generator/luts/lattice.py)."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.luts import lattice
from generator.luts.axes import LogAxis

RNG_SEED = 7


def _display(spec, name):
    return next(d for d in spec.displays if d.name == name)


def _through_ocio(transforms, values) -> np.ndarray:
    pixels = np.ascontiguousarray(values, dtype=np.float32).reshape(-1, 3)
    processor = ocio.Config.CreateRaw().getProcessor(ocio.GroupTransform(transforms))
    processor.getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS).applyRGB(pixels)
    return pixels.astype(np.float64)


def test_coordinates_interpolate_the_shaper_table_uniform_over_the_domain():
    rng = np.random.default_rng(RNG_SEED)
    shaper = np.concatenate([[0.0, 0.0], np.sort(rng.random(60)), [1.0, 1.0]])  # flat runs at both ends
    lat = lattice.Lattice(None, None, "clip", None, None, None, (-0.5, 3.0), shaper, np.zeros((2, 2, 2, 3)))
    code = np.concatenate([rng.uniform(-2.0, 5.0, 5000), np.linspace(-0.5, 3.0, shaper.size), [np.nan]])
    expected = np.interp(np.clip(code, -0.5, 3.0), np.linspace(-0.5, 3.0, shaper.size), shaper)
    got = lattice.coordinates(lat, code)
    assert np.allclose(got, expected, rtol=0, atol=1e-15, equal_nan=True)
    assert np.isnan(got[-1])


def test_a_dim_displays_log_axis_still_reaches_half_float_light(tmp_path):
    """An absolute display of 1 cd/m² (a hundredth of display-referred 1.0): its clip and scale
    lattice reaches 65504 display-referred units, not 65504 times its own peak (655)."""
    from generator.spec import load

    spec = load.parse(
        "[[display]]\nname = 'Dim'\ngamut = 'Rec.709'\neotf = 'gamma 2.2'\npeak_luminance = 1\n"
        "absolute_luminance = true",
        "show.toml",
        tmp_path,
    )
    axis = lattice.display_axis(spec.displays[0], 17, "scale")
    assert axis.high * spec.displays[0].clip_high == pytest.approx(lattice.LOG_DISPLAY_HIGH, rel=1e-9)


@pytest.mark.parametrize(
    "display_name, transform",
    [
        (
            "sRGB - Display",
            ocio.ExponentWithLinearTransform(
                gamma=[2.4] * 3 + [1.0],
                offset=[0.055] * 3 + [0.0],
                negativeStyle=ocio.NEGATIVE_MIRROR,
                direction=ocio.TRANSFORM_DIR_INVERSE,
            ),
        ),
        (
            "Rec.1886 Rec.709 - Display",
            ocio.ExponentTransform(
                value=[2.4] * 3 + [1.0], negativeStyle=ocio.NEGATIVE_MIRROR, direction=ocio.TRANSFORM_DIR_INVERSE
            ),
        ),
    ],
)
def test_a_pre_shaper_is_the_displays_inverse_eotf_as_clf_runs_it(default_spec, display_name, transform):
    """The pre-shaper of an SDR display is CLF's mirrored moncurve or power, inverted: OCIO's own
    operator gives the same values, and the inverse takes them back."""
    pre = lattice.PreShaper.for_display(_display(default_spec, display_name))
    light = np.random.default_rng(RNG_SEED).uniform(-2.0, 4.0, (3000, 3)).astype(np.float32).astype(np.float64)
    np.testing.assert_allclose(pre.forward(light), _through_ocio([transform], light), rtol=2e-6, atol=1e-7)
    np.testing.assert_allclose(pre.inverse(pre.forward(light)), light, rtol=1e-12, atol=1e-15)


def test_an_extended_range_pre_shaper_keeps_the_peak_at_one(default_spec):
    """Display P3 HDR's light passes code 1 at a tenth of its peak: the scaled curve puts the
    peak at 1, code 1 at its own code, and inverts."""
    display = _display(default_spec, "Display P3 HDR - Display")
    pre = lattice.PreShaper.for_display(display)
    assert pre.scale == display.clip_high / display.code_one == 10.0
    assert pre.forward(1.0) == pytest.approx(1.0, abs=1e-15)
    srgb = lattice.PreShaper.for_display(_display(default_spec, "sRGB - Display"))
    assert pre.forward(0.1) == pytest.approx(1.0 / pre.norm, rel=1e-12)
    assert pre.norm == pytest.approx(float(srgb.forward(10.0)), rel=1e-12)
    light = np.geomspace(1e-6, 30.0, 500)
    np.testing.assert_allclose(pre.inverse(pre.forward(light)), light, rtol=1e-12)
    np.testing.assert_allclose(pre.inverse(pre.forward(-light)), -light, rtol=1e-12)


def test_preimages_land_on_the_nodes_through_the_written_shaper(default_spec):
    """OCIO reading the shaper as a file holds it (Range over the domain, then a 1D table) takes
    each preimage to its node's coordinate, to float32."""
    lat = lattice.display_lattice(default_spec, _display(default_spec, "sRGB - Display"), "desaturate", 17)
    values = lattice.preimages(lat.size, lat.shaper, lat.domain)
    table = ocio.Lut1DTransform(length=lat.shaper.size)
    table.setData(np.ascontiguousarray(np.repeat(lat.shaper[:, None], 3, axis=1), dtype=np.float32).ravel())
    lo, hi = lat.domain
    ranged = ocio.RangeTransform(minInValue=lo, maxInValue=hi, minOutValue=0.0, maxOutValue=1.0)
    out = _through_ocio([ranged, table], np.repeat(values[:, None], 3, axis=1))
    np.testing.assert_allclose(out[:, 0], np.arange(lat.size) / (lat.size - 1), rtol=0, atol=2e-6)


def test_preimages_of_a_table_clamped_at_its_top_are_where_a_reader_finds_the_nodes():
    """A shaper whose top entries repeat 1 (input beyond what the axis reaches): a reader
    interpolating the uniform entries finds each node's coordinate at its preimage, the last
    node at the first entry of the run."""
    rng = np.random.default_rng(RNG_SEED)
    shaper = np.concatenate([[0.0], np.sort(rng.random(40)), [1.0, 1.0, 1.0]])
    domain = (-0.5, 3.0)
    values = lattice.preimages(9, shaper, domain)
    read = np.interp(values, np.linspace(*domain, shaper.size), shaper)
    np.testing.assert_allclose(read, np.arange(9) / 8, rtol=0, atol=1e-15)
    assert values[-1] == pytest.approx(np.linspace(*domain, shaper.size)[-3], abs=1e-15)


#: Float64 rounding of a preimage read back through the table: a few roundings of values up to 1.
FLOAT64_READ_BACK = 4 * np.finfo(np.float64).eps


@pytest.mark.parametrize(
    "shaper, first_of_runs",
    [
        (np.array([0.0, 0.0, 0.0, 0.2, 0.5, 1.0]), {0.0: 0}),  # flat run at the start
        (np.array([0.0, 0.2, 0.5, 1.0, 1.0, 1.0]), {1.0: 3}),  # at the end
        (np.array([0.0, 0.0, 0.3, 0.3, 0.3, 0.7, 1.0, 1.0]), {0.0: 0, 0.3: 2, 1.0: 6}),  # both, and between
    ],
)
def test_preimages_of_a_table_with_flat_runs_are_read_back_to_the_nodes(shaper, first_of_runs):
    """A coordinate just above a flat run lies on the segment rising from the run's last entry,
    not its first: a reader interpolating the uniform entries takes every preimage back to its
    node, and a run's own value lands on the run's first entry."""
    domain = (-0.5, 3.0)
    entries = np.linspace(*domain, shaper.size)
    size = 41
    values = lattice.preimages(size, shaper, domain)
    u = np.arange(size) / (size - 1)
    np.testing.assert_allclose(np.interp(values, entries, shaper), u, rtol=0, atol=FLOAT64_READ_BACK)
    lat = lattice.Lattice(None, None, "clip", None, None, None, domain, shaper, np.zeros((2, 2, 2, 3)))
    np.testing.assert_allclose(lattice.coordinates(lat, values), u, rtol=0, atol=FLOAT64_READ_BACK)
    assert np.all(np.diff(values) > 0)
    for value, entry in first_of_runs.items():
        assert values[np.isclose(u, value, rtol=0, atol=1e-15)] == pytest.approx(entries[entry], abs=1e-15)


def test_a_grid_is_red_major(default_spec):
    axis = np.array([0.0, 0.5, 2.0])
    expected = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1)
    np.testing.assert_array_equal(lattice.grid(axis), expected)


def test_greys_of_an_srgb_lattice_are_the_displays_encoding_of_their_light(default_spec):
    """Desaturate leaves greys alone up to the peak and takes brighter ones to it: the lattice's
    diagonal holds the display's encoding (CLF's monCurveRev of 2.4 and 0.055, S-2014-006, as
    colour-science has it) of each node's light clipped to 0 to 1, to the written decimals."""
    import colour

    display = _display(default_spec, "sRGB - Display")
    lat = lattice.display_lattice(default_spec, display, "desaturate", 17)
    light = lat.pre.inverse(lattice.preimages(lat.size, lat.shaper, lat.domain))
    assert light.min() < 0.0 and light.max() > 1.0
    diagonal = lat.cube[np.arange(lat.size), np.arange(lat.size), np.arange(lat.size)]
    expected = colour.models.exponent_function_monitor_curve(np.clip(light, 0.0, 1.0), 2.4, 0.055, style="monCurveRev")
    np.testing.assert_allclose(diagonal[:, 0], expected, rtol=0, atol=0.5 * 10.0**-lattice.CUBE_DECIMALS + 1e-12)
    assert np.all(diagonal == diagonal[:, :1])


def test_node_values_are_never_negative_and_hold_the_written_decimals(default_spec):
    display = _display(default_spec, "sRGB - Display")
    axis = np.array([-1.0, -0.01, 0.0, 0.3, 1.0, 5.0])
    values = lattice.node_values(display, "clip", axis, None, None)
    assert values.shape == (6, 6, 6, 3) and values.min() == 0.0
    np.testing.assert_array_equal(values, np.round(values, lattice.CUBE_DECIMALS))


def test_only_an_sdr_curves_display_encodes_in_clf(default_spec):
    encodes = {d.name: lattice.encodes_in_clf(d) for d in default_spec.displays}
    assert encodes["sRGB - Display"] and encodes["Gamma 2.6 P3-D65 - Display"]
    assert not encodes["Rec.2100-PQ - Display"] and not encodes["Rec.2100-HLG - Display"]


def test_a_step_of_another_kind_is_refused_where_a_pre_shaper_or_table_is_needed(default_spec):
    lat = lattice.display_lattice(default_spec, _display(default_spec, "sRGB - Display"), "scale", 5)
    assert isinstance(lat.pre, LogAxis) and lat.shaper is None
    with pytest.raises(TypeError, match="LogAxis"):
        lattice.as_pre_shaper(lat.pre)
    with pytest.raises(TypeError, match="NoneType"):
        lattice.as_pre_shaper(None)
    with pytest.raises(ValueError, match="no shaper table"):
        lattice.shaper_table(lat)
