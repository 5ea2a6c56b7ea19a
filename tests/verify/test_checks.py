"""What verify checks: coverage from the spec, probe families, the float32 allowance, metrics."""

from __future__ import annotations

import numpy as np
import pytest

from generator import reference, tolerances
from generator.metrics import dequantised, percentile_99
from generator.spec import resolved
from generator.verify import checks, paths, probes
from generator.verify.allowance import float32_allowance


@pytest.fixture(scope="module")
def spec(build_config):
    return resolved.read_beside(build_config((2, 1)))


@pytest.fixture(scope="module")
def built(spec):
    return checks.build_checks(spec, "quick")


def test_every_space_is_checked_both_ways(spec, built):
    to_ref = {c.item for c in built if c.kind == checks.TO_REFERENCE}
    from_ref = {c.item for c in built if c.kind == checks.FROM_REFERENCE}
    names = {s.name for s in spec.colour_spaces} | {d.name for d in spec.displays}
    assert names <= to_ref and names <= from_ref
    assert {f"Colorimetric - {d.name}" for d in spec.displays} <= from_ref


def test_every_view_is_checked_from_three_inputs(spec, built):
    views = [c for c in built if c.kind == checks.VIEW]
    sources = {c.src for c in views}
    assert sources == {"ACEScg", "ACEScct", spec.displays[0].name}
    assert len(views) == 3 * sum(len(d.views) for d in spec.displays)


def test_blender_checks_no_view_from_an_inactive_space():
    """Blender offers no inactive space: a view is not checked there from an inactive
    compositing_log role's space (verify had failed such a config with "enum 'ACEScct' not
    found"), and still is in every other engine."""
    from pathlib import Path

    from generator.spec import load
    from generator.verify.blender import BlenderEngine

    spec = load.parse(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        'inactive = ["acescct_ap1"]\n',
        "show.toml",
        Path("."),
    )
    views = [c for c in checks.build_checks(spec, "quick", kinds=(checks.VIEW,)) if c.view != paths.RAW]
    assert {c.src for c in views} == {"ACEScg", "ACEScct", spec.displays[0].name}
    assert {c.src for c in views if BlenderEngine().supports(c, spec)} == {"ACEScg", spec.displays[0].name}


def test_every_baked_lut_file_is_checked(build_config, built):
    on_disk = {f"luts/{p.name}" for p in (build_config((2, 1)).parent / "luts").iterdir()}
    assert {c.lut for c in built if c.kind == checks.LUT} == on_disk


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


def test_the_float32_allowance_is_large_only_where_a_power_curve_is_steep(spec):
    ends = paths.endpoints(spec)
    ref, gamma = ends["ACES2065-1"], ends["Gamma 2.2 Encoded Rec.709"]
    rec709 = np.array([[0.18, 0.18, 0.18], [0.0, 1.0, 1.0]])
    allowance = float32_allowance(ref, gamma.matrix, gamma.encode, rec709 @ gamma.matrix.T)
    # mid grey: float32 noise far below the tolerance; cyan's zero red: x ** (1 / 2.2) is steep at 0
    assert np.all(allowance[0] < tolerances.ANALYTIC_RELATIVE * tolerances.RELATIVE_FLOOR)
    assert allowance[1, 0] > tolerances.ANALYTIC_RELATIVE
    assert np.all(allowance[1, 1:] < tolerances.ANALYTIC_RELATIVE * tolerances.RELATIVE_FLOOR)


def test_dequantised_takes_off_half_a_step_and_no_more():
    got = dequantised([0.5 + 0.4 / 65535, 0.5 - 2.0 / 65535], [0.5, 0.5], 1.0 / 65535)
    assert got[0] == 0.5 and got[1] == pytest.approx(0.5 - 1.5 / 65535, abs=1e-15)
    assert percentile_99([np.nan, 1.0, 2.0]) == pytest.approx(1.99)


