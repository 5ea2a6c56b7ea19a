"""The ACES 2.0 tone scale against the Academy's published values and its own definition."""

from __future__ import annotations

import numpy as np
import pytest

from generator import tolerances
from generator.rendering.tonescale import tone_scale, tonescale_forward, tonescale_inverse

#: Display luminance (cd/m², three decimals) of scene 0, 0.18, 1.0 and 2.0 by peak: ACES
#: documentation (docs.acescentral.com), Output Transforms, Technical Details, Tone Mapping,
#: "Values". At 100 cd/m², 0.18 gives 9.99993 and 1.0 gives 45.7566 (the CTL's c_d = 10.013
#: is the target of the flare-free curve, which the flare then brings to 10.0).
PUBLISHED = {
    100: (0.000, 10.000, 45.757, 63.988),
    500: (0.000, 13.193, 89.098, 158.949),
    1000: (0.000, 14.512, 106.564, 205.783),
    2000: (0.000, 15.747, 121.664, 248.779),
    4000: (0.000, 16.824, 133.883, 284.433),
}
SCENE = (0.0, 0.18, 1.0, 2.0)


@pytest.mark.parametrize("peak", PUBLISHED)
def test_published_values(peak):
    ours = tonescale_forward(np.asarray(SCENE), tone_scale(peak))
    np.testing.assert_allclose(ours, PUBLISHED[peak], rtol=0, atol=tolerances.published_rounding(3))


@pytest.mark.parametrize("peak", [100, 225, 625, 1000, 1500, 4000, 10000])
def test_the_roof_and_the_clamp(peak):
    """The curve reaches the peak at r_hit (128 at 100 cd/m², 896 at 10 000), which the AP1
    clamp allows 8 times over (aces-core v2.0 ``forward_limit``); the inverse takes luminance up
    to its limit, below the curve's asymptote."""
    ts = tone_scale(peak)
    r_hit = ts.forward_limit / 8.0
    assert r_hit == pytest.approx(128.0 + 768.0 * np.log10(peak / 100.0) / 2.0, rel=1e-14)
    assert tonescale_forward(r_hit, ts) == pytest.approx(peak, rel=1e-12)
    limit = ts.inverse_limit * 100.0
    assert peak < limit < tonescale_forward(1e30, ts)
    assert tonescale_forward(tonescale_inverse(limit, ts), ts) == pytest.approx(limit, rel=1e-9)
    assert tonescale_inverse(2.0 * limit, ts) == tonescale_inverse(limit, ts)


def test_forward_limits_of_the_presets():
    """8 r_hit as OpenColorIO's builtins clamp AP1 (their float32 figures)."""
    expected = {
        100: 1024.0,
        225: 2105.90478515625,
        500: 3171.23583984375,
        625: 3468.943359375,
        1000: 4096.0,
        2000: 5020.76416015625,
        4000: 5945.5283203125,
    }
    for peak, limit in expected.items():
        assert np.float32(tone_scale(peak).forward_limit) == np.float32(limit)


@pytest.mark.parametrize("peak", [100, 225, 1000, 4000, 10000])
def test_inverse_and_monotony(peak):
    ts = tone_scale(peak)
    x = np.geomspace(1e-6, ts.forward_limit, 2001)
    y = tonescale_forward(x, ts)
    assert np.all(np.diff(y) > 0.0)
    np.testing.assert_allclose(tonescale_inverse(y, ts), x, rtol=1e-9)
    assert tonescale_forward(-1.0, ts) == 0.0
    assert tonescale_inverse(0.0, ts) == 0.0
