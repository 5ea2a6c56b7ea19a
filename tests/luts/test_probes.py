"""Probe and training colours of a LUT: only colours the source's encoding holds."""

from __future__ import annotations

import numpy as np
import pytest

from generator import reference
from generator.luts import bake, fit, probes
from generator.spec import load

#: A custom curve tabulated up to linear 1.0 (display white): it cannot hold brighter colours.
TABLE = "code,linear\n0,0\n0.25,0.02\n0.5,0.12\n0.75,0.45\n1,1\n"


@pytest.fixture(scope="module")
def tabulated_spec(tmp_path_factory):
    folder = tmp_path_factory.mktemp("tabulated")
    (folder / "curve.csv").write_text(TABLE)
    (folder / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", '
        '"CIE XYZ-D65 - Scene-referred"]\n'
        '[[custom_space]]\nname = "Tab"\ngamut = "P3-D65"\ntransfer = { family = "tabulated", file = "curve.csv" }\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
    )
    return load.load(folder / "show.toml")


def test_a_tabulated_source_holds_the_colours_within_its_table(tabulated_spec):
    source = tabulated_spec.space("Tab")
    rng = np.random.default_rng(5)
    linear = rng.uniform(-0.2, 1.5, (4000, 3))
    ref = reference.apply_matrix(reference.space_matrix(tabulated_spec, source), linear)
    within = np.all((linear >= 0.0) & (linear <= 1.0), axis=-1)
    assert np.array_equal(probes.representable(tabulated_spec, source, ref), within)


def test_training_colours_of_a_bounded_source_are_colours_it_holds(tabulated_spec):
    source, display = tabulated_spec.space("Tab"), tabulated_spec.displays[0]
    for name, (code, expected) in probes.training(tabulated_spec, source, display, "scale", 2048).items():
        ref = reference.to_reference(tabulated_spec, source, code)
        assert probes.representable(tabulated_spec, source, ref, code).all(), name
        assert len(code) == len(expected)


def test_the_fit_improves_on_sampled_nodes_for_a_bounded_source(tabulated_spec, tmp_path, monkeypatch):
    """Colours beyond the table clamp to its end: trained on them, the fit pulled the top
    nodes toward brighter colours than the input can express (in-gamut p99 73 ten-bit
    codes, against 13.5 for the sampled node values)."""
    import PyOpenColorIO as ocio

    req = bake.request(tabulated_spec, "Tab", "sRGB - Display", "scale", "resolve_cube", 33)

    def measured(name):
        path = tmp_path / name
        path.write_bytes(bake.bake(req)[""])
        apply = probes.ocio_apply(ocio.FileTransform(str(path), interpolation=ocio.INTERP_TETRAHEDRAL))
        return probes.measure(tabulated_spec, req.source, req.display, "scale", apply)

    fitted = measured("fitted.cube")
    monkeypatch.setattr(fit, "reweighted_fit", lambda lat, colours, zero: lat.cube)
    sampled = measured("sampled.cube")
    assert fitted.keys() == sampled.keys()
    for name in fitted:
        assert fitted[name].p99 <= sampled[name].p99, name
