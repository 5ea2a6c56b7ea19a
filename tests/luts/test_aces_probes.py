"""The colours a baked ACES view is fitted to and measured on."""

from __future__ import annotations

import numpy as np

from generator import reference
from generator.luts import aces_probes


def test_six_kinds_drawn_from_a_seed(default_spec):
    display = next(d for d in default_spec.displays if d.name == "sRGB - Display")
    first, again = (aces_probes.sets(display, aces_probes.PROBE_SEED, 100) for _ in range(2))
    assert tuple(first) == aces_probes.SETS and set(aces_probes.LABELS) == set(aces_probes.SETS)
    assert all(np.array_equal(first[k], again[k]) for k in first)
    assert not np.array_equal(first["ap0"], aces_probes.sets(display, aces_probes.TRAINING_SEED, 100)["ap0"])
    greys = first["greys"]  # bench/aces_views.py's ramp: 2001 greys from 1e-4 to 100
    assert greys.shape == (2001, 3) and np.isclose(greys[0, 0], 1e-4) and np.isclose(greys[-1, 0], 100.0)
    assert first["dark"].max(axis=1).min() >= 1e-4 and first["dark"].max(axis=1).max() <= 0.1
    assert first["bright"].max(axis=1).min() >= 1.0 and first["bright"].max(axis=1).max() <= 64.0
    # the camera kind is ARRI Wide Gamut 4's edges: most of it lies outside AP1
    from generator.rendering import views

    ap1 = first["camera"] @ views.tables(views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"]).ap0_to_ap1.T
    assert (ap1.min(axis=1) < 0).mean() > 0.5


def test_colours_in_a_source_are_those_it_holds_with_the_views_codes(default_spec):
    display = next(d for d in default_spec.displays if d.name == "Rec.2100-PQ - Display")
    view = "ACES 2.0 - HDR 1000 nits (P3 D65)"
    aces = aces_probes.sets(display, aces_probes.PROBE_SEED, 200)["ap0"]
    source = default_spec.space("ACEScct")
    code, expected = aces_probes.in_source(default_spec, source, display, view, aces)
    assert len(code) == len(aces)  # ACEScct's curve holds every value
    np.testing.assert_allclose(
        expected, reference.aces_view(default_spec, display, view, reference.to_reference(default_spec, source, code))
    )
    kept, _ = aces_probes.in_source(default_spec, source, display, view, aces, domain=(0.1, 0.5))
    assert 0 < len(kept) < len(aces) and kept.min() >= 0.1 and kept.max() <= 0.5
