"""Probe images on disk through OpenImageIO: samples written as an uncompressed float EXR 128
pixels wide and read back exactly; a 16-bit file read with its step; what cannot be judged refused."""

from __future__ import annotations

import numpy as np
import OpenImageIO as oiio
import pytest

from generator import tolerances
from generator.verify import images


def test_samples_come_back_exactly_from_a_float_exr(tmp_path):
    """300 samples: three rows of 128, the last padded with the last sample; every float32 value
    (negative, over-range, NaN, ±Inf) comes back as it was written, with no quantisation step."""
    values = np.random.default_rng(8).normal(0.0, 100.0, (300, 3))
    values[:3] = [[np.nan, 0.18, 0.18], [np.inf, -np.inf, 65504.0], [-0.0, 1e-30, -1e-7]]
    path = tmp_path / "probes.exr"
    images.write(path, values)
    spec = oiio.ImageInput.open(str(path)).spec()
    assert (spec.width, spec.height, spec.nchannels) == (128, 3, 3)
    assert spec.format == oiio.FLOAT and spec.get_string_attribute("compression") == "none"
    back, step = images.read(path, len(values))
    assert step == 0.0
    np.testing.assert_array_equal(back, values.astype(np.float32).astype(np.float64))
    padded = np.asarray(oiio.ImageBuf(str(path)).get_pixels(oiio.FLOAT)).reshape(-1, 3)
    np.testing.assert_array_equal(padded[300:], np.repeat(back[-1:], 84, axis=0))


def test_a_16_bit_file_is_read_with_its_step(tmp_path):
    path = tmp_path / "view.tif"
    codes = np.arange(0, 65536, 257, dtype=np.uint16)[:, None].repeat(3, axis=1)  # 256 samples
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), oiio.ImageSpec(128, 2, 3, oiio.UINT16))
    assert out.write_image(codes.reshape(2, 128, 3))
    out.close()
    values, step = images.read(path, 256)
    assert step == tolerances.UINT16_STEP == 1.0 / 65535
    np.testing.assert_allclose(values, codes / 65535.0, rtol=0, atol=1e-7)


def test_an_8_bit_file_is_refused(tmp_path):
    """An 8-bit file's rounding (1/255) is no engine's error: the verifier does not judge it."""
    path = tmp_path / "view.png"
    assert oiio.ImageBuf(oiio.ImageSpec(4, 1, 3, oiio.UINT8)).write(str(path))
    with pytest.raises(OSError, match="stored as uint8; the verifier reads float or 16-bit files"):
        images.read(path, 4)


def test_a_file_with_fewer_pixels_than_samples_is_refused(tmp_path):
    path = tmp_path / "short.exr"
    images.write(path, np.zeros((5, 3)))
    assert len(images.read(path, 128)[0]) == 128  # the padding is there to read
    with pytest.raises(OSError, match="holds 128 pixels, 129 expected"):
        images.read(path, 129)


def test_what_cannot_be_written_or_read_is_an_error_naming_the_file(tmp_path):
    with pytest.raises(OSError, match="missing.exr: cannot read"):
        images.read(tmp_path / "missing.exr", 1)
    with pytest.raises(OSError, match="cannot write"):
        images.write(tmp_path / "no-folder" / "probes.exr", np.zeros((1, 3)))
