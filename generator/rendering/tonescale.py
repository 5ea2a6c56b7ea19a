"""The ACES 2.0 tone scale: Daniele Siragusano's curve, set by the display's peak luminance.

Academy of Motion Picture Arts and Sciences, aces-core v2.0 (2025),
``lib/Lib.Academy.Tonescale.ctl`` (``init_TSParams``, ``tonescale_fwd``, ``tonescale_inv``).
A Michaelis-Menten curve ``f = m_2 (x / (x + s_2))^g`` followed by a flare term
``f^2 / (f + t_1)``, scaled so that 1.0 is 100 cd/m²:

* its contrast ``g`` and flare ``t_1`` are fixed;
* scene 0.18 reaches ``c_d`` = 10.013 cd/m² at a 100 cd/m² peak, 14% more per stop of
  peak above 100 (``c_t``);
* the scene value that "hits the roof", ``r_hit``, grows with log peak from 128 (100
  cd/m²) to 896 (10 000 cd/m²): the curve reaches the peak there and goes on towards
  its asymptote, 0.9% (100 cd/m²) to 5.1% (10 000 cd/m²) above (the output transform clamps
  to the peak; the inverse takes luminance up to ``inverse_limit``, just below the asymptote).

At a 100 cd/m² peak scene 0.18 gives 9.99993 cd/m² (the derivation aims ``c_d`` at the
flare-free curve) and scene 1.0 gives 45.7566 cd/m², the figures the Academy publishes as
10 and 45.757.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Luminance (cd/m²) that 1.0 of the curve's output stands for (n_r).
NORMALISED_WHITE = 100.0
#: Contrast (surround) exponent g and the flare (toe) term t_1.
CONTRAST = 1.15
FLARE = 0.04
#: Scene mid grey and its display luminance (cd/m²) at a 100 cd/m² peak.
MID_GREY = 0.18
MID_GREY_LUMINANCE = 10.013
#: Relative rise of mid grey's luminance per stop of peak above 100 cd/m² (w_g).
MID_GREY_GAIN = 0.14
#: Scene values hitting the roof at 100 and 10 000 cd/m² peaks.
ROOF_SDR = 128.0
ROOF_HDR = 896.0
#: The ACES clamp's headroom over the roof: three stops (aces-core v2.0 ``forward_limit``).
ROOF_HEADROOM = 8.0


@dataclass(frozen=True)
class ToneScale:
    """Constants of the tone scale for one peak (aces-core v2.0 ``TSParams``)."""

    peak: float
    c_t: float
    s_2: float
    u_2: float
    m_2: float
    #: Upper limit of the AP1 clamp before the transform: 8 r_hit.
    forward_limit: float
    #: Largest normalised output the inverse takes, peak / (u_2 100): just below the curve's
    #: asymptote m_2^2 / (m_2 + t_1) (by 0.03% of peak at 100 cd/m²).
    inverse_limit: float
    #: log10(peak / 100).
    log_peak: float


def tone_scale(peak: float) -> ToneScale:
    """The tone scale's constants for a display of ``peak`` cd/m² (aces-core v2.0 ``init_TSParams``)."""
    n = float(peak)
    r_hit = ROOF_SDR + (ROOF_HDR - ROOF_SDR) * np.log(n / NORMALISED_WHITE) / np.log(10000.0 / 100.0)
    m_0 = n / NORMALISED_WHITE
    m_1 = 0.5 * (m_0 + np.sqrt(m_0 * (m_0 + 4.0 * FLARE)))
    u = ((r_hit / m_1) / ((r_hit / m_1) + 1.0)) ** CONTRAST
    m = m_1 / u
    w_i = np.log2(n / 100.0)
    c_t = MID_GREY_LUMINANCE / NORMALISED_WHITE * (1.0 + w_i * MID_GREY_GAIN)
    g_ip = 0.5 * (c_t + np.sqrt(c_t * (c_t + 4.0 * FLARE)))
    g_ipp2 = -(m_1 * (g_ip / m) ** (1.0 / CONTRAST)) / ((g_ip / m) ** (1.0 / CONTRAST) - 1.0)
    w_2 = MID_GREY / g_ipp2
    s_2 = w_2 * m_1
    u_2 = ((r_hit / m_1) / ((r_hit / m_1) + w_2)) ** CONTRAST
    m_2 = m_1 / u_2
    return ToneScale(
        peak=n,
        c_t=float(c_t),
        s_2=float(s_2),
        u_2=float(u_2),
        m_2=float(m_2),
        forward_limit=float(ROOF_HEADROOM * r_hit),
        inverse_limit=float(n / (u_2 * NORMALISED_WHITE)),
        log_peak=float(np.log10(n / NORMALISED_WHITE)),
    )


def tonescale_forward(x, ts: ToneScale):
    """Scene-linear luminance (1.0 = 100 cd/m² of scene light) to display luminance in cd/m²
    (aces-core v2.0 ``tonescale_fwd``)."""
    x = np.asarray(x, dtype=np.float64)
    f = ts.m_2 * (np.maximum(x, 0.0) / (x + ts.s_2)) ** CONTRAST
    return np.maximum(0.0, f * f / (f + FLARE)) * NORMALISED_WHITE


def tonescale_inverse(y, ts: ToneScale):
    """Display luminance in cd/m² to scene-linear luminance; luminance beyond ``inverse_limit``
    is taken as it (aces-core v2.0 ``tonescale_inv``)."""
    z = np.clip(np.asarray(y, dtype=np.float64) / NORMALISED_WHITE, 0.0, ts.inverse_limit)
    h = (z + np.sqrt(z * (4.0 * FLARE + z))) / 2.0
    with np.errstate(divide="ignore"):
        return ts.s_2 / ((ts.m_2 / h) ** (1.0 / CONTRAST) - 1.0)
