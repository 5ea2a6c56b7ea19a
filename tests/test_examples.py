"""The worked examples in examples/: each builds with the CLI and passes ocioforge verify."""

from __future__ import annotations

from pathlib import Path

import click
from click.testing import CliRunner

from generator.cli import main

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
