"""The default config through every engine, once: PyOpenColorIO (default and lossless
flags), oiiotool, Debian's ocioconvert and Blender. Under CI=true a missing host fails.
The in-process engines name a missing LUT file, and a default flag's departure by its operator.

ocioconvert converts one image per process (a third of a second each, mostly its
start-up), so here it covers every view from the scene_linear role; ``ocioforge
verify`` runs it on every check.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from generator.verify.checks import KINDS, LUT, TO_REFERENCE, VIEW
from generator.verify.judge import APPROX, NOT_RUN, PASS
from generator.verify.run import engine_registry, verify
from tests.conftest import host_missing
from tests.verify.conftest import newly_failing


@pytest.fixture(scope="module")
def everywhere(build_config):
    config = build_config((2, 1))
    missing = [
        f"{e.name}: {reason}" for family in engine_registry().values() for e in family if (reason := e.missing(config))
    ]
    if missing:
        host_missing("; ".join(missing))
    hosts = verify(config, ("ocio", "oiiotool", "blender"), density="quick", kinds=KINDS)
    convert = verify(config, ("ocio", "ocioconvert"), density="quick", kinds=(VIEW,), only=" from ACEScg")
    extra = [o for o in convert.outcomes if o.engine.startswith("ocioconvert")]
    return replace(hosts, outcomes=hosts.outcomes + tuple(extra), engines=hosts.engines + convert.engines[2:])


def test_every_engine_on_the_default_config(everywhere):
    """One test, so that the module's one verification runs once under pytest-xdist."""
    assert not [e for e in everywhere.engines if e.skipped]
    assert {e.name for e in everywhere.engines} == {
        "ocio default",
        "ocio lossless",
        *(e.name for e in engine_registry()["oiiotool"]),  # Debian's too, where it is installed
        "ocioconvert",
        "blender",
    }
    assert all(o.verdict != NOT_RUN for o in everywhere.outcomes)
    views = {o.engine for o in everywhere.outcomes if o.check.kind == "view"}
    assert {
        "oiiotool (EXR float)",
        "oiiotool (TIFF uint16)",
        "ocioconvert (EXR float)",
        "blender (PNG uint16)",
    } <= views
    approx = [o.note for o in everywhere.outcomes if o.verdict == APPROX]
    assert all("OPTIMIZATION_" in note and "Transform" in note for note in approx), approx
    inexact = [
        (o.check.title, f"{o.worst:.3g}")
        for o in everywhere.outcomes
        if o.engine == "ocio lossless" and o.verdict != PASS
    ]
    assert not inexact, f"the lossless engine misses its tolerance: {inexact}"
    failing = [(o.check.title, o.engine, f"{o.worst:.3g}", o.worst_input, o.note) for o in everywhere.failures]
    assert not failing, failing


def test_a_desaturate_chains_flag_is_named_with_its_operator(tmp_path):
    """A Desaturate chain (RGB_TO_HSV, half-domain tables, the lattice) run operator by operator
    had departed by itself (650 codes), so no operator was named: OCIO's processor cache had
    given its hue table's inverse the table's own processor (one length, a key without the
    values). Built uncached, the chain holds, and the power the fast flag approximates is named."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from generator.verify.judge import APPROX

    text = (
        '[[display]]\nname = "Odd Wide D50 - Display"\nprimaries = [[0.70, 0.29], [0.12, 0.84], [0.145, 0.035]]\n'
        'white = "D50"\neotf = { family = "gamma", exponent = 2.4 }\n'
        '[[display]]\nname = "Dim 48 - Display"\nprimaries = [[0.68, 0.32], [0.265, 0.69], [0.15, 0.06]]\n'
        'white = "D65"\neotf = { family = "gamma", exponent = 2.6 }\npeak_luminance = 48\n'
        'absolute_luminance = true\nviews = ["Desaturate"]\n'
    )
    folder = tmp_path / "dim"
    build(for_folder(load.parse(text, "dim.toml", tmp_path), folder), folder)
    result = verify(folder / "config.ocio", ("ocio",), only="Dim 48 - Display / Desaturate from Odd Wide")
    explained = [o.note for o in result.outcomes if o.verdict == APPROX]
    assert explained and all("OPTIMIZATION_FAST_LOG_EXP_POW in ExponentTransform" in note for note in explained), (
        explained
    )


def test_a_missing_lut_file_is_named_not_a_traceback(config_copy):
    missing = config_copy.parent / "luts" / "mi_log_to_linear.spi1d"
    assert newly_failing(config_copy, lambda path: missing.unlink(), (TO_REFERENCE, LUT)) == {
        "Mi-Log Rec.2020",
        "luts/mi_log_to_linear.spi1d",
    }
    result = verify(config_copy, ("ocio",), density="quick", kinds=(TO_REFERENCE, LUT), only="Mi-Log")
    notes = {o.check.item: o.note for o in result.failures}
    assert notes and all("mi_log_to_linear.spi1d" in note for note in notes.values())
    result = verify(config_copy, ("ocio",), density="quick", kinds=(LUT,), only="mi_log")
    assert {o.note for o in result.failures} == {"FileNotFoundError: missing LUT file luts/mi_log_to_linear.spi1d"}
