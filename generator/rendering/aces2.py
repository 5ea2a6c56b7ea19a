"""The ACES 2.0 Output Transform in float64, forward and inverse.

Academy of Motion Picture Arts and Sciences, aces-core v2.0 (2025),
``lib/Lib.Academy.OutputTransform.ctl`` (``init_ODTParams``, ``outputTransform_fwd``,
``outputTransform_inv``), ``lib/Lib.Academy.DisplayEncoding.ctl`` (``apply_white_scale``,
``display_encoding``) and the presets' main functions in aces-output v2.0.

:func:`output_rgb` is the rendering as OpenColorIO's ``FixedFunctionTransform``
``ACES2_OutputTransform`` defines it (parameters: peak and limiting primaries and white):
ACES2065-1 to JMh, the tone scale on J with chroma compression of M, gamut compression
towards the focus, then limiting-primaries RGB (1.0 = 100 cd/m²). :func:`forward` is the
whole view as OpenColorIO 2.6's builtin ``ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 -
<preset>_2.0`` runs it: AP0 to AP1, clamp to [0, 8 r_hit] (the CTL's ``clamp_AP0_to_AP1``),
back to AP0, :func:`output_rgb`, clamp to [0, peak / 100], the white scaling where it applies,
the linear scale, limiting RGB to CIE XYZ (1.0 = 100 cd/m²). The inverses run the same steps
back; the inverse white scaling is followed by a clamp to [0, peak / 100] as in OpenColorIO.

The CTL is followed step by step, in float64, except where it slips and OpenColorIO does not:
the inverse white scaling's clamp (the CTL's is [0, 1], which would cut an HDR preset's
highlights), the upper hull's interpolation by hue (``aces2_compress.hue_dependent``) and the
rotation of the limiting gamut's corners (``aces2_tables``). NaN in gives NaN out.
"""

from __future__ import annotations

import numpy as np

from generator.colorimetry.matrices import normalised_primary_matrix
from generator.rendering.aces2_compress import chroma_compress, chroma_compress_norm, gamut_compress
from generator.rendering.aces2_params import CUBE_CORNERS, ACES2Params, ACES2Tables
from generator.rendering.aces2_tables import cusp_table, hue_table, reach_corners, reach_m_table, upper_hull_gamma_table
from generator.rendering.jmh import (
    JMhParams,
    aab_to_jmh,
    aab_to_rgb,
    hue_direction,
    j_to_y,
    jmh_params,
    jmh_to_aab,
    rgb_to_aab,
    rgb_to_jmh,
    y_to_j,
)
from generator.rendering.tonescale import tone_scale, tonescale_forward, tonescale_inverse

__all__ = ["ACES2Params", "ACES2Tables", "forward", "inverse", "output_rgb", "output_rgb_inverse", "tables"]

#: ACES white and the AP0 (SMPTE ST 2065-1) and AP1 (Academy S-2014-004) primaries, as the CTL writes them.
ACES_WHITE = (0.32168, 0.33767)
AP0_PRIMARIES = ((0.73470, 0.26530), (0.00000, 1.00000), (0.00010, -0.07700))
AP1_PRIMARIES = ((0.713, 0.293), (0.165, 0.830), (0.128, 0.044))
#: Chroma compression presets: compression and its growth with log peak, expansion, its
#: fall with log peak, its floor and its threshold (aces-core v2.0).
CHROMA_COMPRESS, CHROMA_COMPRESS_FACT = 2.4, 3.3
CHROMA_EXPAND, CHROMA_EXPAND_FACT, CHROMA_EXPAND_MIN, CHROMA_EXPAND_THR = 1.3, 0.69, 0.2, 0.5
#: The chroma normaliser's scale (0.03379 n)^0.30596 - 0.45135.
NORM_SCALE = (0.03379, 0.30596, 0.45135)
#: Focus distance and its growth with log peak; lower hull gamma and its growth.
FOCUS_DISTANCE, FOCUS_DISTANCE_SCALING = 1.35, 1.75
LOWER_HULL_GAMMA = (1.14, 0.07)


