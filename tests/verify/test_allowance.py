"""The float32 limit of a check: what OCIO's float32 evaluation of a path departs by, carried
where a curve is steep (a power law at 0, a log curve's offset, a lattice near black, OCIO's
tabulated PQ) and nowhere else."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.rendering import views
from generator.verify import paths
from generator.verify.allowance import (
    builtin_encoding_allowance,
    float32_allowance,
    pq_table_departure,
    view_allowance,
    with_encoding,
)
from generator.verify.check import VIEW
from generator.verify.run import verify
from tests.verify.conftest import verified_on


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


def test_the_float32_allowance_is_large_only_where_a_power_curve_is_steep(spec):
    ends = paths.LazyEndpoints(spec)
    ref, gamma = ends["ACES2065-1"], ends["Gamma 2.2 Encoded Rec.709"]
    rec709 = np.array([[0.18, 0.18, 0.18], [0.0, 1.0, 1.0]])
    allowance = float32_allowance(ref, gamma.matrix, gamma.encode, rec709 @ gamma.matrix.T)
    # mid grey: float32 noise far below the tolerance; cyan's zero red: x ** (1 / 2.2) is steep at 0
    assert np.all(allowance[0] < tolerances.ANALYTIC_RELATIVE * tolerances.RELATIVE_FLOOR)
    assert allowance[1, 0] > tolerances.ANALYTIC_RELATIVE
    assert np.all(allowance[1, 1:] < tolerances.ANALYTIC_RELATIVE * tolerances.RELATIVE_FLOOR)


def test_a_log_curve_carries_its_offsets_rounding_into_the_allowance(tmp_path):
    """A Rec.2020 display with a pure 2.4 power, from ACEScct: OCIO's decode near black sits
    3.4e-9 below the exact linear segment (it derives the segment from the log offset, 0.55,
    in float32), which the power turned into a false failure while the allowance carried
    only the code's own rounding (0.07)."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    text = (
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", '
        '"CIE XYZ-D65 - Scene-referred"]\n[[display]]\nname = "Wide"\ngamut = "Rec.2020"\neotf = "Gamma 2.4"\n'
        'views = ["Colorimetric", "Raw"]\n[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
    )
    (tmp_path / "show.toml").write_text(text)
    folder = tmp_path / "show"
    build(for_folder(load.load(tmp_path / "show.toml"), folder, (2, 1)), folder)
    result = verify(folder / "config.ocio", ("ocio",), kinds=(VIEW,), only="Wide / Colorimetric from ACEScct")
    assert result.outcomes and result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]
    acescct = load.load(tmp_path / "show.toml").space("ACEScct").curve
    assert acescct.code_constant == pytest.approx(0.5547945205479452)


@pytest.mark.parametrize("size", [4096, 0])
def test_the_pq_table_departure_is_what_ocio_makes_of_its_tabulated_pq(default_spec, size):
    """OCIO tabulates PQ (4096 codes before 2.4, every half-float code after: size 0) and a
    display encodes through the table's inverse, which default flags tabulate again over
    half-float light: the modelled departure bounds both evaluations through PyOpenColorIO (to
    a few float32 roundings of a code up to 1) and is what they reach, near black."""
    from generator.ocio.capabilities import HALF_DOMAIN, PQ_BUILTIN

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


