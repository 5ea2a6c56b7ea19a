"""One frame through a config: read, converted by OCIO, written whole under its name
(generator/convert/frame.py), driven through the command in-process."""

from __future__ import annotations

import os

import numpy as np

from generator.avx_state import upper_in_use
from tests.convert import images
from tests.convert.images import convert
from tests.test_avx_state import dirty_upper, needs_xinuse


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


def test_skip_existing_resumes_and_force_replaces(tmp_path, capsys, config):
    images.sequence(tmp_path / "in", "s", range(1, 4))
    args = images.cg_to_cct(tmp_path / "in" / "s.####.exr", config, tmp_path / "out", 1)
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
        *images.cg_to_cct(str(folder / "s.####.exr"), str(config), str(tmp_path / "out"), "2"),
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


def _plan(config, **options):
    from generator.convert.frame import Plan

    return Plan(str(config), "ACEScg", "ACEScct", **options)


def _source(tmp_path, name="s.0001.exr", **attributes):
    from generator.convert.frames import Source

    (tmp_path / "in").mkdir(exist_ok=True)
    (tmp_path / "out").mkdir(exist_ok=True)
    path = images.write(tmp_path / "in" / name, images.pixels(6), "half", **attributes)
    return Source(str(path), str(tmp_path / "out" / name))


def _left(tmp_path) -> list[str]:
    return sorted(p.name for p in (tmp_path / "out").iterdir())


def test_the_written_space_is_the_configs_name_for_it(config):
    from generator.convert.frame import Plan, written_space

    assert written_space(Plan(str(config), "ACEScct", "lin_ap1")) == "ACEScg"
    shown = Plan(str(config), "ACEScg", display="sRGB - Display", view="Colorimetric")
    assert written_space(shown) == "Colorimetric - sRGB - Display"
    assert written_space(Plan(str(config), "ACEScg", display="sRGB - Display", view="Raw")) == "Raw"


def test_a_sample_of_pixels_is_evenly_spaced_rows_first_and_last_included(tmp_path):
    from generator.convert import pixels
    from generator.convert.frame import EVERY_PIXEL, sampled_rows

    path = images.write(tmp_path / "a.exr", images.pixels(1), "half")
    inp = pixels.open_input(str(path))
    part = pixels.parts(inp, False)[0]
    inp.close()
    assert sampled_rows(part, EVERY_PIXEL) == list(range(images.HEIGHT))
    rows = sampled_rows(part, 5 * images.WIDTH)
    assert rows == [0, 12, 24, 35, images.HEIGHT - 1]
    assert sampled_rows(part, 1) == [0, images.HEIGHT - 1]
    assert sampled_rows(part, 10**9) == list(range(images.HEIGHT))


def test_a_source_compressed_lossily_cannot_be_verified_and_leaves_nothing(tmp_path, config):
    """Its compression kept (dwaa), the frame would be written lossily: it fails, unwritten."""
    from generator.convert.frame import EVERY_PIXEL, FAILED, convert_frame

    result = convert_frame(_plan(config, verify=EVERY_PIXEL), _source(tmp_path, compression="dwaa:45"))
    assert result.status == FAILED and "lossy" in result.reason and not result.ok
    assert _left(tmp_path) == []
    written = convert_frame(_plan(config, verify=EVERY_PIXEL, compression="zip"), _source(tmp_path))
    assert written.ok and written.verdict.passed and written.src == "ACEScg"


def test_an_output_that_appears_meanwhile_is_kept_unless_it_is_this_frames_own(tmp_path, config):
    """Without --force, an output there already was written during the run: the same bytes are a
    worker's that died before saying so, and stand; another file is refused and left alone."""
    from generator.convert.frame import FAILED, WRITTEN, convert_frame

    source = _source(tmp_path)
    assert convert_frame(_plan(config), source).status == WRITTEN
    first = (tmp_path / "out" / "s.0001.exr").read_bytes()
    assert convert_frame(_plan(config), source).status == WRITTEN
    (tmp_path / "out" / "s.0001.exr").write_bytes(b"someone else's")
    refused = convert_frame(_plan(config), source)
    assert refused.status == FAILED and "appeared during the run" in refused.reason
    assert (tmp_path / "out" / "s.0001.exr").read_bytes() == b"someone else's" and _left(tmp_path) == ["s.0001.exr"]
    os.chmod(tmp_path / "out" / "s.0001.exr", 0o640)
    assert convert_frame(_plan(config, force=True), source).status == WRITTEN
    assert (tmp_path / "out" / "s.0001.exr").read_bytes() == first
    assert (tmp_path / "out" / "s.0001.exr").stat().st_mode & 0o777 == 0o640


@needs_xinuse
def test_ocio_and_the_check_run_with_the_avx_upper_halves_unused(tmp_path, capsys, config, monkeypatch):
    # a reader leaving them in use made OCIO's SSE code ten times slower, numpy's 2.5 times
    import PyOpenColorIO as ocio

    from generator.convert import frame, pixels

    apply_rgb, judge, seen = ocio.CPUProcessor.applyRGB, frame.judge, []

    def dirtying(read):
        def read_then_dirty(*args):
            out = read(*args)
            dirty_upper()
            return out

        return read_then_dirty

    def seen_then(function):
        def wrapped(*args):
            seen.append((function.__name__, upper_in_use()))
            return function(*args)

        return wrapped

    monkeypatch.setattr(pixels, "read_rows", dirtying(pixels.read_rows))
    monkeypatch.setattr(frame, "_sampled", dirtying(frame._sampled))
    monkeypatch.setattr(ocio.CPUProcessor, "applyRGB", seen_then(apply_rgb))
    monkeypatch.setattr(frame, "judge", seen_then(judge))
    (tmp_path / "in").mkdir()
    source = images.write(tmp_path / "in" / "p.exr", images.pixels(2, 3), "half", compression="zip")
    out = tmp_path / "out"
    code, text, _ = convert(capsys, source, "--config", config, "--to", "ACEScg", "-o", out, "--jobs", 1, "--verify")
    assert code == 0 and "1 written" in text
    assert {name for name, _ in seen} == {"applyRGB", "judge"} and not any(dirty for _, dirty in seen)
