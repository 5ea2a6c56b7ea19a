"""Frame patterns, ranges, folders and output names (generator/convert/frames.py)."""

from __future__ import annotations

import pytest

from generator.convert.frames import FramesError, Pattern, parse_frames, parse_pattern, sources


@pytest.mark.parametrize(
    "text, expected",
    [
        ("plates/A001.####.exr", Pattern("plates/A001.", 4, ".exr")),
        ("plates/A001.#.exr", Pattern("plates/A001.", 4, ".exr")),
        ("shot.%04d.exr", Pattern("shot.", 4, ".exr")),
        ("shot.%d.exr", Pattern("shot.", 1, ".exr")),
        ("shot_@@@.dpx", Pattern("shot_", 3, ".dpx")),
        ("shot.@.png", Pattern("shot.", 1, ".png")),
        ("shot.1001.exr", None),
    ],
)
def test_patterns_mark_the_frame_number(text, expected):
    assert parse_pattern(text) == expected


def test_a_pattern_marks_one_number():
    with pytest.raises(FramesError, match="2 times"):
        parse_pattern("a.####.####.exr")


def test_pattern_paths_pad_and_grow():
    pattern = parse_pattern("s.####.exr")
    assert pattern.path(7) == "s.0007.exr" and pattern.path(12345) == "s.12345.exr"
    assert pattern.regex().match("s.0007.exr") and pattern.regex().match("s.12345.exr")
    assert not pattern.regex().match("s.007.exr") and not pattern.regex().match("s.00007.exr")


@pytest.mark.parametrize(
    "text, frames",
    [
        ("1001-1004", (1001, 1002, 1003, 1004)),
        ("1-9x4", (1, 5, 9)),
        ("5,1-2,5", (5, 1, 2)),
        ("7", (7,)),
    ],
)
def test_ranges(text, frames):
    assert parse_frames(text) == frames


@pytest.mark.parametrize("text", ["1001-", "a-b", "10-1", "1-9x0", "-5", "1-2000000"])
def test_bad_ranges_are_refused(text):
    with pytest.raises(FramesError):
        parse_frames(text)


def _touch(folder, *names):
    folder.mkdir(parents=True, exist_ok=True)
    for name in names:
        (folder / name).write_bytes(b"")


def test_a_pattern_lists_its_frames_on_disk_in_order(tmp_path):
    _touch(tmp_path / "in", "s.1002.exr", "s.1001.exr", "s.10000.exr", "s.101.exr", "t.1001.exr", "s.1001.exr.bak")
    found = sources((str(tmp_path / "in" / "s.####.exr"),), None, str(tmp_path / "out"), ".png")
    assert [s.path.rsplit("/", 1)[1] for s in found] == ["s.1001.exr", "s.1002.exr", "s.10000.exr"]
    assert found[0].output == str(tmp_path / "out" / "s.1001.png")


def test_frames_name_exactly_the_frames_asked(tmp_path):
    _touch(tmp_path, "s.0001.exr")
    found = sources((str(tmp_path / "s.%04d.exr"),), "1-3", str(tmp_path / "out"), ".exr")
    assert [s.path for s in found] == [str(tmp_path / f"s.{f:04d}.exr") for f in (1, 2, 3)]


def test_a_folder_is_its_images_sorted(tmp_path):
    _touch(tmp_path / "in", "b.exr", "a.png", "notes.txt", ".hidden.exr")
    found = sources((str(tmp_path / "in"),), None, str(tmp_path / "out"), ".exr")
    assert [s.path.rsplit("/", 1)[1] for s in found] == ["a.png", "b.exr"]


@pytest.mark.parametrize(
    "inputs, frames, message",
    [
        (("missing.exr",), None, "does not exist"),
        (("s.####.exr",), None, "matches no file"),
        (("a.exr",), "1-2", "no input is a frame pattern"),
        (("a.exr", "a.png"), None, "would both be written"),
        (("empty",), None, "holding no image"),
    ],
)
def test_inputs_that_name_nothing_are_refused(tmp_path, monkeypatch, inputs, frames, message):
    monkeypatch.chdir(tmp_path)
    _touch(tmp_path, "a.exr", "a.png")
    (tmp_path / "empty").mkdir()
    with pytest.raises(FramesError, match=message):
        sources(inputs, frames, "out", ".exr")


def test_an_input_is_never_written_over(tmp_path):
    _touch(tmp_path, "a.exr")
    with pytest.raises(FramesError, match="over itself"):
        sources((str(tmp_path / "a.exr"),), None, str(tmp_path), ".exr")