def test_ocio_21s_tabulated_pq_is_carried_near_black(tmp_path):
    """OCIO 2.1 tabulates PQ over 4096 codes, and its default flags tabulate the display's
    inverse again over half-float light: a blue-only code near black from a log space (red at
    5e-6 cd/m² after the matrices) came back 0.0102 ΔE ITP away, over the 0.01 tolerance, which
    no config can change. Verify carries that departure."""
    rows = "".join(f"{c:.6f},{(10.0 ** (5 * c) - 1) * 1e-3:.9g}\n" for c in (i / 256 for i in range(257)))
    (tmp_path / "curve.csv").write_text("code,linear\n" + rows)
    result = verified_on(
        tmp_path,
        "ocioconvert",
        'chromatic_adaptation = "CAT02"\n'
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Tab Log"\nprimaries = [[0.70, 0.30], [0.17, 0.80], [0.13, 0.04]]\nwhite = 5600\n'
        'transfer = { family = "tabulated", file = "curve.csv" }\nencoding = "log"\n'
        '[[display]]\nname = "Rec.2100-PQ - Display"\nviews = ["Colorimetric", "Raw"]\n'
        '[roles]\ncompositing_log = "Tab Log"\n',
        kinds=(VIEW,),
        only="Colorimetric from Tab Log",
    )
    assert result.passed, [(o.check.title, o.engine, o.worst, o.worst_input) for o in result.failures]


def test_ocio_21s_tabulated_pq_is_carried_for_a_scene_encoding(tmp_path):
    """A scene space encoded with ST 2084 goes through OCIO's PQ builtin too: OCIO 2.1's
    4096-code table put a near-black code 1.24e-4 relative off, over the 1e-4 tolerance (the
    allowance covered display encodings only)."""
    result = verified_on(
        tmp_path,
        "ocioconvert",
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "PQ Scene"\ngamut = "Rec.2020"\ntransfer = "ST 2084"\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n',
        only="PQ Scene",
    )
    assert result.passed, [(o.check.title, o.engine, o.worst, o.worst_input) for o in result.failures]


def test_the_float32_allowance_bounds_what_ocio_departs_by_on_a_steep_power(build_config, spec):
    """ACES2065-1 to Gamma 2.2 Encoded Rec.709 through the config, lossless: colours with a
    Rec.709 channel at or near 0 come back up to 1e-3 of a code from the float64 reference (over
    the tolerance, which no float32 engine can do better than); the allowance holds every
    departure, and is no loose bound: the largest reaches a quarter of it or more."""
    ends = paths.LazyEndpoints(spec)
    ref, gamma = ends["ACES2065-1"], ends["Gamma 2.2 Encoded Rec.709"]
    rng = np.random.default_rng(7)
    count = 4000
    rec709 = rng.random((count, 3))
    rec709[np.arange(count), rng.integers(0, 3, count)] = np.where(
        rng.random(count) < 0.5, 0.0, 10.0 ** rng.uniform(-9.0, -3.0, count)
    )
    aces = (rec709 @ gamma.matrix.T).astype(np.float32).astype(np.float64)
    expected = gamma.encode(aces)
    allowance = float32_allowance(ref, gamma.matrix, gamma.encode, aces)
    cfg = ocio.Config.CreateFromFile(str(build_config((2, 1))))
    cpu = cfg.getProcessor(ref.name, gamma.name).getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS)
    pixels = np.ascontiguousarray(aces, dtype=np.float32)
    cpu.applyRGB(pixels)
    departure = np.abs(pixels - expected)
    assert departure.max() > tolerances.ANALYTIC_RELATIVE * tolerances.RELATIVE_FLOOR  # needed: over the tolerance
    assert np.all(departure <= allowance), np.max(departure - allowance)
    assert np.max(departure / np.maximum(allowance, 1e-12)) >= 0.25


def test_only_an_encoding_ocio_tabulates_adds_to_the_allowance(spec):
    """OCIO's PQ builtin is a table, most off near black: a PQ display's codes carry its
    departure on top of the float32 allowance; an sRGB display's, computed exactly, carry
    nothing more, and a check without expected codes is left as it is."""
    codes = np.repeat(np.linspace(0.0, 1.0, 65)[:, None], 3, axis=1)
    base = np.full_like(codes, 1e-6)
    pq, srgb = (
        next(d for d in spec.displays if d.name == name) for name in ("Rec.2100-PQ - Display", "sRGB - Display")
    )
    encoding = builtin_encoding_allowance(spec, pq, codes)
    assert encoding is not None and encoding[0, 0] > 1e-7 and encoding[0, 0] == encoding.max()
    np.testing.assert_array_equal(with_encoding(base, spec, pq, codes), base + encoding)
    np.testing.assert_array_equal(with_encoding(None, spec, pq, codes), encoding)
    assert builtin_encoding_allowance(spec, srgb, codes) is None
    assert with_encoding(base, spec, srgb, codes) is base and with_encoding(base, spec, pq, None) is base


