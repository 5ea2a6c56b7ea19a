"""The simplified Hellwig 2022 JMh model of the ACES 2.0 Output Transform.

L. Hellwig, D. Stolitzka and M. D. Fairchild, "Extending CIECAM02 and CAM16 for the
Helmholtz-Kohlrausch effect", JOSA A 39 (2022), as the Academy's ACES 2.0 reference
implementation simplifies it (aces-core v2.0, 2025, ``lib/Lib.Academy.OutputTransform.ctl``:
``init_JMhParams``, ``RGB_to_Aab``, ``Aab_to_JMh``, ``JMh_to_Aab``, ``Aab_to_RGB``,
``Y_to_J``, ``J_to_Y``):

* the viewing conditions are fixed: adapting luminance L_A = 100 cd/m², background
  Y_b = 20, dim surround (F, c, N_c) = (0.9, 0.59, 0.9);
* each RGB space is fully adapted to its own white (D = 1): its RGB at 100 cd/m² goes
  to CAM16's sharpened cone space (the matrix of the "primaries" CAM16 publishes) and
  is scaled per channel so that the white's three responses equal F_L;
* the cone responses are compressed as x^0.42 / (27.13 + x^0.42) (sign kept), without
  CAM16's factor 400, which moves into the matrix to (A, a, b);
* A is normalised to 1 at the space's white, J = 100 A^(c z), M = 43 N_c |(a, b)| with
  the compressed responses' opponent axes, h = atan2(b, a) in degrees in [0, 360);
  no Helmholtz-Kohlrausch term.

Colours are (..., 3) float64 arrays; RGB 1.0 means 100 cd/m².
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.colorimetry.matrices import normalised_primary_matrix

#: Reference luminance (cd/m²) of RGB 1.0 and of J = 100.
REFERENCE_LUMINANCE = 100.0
#: Adapting field luminance L_A (cd/m²) and relative background luminance Y_b.
ADAPTING_LUMINANCE = 100.0
BACKGROUND = 20.0
#: The dim surround's (F, c, N_c).
SURROUND = (0.9, 0.59, 0.9)
#: The cone compression's offset and the scale moved into the (A, a, b) matrix.
CONE_OFFSET = 0.2713 * REFERENCE_LUMINANCE
CONE_SCALE = 4.0 * REFERENCE_LUMINANCE
#: Exponent of the cone compression and the largest compressed response its inverse takes.
CONE_EXPONENT = 0.42
CONE_INVERSE_LIMIT = 0.99
#: CAM16's sharpened cone space as chromaticities of its "primaries" and white.
CAM16_PRIMARIES = ((0.8336, 0.1735), (2.3854, -1.4659), (0.087, -0.125))
CAM16_WHITE = (0.333, 0.333)
#: Compressed cone responses (rows R, G, B) to (A, a, b), before scaling (Hellwig 2022, eqs. 7-9).
CONE_TO_AAB = ((2.0, 1.0, 1.0 / 9.0), (1.0, -12.0 / 11.0, 1.0 / 9.0), (1.0 / 20.0, 1.0 / 11.0, -2.0 / 9.0))
#: The lightness exponent c z, z = 1.48 + sqrt(Y_b / 100), and J's scale.
MODEL_GAMMA = SURROUND[1] * (1.48 + np.sqrt(BACKGROUND / REFERENCE_LUMINANCE))
J_SCALE = 100.0


def luminance_adaptation() -> float:
    """The luminance-level adaptation factor F_L of L_A (CIECAM02, CIE 159:2004, eq. 7.2)."""
    k = 1.0 / (5.0 * ADAPTING_LUMINANCE + 1.0)
    k4 = k**4
    return 0.2 * k4 * (5.0 * ADAPTING_LUMINANCE) + 0.1 * (1.0 - k4) ** 2 * (5.0 * ADAPTING_LUMINANCE) ** (1.0 / 3.0)


@dataclass(frozen=True, eq=False)
class JMhParams:
    """What JMh needs of one RGB space (aces-core v2.0 ``JMhParams``).

    Matrices act on column vectors: ``cone = rgb_to_cone @ rgb``.
    """

    rgb_to_cone: np.ndarray
    cone_to_rgb: np.ndarray
    cone_to_aab: np.ndarray
    aab_to_cone: np.ndarray
    #: F_L / 100: luminance (cd/m²) to the cone compression's input.
    fl_n: float
    #: The compressed response of a grey at 100 cd/m² (A_w_J).
    a_w_j: float


def jmh_params(primaries, white) -> JMhParams:
    """The JMh matrices of the RGB space ``primaries`` (3x2 xy), ``white`` (xy)
    (aces-core v2.0 ``init_JMhParams``)."""
    rgb_to_xyz = normalised_primary_matrix(primaries, white)
    xyz_to_cam16 = np.linalg.inv(normalised_primary_matrix(CAM16_PRIMARIES, CAM16_WHITE))
    white_xyz = rgb_to_xyz @ np.full(3, REFERENCE_LUMINANCE)
    white_cone = xyz_to_cam16 @ white_xyz
    f_l = luminance_adaptation()
    fl_n = f_l / REFERENCE_LUMINANCE
    gains = fl_n * white_xyz[1] / white_cone
    rgb_to_cone = (gains[:, None] * xyz_to_cam16) @ rgb_to_xyz * REFERENCE_LUMINANCE
    scaled = CONE_SCALE * np.asarray(CONE_TO_AAB).T
    a_w = scaled[0] @ compress_cone(gains * white_cone)
    cone_to_aab = np.vstack([scaled[0] / a_w, scaled[1:] * 43.0 * SURROUND[2]])
    return JMhParams(
        rgb_to_cone=rgb_to_cone,
        cone_to_rgb=np.linalg.inv(rgb_to_cone),
        cone_to_aab=cone_to_aab,
        aab_to_cone=np.linalg.inv(cone_to_aab),
        fl_n=fl_n,
        a_w_j=float(compress_cone(f_l)),
    )


def compress_cone(v):
    """Post-adaptation cone response compression, sign kept (Hellwig 2022, eq. 6, without 400)."""
    v = np.asarray(v, dtype=np.float64)
    p = np.abs(v) ** CONE_EXPONENT
    return np.copysign(p / (CONE_OFFSET + p), v)


def decompress_cone(v):
    """Inverse of :func:`compress_cone`; responses beyond 0.99 are taken as 0.99 (aces-core v2.0)."""
    v = np.asarray(v, dtype=np.float64)
    r = np.minimum(np.abs(v), CONE_INVERSE_LIMIT)
    return np.copysign((CONE_OFFSET * r / (1.0 - r)) ** (1.0 / CONE_EXPONENT), v)


def _apply(matrix: np.ndarray, values: np.ndarray) -> np.ndarray:
    return values @ matrix.T


def rgb_to_aab(rgb, p: JMhParams) -> np.ndarray:
    """RGB to (A, a, b): A is 1 at the space's white (aces-core v2.0 ``RGB_to_Aab``)."""
    return _apply(p.cone_to_aab, compress_cone(_apply(p.rgb_to_cone, np.asarray(rgb, dtype=np.float64))))


