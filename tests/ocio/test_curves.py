"""Transfer records as OCIO transforms: the transforms decode as the reference does."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import reference, tolerances
from generator.colorimetry import transfer
from generator.colorimetry.curves import CURVES
from generator.luts.names import slug
from generator.metrics import colour_relative_error, relative_error
from generator.ocio.curves import code_clamp, curve_label, decode_transforms, is_baked
from tests.conftest import VERSIONS


def decode_through_ocio(transforms: list, codes: np.ndarray, direction=ocio.TRANSFORM_DIR_FORWARD) -> np.ndarray:
    """``codes`` (one per channel) through the transforms in an empty config (or the reverse)."""
    cfg = ocio.Config.CreateRaw()
    processor = cfg.getProcessor(ocio.GroupTransform(transforms), direction).getDefaultCPUProcessor()
    rgb = np.ascontiguousarray(np.repeat(codes[:, None], 3, axis=1), dtype=np.float32)
    processor.applyRGB(rgb)
    return rgb[:, 0].astype(np.float64)


LOG_AFFINE = transfer.LogCamera(
    base=10.0, log_side_slope=0.25, log_side_offset=0.4, lin_side_slope=5.0, lin_side_offset=0.05
)
LOG_CAMERA = transfer.LogCamera(
    base=10.0,
    log_side_slope=0.247,
    log_side_offset=0.385,
    lin_side_slope=5.56,
    lin_side_offset=0.052,
    lin_side_break=0.0109,
    linear_slope=5.37,
)


@pytest.mark.parametrize("curve", [LOG_AFFINE, LOG_CAMERA], ids=["no break", "break"])
def test_log_camera_decodes_as_the_reference(curve):
    """With or without a linear segment, in the record's own base (not OCIO's default 2)."""
    codes = np.linspace(0.1, 1.0, 91).astype(np.float32).astype(np.float64)
    out = decode_through_ocio(decode_transforms("custom", curve, (2, 1), {}), codes)
    assert relative_error(out, curve.decode(codes)).max() < tolerances.ANALYTIC_RELATIVE


@pytest.mark.parametrize("version", VERSIONS, ids=lambda v: f"ocio{v[0]}.{v[1]}")
def test_a_pq_scene_space_is_defined_on_the_signal_range_only(version):
    """OCIO's PQ builtin mirrors negative codes and light and decodes codes from 2 up to 0;
    a scene space clamps its codes first, and decodes and encodes as the reference does
    beyond the signal range too (the space failed verify by 1.45 relative before)."""
    pq = CURVES["ST 2084"]
    transforms = code_clamp("ST 2084", version) + decode_transforms("ST 2084", pq, version, {})
    codes = np.array([-1.0, -0.457, -0.01, 0.0, 0.5, 1.0, 1.01, 1.5, 2.5, 10.04, 11.5])
    decoded = decode_through_ocio(transforms, codes)
    assert relative_error(decoded, pq.decode(codes)).max() < tolerances.ANALYTIC_RELATIVE
    light = np.array([-1.0, -0.1, -1e-4, 0.0, 1.0, 100.0, 101.0, 1e5])
    encoded = decode_through_ocio(transforms, light, ocio.TRANSFORM_DIR_INVERSE)
    assert relative_error(encoded, pq.encode(light)).max() < tolerances.ANALYTIC_RELATIVE


# --- baked curve files: one per curve --------------------------------------------------------


def test_curves_named_alike_get_files_of_their_own(slugging_alike):
    spec, folder = slugging_alike
    labels = {
        s.name: curve_label(spec, s.name, s.curve_name)
        for s in spec.colour_spaces
        if is_baked(s.curve_name, s.curve, spec.ocio_version)
    }
    assert labels["CanonLog2 CinemaGamut D55"] == "Canon Log 2"
    assert len(set(map(slug, labels.values()))) == len(labels)
    files = {p.name for p in (folder / "luts").iterdir()}
    assert {f"{slug(label)}_to_linear.spi1d" for label in labels.values()} == files


def test_each_space_decodes_with_its_own_curve(slugging_alike):
    """Through the built config, every baked space decodes as its own curve does (the spaces
    named alike shared one file before, and all but one decoded with another's curve)."""
    spec, folder = slugging_alike
    cfg = ocio.Config.CreateFromFile(str(folder / "config.ocio"))
    codes = np.repeat(np.linspace(0.0, 1.0, 257)[:, None], 3, axis=1)
    for space in (s for s in spec.colour_spaces if is_baked(s.curve_name, s.curve, spec.ocio_version)):
        out = np.ascontiguousarray(codes, dtype=np.float32)
        cfg.getProcessor(space.name, spec.scene_reference).getDefaultCPUProcessor().applyRGB(out)
        gain = np.abs(reference.space_matrix(spec, space)).sum(1).max()
        error = colour_relative_error(out, reference.to_reference(spec, space, codes)) / gain
        assert error.max() < tolerances.BAKED_CURVE_RELATIVE, space.name


def test_library_curves_slug_apart():
    assert len({slug(name) for name in CURVES}) == len(CURVES)
