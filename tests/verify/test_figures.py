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
