"""The default config through every engine, once: PyOpenColorIO (default and lossless
flags), oiiotool, Debian's ocioconvert and Blender. Under CI=true a missing host fails.

ocioconvert converts one image per process (a third of a second each, mostly its
start-up), so here it covers every view from the scene_linear role; ``ocioforge
verify`` runs it on every check.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from generator.verify.checks import KINDS, VIEW
from generator.verify.judge import APPROX, NOT_RUN, PASS
from generator.verify.run import engine_registry, verify
from tests.conftest import host_missing


@pytest.fixture(scope="module")
def everywhere(build_config):
    config = build_config((2, 1))
    missing = [f"{e.name}: {reason}" for family in engine_registry().values() for e in family
               if (reason := e.missing(config))]
    if missing:
        host_missing("; ".join(missing))
    hosts = verify(config, ("ocio", "oiiotool", "blender"), density="quick", kinds=KINDS)
    convert = verify(config, ("ocio", "ocioconvert"), density="quick", kinds=(VIEW,), only=" from ACEScg")
    extra = [o for o in convert.outcomes if o.engine.startswith("ocioconvert")]
    return replace(hosts, outcomes=hosts.outcomes + tuple(extra), engines=hosts.engines + convert.engines[2:])


def test_every_engine_on_the_default_config(everywhere):
    """One test, so that the module's one verification runs once under pytest-xdist."""
    assert not [e for e in everywhere.engines if e.skipped]
    assert {e.name for e in everywhere.engines} == {"ocio default", "ocio lossless", "oiiotool", "ocioconvert", "blender"}
    assert all(o.verdict != NOT_RUN for o in everywhere.outcomes)
    views = {o.engine for o in everywhere.outcomes if o.check.kind == "view"}
    assert {"oiiotool (EXR float)", "oiiotool (TIFF uint16)", "ocioconvert (EXR float)", "blender (PNG uint16)"} <= views
    approx = [o.note for o in everywhere.outcomes if o.verdict == APPROX]
    assert all("OPTIMIZATION_" in note and "Transform" in note for note in approx), approx
    inexact = [(o.check.title, f"{o.worst:.3g}") for o in everywhere.outcomes
               if o.engine == "ocio lossless" and o.verdict != PASS]
    assert not inexact, f"the lossless engine misses its tolerance: {inexact}"
    failing = [(o.check.title, o.engine, f"{o.worst:.3g}", o.worst_input, o.note) for o in everywhere.failures]
    assert not failing, failing
