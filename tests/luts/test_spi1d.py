"""The .spi1d writer (generator/luts/spi1d.py), read back by OCIO and colour-science."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio

from generator.luts.spi1d import format_spi1d


def _read(path, values) -> np.ndarray:
    pixels = np.ascontiguousarray(np.repeat(np.asarray(values)[:, None], 3, axis=1), dtype=np.float32)
    transform = ocio.FileTransform(str(path), interpolation=ocio.INTERP_LINEAR)
    ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor().applyRGB(pixels)
    return pixels[:, 0]


def test_every_float32_value_reads_back_exactly():
    """Nine significant digits: a curve's toe, a huge value, a negative one and zero come back as
    the same float32, from the text and through colour-science's reader."""
    rng = np.random.default_rng(7)
    values = np.concatenate(
        [
            rng.choice([-1.0, 1.0], 4000) * 10.0 ** rng.uniform(-30, 30, 4000),
            [0.0, 1.0, -0.0078125, 1.0 / 3.0, np.finfo(np.float32).tiny, np.finfo(np.float32).max],
        ]
    ).astype(np.float32)
    text = format_spi1d(values)
    lines = text.splitlines()
    assert lines[:5] == ["Version 1", "From 0 1", f"Length {values.size}", "Components 1", "{"] and lines[-1] == "}"
    assert np.array_equal(np.array([float(line) for line in lines[5:-1]], dtype=np.float32), values)


def test_ocio_and_colour_science_read_the_table_over_its_domain(tmp_path):
    import colour

    values = (np.linspace(0.0, 1.0, 33) ** 2.6 * 7.0 - 0.5).astype(np.float32)
    path = tmp_path / "curve.spi1d"
    path.write_text(format_spi1d(values, (-0.25, 1.75)))
    lut = colour.read_LUT(str(path))
    np.testing.assert_array_equal(lut.domain, [-0.25, 1.75])
    np.testing.assert_array_equal(lut.table.astype(np.float32), values)
    entries = np.linspace(-0.25, 1.75, 33)
    np.testing.assert_allclose(_read(path, entries), values, rtol=1e-6, atol=1e-6)
    between = (entries[:-1] + entries[1:]) / 2.0
    np.testing.assert_allclose(_read(path, between), (values[:-1] + values[1:]) / 2.0, rtol=1e-6, atol=1e-6)
    np.testing.assert_allclose(_read(path, [-3.0, 9.0]), values[[0, -1]], rtol=1e-6)  # clamped at the ends


def test_the_same_values_give_the_same_bytes():
    values = np.random.default_rng(3).random(100)
    assert format_spi1d(values, (0.0, 2.0)) == format_spi1d(list(values), (0, 2))