def test_a_log_curve_carries_its_offsets_rounding_into_the_allowance(tmp_path):
    """A Rec.2020 display with a pure 2.4 power, from ACEScct: OCIO's decode near black sits
    3.4e-9 below the exact linear segment (it derives the segment from the log offset, 0.55,
    in float32), which the power turned into a false failure while the allowance carried
    only the code's own rounding (0.07)."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from generator.verify.run import verify

    text = (
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", '
        '"CIE XYZ-D65 - Scene-referred"]\n[[display]]\nname = "Wide"\ngamut = "Rec.2020"\neotf = "Gamma 2.4"\n'
        'views = ["Colorimetric", "Raw"]\n[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
    )
    (tmp_path / "show.toml").write_text(text)
    folder = tmp_path / "show"
    build(for_folder(load.load(tmp_path / "show.toml"), folder, (2, 1)), folder)
    result = verify(folder / "config.ocio", ("ocio",), kinds=(checks.VIEW,), only="Wide / Colorimetric from ACEScct")
    assert result.outcomes and result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]
    acescct = load.load(tmp_path / "show.toml").space("ACEScct").curve
    assert acescct.code_constant == pytest.approx(0.5547945205479452)


@pytest.mark.parametrize("name", ["CanonLog2", "CanonLog3", "Apple Log"])
def test_curves_a_clamping_builtin_expresses_are_judged_on_its_codes(build_config, name):
    """From OCIO 2.2 (2.4 for Apple Log) the config decodes Canon Log 2 and 3 with OCIO's
    builtins, which tabulate codes 0 to 1 and clamp outside (Apple Log's below 0): verify
    judges those spaces on those codes, as it does a baked curve on its LUT's domain
    (it failed every Canon space of the default spec at 2.2 and later before)."""
    from generator.verify.run import verify
    from tests.conftest import NEWEST

    result = verify(
        build_config(NEWEST), ("ocio",), density="quick", kinds=(checks.TO_REFERENCE, checks.FROM_REFERENCE), only=name
    )
    assert result.outcomes and result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]


def test_custom_curves_are_checked_under_their_files_names_and_as_code_values(tmp_path):
    """A custom tabulated curve is baked under its space's or display's name, and verify checks
    that file on its own (a display's was only read through its views);
    a gamma-encoded space labelled scene-linear is still judged as code values, with the
    float32 limit of its steep power (it failed by colour relative error before)."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from generator.verify.run import verify

    (tmp_path / "curve.csv").write_text("code,linear\n0,0\n0.25,0.02\n0.5,0.12\n0.75,0.45\n1,1\n")
    text = (
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", '
        '"CIE XYZ-D65 - Scene-referred"]\n'
        '[[custom_space]]\nname = "Tab"\ngamut = "P3-D65"\ntransfer = { family = "tabulated", file = "curve.csv" }\n'
        '[[custom_space]]\nname = "Warm"\nencoding = "scene-linear"\nprimaries = [[0.70, 0.30], [0.17, 0.80], '
        '[0.13, 0.04]]\nwhite = 5000\ntransfer = { family = "gamma", exponent = 2.2 }\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
        '[[display]]\nname = "Tab Monitor"\ngamut = "Rec.709"\neotf = { family = "tabulated", file = "curve.csv" }\n'
        'views = ["Colorimetric", "Raw"]\n'
    )
    (tmp_path / "show.toml").write_text(text)
    folder = tmp_path / "show"
    build(for_folder(load.load(tmp_path / "show.toml"), folder, (2, 1)), folder)
    files = {"luts/tab_to_linear.spi1d", "luts/tab_monitor_to_linear.spi1d"}
    assert {f"luts/{p.name}" for p in (folder / "luts").iterdir()} == files
    result = verify(
        folder / "config.ocio",
        ("ocio",),
        density="quick",
        kinds=(checks.TO_REFERENCE, checks.FROM_REFERENCE, checks.LUT),
    )
    assert files <= {o.check.item for o in result.outcomes}
    assert result.passed, [(o.check.title, o.engine, o.worst, o.note) for o in result.failures]


@pytest.mark.parametrize("size", [4096, 0])
def test_the_pq_table_departure_is_what_ocio_makes_of_its_tabulated_pq(default_spec, size):
    """OCIO tabulates PQ (4096 codes before 2.4, every half-float code after: size 0) and a
    display encodes through the table's inverse, which default flags tabulate again over
    half-float light: the modelled departure bounds both evaluations through PyOpenColorIO (to
    a few float32 roundings of a code up to 1) and is what they reach, near black."""
    import PyOpenColorIO as ocio

    from generator.ocio.capabilities import HALF_DOMAIN, PQ_BUILTIN
    from generator.verify.allowance import pq_table_departure

    curve = next(d for d in default_spec.displays if d.eotf_name == "ST 2084").eotf
    if size == HALF_DOMAIN:
        transform = ocio.BuiltinTransform(PQ_BUILTIN, ocio.TRANSFORM_DIR_INVERSE)
    else:  # the table of libraries before 2.4, through this library's inverse
        transform = ocio.Lut1DTransform(length=size, direction=ocio.TRANSFORM_DIR_INVERSE)
        for index, value in enumerate(np.asarray(curve.decode(np.linspace(0.0, 1.0, size)), dtype=np.float32)):
            transform.setValue(index, float(value), float(value), float(value))
    light = np.concatenate([[0.0], np.geomspace(1e-9, 10.0, 2001)]).astype(np.float32).astype(np.float64)
    exact = curve.encode(light)
    model = pq_table_departure(curve, size, light)
    processor = ocio.Config.CreateRaw().getProcessor(transform)
    reached = 0.0
    for flags in (ocio.OPTIMIZATION_DEFAULT, ocio.OPTIMIZATION_LOSSLESS):
        pixels = np.ascontiguousarray(np.repeat(light[:, None], 3, axis=1), dtype=np.float32)
        processor.getOptimizedCPUProcessor(flags).applyRGB(pixels)
        departure = np.abs(pixels[:, 0] - exact)
        assert np.all(departure <= model + tolerances.FLOAT32_MATRIX_ROUNDINGS * tolerances.FLOAT32_UNIT_ROUNDOFF)
        reached = max(reached, float(departure.max()))
    assert reached >= 0.95 * model.max() and 1023 * model[light < 1e-6].max() > 0.05


def test_verify_checks_each_space_against_its_own_curve_file(slugging_alike):
    """Spaces whose names slug alike (one as a library curve's) each have a file; verify
    checks every one, and each space through its own (they shared one file before, and
    verify failed the spaces decoding with another's curve)."""
    from generator.verify.run import verify

    _spec, folder = slugging_alike
    result = verify(
        folder / "config.ocio",
        ("ocio",),
        density="quick",
        kinds=(checks.TO_REFERENCE, checks.FROM_REFERENCE, checks.LUT),
    )
    files = {f"luts/{p.name}" for p in (folder / "luts").iterdir()}
    assert len(files) == 4 and files <= {o.check.item for o in result.outcomes}
    assert result.passed, [(o.check.title, o.engine, o.worst, o.note) for o in result.failures]


@pytest.mark.parametrize("version", [(2, 1), "newest"])
def test_a_pq_scene_space_passes_beyond_the_signal_range(tmp_path, version):
    """A scene space encoded with ST 2084 is judged on negative and over-range colours too:
    config and reference both clamp to the signal range (it failed by 1.45 relative)."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from generator.verify.run import verify
    from tests.conftest import NEWEST

    (tmp_path / "pq.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "P3 PQ"\ngamut = "P3-D65"\ntransfer = "ST 2084"\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
    )
    folder = tmp_path / "pq"
    build(for_folder(load.load(tmp_path / "pq.toml"), folder, NEWEST if version == "newest" else version), folder)
    result = verify(
        folder / "config.ocio",
        ("ocio",),
        density="quick",
        kinds=(checks.TO_REFERENCE, checks.FROM_REFERENCE),
        only="P3 PQ",
    )
    assert result.outcomes and result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]


def test_a_table_rising_steeply_between_two_rows_verifies(tmp_path):
    """A 10-bit table whose top row flags a clip (20 to 100 over one step) is baked on its rows,
    and verify carries the float32 rounding of the codes times that slope (1.04e-4 of the value
    at the top row, over 1e-4, which no float32 engine can do better than)."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from generator.verify.run import verify

    rows = "".join(f"{i / 1023:.9f},{20 * (i / 1023) ** 2.4:.9g}\n" for i in range(1023))
    (tmp_path / "clip.csv").write_text("code,linear\n" + rows + "1,100\n")
    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Clip"\ngamut = "Rec.709"\ntransfer = { family = "tabulated", file = "clip.csv" }\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
    )
    folder = tmp_path / "show"
    build(for_folder(load.load(tmp_path / "show.toml"), folder, (2, 1)), folder)
    result = verify(folder / "config.ocio", ("ocio",), density="quick", only="Clip")
    assert result.outcomes and result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]
