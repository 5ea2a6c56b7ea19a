"""The float64 evaluation of a display-layout view file against OCIO running the file."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import tolerances
from generator.luts import evaluate
from generator.luts.view import bake_view_lut, view_lattice


def _colours(rng) -> np.ndarray:
    """Normalised display-linear colours, float32-exact: inside the cube, on its faces, outside
    it (negative and over the peak) and far out, where the file's Range clamps."""
    inside = rng.uniform(0.0, 1.0, (2048, 3))
    faces = inside.copy()
    faces[np.arange(2048), rng.integers(0, 3, 2048)] = rng.choice([0.0, 1.0], 2048)
    outside = rng.uniform(-0.6, 3.0, (2048, 3))
    far = rng.uniform(-100.0, 100.0, (256, 3))
    return np.concatenate([inside, faces, outside, far]).astype(np.float32).astype(np.float64)


@pytest.mark.parametrize(
    "display_name",
    ["sRGB - Display", "Rec.1886 Rec.709 - Display", "Rec.2100-PQ - Display", "Display P3 HDR - Display"],
)
def test_display_file_is_the_file_as_ocio_runs_it(default_spec, tmp_path, display_name):
    """sRGB's pre-shaper is CLF's moncurve, Rec.1886's a mirrored power, PQ's and Display P3
    HDR's (extended range) files end in display light through the pre-shaper's inverse: OCIO
    (lossless) and the evaluation agree
    to the float32 reading of the file's values (measured 3e-6 of a code value)."""
    display = next(d for d in default_spec.displays if d.name == display_name)
    view = bake_view_lut(default_spec, display, "perceptual")
    path = tmp_path / view.filename
    path.write_bytes(view.data)
    cfg = ocio.Config.CreateRaw()
    cpu = cfg.getProcessor(
        ocio.FileTransform(str(path), interpolation=ocio.INTERP_TETRAHEDRAL)
    ).getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS)
    colours = _colours(np.random.default_rng(7))
    pixels = np.ascontiguousarray(colours, dtype=np.float32)
    cpu.applyRGB(pixels)
    lat = view_lattice(default_spec, display, "perceptual")
    expected = evaluate.display_file(lat, colours)
    if lat.light is not None:  # compared as the lattice holds them, before the exact inverse
        pixels, expected = lat.light.forward(pixels), lat.light.forward(expected)
    assert np.max(np.abs(pixels - expected)) <= tolerances.LUT_NODE_ABSOLUTE


def test_display_file_keeps_nan_and_clamps_infinity(default_spec):
    display = default_spec.displays[0]
    lat = view_lattice(default_spec, display, "perceptual")
    out = evaluate.display_file(lat, np.array([[np.nan, 0.5, 0.5], [np.inf, 0.5, 0.5], [1e30, 0.5, 0.5]]))
    assert np.isnan(out[0]).all() and np.array_equal(out[1], out[2]) and np.isfinite(out[1]).all()


def test_display_file_refuses_other_layouts(default_spec):
    display = default_spec.displays[0]
    with pytest.raises(ValueError, match="pre-shaper"):
        evaluate.display_file(view_lattice(default_spec, display, "scale"), np.zeros((1, 3)))


@pytest.mark.parametrize("display_name", ["sRGB - Display", "Display P3 HDR - Display"])
def test_index_rounding_bounds_ocio_coordinates_near_black(default_spec, tmp_path, display_name):
    """OCIO's lattice coordinates of a view file's pre-shaped values (its Range and shaper
    table) depart from the float64 ones by the table's output rounding (FLOAT32_MATRIX_ROUNDINGS
    u) and its index's (:func:`evaluate.index_rounding`), no more; near Display P3 HDR's black
    the index's is the larger (a thousand-entry table read hundreds of entries in)."""
    display = next(d for d in default_spec.displays if d.name == display_name)
    view = bake_view_lut(default_spec, display, "perceptual")
    path = tmp_path / view.filename
    path.write_bytes(view.data)
    cfg = ocio.Config.CreateRaw()
    ops = cfg.getProcessor(ocio.FileTransform(str(path))).createGroupTransform()
    shaper = next(i for i, op in enumerate(ops) if isinstance(op, ocio.Lut1DTransform))
    assert isinstance(ops[1], ocio.RangeTransform) and shaper == 2
    cpu = cfg.getProcessor(ocio.GroupTransform([ops[1], ops[2]])).getDefaultCPUProcessor()
    lat = view_lattice(default_spec, display, "perceptual")
    rng = np.random.default_rng(5)
    colours = rng.choice([-1.0, 1.0], (4000, 3)) * rng.random((4000, 3)) * 10.0 ** rng.uniform(-12, -1, (4000, 1))
    shaped = lat.pre.forward(colours).astype(np.float32).astype(np.float64)  # the pre-shaper's output, as OCIO holds it
    colours = lat.pre.inverse(shaped)
    pixels = np.ascontiguousarray(shaped, dtype=np.float32)
    cpu.applyRGB(pixels)
    departure = np.abs(pixels - evaluate.coordinates(lat, colours))
    table = tolerances.FLOAT32_MATRIX_ROUNDINGS * tolerances.FLOAT32_UNIT_ROUNDOFF
    assert np.all(departure <= table + evaluate.index_rounding(lat, colours))
    if display.clip_high > 1.0:
        assert np.any(departure > table)
