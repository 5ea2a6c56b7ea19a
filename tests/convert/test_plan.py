"""A convert run's arguments checked and planned before any frame is read
(generator/convert/plan.py); its refusals through the command are in tests/cli/test_convert.py."""

from __future__ import annotations

import os

import pytest

from generator.convert import plan
from generator.convert.frame import EVERY_PIXEL
from generator.files import Refused
from generator.spec.schema import SpecError
from tests.convert import images


def _plan(inputs, output, config, **options):
    arguments = dict(
        src=None,
        dst="ACEScct",
        display="",
        view=None,
        frames=None,
        fmt=None,
        depth=None,
        compression=None,
        verify=False,
        sample="4096",
        skip_existing=False,
        force=False,
        memory=2**20,
    )
    arguments.update(options)
    return plan.plan_run(
        tuple(map(str, inputs)),
        str(output),
        str(config),
        arguments["src"],
        arguments["dst"],
        arguments["display"],
        arguments["view"],
        arguments["frames"],
        arguments["fmt"],
        arguments["depth"],
        arguments["compression"],
        arguments["verify"],
        arguments["sample"],
        arguments["skip_existing"],
        arguments["force"],
        arguments["memory"],
    )


@pytest.fixture
def plate(tmp_path):
    (tmp_path / "in").mkdir()
    return images.write(tmp_path / "in" / "a.png", images.pixels(1, low=0.0, high=1.0), "uint8")


def test_the_format_is_the_inputs_and_names_are_the_configs_own(tmp_path, config, plate, monkeypatch):
    """Without --format a PNG is written as PNG; an alias and a role are the colour spaces they
    name; the config's path is absolute."""
    monkeypatch.chdir(config.parent)
    planned, found = _plan([plate], tmp_path / "out", "config.ocio", src="lin_ap1", dst="color_timing")
    assert (planned.format, planned.src, planned.dst) == ("png", "ACEScg", "ACEScct")
    assert planned.config == str(config) and os.path.isabs(planned.config)
    assert [s.output for s in found] == [str(tmp_path / "out" / "a.png")]
    assert planned.verify == 0 and planned.memory == 2**20


def test_a_display_without_a_view_takes_its_default(tmp_path, config, plate):
    planned, _ = _plan([plate], tmp_path / "out", config, dst="", display="sRGB - Display", fmt="EXR", depth="HALF")
    assert (planned.display, planned.view) == ("sRGB - Display", "ACES 2.0 - SDR 100 nits (Rec.709)")
    assert (planned.format, planned.depth) == ("exr", "half")


@pytest.mark.parametrize("sample, pixels", [("all", EVERY_PIXEL), ("ALL", EVERY_PIXEL), ("500", 500)])
def test_a_sample_is_every_pixel_or_a_count_and_only_with_verify(tmp_path, config, plate, sample, pixels):
    assert _plan([plate], tmp_path / "out", config, verify=True, sample=sample)[0].verify == pixels
    assert _plan([plate], tmp_path / "out", config, verify=False, sample=sample)[0].verify == 0


def test_an_output_folder_that_is_a_file_is_refused(tmp_path, config, plate):
    (tmp_path / "out").write_text("a file")
    with pytest.raises(SpecError) as caught:
        _plan([plate], tmp_path / "out", config)
    assert caught.value.source == "-o" and "not a folder" in caught.value.message


def test_an_existing_output_is_kept_by_skip_existing_and_written_through_its_link_with_force(tmp_path, config, plate):
    """--skip-existing leaves the output for the frame to skip; --force writes the file a link
    there points to; neither, and the link is refused before any frame is read."""
    (tmp_path / "out").mkdir()
    (tmp_path / "elsewhere.png").write_bytes(b"old")
    (tmp_path / "out" / "a.png").symlink_to(tmp_path / "elsewhere.png")
    _, kept = _plan([plate], tmp_path / "out", config, skip_existing=True)
    assert [s.output for s in kept] == [str(tmp_path / "out" / "a.png")]
    _, forced = _plan([plate], tmp_path / "out", config, force=True)
    assert [s.output for s in forced] == [str(tmp_path / "elsewhere.png")]
    with pytest.raises(Refused, match="is a link; pass --force"):
        _plan([plate], tmp_path / "out", config)
