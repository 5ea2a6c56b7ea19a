"""The ACES views' catalogue: studio names, what a display can show, a custom display's own view."""

from pathlib import Path

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.colorimetry.gamuts import gamuts
from generator.rendering import views


def test_every_studio_view_is_catalogued_under_the_studio_configs_name():
    """The names a show moving from the ACES studio configs keeps: every view of v5.0.0
    (ACES 2.0) and v2.2.0 (ACES 1.3), each with that config's builtin."""
    names = {}
    for config in ("studio-config-v5.0.0_aces-v2.1_ocio-v2.6", "studio-config-v2.2.0_aces-v1.3_ocio-v2.4"):
        cfg = ocio.Config.CreateFromFile(f"ocio://{config}")
        for vt in cfg.getViewTransforms():
            transform = vt.getTransform(ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
            if isinstance(transform, ocio.BuiltinTransform) and transform.getStyle().startswith("ACES-OUTPUT"):
                names[vt.getName()] = transform.getStyle()
    assert len(names) == 27  # 11 ACES 2.0 views, 16 ACES 1.3
    for name, style in names.items():
        assert views.catalogue()[name].style == style


@pytest.mark.parametrize(
    "display, view, words",
    [
        ("sRGB - Display", "ACES 2.0 - HDR 1000 nits (P3 D65)", "HDR view"),
        ("sRGB - Display", "ACES 2.0 - SDR 100 nits (P3 D65)", "limiting red and green primaries"),
        ("Rec.2100-PQ - Display", "ACES 2.0 - HDR 4000 nits (Rec.2020)", "passes the display's, 1000"),
    ],
)
def test_a_display_cannot_show_a_view_beyond_its_gamut_or_peak(display, view, words):
    from generator.spec.load import parse
    from generator.spec.schema import SpecError

    gamut = gamuts()["Rec.2020" if "PQ" in display else "Rec.709"]
    peak = 1000.0 if "PQ" in display else 100.0
    assert words in views.cannot_show(views.catalogue()[view], gamut.primaries, peak, "PQ" in display)
    with pytest.raises(SpecError, match="cannot show") as caught:
        parse(f'[[display]]\nname = "{display}"\nviews = ["{view}"]', "s.toml", Path("."))
    assert caught.value.field == "display[0].views[0]"


def test_the_studio_views_of_every_library_display_are_shown_by_it(default_spec):
    for display in default_spec.displays:
        for name in views.STUDIO_VIEWS[display.name]:
            assert (
                views.cannot_show(views.catalogue()[name], display.gamut.primaries, display.peak, display.is_hdr) == ""
            )


def test_a_custom_display_has_an_own_view_with_its_peak_and_primaries():
    wall = views.own_view("LED Wall", 1500.0, ((0.70, 0.29), (0.17, 0.75), (0.135, 0.045)), (0.3127, 0.3290))
    assert wall.name == "ACES 2.0 - HDR 1500 nits (LED Wall)"
    assert wall.params.peak_luminance == 1500.0
    assert views.resolve(wall.name, "LED Wall", 1500.0, wall.limiting, wall.white) == wall
    assert views.resolve(wall.name, "Other Wall", 1500.0, wall.limiting, wall.white) is None
    with pytest.raises(ValueError, match="peak_luminance"):
        views.own_view("Dim", 10.0, wall.limiting, wall.white)


def test_a_view_ends_in_display_light_of_its_peak():
    """White at the peak: ACES 2.0's SDR view takes a very bright grey to 100 cd/m² (Y = 1),
    its 1000-nit view to 1000 cd/m² (Y = 10)."""
    grey = np.full((1, 3), 1e4)
    for name, peak in (("ACES 2.0 - SDR 100 nits (Rec.709)", 1.0), ("ACES 2.0 - HDR 1000 nits (P3 D65)", 10.0)):
        assert views.evaluate(views.catalogue()[name], grey)[0, 1] == pytest.approx(peak, rel=1e-3)
