"""The worked examples in examples/: each builds with the CLI and passes ocioforge verify."""

from __future__ import annotations

import shutil
from pathlib import Path

import click
from click.testing import CliRunner

from generator.cli import main
from generator.luts import aces_probes, pack, probes
from generator.spec import load

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@click.command(context_settings={"ignore_unknown_options": True, "help_option_names": []})
@click.argument("argv", nargs=-1, type=click.UNPROCESSED)
def ocioforge(argv):
    """The command line through its entry point, whose error handling is part of what is tested."""
    main(list(argv))


def run(command, *args):
    return CliRunner().invoke(ocioforge, [command, *map(str, args)])


def test_show_builds_and_verifies(tmp_path):
    folder = tmp_path / "show"
    built = run("build", EXAMPLES / "show" / "spec.toml", "-o", folder)
    assert built.exit_code == 0, built.output
    config = (folder / "config.ocio").read_text()
    assert "ACES 2.0 - HDR 1500 nits (LED Wall)" in config
    assert "ACES 2.0 - SDR 100 nits (Rec.709)" in config
    assert (folder / "luts" / "view_led_wall_scale_17.clf").is_file()
    # PyOpenColorIO alone (default and lossless flags), every check on the full probe sets.
    verified = run("verify", folder, "--engines", "ocio", "--summary")
    assert verified.exit_code == 0, verified.output
    assert "verify passed" in verified.output
    # The monitor's view applies the show look and the shot's grade: each shot's file checked.
    assert (folder / "looks" / "shots" / "sh020.cc").is_file()
    other_shot = run("verify", folder, "--engines", "ocio", "--summary", "--context", "SHOT=sh020", "--only", "look")
    assert other_shot.exit_code == 0, other_shot.output


def test_show_pack_bakes(tmp_path, monkeypatch):
    """The show's [[lut_pack]] tables plan as written, and bake (at small sizes, fewer probes)."""
    spec = EXAMPLES / "show" / "spec.toml"
    names = [item.name for item in pack.plan(load.load(spec))]
    assert "arri_logc4_led_wall.cube" in names and "acescg_to_led_wall.clf" in names and len(names) == 14
    monkeypatch.setattr(probes, "COUNT", 128)
    monkeypatch.setattr(aces_probes, "PROBE_COUNT", 128)
    shutil.copytree(spec.parent, tmp_path / "show")  # with the files the spec names (looks)
    small = tmp_path / "show" / "spec.toml"
    small.write_text(spec.read_text().replace("size = 33", "size = 5").replace("size = 17", "size = 5"))
    packed = run("pack", small, "-o", tmp_path / "luts")
    assert packed.exit_code == 0, packed.output
    written = {p.name for p in (tmp_path / "luts").iterdir()}
    assert written == {*names, "README.md", ".ocioforge-pack.json"}
    readme = (tmp_path / "luts" / "README.md").read_text()
    assert "| arri_logc4_led_wall.cube | ARRI LogC4 | ACES 2.0 - HDR 1500 nits (LED Wall) | LED Wall | 5³ |" in readme
