"""A show's 3D LUT files: read as colour-science writes them and applied as OpenColorIO's
FileTransform applies them, trilinear and tetrahedral, inside and outside the file's domain."""

from __future__ import annotations

import os

import colour
import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.colorimetry.look_luts import LutFileError, apply_lut3d, cached_lut3d, read_lut3d

OCIO_INTERPOLATION = {"linear": ocio.INTERP_LINEAR, "tetrahedral": ocio.INTERP_TETRAHEDRAL}
#: OpenColorIO's float32 against the float64 interpolation (measured 3.7e-7); trilinear and
#: tetrahedral interpolation of the LUTs below differ by 5e-3.
OCIO_ABSOLUTE = 2e-6


def grade(rgb: np.ndarray) -> np.ndarray:
    """A smooth, channel-mixing function for the LUTs' tables."""
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    return np.stack([r * r + 0.1 * g, np.sin(1.5 * g) + 0.2 * b, 0.5 * b + 0.3 * r * g], axis=-1)


def write(folder, name: str, domain=((0.0, 0.0, 0.0), (1.0, 1.0, 1.0)), size: int = 9) -> tuple[str, colour.LUT3D]:
    lut = colour.LUT3D(size=size, domain=np.asarray(domain, dtype=np.float64))
    lut.table = grade(lut.table)
    path = str(folder / name)
    colour.write_LUT(lut, path)
    return path, lut


def through_ocio(path: str, rgb: np.ndarray, interpolation: str) -> np.ndarray:
    config = ocio.Config.CreateRaw()
    transform = ocio.FileTransform(path, interpolation=OCIO_INTERPOLATION[interpolation])
    pixels = np.ascontiguousarray(rgb, dtype=np.float32).copy()
    config.getProcessor(transform).getDefaultCPUProcessor().applyRGB(pixels)
    return pixels.astype(np.float64)


def probes() -> np.ndarray:
    """Colours inside and beyond the domains, float32 as OCIO takes them."""
    rgb = np.random.default_rng(1).uniform(-1.0, 2.5, (2000, 3))
    return rgb.astype(np.float32).astype(np.float64)


@pytest.mark.parametrize(
    "name, domain",
    [
        ("grade.cube", ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))),
        ("wide.cube", ((-0.5, -0.25, 0.0), (1.5, 2.0, 1.0))),
        ("grade.spi3d", ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))),
    ],
)
@pytest.mark.parametrize("interpolation", ["linear", "tetrahedral"])
def test_a_lut_applies_as_ocio_applies_it(tmp_path, name, domain, interpolation):
    path, written = write(tmp_path, name, domain)
    lut = read_lut3d(path)
    np.testing.assert_allclose(lut.domain, domain, rtol=0, atol=1e-7)
    np.testing.assert_allclose(lut.table, written.table, rtol=0, atol=1e-7)  # the file's 7 decimals
    rgb = probes()
    ours = apply_lut3d(lut, rgb, interpolation)
    np.testing.assert_allclose(ours, through_ocio(path, rgb, interpolation), rtol=0, atol=OCIO_ABSOLUTE)


def test_nan_lands_on_the_domain_minimum_as_in_ocio(tmp_path):
    """OCIO scales a value onto the lattice before it meets a NaN: with DOMAIN_MIN -0.5 a NaN
    channel reads as -0.5, not as 0."""
    path = write(tmp_path, "wide.cube", ((-0.5, -0.5, -0.5), (1.5, 1.5, 1.5)))[0]
    lut = read_lut3d(path)
    nan = np.array([[np.nan, 0.5, 1.0]])
    for interpolation in ("linear", "tetrahedral"):
        minimum = apply_lut3d(lut, [[-0.5, 0.5, 1.0]], interpolation)
        assert np.array_equal(apply_lut3d(lut, nan, interpolation), minimum)
        np.testing.assert_allclose(minimum, through_ocio(path, nan, interpolation), rtol=0, atol=OCIO_ABSOLUTE)


def test_the_lattice_nodes_give_the_table_and_nan_is_zero_as_in_ocio(tmp_path):
    path = write(tmp_path, "grade.spi3d", size=5)[0]
    lut = read_lut3d(path)
    nodes = colour.LUT3D.linear_table(5)
    nan = np.array([[np.nan, 0.5, 1.0]])
    for interpolation in ("linear", "tetrahedral"):
        np.testing.assert_allclose(apply_lut3d(lut, nodes, interpolation), lut.table, rtol=0, atol=1e-15)
        zero = apply_lut3d(lut, [[0.0, 0.5, 1.0]], interpolation)
        assert np.array_equal(apply_lut3d(lut, nan, interpolation), zero)
        np.testing.assert_allclose(zero, through_ocio(path, nan, interpolation), rtol=0, atol=OCIO_ABSOLUTE)


@pytest.mark.parametrize(
    "text, words",
    [
        ("LUT_1D_SIZE 2\n0 0 0\n1 1 1\n", "holds a LUT3x1D, not a 3D LUT alone"),
        ("LUT_3D_SIZE 2\n0 0\n1 1 1\n", "colour-science cannot read it"),
    ],
    ids=["1D", "malformed"],
)
def test_a_file_that_is_no_3d_lut_is_refused(tmp_path, text, words):
    path = tmp_path / "bad.cube"
    path.write_text(text)
    with pytest.raises(LutFileError, match=words):
        read_lut3d(path)


def test_a_cached_lut_is_read_again_when_its_file_changes(tmp_path):
    path = write(tmp_path, "grade.cube", size=3)[0]
    first = cached_lut3d(path)
    assert cached_lut3d(path) is first
    lut = colour.LUT3D(size=3)
    lut.table = 1.0 - lut.table
    colour.write_LUT(lut, path)
    stat = os.stat(path)
    os.utime(path, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    again = cached_lut3d(path)
    assert again is not first
    np.testing.assert_allclose(again.table, 1.0 - colour.LUT3D.linear_table(3), rtol=0, atol=1e-7)
