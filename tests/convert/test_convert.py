"""Frames through a config (generator/convert), driven through the command in-process."""

from __future__ import annotations

import os

import numpy as np
import pytest

from generator.cli import main
from tests.convert import images


def convert(capsys, *argv):
    try:
        main(["convert", *map(str, argv)])
        code = 0
    except SystemExit as exit_:
        code = exit_.code
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(scope="module")
def config(build_config):
    return build_config((2, 1))


def test_output_is_pyopencolorio_on_the_same_pixels(tmp_path, capsys, config):
    (tmp_path / "in").mkdir()
    source = images.write(tmp_path / "in" / "p.exr", images.pixels(1, 5), "float", compression="zip")
    code, out, _ = convert(
        capsys, source, "--config", config, "--from", "ACEScct", "--to", "ACEScg", "-o", tmp_path / "out", "--jobs", 1
    )
    assert code == 0 and "1 written" in out
    written, spec = images.read(tmp_path / "out" / "p.exr")
    values, _ = images.read(source)
    assert np.array_equal(written[..., :3], images.ocio_applied(config, values, "ACEScct", "ACEScg"))
    assert np.array_equal(written[..., 3:], values[..., 3:])  # alpha and the fifth channel as read
    assert spec.format == "float" and spec.get_string_attribute("compression") == "zip"
    assert spec.get_string_attribute("ocioforge:ColorSpace") == "ACEScg"


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
        path,
        "--config",
        config,
        "--from",
        "ACEScg",
        "--to",
        "ACEScct",
        "-o",
        tmp_path / "out",
        "--jobs",
        1,
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


def test_corrupt_and_truncated_frames_fail_alone(tmp_path, capsys, config):
    frames = images.sequence(tmp_path / "in", "s", range(1, 5))
    frames[1].write_bytes(frames[1].read_bytes()[: len(frames[1].read_bytes()) // 2])  # truncated
    frames[2].write_bytes(b"not an image at all" * 10)  # corrupt
    code, out, _ = convert(
        capsys,
        tmp_path / "in" / "s.####.exr",
        "--config",
        config,
        "--from",
        "ACEScg",
        "--to",
        "ACEScct",
        "-o",
        tmp_path / "out",
        "--jobs",
        2,
    )
    assert code == 1
    assert "FAILED" in out and "s.0002.exr" in out and "s.0003.exr" in out and "2 written" in out and "2 failed" in out
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["s.0001.exr", "s.0004.exr"]
    code, out, _ = convert(
        capsys,
        tmp_path / "in" / "s.####.exr",
        "--config",
        config,
        "--from",
        "ACEScg",
        "--to",
        "ACEScct",
        "-o",
        tmp_path / "out2",
        "--jobs",
        1,
        "--fail-fast",
    )
    assert code == 1 and "1 written" in out and "1 failed" in out and "2 not run" in out


def test_skip_existing_resumes_and_force_replaces(tmp_path, capsys, config):
    images.sequence(tmp_path / "in", "s", range(1, 4))
    args = (
        tmp_path / "in" / "s.####.exr",
        "--config",
        config,
        "--from",
        "ACEScg",
        "--to",
        "ACEScct",
        "-o",
        tmp_path / "out",
        "--jobs",
        1,
    )
    assert convert(capsys, *args, "--frames", "1-2")[0] == 0
    before = (tmp_path / "out" / "s.0001.exr").stat().st_mtime_ns
    code, out, _ = convert(capsys, *args, "--skip-existing")
    assert code == 0 and "1 written, 2 skipped" in out
    assert (tmp_path / "out" / "s.0001.exr").stat().st_mtime_ns == before
    code, _, err = convert(capsys, *args)
    assert code == 2 and err.count("\n") == 1 and "--force" in err
    assert convert(capsys, *args, "--force")[0] == 0


def test_frames_read_as_their_metadata_or_the_file_rules(tmp_path, capsys, config):
    (tmp_path / "in").mkdir()
    images.write(tmp_path / "in" / "tagged.exr", images.pixels(3), "half", ocioforge__ColorSpace="ACEScct")
    images.write(tmp_path / "in" / "plain.exr", images.pixels(4), "half")
    code, out, _ = convert(
        capsys, tmp_path / "in", "--config", config, "--to", "ACEScct", "-o", tmp_path / "out", "--jobs", 1
    )
    assert code == 0, out
    tagged, _ = images.read(tmp_path / "out" / "tagged.exr")
    assert np.array_equal(tagged, images.read(tmp_path / "in" / "tagged.exr")[0])  # ACEScct to itself
    plain, _ = images.read(tmp_path / "out" / "plain.exr")  # EXR: the file rules' scene_linear, ACEScg
    values = images.read(tmp_path / "in" / "plain.exr")[0]
    expected = images.ocio_applied(config, values, "ACEScg", "ACEScct")
    assert np.array_equal(plain[..., :3], expected.astype(np.float16).astype(np.float32))


def test_verify_names_a_frame_that_departs_with_its_worst_pixel(tmp_path, capsys, build_config):
    """A config whose numbers are not its stored spec's (a matrix edited, nothing else) writes frames
    that depart; the run says where and fails."""
    import shutil

    folder = tmp_path / "edited"
    shutil.copytree(build_config((2, 1)).parent, folder)
    text = (folder / "config.ocio").read_text()
    import re

    block = text[text.index("name: ACEScct") :]
    match = re.search(r"matrix: \[([-0-9.e]+)", block)
    edited = block.replace(match.group(0), f"matrix: [{float(match.group(1)) * 1.01!r}", 1)
    (folder / "config.ocio").write_text(text[: text.index("name: ACEScct")] + edited)
    images.sequence(tmp_path / "in", "s", [1])
    code, out, _ = convert(
        capsys,
        tmp_path / "in" / "s.0001.exr",
        "--config",
        folder,
        "--from",
        "ACEScct",
        "--to",
        "ACEScg",
        "-o",
        tmp_path / "out",
        "--jobs",
        1,
        "--verify",
    )
    assert code == 1
    assert "DEPARTS" in out and "pixel (" in out and "above 0.0001" in out and "1 depart" in out


def test_sigkill_leaves_no_partial_frame_under_a_final_name(tmp_path, config):
    import signal
    import subprocess
    import sys
    import time

    folder = tmp_path / "in"
    folder.mkdir()
    big = images.pixels(5)
    big = np.tile(big, (12, 12, 1))  # 768 x 576: frames that take a moment
    for f in range(1, 13):
        images.write(folder / f"s.{f:04d}.exr", big, "float", compression="zip")
    args = [
        sys.executable,
        "-m",
        "generator",
        "convert",
        str(folder / "s.####.exr"),
        "--config",
        str(config),
        "--from",
        "ACEScg",
        "--to",
        "ACEScct",
        "-o",
        str(tmp_path / "out"),
        "--jobs",
        "2",
    ]
    process = subprocess.Popen(args, start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and not any(p.suffix == ".exr" for p in (tmp_path / "out").glob("*.exr")):
        time.sleep(0.01)
    os.killpg(process.pid, signal.SIGKILL)
    process.wait()
    finals = sorted((tmp_path / "out").glob("*.exr"))
    assert 0 < len(finals) < 12, "killed before any frame, or after all: no test"
    for path in finals:  # each whole: every pixel reads and is what the complete frame holds
        written, _ = images.read(path)
        values, _ = images.read(folder / path.name)
        assert np.array_equal(written[..., :3], images.ocio_applied(config, values, "ACEScg", "ACEScct"))
        assert np.array_equal(written[..., 3], values[..., 3])
