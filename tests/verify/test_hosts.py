"""Which OpenColorIO each host engine runs, said beside its result; Debian's oiiotool beside pip's."""

from __future__ import annotations

import os
import re
import shutil

import pytest

from generator.verify.hosts import OcioconvertEngine, linked_ocio, ocio_in, oiiotool_engines
from tests.conftest import host_missing, require_program

VERSION = re.compile(r"OCIO \d+\.\d+\.\d+")


@pytest.mark.parametrize(
    "text, version",
    [
        ("OpenColorIO 2.1.2, color config: built-in", "2.1.2"),  # oiiotool 2.4's --help
        ("Dependencies: expat 2.6.3, OpenColorIO 2.5.1, OpenEXR 3.5.2", "2.5.1"),  # oiiotool 3.x
        ("no colour management", ""),
    ],
)
def test_the_ocio_a_host_names_is_read_from_its_words(text, version):
    assert ocio_in(text) == version


def test_the_ocio_a_program_loads_is_read_from_its_library():
    program = require_program("ocioconvert")
    assert re.fullmatch(r"2\.\d+\.\d+", linked_ocio(program)), linked_ocio(program)
    assert linked_ocio(shutil.which("ldd") or program) == ""  # no OCIO linked: no version


def test_debians_oiiotool_is_an_engine_of_its_own_beside_pips():
    system = shutil.which("oiiotool", path="/usr/bin")
    engines = oiiotool_engines()
    if system is None or len(engines) == 1:
        host_missing("one oiiotool only: a second engine needs pip's and Debian's")
    assert [e.name for e in engines] == ["oiiotool", "oiiotool system"]
    assert os.path.realpath(engines[1].executable()) == os.path.realpath(system)
    assert all(VERSION.search(e.version()) for e in engines)
    assert "OCIO 2.1" in engines[1].version() and f"({system})" in engines[1].version()


def test_verify_says_which_ocio_each_host_runs(build_config, tmp_path):
    """Each engine's line names the OpenColorIO it runs: oiiotool's from its help, ocioconvert's
    and Blender's from the library they load (they print none)."""
    from tests.cli.test_verify_cli import run

    require_program("ocioconvert")
    require_program("oiiotool")
    engines = ("--engines", "oiiotool,ocioconvert")
    result = run("verify", build_config((2, 1)), *engines, "--quick", "--only", "ACEScct -> ACES2065-1", "--summary")
    lines = [line for line in result.output.splitlines() if re.match(r"  engine [^:]+: ", line)]
    names = [e.name for e in oiiotool_engines()] + ["ocioconvert"]
    assert [line.split(":")[0].removeprefix("  engine ") for line in lines] == names, result.output
    assert all(VERSION.search(line) for line in lines), lines
    assert result.exit_code == 0, result.output


def test_a_host_that_cannot_load_the_config_says_which_ocio_refused_it(build_config):
    """Debian's ocioconvert and oiiotool (OCIO 2.1) cannot load a 2.5 config: each is reported not
    run with the OCIO it runs; Debian's oiiotool, run beside pip's (which loads it), fails nothing."""
    from generator.verify.report import summary
    from generator.verify.run import verify
    from tests.conftest import NEWEST

    require_program("ocioconvert")
    assert NEWEST >= (2, 5), "the pinned PyOpenColorIO writes 2.5 configs"
    only = "ACEScct -> ACES2065-1"
    result = verify(build_config((2, 5)), ("oiiotool", "ocioconvert"), density="quick", only=only, strict=True)
    runs = {e.name: e for e in result.engines}
    assert runs["ocioconvert"].skipped, f"Debian's ocioconvert loaded a 2.5 config ({runs['ocioconvert'].version})"
    assert runs["ocioconvert"].version == OcioconvertEngine().version() and VERSION.search(runs["ocioconvert"].version)
    lines = summary(result).splitlines()
    assert f"  engine ocioconvert: not run ({runs['ocioconvert'].version}): " in "\n".join(lines)
    assert result.missing == ["ocioconvert"] and not result.passed  # named, it must run
    system = runs.get("oiiotool system")
    if system is not None:
        assert system.skipped and "OCIO 2.1" in system.version and not runs["oiiotool"].skipped
        assert any(line.startswith("  engine oiiotool system: not run (OpenImageIO") for line in lines)
        alone = verify(build_config((2, 5)), ("oiiotool",), density="quick", only=only, strict=True)
        assert alone.passed and [e.name for e in alone.engines if e.skipped] == ["oiiotool system"]


def test_blender_says_which_ocio_it_runs():
    from generator.verify.blender import BlenderEngine

    require_program("blender")
    assert re.search(r"^Blender \d.*, OCIO (\d+\.\d+\.\d+|unknown)", BlenderEngine().version())
