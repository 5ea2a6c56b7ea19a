"""CLF files written by OCIO from the transforms the config uses (generator/luts/clf.py)."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.luts import clf, formats, hsv, transforms
from generator.luts.lattice import display_lattice


def _probes() -> np.ndarray:
    rng = np.random.default_rng(7)
    halves = np.arange(65536, dtype=np.uint16).view(np.float16).astype(np.float32)
    halves = halves[np.isfinite(halves)]
    parts = [
        rng.uniform(-1.0, 2.0, (20000, 3)),
        np.sign(rng.uniform(-1.0, 1.0, (20000, 3))) * np.exp2(rng.uniform(-24.0, 16.0, (20000, 3))),
        np.stack([halves, np.roll(halves, 7), np.abs(halves)], axis=-1),
    ]
    return np.ascontiguousarray(np.concatenate(parts), dtype=np.float32)


def _apply(transform, folder=None) -> np.ndarray:
    cfg = ocio.Config.CreateRaw()
    if folder is not None:
        cfg.setSearchPath(str(folder))
    out = _probes()
    cfg.getProcessor(transform).getOptimizedCPUProcessor(ocio.OPTIMIZATION_NONE).applyRGB(out)
    return out


def _file_agrees_with_its_transforms(tmp_path, data: bytes, steps: list) -> None:
    """The written file, read back by OCIO, runs as the transforms it was written from, to
    float32 precision (OCIO writes a matrix's and a parameter's doubles to 15 digits)."""
    (tmp_path / "f.clf").write_bytes(data)
    read = _apply(ocio.FileTransform("f.clf", interpolation=ocio.INTERP_DEFAULT), tmp_path)
    held = _apply(ocio.GroupTransform(steps))
    assert np.array_equal(np.isnan(read), np.isnan(held))
    finite = np.isfinite(held)
    assert np.array_equal(read[~finite & ~np.isnan(held)], held[~finite & ~np.isnan(held)])
    np.testing.assert_allclose(read[finite], held[finite], rtol=2.0**-22, atol=1e-30)


@pytest.mark.parametrize(
    "values",
    [
        np.round(np.random.default_rng(1).uniform(-2.0, 8.0, (500, 3)), 5),
        np.random.default_rng(2).uniform(0.0, 1.0, (500, 1)),
        np.exp2(np.random.default_rng(3).uniform(-30.0, 43.0, (500, 3))),
        np.array([[np.nan, np.inf, -np.inf], [0.0, -0.0, 1e-45]]),
    ],
    ids=["five decimals", "float32", "wide", "not finite"],
)
def test_a_table_reads_back_to_the_same_float32(values):
    values = values.astype(np.float32)
    text = clf.table_text(values)
    back = np.array([[float(v) for v in line.split()] for line in text.splitlines()], dtype=np.float32)
    assert np.array_equal(back, values, equal_nan=True)


def test_a_table_rounded_to_decimals_is_written_at_those_decimals():
    """A lattice's values keep the text its decimals give (the pack's size rests on it)."""
    text = clf.table_text(np.array([[0.5, 0.12345, 1.0], [-0.25, 0.3, 0.0]], dtype=np.float32))
    assert text == "0.5 0.12345 1\n-0.25 0.3 0\n"


@pytest.mark.parametrize(
    "source, display, method",
    [
        ("ACEScct", "sRGB - Display", "scale"),
        ("ARRI LogC4", "Rec.2100-PQ - Display", "perceptual"),
        ("sRGB Encoded Rec.709 (sRGB)", "Display P3 HDR - Display", "desaturate"),
    ],
)
def test_a_lattice_file_runs_as_its_transforms(tmp_path, default_spec, source, display, method):
    shown = next(d for d in default_spec.displays if d.name == display)
    lat = display_lattice(default_spec, shown, method, 9, source=default_spec.space(source))
    data = formats.clf(lat, "ocioforge:test", "a test")
    _file_agrees_with_its_transforms(tmp_path, data, formats.clf_steps(lat))


def test_the_hsv_files_run_as_their_transforms(tmp_path):
    (tmp_path / "f.clf").write_bytes(hsv.shared_clf())
    read = _apply(ocio.FileTransform("f.clf", interpolation=ocio.INTERP_DEFAULT), tmp_path)
    assert np.array_equal(read, _apply(ocio.GroupTransform(hsv.shared_steps())), equal_nan=True)


def test_tables_of_every_kind_are_written_whole(tmp_path):
    """OCIO writes two-entry stand-ins; each array and its dimensions are the table's own: a
    one-column 1D table, one whose channels differ in a single entry, and a trilinear 3D table."""
    ramp = np.linspace(0.0, 1.0, 11) ** 2
    mono = np.repeat(ramp[:, None], 3, axis=1)
    nearly = mono.copy()
    nearly[5, 2] += 2.0**-20
    cube = np.random.default_rng(4).uniform(-0.1, 1.1, (5, 5, 5, 3))
    steps = [transforms.lut1d(mono), transforms.lut1d(nearly), transforms.lut3d(cube, ocio.INTERP_LINEAR)]
    data = clf.clf_file(steps, "ocioforge:test", "tables")
    dims = [line.split('"')[1] for line in data.decode().splitlines() if line.startswith("<Array dim=")]
    assert dims == ["11 1", "11 3", "5 5 5 3"]
    _file_agrees_with_its_transforms(tmp_path, data, steps)
