"""Output formats and how a written value is quantised (generator/convert/formats.py), against
OpenImageIO reading the files and half floats' own spacing."""

from __future__ import annotations

import numpy as np
import pytest

from generator.convert import formats
from tests.convert import images
from tests.convert.images import convert


@pytest.mark.parametrize(
    "fmt, depth, bits",
    [("png", "uint8", 8), ("png", "uint16", 16), ("tiff", "uint16", 16), ("dpx", "uint10", 10), ("exr", "half", 0)],
)
def test_formats_hold_the_processor_output_in_their_precision(tmp_path, capsys, config, fmt, depth, bits):
    (tmp_path / "in").mkdir()
    source = images.write(tmp_path / "in" / "p.exr", images.pixels(2), "half")
    code, out, _ = convert(
        capsys,
        source,
        "--config",
        config,
        "--from",
        "ACEScg",
        "--display",
        "sRGB - Display",
        "--view",
        "Colorimetric",
        "-o",
        tmp_path / "out",
        "--format",
        fmt,
        "--depth",
        depth,
        "--jobs",
        1,
        "--verify",
        "--sample",
        "all",
    )
    assert code == 0, out
    written_path = next((tmp_path / "out").iterdir())
    values, _ = images.read(source)
    expected = images.ocio_applied(config, values, "ACEScg", display="sRGB - Display", view="Colorimetric")
    if bits:
        stored, _ = images.read(written_path, "uint16" if bits > 8 else "uint8")
        codes = stored[..., :3].astype(np.int64) >> (16 - bits if bits > 8 else 0)
        assert np.array_equal(codes, np.rint(np.clip(expected, 0, 1) * (2**bits - 1)).astype(np.int64))
    else:
        stored, _ = images.read(written_path, "half")
        assert np.array_equal(stored[..., :3], expected.astype(np.float16))
    assert "0 depart" in out


@pytest.mark.parametrize(
    "path, name",
    [
        ("a.EXR", "exr"),
        ("a.tif", "tiff"),
        ("a.TIFF", "tiff"),
        ("s.0001.jpeg", "jpeg"),
        ("a.dpx", "dpx"),
        ("a.cin", None),
    ],
)
def test_a_suffix_names_its_format_in_any_case(path, name):
    assert formats.format_of(path) == name


@pytest.mark.parametrize(
    "fmt, asked, source_type, bits, depth",
    [
        ("exr", "float", "half", 16, "float"),  # asked
        ("exr", None, "half", 16, "half"),  # a half EXR stays half
        ("dpx", None, "uint16", 10, "uint10"),  # a 10-bit DPX stays 10-bit
        ("png", None, "uint16", 10, "uint8"),  # PNG holds no 10 bits: its default
        ("tiff", None, "double", 64, "float"),
        ("exr", None, "uint8", 8, "half"),
    ],
)
def test_the_sample_type_is_the_asked_the_sources_or_the_formats_default(fmt, asked, source_type, bits, depth):
    assert formats.choose_depth(formats.FORMATS[fmt], asked, source_type, bits) == depth


def test_the_compression_is_the_asked_the_sources_or_the_formats_default():
    exr, png = formats.FORMATS["exr"], formats.FORMATS["png"]
    assert formats.choose_compression(exr, "piz", "exr", "dwaa:45") == "piz"
    assert formats.choose_compression(exr, None, "exr", "dwaa:45") == "dwaa:45"  # its level kept
    assert formats.choose_compression(exr, None, "tiff", "lzw") == "zip"
    assert formats.choose_compression(formats.FORMATS["tiff"], None, "exr", "zip") == "zip"
    assert formats.choose_compression(png, None, "png", "") == ""


@pytest.mark.parametrize(
    "fmt, compression, depth, lossy",
    [
        ("jpeg", "", "uint8", True),
        ("exr", "dwaa:45", "half", True),
        ("exr", "B44", "half", True),
        ("exr", "pxr24", "half", False),  # 24 bits hold a half exactly
        ("exr", "pxr24", "float", True),
        ("exr", "zip", "float", False),
        ("tiff", "lzw", "uint16", False),
    ],
)
def test_only_jpeg_and_lossy_exr_compressions_are_lossy(fmt, compression, depth, lossy):
    assert formats.is_lossy(formats.FORMATS[fmt], compression, depth) is lossy


def test_ten_bit_codes_are_the_rounded_values_a_dpx_holds(tmp_path):
    """A 10-bit code goes in the top bits of a uint16, as OIIO's DPX writer takes it: the file OIIO
    writes holds the code of each clipped value, rounded (OIIO's own float reading goes through
    16 bits and is no code's value: read as stored)."""
    import OpenImageIO as oiio

    values = images.pixels(3, 3, low=-0.2, high=1.2).astype(np.float64)
    values[0, 0, :3] = [np.nan, 0.49 / 1023, 1.51 / 1023]  # not a number is black
    stored = formats.quantised(values, "uint10")
    spec = oiio.ImageSpec(images.WIDTH, images.HEIGHT, 3, "uint16")
    spec.attribute("oiio:BitsPerSample", 10)
    out = oiio.ImageOutput.create(str(tmp_path / "a.dpx"))
    assert out.open(str(tmp_path / "a.dpx"), spec) and out.write_image(stored) and out.close()
    read, written = images.read(tmp_path / "a.dpx", "uint16")
    assert written.get_int_attribute("oiio:BitsPerSample") == 10
    codes = np.rint(np.clip(np.nan_to_num(values), 0.0, 1.0) * 1023.0)
    np.testing.assert_array_equal(read.astype(np.int64) >> 6, codes)
    assert list(codes[0, 0]) == [0.0, 0.0, 2.0]
    np.testing.assert_array_equal(formats.dequantised(read, "uint10"), codes / 1023.0)


@pytest.mark.parametrize("depth, bits", [("uint8", 8), ("uint16", 16)])
def test_integer_codes_round_the_clipped_value(depth, bits):
    values = np.array([-1.0, 0.0, 0.3, 1.0 / 3.0, 1.0, 7.0, np.nan])
    stored = formats.quantised(values, depth)
    assert stored.dtype == (np.uint8 if bits == 8 else np.uint16)
    expected = np.rint(np.clip(np.nan_to_num(values), 0.0, 1.0) * (2**bits - 1))
    np.testing.assert_array_equal(stored, expected)
    np.testing.assert_array_equal(formats.dequantised(stored, depth), expected / (2**bits - 1))
    assert formats.step(stored, values, depth) == 1.0 / (2**bits - 1)


def test_a_half_floats_step_is_its_gap_toward_the_reference():
    """IEEE half: 10 fraction bits, so at 1 the next half up is 2^-10 away and the one below
    2^-11; no step beyond the largest half (65504)."""
    written = np.array([1.0, 1.0, 1024.0, 65504.0, 0.0])
    expected = np.array([1.1, 0.9, 1023.0, 1e6, 1e-9])
    step = formats.step(written, expected, "half")
    np.testing.assert_array_equal(step, [2.0**-10, 2.0**-11, 0.5, 0.0, 2.0**-24])
    assert formats.step(written, expected, "float") == 0.0
    values = np.array([0.1, 1.5])
    assert formats.quantised(values, "half") is values  # floats are written as given