def _assert_aces_allowance_bounds_ocio(build_config, spec, display_name: str, aces: np.ndarray) -> None:
    """ACES2065-1 ``aces`` (float32 values) through the baked ACES 2.0 SDR Rec.709 view on
    ``display_name`` with OCIO's lossless flags: the departure from the reference passes the
    tolerance somewhere (the allowance is needed), stays within the allowance everywhere, and
    reaches a tenth of it or more (the allowance is tight)."""
    display = next(d for d in spec.displays if d.name == display_name)
    view = "ACES 2.0 - SDR 100 nits (Rec.709)"
    ends = paths.LazyEndpoints(spec)
    src, target = ends["ACES2065-1"], ends[display.name]
    expected = paths.aces_view_function(spec, display, view)(src.linear(aces) @ src.matrix.T)
    allowance = view_allowance(spec, src, target.matrix, display, view, aces, expected, target.encode)
    cfg = ocio.Config.CreateFromFile(str(build_config((2, 1))))
    processor = cfg.getProcessor(src.name, display.name, view, ocio.TRANSFORM_DIR_FORWARD)
    pixels = np.ascontiguousarray(aces, dtype=np.float32)
    processor.getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS).applyRGB(pixels)
    departure = np.abs(pixels - expected)
    assert departure.max() > tolerances.ANALYTIC_RELATIVE * tolerances.RELATIVE_FLOOR  # needed: over the tolerance
    assert np.all(departure <= allowance), np.max(departure - allowance)
    assert np.max(departure / np.maximum(allowance, 1e-12)) >= 0.1


def test_the_baked_aces_allowance_bounds_what_ocio_departs_by_near_black(build_config, spec):
    """ACES2065-1 near black through the baked ACES 2.0 SDR view on Gamma 2.6, lossless: OCIO's
    float32 sum of AP1 and the Log operator's toe cannot resolve 1e-9, which the pure power
    turns into codes over the tolerance; the allowance holds every departure, tightly (the
    largest reaches a tenth of it or more)."""
    rng = np.random.default_rng(9)
    count = 3000
    aces = rng.random((count, 3)) * 10.0 ** rng.uniform(-10.0, -5.0, (count, 1))
    aces[np.arange(count), rng.integers(0, 3, count)] = 0.0
    _assert_aces_allowance_bounds_ocio(
        build_config, spec, "Gamma 2.6 P3-D65 - Display", aces.astype(np.float32).astype(np.float64)
    )


def test_the_baked_aces_allowance_bounds_what_ocio_departs_by_near_ap1s_faces(build_config, spec):
    """ACES2065-1 just inside AP1's B = 0 face through the baked ACES 2.0 SDR view on Rec.1886,
    lossless: OCIO's float32 chromaticity, where the table's nodes crowd, moves a display channel
    near 0, which the pure power turns into codes over the tolerance; the allowance holds every
    departure, tightly. Without the chromaticity's rounding (ACES_CHROMA_ROUNDINGS) it did not."""
    rng = np.random.default_rng(12)
    count = 20000
    ap1 = rng.random((count, 3)) * np.array([1.0, 1.0, 0.0]) + np.array([0.0, 0.0, 1.0]) * 10.0 ** rng.uniform(
        -5.0, -2.0, (count, 1)
    )
    ap1 *= 10.0 ** rng.uniform(-1.0, 0.5, (count, 1))
    to_ap0 = views.tables(views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"]).ap1_to_ap0
    _assert_aces_allowance_bounds_ocio(
        build_config, spec, "Rec.1886 Rec.709 - Display", (ap1 @ to_ap0.T).astype(np.float32).astype(np.float64)
    )
