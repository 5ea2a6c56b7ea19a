"""Reading and writing a frame's pixels through OpenImageIO, a band of rows at a time
(generator/convert/pixels.py)."""

from __future__ import annotations

import itertools
import os

import numpy as np
import pytest

from generator.convert import formats, pixels
from tests.convert import images
from tests.convert.images import convert


def _part(path, index: int = 0) -> pixels.Part:
    inp = pixels.open_input(str(path))
    try:
        return pixels.parts(inp, True)[index]
    finally:
        inp.close()


def test_windows_tiles_metadata_and_parts_are_kept(tmp_path, capsys, config):
    import OpenImageIO as oiio

    (tmp_path / "in").mkdir()
    path = tmp_path / "in" / "multi.exr"
    specs = []
    for index, (channels, tile) in enumerate(((4, 16), (3, 16))):
        spec = oiio.ImageSpec(images.WIDTH, images.HEIGHT, channels, oiio.HALF)
        spec.x, spec.y = 5, 3
        spec.full_x, spec.full_y, spec.full_width, spec.full_height = 0, 0, 80, 60
        spec.tile_width = spec.tile_height = tile
        spec.attribute("name", f"part{index}")
        spec.attribute("Artist", "someone")
        spec.attribute("compression", "piz")
        specs.append(spec)
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), specs)
    for index, spec in enumerate(specs):
        assert index == 0 or out.open(str(path), spec, "AppendSubimage")
        assert out.write_image(images.pixels(10 + index, spec.nchannels))
    out.close()
    code, stdout, _ = convert(
        capsys,
        *images.cg_to_cct(path, config, tmp_path / "out", 1),
        "--verify",
        "--memory",
        1,
    )
    assert code == 0, stdout
    for index in range(2):
        written, spec = images.read(tmp_path / "out" / "multi.exr", subimage=index)
        values, source = images.read(path, subimage=index)
        assert (spec.x, spec.y, spec.full_width, spec.full_height, spec.tile_width) == (5, 3, 80, 60, source.tile_width)
        assert spec.get_string_attribute("Artist") == "someone" and spec.get_string_attribute("compression") == "piz"
        expected = images.ocio_applied(config, values, "ACEScg", "ACEScct")
        assert np.array_equal(written[..., :3], expected.astype(np.float16).astype(np.float32))


def test_bands_of_rows_write_the_same_bytes(tmp_path, capsys, config):
    images.sequence(tmp_path / "in", "s", [1])
    args = (tmp_path / "in" / "s.####.exr", "--config", config, "--from", "ACEScg", "--to", "ACEScct", "--jobs", 1)
    assert convert(capsys, *args, "-o", tmp_path / "whole")[0] == 0
    assert convert(capsys, *args, "-o", tmp_path / "bands", "--memory", 1)[0] == 0  # 1 MiB: bands of rows
    import generator.convert.pixels as pixels

    assert (tmp_path / "whole" / "s.0001.exr").read_bytes() == (tmp_path / "bands" / "s.0001.exr").read_bytes()
    assert pixels.band_rows(images.read(tmp_path / "in" / "s.0001.exr")[1], 2**20, 1) < images.HEIGHT * 100


@pytest.mark.parametrize(
    "names, rgb",
    [
        (("R", "G", "B", "A"), (0, 1, 2)),
        (("a", "b", "g", "r"), (3, 2, 1)),
        (("Z", "R", "G", "B"), (1, 2, 3)),
        (("diffuse.R", "diffuse.G", "diffuse.B"), ()),
        (("R", "G", "A"), ()),
        (("Y",), ()),
    ],
)
def test_colour_channels_are_found_by_name_in_any_case(names, rgb):
    assert pixels.rgb_channels(names) == rgb


def test_a_file_that_is_no_image_is_one_line(tmp_path):
    (tmp_path / "a.exr").write_bytes(b"not an image" * 20)
    with pytest.raises(pixels.FrameError) as caught:
        pixels.open_input(str(tmp_path / "a.exr"))
    assert str(caught.value) and "\n" not in str(caught.value)


@pytest.mark.parametrize("tile", [0, 16])
def test_bands_cover_the_data_window_and_read_as_oiio_reads_the_image(tmp_path, tile):
    """A band of rows (whole rows of tiles in a tiled file) read piecewise is the image OIIO
    reads whole; bands start on a tile's first row."""
    import OpenImageIO as oiio

    path = str(tmp_path / "a.exr")
    values = images.pixels(9)
    spec = oiio.ImageSpec(images.WIDTH, images.HEIGHT, 4, oiio.FLOAT)
    spec.y, spec.x = 3, 5
    spec.tile_width = spec.tile_height = tile
    out = oiio.ImageOutput.create(path)
    assert out.open(path, spec) and out.write_image(values) and out.close()
    part = _part(path)
    budget = images.WIDTH * 4 * 4 * pixels.BAND_COPIES * 20  # twenty rows
    bands = pixels.bands(part, budget)
    assert bands[0][0] == 3 and bands[-1][1] == 3 + images.HEIGHT
    assert all(a[1] == b[0] for a, b in itertools.pairwise(bands)) and len(bands) == 3
    if tile:
        assert all((y0 - 3) % tile == 0 for y0, _ in bands)
    inp = pixels.open_input(path)
    try:
        read = np.concatenate([pixels.read_rows(inp, part, y0, y1) for y0, y1 in bands])
        middle = pixels.read_rows(inp, part, 20, 22)  # inside a tile's rows
    finally:
        inp.close()
    np.testing.assert_array_equal(read, values)
    np.testing.assert_array_equal(middle, values[17:19])