def _white_scale(params: ACES2Params) -> float:
    """1 / the largest channel of the limiting white in encoding RGB (``apply_white_scale``), or 1."""
    if not params.applies_white_scale:
        return 1.0
    to_encoding = np.linalg.solve(
        normalised_primary_matrix(params.encoding_primaries, params.encoding_white),
        normalised_primary_matrix(params.limiting_primaries, params.limiting_white),
    )
    return float(1.0 / np.max(to_encoding @ np.ones(3)))


def _hue_tables(params: ACES2Params, reach: JMhParams, limit: JMhParams, j_max: float, forward_limit: float):
    peak = params.peak_luminance
    limit_hues = rgb_to_jmh(np.asarray(CUBE_CORNERS) * (peak / 100.0), limit)[:, 2]
    reach_hues = reach_corners(reach, j_max, forward_limit)[1:-1, 2]
    hues = hue_table(np.unique(np.concatenate([reach_hues, limit_hues])))
    return hues, *cusp_table(hues, limit, peak)


def tables(params: ACES2Params) -> ACES2Tables:
    """Everything the transform precomputes for ``params`` (aces-core v2.0 ``init_ODTParams``)."""
    peak = params.peak_luminance
    tone = tone_scale(peak)
    source, reach = jmh_params(AP0_PRIMARIES, ACES_WHITE), jmh_params(AP1_PRIMARIES, ACES_WHITE)
    limit = jmh_params(params.limiting_primaries, params.limiting_white)
    j_max, mid_j = float(y_to_j(peak, source)), float(y_to_j(tone.c_t * 100.0, source))
    focus_dist = FOCUS_DISTANCE + FOCUS_DISTANCE * FOCUS_DISTANCE_SCALING * tone.log_peak
    lower_hull_gamma_inv = 1.0 / (LOWER_HULL_GAMMA[0] + LOWER_HULL_GAMMA[1] * tone.log_peak)
    hues, cusp_j, cusp_m = _hue_tables(params, reach, limit, j_max, tone.forward_limit)
    gamma = upper_hull_gamma_table(hues, cusp_j, cusp_m, limit, peak, j_max, mid_j, focus_dist, lower_hull_gamma_inv)
    ap0 = normalised_primary_matrix(AP0_PRIMARIES, ACES_WHITE)
    ap1 = normalised_primary_matrix(AP1_PRIMARIES, ACES_WHITE)
    limit_to_xyz = normalised_primary_matrix(params.limiting_primaries, params.limiting_white)
    return ACES2Tables(
        params=params,
        input=source,
        reach=reach,
        limit=limit,
        tone=tone,
        limit_j_max=j_max,
        mid_j=mid_j,
        focus_dist=focus_dist,
        lower_hull_gamma_inv=lower_hull_gamma_inv,
        sat=max(CHROMA_EXPAND_MIN, CHROMA_EXPAND - CHROMA_EXPAND * CHROMA_EXPAND_FACT * tone.log_peak),
        sat_thr=CHROMA_EXPAND_THR / peak,
        compr=CHROMA_COMPRESS + CHROMA_COMPRESS * CHROMA_COMPRESS_FACT * tone.log_peak,
        chroma_compress_scale=(NORM_SCALE[0] * peak) ** NORM_SCALE[1] - NORM_SCALE[2],
        reach_m=reach_m_table(reach, j_max),
        hues=hues,
        cusp_j=cusp_j,
        cusp_m=cusp_m,
        gamma_top_inv=gamma,
        ap0_to_ap1=np.linalg.solve(ap1, ap0),
        ap1_to_ap0=np.linalg.solve(ap0, ap1),
        limit_to_xyz=limit_to_xyz,
        xyz_to_limit=np.linalg.inv(limit_to_xyz),
        display_scale=_white_scale(params) * params.linear_scale,
    )


#: Colours per pass: a pass's few dozen temporaries then stay in the processor's cache
#: (measured on 65³ colours: 0.21 s in passes of this size, 0.46 s in one).
CHUNK = 16384


def _colours(values) -> tuple[np.ndarray, tuple[int, ...]]:
    values = np.asarray(values, dtype=np.float64)
    if values.shape[-1:] != (3,):
        raise ValueError(f"colours must have 3 components on their last axis, got shape {values.shape}")
    return values.reshape(-1, 3), values.shape


