"""The built config against the reference evaluation, for every target version.

OCIO runs with lossless optimisation here (the maths must be exact up to
float32); what hosts' default flags cost is measured by ``ocioforge verify``.
"""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import reference, tolerances
from generator.metrics import colour_relative_error, delta_e_itp, relative_error
from generator.ocio.curves import is_baked
from generator.spec import resolved
from tests.conftest import VERSIONS

LOSSLESS = ocio.OPTIMIZATION_LOSSLESS

#: ADX16 codes above this decode past half-float max, where OCIO's builtin clamps (65504).
ADX16_MAX_CODE = 0.45


def cpu(cfg, src, dst):
    return cfg.getProcessor(src, dst).getOptimizedCPUProcessor(LOSSLESS)


def apply(processor, rgb) -> np.ndarray:
    out = np.ascontiguousarray(rgb, dtype=np.float32).copy()
    processor.applyRGB(out)
    return out.astype(np.float64)


def code_probes(space) -> np.ndarray:
    """Neutral ramps over the code range and random code triplets, float32-representable."""
    top = ADX16_MAX_CODE if space.special == "adx16" else 1.0
    ramp = np.repeat(np.linspace(0.0, top, 1025)[:, None], 3, axis=1)
    rng = np.random.default_rng(7)
    return np.concatenate([ramp, rng.uniform(0.0, top, (1024, 3))]).astype(np.float32).astype(np.float64)


@pytest.fixture(scope="module", params=VERSIONS, ids=lambda v: f"ocio{v[0]}.{v[1]}")
def built(request, build_config):
    path = build_config(request.param)
    return ocio.Config.CreateFromFile(str(path)), resolved.read_beside(path)


def test_config_validates_and_declares_its_version(built):
    cfg, spec = built
    cfg.validate()
    assert (cfg.getMajorVersion(), cfg.getMinorVersion()) == spec.ocio_version
    assert cfg.getName() == "ocioforge-test"


def test_every_space_matches_the_reference(built):
    """Analytic spaces value by value; baked ones relative to each colour's largest
    component (the LUT's bound holds per channel before the matrix mixes them)."""
    cfg, spec = built
    worst = {}
    for space in (s for s in spec.colour_spaces if not s.is_data):
        codes = code_probes(space)
        codes = codes[np.all(_monotone(space, codes), axis=1)]
        ocio_out = apply(cpu(cfg, space.name, spec.scene_reference), codes)
        expected = reference.to_reference(spec, space, codes)
        if is_baked(space.curve_name, space.curve, spec.ocio_version):
            error = colour_relative_error(ocio_out, expected) / np.abs(reference.space_matrix(spec, space)).sum(1).max()
        else:
            error = relative_error(ocio_out, expected)
        worst[space.name] = float(error.max())
    failing = {k: v for k, v in worst.items() if v > tolerances.ANALYTIC_RELATIVE}
    assert not failing, f"OCIO differs from the reference evaluation: {failing}"


def float32_limit(space, codes, matrix) -> np.ndarray:
    """The round-trip error float32 arithmetic imposes on codes: the linear value's error
    through the matrix and back (|fl(Mx) - Mx| <= 3u |M||x| each way, Higham 2002, 3.5)
    over the curve's slope, relative to the code (floored)."""
    step = 1e-6
    linear = space.curve.decode(codes)
    slope = np.abs(space.curve.decode(codes + step) - linear) / step
    growth = 1.0 + 3.0 * np.abs(matrix).sum(1).max() * (1.0 + 3.0 * np.abs(np.linalg.inv(matrix)).sum(1).max())
    limit = growth * tolerances.FLOAT32_UNIT_ROUNDOFF * np.abs(linear) / np.maximum(slope, 1e-30)
    return limit / np.maximum(np.abs(codes), tolerances.RELATIVE_FLOOR)


#: Half-width, in code values, of the band around a published discontinuity where
#: decoding is not monotonic (N-Log: two 10-bit codes), left out of round trips.
NON_MONOTONE_BAND = 2.0 / 1023.0