def aab_to_jmh(aab) -> np.ndarray:
    """(A, a, b) to (J, M, h); A <= 0 gives (0, 0, 0) (aces-core v2.0 ``Aab_to_JMh``).

    A hue that rounds to 360 is 0, the same hue (OpenColorIO's fix of the CTL's wrap, #2220).
    """
    aab = np.asarray(aab, dtype=np.float64)
    a_n, a, b = aab[..., 0], aab[..., 1], aab[..., 2]
    lit = a_n > 0.0
    j = J_SCALE * np.maximum(a_n, 0.0) ** MODEL_GAMMA
    h = np.degrees(np.arctan2(b, a))
    h = np.where(h < 0.0, h + 360.0, h)
    h = np.where(h >= 360.0, h - 360.0, h)
    return np.stack([np.where(lit, j, 0.0), np.where(lit, np.hypot(a, b), 0.0), np.where(lit, h, 0.0)], axis=-1)


def rgb_to_jmh(rgb, p: JMhParams) -> np.ndarray:
    """RGB (1.0 = 100 cd/m²) to JMh (aces-core v2.0 ``RGB_to_JMh``)."""
    return aab_to_jmh(rgb_to_aab(rgb, p))


def hue_direction(aab) -> tuple[np.ndarray, np.ndarray]:
    """cos h and sin h of (A, a, b) as a / M and b / M, (1, 0) where M = 0 (h = 0): what
    :func:`jmh_to_aab` takes from h, without the round trip through degrees."""
    aab = np.asarray(aab, dtype=np.float64)
    m = np.hypot(aab[..., 1], aab[..., 2])
    some = m > 0.0
    safe = np.where(some, m, 1.0)
    return np.where(some, aab[..., 1] / safe, 1.0), np.where(some, aab[..., 2] / safe, 0.0)


def jmh_to_aab(jmh, direction: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """(J, M, h) to (A, a, b) (aces-core v2.0 ``JMh_to_Aab``); ``direction`` is (cos h, sin h)
    when known (:func:`hue_direction`), else it is computed from h."""
    jmh = np.asarray(jmh, dtype=np.float64)
    if direction is None:
        hr = np.radians(jmh[..., 2])
        direction = (np.cos(hr), np.sin(hr))
    m = jmh[..., 1]
    return np.stack([j_to_achromatic(jmh[..., 0]), m * direction[0], m * direction[1]], axis=-1)


def aab_to_rgb(aab, p: JMhParams) -> np.ndarray:
    """(A, a, b) to RGB (aces-core v2.0 ``Aab_to_RGB``)."""
    return _apply(p.cone_to_rgb, decompress_cone(_apply(p.aab_to_cone, np.asarray(aab, dtype=np.float64))))


def jmh_to_rgb(jmh, p: JMhParams) -> np.ndarray:
    """JMh to RGB (1.0 = 100 cd/m²) (aces-core v2.0 ``JMh_to_RGB``)."""
    return aab_to_rgb(jmh_to_aab(jmh), p)


def j_to_achromatic(j):
    """Lightness J to the normalised achromatic response A (aces-core v2.0 ``J_to_Achromatic_n``)."""
    return (np.asarray(j, dtype=np.float64) / J_SCALE) ** (1.0 / MODEL_GAMMA)


def y_to_j(y, p: JMhParams):
    """Luminance of a grey (cd/m²) to J, sign kept (aces-core v2.0 ``Y_to_J``)."""
    y = np.asarray(y, dtype=np.float64)
    response = compress_cone(np.abs(y) * p.fl_n)
    return np.copysign(J_SCALE * (response / p.a_w_j) ** MODEL_GAMMA, y)


def j_to_y(j, p: JMhParams):
    """J of a grey to its luminance (cd/m²), taking |J| (aces-core v2.0 ``J_to_Y``)."""
    return decompress_cone(p.a_w_j * j_to_achromatic(np.abs(j))) / p.fl_n