def _in_passes(rows, values, t: ACES2Tables) -> np.ndarray:
    """``rows`` (a function of (n, 3) colours and ``t``) over ``values`` (..., 3), CHUNK colours at a time."""
    flat, shape = _colours(values)
    out = np.empty_like(flat)
    for start in range(0, flat.shape[0], CHUNK):
        out[start : start + CHUNK] = rows(flat[start : start + CHUNK], t)
    return out.reshape(shape)


def _output_rows(rgb: np.ndarray, t: ACES2Tables) -> np.ndarray:
    aab = rgb_to_aab(rgb, t.input)
    jmh, direction = aab_to_jmh(aab), hue_direction(aab)
    j, m, h = jmh[:, 0], jmh[:, 1], jmh[:, 2]
    j_ts = y_to_j(tonescale_forward(j_to_y(j, t.input) / 100.0, t.tone), t.input)
    norm = chroma_compress_norm(*direction, t.chroma_compress_scale)
    toned = np.stack([j_ts, chroma_compress(j, j_ts, m, h, norm, t), h], axis=-1)
    return aab_to_rgb(jmh_to_aab(gamut_compress(toned, t), direction), t.limit)


def _output_inverse_rows(rgb: np.ndarray, t: ACES2Tables) -> np.ndarray:
    aab = rgb_to_aab(rgb, t.limit)
    direction = hue_direction(aab)
    toned = gamut_compress(aab_to_jmh(aab), t, invert=True)
    j_ts, m, h = toned[:, 0], toned[:, 1], toned[:, 2]
    j = y_to_j(tonescale_inverse(j_to_y(j_ts, t.input), t.tone) * 100.0, t.input)
    norm = chroma_compress_norm(*direction, t.chroma_compress_scale)
    jmh = np.stack([j, chroma_compress(j, j_ts, m, h, norm, t, invert=True), h], axis=-1)
    return aab_to_rgb(jmh_to_aab(jmh, direction), t.input)


def _clamp_ap1(aces: np.ndarray, t: ACES2Tables) -> np.ndarray:
    ap1 = np.clip(aces @ t.ap0_to_ap1.T, 0.0, t.tone.forward_limit)
    return ap1 @ t.ap1_to_ap0.T


def _forward_rows(aces: np.ndarray, t: ACES2Tables) -> np.ndarray:
    display = np.clip(_output_rows(_clamp_ap1(aces, t), t), 0.0, t.params.peak_luminance / 100.0)
    return (display * t.display_scale) @ t.limit_to_xyz.T


def _inverse_rows(xyz: np.ndarray, t: ACES2Tables) -> np.ndarray:
    display = np.clip((xyz @ t.xyz_to_limit.T) / t.display_scale, 0.0, t.params.peak_luminance / 100.0)
    return _clamp_ap1(_output_inverse_rows(display, t), t)


def output_rgb(aces, t: ACES2Tables) -> np.ndarray:
    """ACES2065-1 (..., 3) to limiting-primaries display-linear RGB, 1.0 = 100 cd/m²
    (aces-core v2.0 ``outputTransform_fwd`` without its AP1 clamp, as OpenColorIO's fixed function)."""
    return _in_passes(_output_rows, aces, t)


def output_rgb_inverse(rgb, t: ACES2Tables) -> np.ndarray:
    """Limiting-primaries display-linear RGB (..., 3) back to ACES2065-1 (aces-core v2.0
    ``outputTransform_inv``, as OpenColorIO's inverse fixed function)."""
    return _in_passes(_output_inverse_rows, rgb, t)


def forward(aces, t: ACES2Tables) -> np.ndarray:
    """ACES2065-1 (..., 3) to CIE XYZ of the display's light, 1.0 = 100 cd/m² (the whole view)."""
    return _in_passes(_forward_rows, aces, t)


def inverse(xyz, t: ACES2Tables) -> np.ndarray:
    """CIE XYZ of the display's light (..., 3), 1.0 = 100 cd/m², back to ACES2065-1."""
    return _in_passes(_inverse_rows, xyz, t)