def test_a_truncated_file_fails_as_a_read_error(tmp_path):
    path = images.write(tmp_path / "a.exr", images.pixels(2), "float", compression="none")
    path.write_bytes(path.read_bytes()[: path.stat().st_size // 2])
    part = _part(path)
    inp = pixels.open_input(str(path))
    try:
        with pytest.raises(pixels.FrameError, match=f"rows 0 to {images.HEIGHT - 1}"):
            pixels.read_rows(inp, part, 0, images.HEIGHT)
    finally:
        inp.close()


@pytest.mark.parametrize(
    "fmt, kept",
    [("exr", (0, 1, 2, 3, 4)), ("tiff", (0, 1, 2, 3, 4)), ("png", (0, 1, 2, 3)), ("jpeg", (0, 1, 2))],
)
def test_a_format_keeps_the_channels_it_holds(tmp_path, fmt, kept):
    import OpenImageIO as oiio

    path = str(tmp_path / "a.exr")
    spec = oiio.ImageSpec(images.WIDTH, images.HEIGHT, 5, oiio.HALF)
    spec.channelnames = ("R", "G", "B", "A", "Z")
    spec.alpha_channel, spec.z_channel = 3, 4
    out = oiio.ImageOutput.create(path)
    assert out.open(path, spec) and out.write_image(images.pixels(1, 5)) and out.close()
    assert pixels.kept_channels(_part(path), formats.FORMATS[fmt]) == kept


def test_a_frame_without_colour_channels_is_refused_where_the_format_needs_them(tmp_path):
    import OpenImageIO as oiio

    path = str(tmp_path / "depth.exr")
    spec = oiio.ImageSpec(images.WIDTH, images.HEIGHT, 1, oiio.FLOAT)
    spec.channelnames = ("Z",)
    out = oiio.ImageOutput.create(path)
    assert out.open(path, spec) and out.write_image(images.pixels(1, 1)) and out.close()
    part = _part(path)
    assert part.rgb == () and pixels.kept_channels(part, formats.FORMATS["exr"]) == (0,)
    with pytest.raises(pixels.FrameError, match=r"no R, G, B channels \(Z\)"):
        pixels.kept_channels(part, formats.FORMATS["png"])


def test_an_output_spec_records_its_colour_space_sample_type_and_date(tmp_path):
    """The date is the source's, else the stamp given: the source file's modification time in
    UTC (a PNG holds no date), so that a rerun writes the same bytes."""
    path = images.write(tmp_path / "a.png", images.pixels(4, low=0.0, high=1.0), "uint8")
    os.utime(path, (1_000_000_000, 1_000_000_000))
    stamp = pixels.stamp_of(str(path))
    assert stamp == "2001:09:09 01:46:40"
    part = _part(path)
    assert not part.spec.getattribute("DateTime")
    spec = pixels.output_spec(part, formats.FORMATS["dpx"], "uint10", "", "ACEScct", (0, 1, 2, 3), stamp)
    assert spec.get_int_attribute("oiio:BitsPerSample") == 10 and str(spec.format) == "uint16"
    assert spec.get_string_attribute(pixels.COLOUR_SPACE) == "ACEScct"
    assert spec.get_string_attribute("DateTime") == stamp and spec.alpha_channel == 3
    assert spec.get_int_attribute("oiio:UnassociatedAlpha") == 1 and spec.get_string_attribute("compression") == ""
    tiled = images.write(tmp_path / "b.exr", images.pixels(4), "half", tile=16, DateTime="2020:01:02 03:04:05")
    kept = pixels.output_spec(_part(tiled), formats.FORMATS["exr"], "half", "piz", "ACEScct", (0, 1, 2), stamp)
    assert kept.tile_width == 16 and kept.nchannels == 3 and kept.alpha_channel == -1
    assert kept.get_string_attribute("DateTime") == "2020:01:02 03:04:05"
    assert kept.get_string_attribute("compression") == "piz" and str(kept.format) == "half"
    untiled = pixels.output_spec(_part(tiled), formats.FORMATS["png"], "uint8", "", "ACEScct", (0, 1, 2, 3), stamp)
    assert untiled.tile_width == 0