def _monotone(space, codes) -> np.ndarray:
    keep = np.ones(codes.shape, dtype=bool)
    for jump in getattr(space.curve, "discontinuities", ()):
        keep &= np.abs(codes - jump) > NON_MONOTONE_BAND
    return keep


def test_every_space_round_trips_through_the_reference(built):
    """Codes -> reference -> codes on neutral ramps, and reference -> codes -> reference
    on every colour the encoding represents (the decoded random codes)."""
    cfg, spec = built
    failing = {}
    for space in (s for s in spec.colour_spaces if not s.is_data):
        probes = code_probes(space)
        neutral = probes[:1025][_monotone(space, probes[:1025, 0])]
        scene = reference.to_reference(spec, space, probes[1025:])
        scene = scene.astype(np.float32).astype(np.float64)
        to_ref, from_ref = cpu(cfg, space.name, spec.scene_reference), cpu(cfg, spec.scene_reference, space.name)
        code_error = colour_relative_error(apply(from_ref, apply(to_ref, neutral)), neutral)
        code_trip = (
            np.max(code_error - float32_limit(space, neutral[:, 0], reference.space_matrix(spec, space)))
            if not space.special
            else code_error.max()
        )
        scene_trip = colour_relative_error(apply(to_ref, apply(from_ref, scene)), scene).max()
        if max(code_trip, scene_trip) > tolerances.ROUND_TRIP_RELATIVE:
            failing[space.name] = (float(code_trip), float(scene_trip))
    assert not failing, f"round trips beyond {tolerances.ROUND_TRIP_RELATIVE}: {failing}"


def test_colorimetric_views_match_the_reference(built):
    cfg, spec = built
    rng = np.random.default_rng(11)
    scene = np.concatenate([rng.uniform(-0.05, 2.0, (4096, 3)), np.geomspace(1e-4, 100.0, 256)[:, None] * [1, 1, 1]])
    scene = scene.astype(np.float32).astype(np.float64)
    for display in spec.displays:
        processor = cfg.getProcessor(
            spec.scene_reference, display.name, "Colorimetric", ocio.TRANSFORM_DIR_FORWARD
        ).getOptimizedCPUProcessor(LOSSLESS)
        expected = reference.colorimetric_view(spec, display, scene)
        if not display.is_hdr:
            error = relative_error(apply(processor, scene), expected).max()
            assert error <= tolerances.ANALYTIC_RELATIVE, (display.name, float(error))
            continue
        error = delta_e_itp(display, apply(processor, scene), expected)
        if display.eotf_name == "HLG":
            light = reference.display_decode(display, expected) @ display.gamut.rgb_to_xyz[1] * 100.0
            error = error[light >= tolerances.HLG_BUILTIN_BLACK]
        assert error.max() <= tolerances.ANALYTIC_DELTA_E_ITP, (display.name, float(error.max()))


def test_display_codes_beyond_the_signal_read_back_as_its_ends(built):
    """A display's codes past the signal's range, read back into the scene, come to what its
    ends give (OCIO's PQ builtin from 2.2 on decodes PQ code 2 as black, 2.1's as the peak)."""
    cfg, spec = built
    for display in spec.displays:
        top = float(reference.display_encode(display, np.full(3, display.clip_high))[0])
        codes = np.array([[2.0, 2.0, 2.0], [1.5, 1.0, 1.2], [-0.5, -2.0, 0.0]]) * max(top, 1.0)
        ends = np.clip(codes, 0.0, top)
        processor = cfg.getProcessor(display.name, spec.scene_reference).getOptimizedCPUProcessor(LOSSLESS)
        assert np.allclose(
            apply(processor, codes), apply(processor, ends), rtol=tolerances.ANALYTIC_RELATIVE, atol=0.0
        ), display.name


