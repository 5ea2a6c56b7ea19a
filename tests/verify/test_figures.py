"""The report's figures: chromaticities drawn only for colours that have one."""

from __future__ import annotations

import numpy as np

from generator.verify.figures import _xy


def test_black_has_no_chromaticity_and_is_not_drawn():
    """Desaturate sends a colour of negative luminance to black; it was drawn at xy (0, 0)."""
    xyz = np.array([[0.9505, 1.0, 1.089], [0.0, 0.0, 0.0], [0.2, 0.1, 0.0]])
    xy = _xy(xyz)
    assert xy.shape == (2, 2)
    np.testing.assert_allclose(xy, [[0.3127, 0.3290], [2.0 / 3.0, 1.0 / 3.0]], atol=1e-4)


def test_a_name_the_font_lacks_draws_without_warnings():
    """A display named in a script the font lacks (日本): matplotlib warned per glyph on the
    command's standard error."""
    import warnings

    from generator.verify.figures import _pyplot, png

    figure, axes = _pyplot().subplots()
    axes.set_title("LED Wall 日本")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert png(figure).startswith(b"\x89PNG")
    assert not [w for w in caught if "Glyph" in str(w.message)]


def _panels(figure) -> dict:
    """The drawn panels of a figure by title."""
    return {axes.get_title(): axes for axes in figure.axes if axes.axison}


def test_the_mapping_figure_has_a_panel_per_method_and_desaturate_moves_toward_white(default_spec):
    """The lecture's picture: each probe's move is a line from where it was to where the method
    put it; desaturation's lines run toward the display's white."""
    from generator.gamut import METHODS
    from generator.verify.figures import _pyplot, mapping

    display = next(d for d in default_spec.displays if not d.is_hdr)
    figure = mapping(default_spec, display)
    panels = _panels(figure)
    names = [title.split(":")[0] for title in panels]
    assert names[: len(METHODS)] == list(METHODS)
    desaturate = next(axes for title, axes in panels.items() if title.startswith("desaturate:"))
    (moves,) = [c for c in desaturate.collections if c.get_label() == "moves"]
    segments = np.array([s for s in moves.get_segments() if np.hypot(*(s[1] - s[0])) > 1e-6])
    assert len(segments) > 10
    start, end = segments[:, 0], segments[:, 1]
    white = np.asarray(display.gamut.whitepoint)
    across = np.cross(end - start, white - start) / np.hypot(*(white - start).T)
    np.testing.assert_allclose(across, 0.0, atol=1e-6)  # the final clamp leaves 3e-8
    _pyplot().close(figure)


def test_the_diagram_draws_the_displays_and_the_spaces_asked_for(default_spec):
    from generator.verify.figures import _pyplot, chromaticity

    acescg = next(s for s in default_spec.colour_spaces if s.name == "ACEScg")
    figure = chromaticity(default_spec, [acescg])
    labels = [line.get_label() for line in figure.axes[0].get_lines() if not line.get_label().startswith("_")]
    assert [d.name for d in default_spec.displays] == labels[1:] and labels[0] == "ACEScg (AP1)", labels
    _pyplot().close(figure)


def test_highlights_clip_in_colorimetric_and_keep_apart_in_aces_2(default_spec):
    """The ramps the highlights figure draws, on the sRGB display: Colorimetric shows scene grey
    1, 8 and 16 as the same white; ACES 2.0 keeps them apart, rising, with scene 1.0 at the
    Academy's 45.757 cd/m² (the tone scale's published figure)."""
    from generator import reference
    from generator.verify.figures import HIGHLIGHT_COLOURS, highlight_codes

    display = next(d for d in default_spec.displays if d.name == "sRGB - Display")
    exposures, shown = highlight_codes(default_spec, display)
    assert list(shown) == [v for v in display.views if v != "Raw"]
    grey = list(HIGHLIGHT_COLOURS).index("grey")
    bright = exposures >= 1.0
    white = shown["Colorimetric"][grey, exposures > 1.0]
    assert np.all(white == white[0]) and np.allclose(white, 1.0, rtol=0, atol=1e-12)
    aces = shown["ACES 2.0 - SDR 100 nits (Rec.709)"][grey]
    assert np.all(np.diff(aces[bright, 1]) > 0.0) and aces[-1, 1] < 1.0
    one = int(np.flatnonzero(exposures == 1.0)[0])
    light = reference.display_decode(display, aces[one])
    np.testing.assert_allclose(light, 0.45757, atol=5e-5)