def test_roles_and_rules_hosts_read(built):
    cfg, _ = built
    roles = dict(cfg.getRoles())
    for role in (
        "scene_linear",
        "rendering",
        "compositing_log",
        "color_timing",
        "color_picking",
        "texture_paint",
        "matte_paint",
        "data",
        "default",
        "aces_interchange",
        "cie_xyz_d65_interchange",
        "default_byte",
        "default_float",
        "default_sequencer",
    ):
        assert cfg.getColorSpace(roles[role]) is not None, role
    rules = cfg.getFileRules()
    assert cfg.getColorSpaceFromFilepath("shot.0001.exr")[0] == "scene_linear"
    assert cfg.getColorSpaceFromFilepath("albedo.png")[0] == "texture_paint"
    assert rules.getColorSpace(rules.getNumEntries() - 1) == "default"


@pytest.mark.parametrize(
    "alias",
    [
        "lin_ciexyzd65",
        "lin_ciexyze",
        "lin_ciergb",
        "lin_rec709",
        "lin_rec2020",
        "lin_p3d65",
        "acescg",
        "aces2065_1",
        "acescct",
        "srgb_tx",
        "srgb_display",
        "srgb_texture",
        "lin_ap1",
        "arri_logc4",
        "slog3_sgamut3cine",
        "flog2_fgamut",
    ],
)
def test_required_aliases_resolve(build_config, alias):
    cfg = ocio.Config.CreateFromFile(str(build_config((2, 1))))
    assert cfg.getColorSpace(alias) is not None


def test_studio_config_names_and_aliases_are_all_present(build_config):
    ours = ocio.Config.CreateFromFile(str(build_config((2, 1))))
    studio = ocio.Config.CreateFromFile("ocio://studio-config-latest")
    missing = []
    for cs in studio.getColorSpaces(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL):
        names = [cs.getName(), *(a for a in cs.getAliases() if not a.startswith("ocio:"))]
        missing += [n for n in names if ours.getColorSpace(n) is None]
    assert not missing, sorted(missing)


def test_scene_spaces_carry_the_studio_configs_menu_categories(build_config):
    """Hosts build their working-space and texture menus from categories: the camera encodings had
    been offered as working spaces and no linear space as a texture's. Every scene space the ACES
    studio config shares with the build has its categories."""
    ours = ocio.Config.CreateFromFile(str(build_config((2, 6))))
    studio = ocio.Config.CreateFromFile("ocio://studio-config-latest")
    differ = []
    for cs in studio.getColorSpaces(ocio.SEARCH_REFERENCE_SPACE_SCENE, ocio.COLORSPACE_ALL):
        held = ours.getColorSpace(cs.getName())
        if held is not None and list(held.getCategories()) != list(cs.getCategories()):
            differ.append((cs.getName(), list(held.getCategories()), list(cs.getCategories())))
    assert not differ, differ
    working = ocio.ColorSpaceMenuHelper(ocio.ColorSpaceMenuParameters(ours, appCategories="working-space"))
    assert {working.getName(i) for i in range(working.getNumColorSpaces())} >= {"ACEScg", "ACEScct"}
    assert "ARRI LogC4" not in {working.getName(i) for i in range(working.getNumColorSpaces())}


def test_each_display_keeps_its_own_view_order_and_default(tmp_path):
    """Views are listed, and the default is the first, as each display gives them: a config-wide
    active_views list had ordered Display P3's (Raw, Scale, Perceptual) after sRGB's, making
    Perceptual its default view in every host."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    text = (
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Perceptual", "Colorimetric", "Raw"]\n'
        '[[display]]\nname = "Display P3 - Display"\nviews = ["Raw", "Scale", "Perceptual"]\n'
    )
    folder = tmp_path / "order"
    build(for_folder(load.parse(text, "order.toml", tmp_path), folder), folder)
    cfg = ocio.Config.CreateFromFile(str(folder / "config.ocio"))
    assert list(cfg.getViews("sRGB - Display")) == ["Perceptual", "Colorimetric", "Raw"]
    assert list(cfg.getViews("Display P3 - Display")) == ["Raw", "Scale", "Perceptual"]
    assert cfg.getDefaultView("Display P3 - Display") == "Raw"
