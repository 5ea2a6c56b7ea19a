"""Academy Density Exchange (ADX) encodings to ACES2065-1 and back.

ADX (SMPTE ST 2065-3) stores scanned negative film as printing density. The
Academy's reference transforms ``ACEScsc.ADX10_to_ACES.ctl`` and
``ACEScsc.ADX16_to_ACES.ctl`` (ACES 1.x, repository aces-dev, now
aces-core, ``transforms/ctl/csc/ADX/``; transform ids
``ACEScsc.ADX10_to_ACES.a1.0.0`` in ACES 1.0,
``ACEScsc.Academy.ADX16_to_ACES.a1.0.3`` in ACES 1.3, same constants)
convert it to ACES2065-1 in five steps, each expressed here as data plus a
small pure function:

1. ADX code value -> channel-dependent density (CDD):
   ``cdd = (code - offset) / scale``, offset 95 and scale 500 for 10-bit,
   1520 and 8000 for 16-bit (so code 0 is density -0.19 in both);
2. CDD -> channel-independent density (CID): a 3x3 matrix;
3. CID -> relative log exposure: an 11-point piecewise-linear table up to
   density 0.6, a straight line of slope 100/55 above it;
4. relative log exposure -> relative exposure: ``10 ** logE``;
5. relative exposure -> ACES2065-1: a 3x3 matrix.

Below the table's first density (-0.19) the CTL's ``interpolate1D`` holds the
first log exposure (-6), so the forward transform is flat there and cannot be
inverted; :func:`aces_to_adx` maps every exposure at or below ``1e-6`` (and
every non-positive exposure) to density -0.19.

Code values are normalised, ``code / (2**bits - 1)``, as the CTL and OCIO's
built-in transforms take them. Nothing is clamped or quantised.

The CTL stores its matrices for row vectors (``mult_f3_f33(v, M) = v M``);
they are kept here transposed, for column vectors (``M @ v``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np


@dataclass(frozen=True)
class AdxEncoding:
    """Code value to channel-dependent density of one ADX bit depth.

    ``cdd = (code * max_code - offset) / scale`` (``ACEScsc.ADX10_to_ACES.ctl``,
    ``ACEScsc.ADX16_to_ACES.ctl``).
    """

    bits: int
    offset: float
    scale: float

    @property
    def max_code(self) -> float:
        """The largest integer code of the encoding's bit depth."""
        return float(2**self.bits - 1)


#: The two ADX bit depths: 10-bit (offset 95, 500 codes per density unit) and
#: 16-bit (offset 1520, 8000 codes per density unit).
ENCODINGS = MappingProxyType(
    {
        10: AdxEncoding(bits=10, offset=95.0, scale=500.0),
        16: AdxEncoding(bits=16, offset=1520.0, scale=8000.0),
    }
)

#: Channel-dependent to channel-independent density, for column vectors
#: (the transpose of the CTL's ``CDD_TO_CID``). Rows sum to 1: neutral
#: densities are unchanged.
CDD_TO_CID = np.array(
    [
        [0.75573, 0.22197, 0.02230],
        [0.05901, 0.96928, -0.02829],
        [0.16134, 0.07406, 0.76460],
    ]
)

#: Relative exposure to ACES2065-1, for column vectors (the transpose of the
#: CTL's ``EXP_TO_ACES``).
EXP_TO_ACES = np.array(
    [
        [0.72286, 0.12630, 0.15084],
        [0.11923, 0.76418, 0.11659],
        [0.01427, 0.08213, 0.90359],
    ]
)

#: Channel-independent density (first column) -> relative log10 exposure
#: (second column), the CTL's ``LUT_1D``, interpolated linearly.
CID_TO_LOG_EXPOSURE = np.array(
    [
        [-0.19, -6.0],
        [0.010, -2.721718645],
        [0.028, -2.521718645],
        [0.054, -2.321718645],
        [0.095, -2.121718645],
        [0.145, -1.921718645],
        [0.220, -1.721718645],
        [0.300, -1.521718645],
        [0.400, -1.321718645],
        [0.500, -1.121718645],
        [0.600, -0.926545676714876],
    ]
)

#: Slope of log exposure against density above the table (the film gamma,
#: 0.55, inverted).
LINEAR_SLOPE = 100.0 / 55.0

#: Offset of that line: ADX16 code 7120 (density 0.7) is 18 % grey.
REFERENCE_POINT = (7120.0 - 1520.0) / 8000.0 * LINEAR_SLOPE - math.log10(0.18)


def _encoding(bits: int) -> AdxEncoding:
    if bits not in ENCODINGS:
        raise ValueError(f"ADX bit depth {bits!r} is not supported; allowed: 10, 16")
    return ENCODINGS[bits]


def _rgb(values) -> np.ndarray:
    rgb = np.asarray(values, dtype=np.float64)
    if rgb.ndim == 0 or rgb.shape[-1] != 3:
        raise ValueError(f"expected RGB values of shape (..., 3), got shape {rgb.shape}")
    return rgb


def _apply(matrix: np.ndarray, rgb: np.ndarray) -> np.ndarray:
    return rgb @ matrix.T


def cid_to_log_exposure(cid) -> np.ndarray:
    """Channel-independent density to relative log10 exposure, elementwise.

    Linear interpolation in :data:`CID_TO_LOG_EXPOSURE` up to density 0.6,
    holding -6 below density -0.19, and ``LINEAR_SLOPE * cid - REFERENCE_POINT``
    above 0.6 (continuous there), as in ``ACEScsc.ADX10_to_ACES.ctl``.
    """
    cid = np.asarray(cid, dtype=np.float64)
    table = CID_TO_LOG_EXPOSURE
    inside = np.interp(cid, table[:, 0], table[:, 1])
    return np.where(cid > table[-1, 0], LINEAR_SLOPE * cid - REFERENCE_POINT, inside)


def log_exposure_to_cid(log_exposure) -> np.ndarray:
    """Relative log10 exposure to channel-independent density, elementwise.

    The inverse of :func:`cid_to_log_exposure` where it is strictly
    increasing (log exposure above -6); at or below -6, including ``-inf``,
    it returns the table's first density, -0.19.
    """
    log_e = np.asarray(log_exposure, dtype=np.float64)
    table = CID_TO_LOG_EXPOSURE
    inside = np.interp(log_e, table[:, 1], table[:, 0])
    above = (log_e + REFERENCE_POINT) / LINEAR_SLOPE
    return np.where(log_e > table[-1, 1], above, inside)


def adx_to_cdd(code, bits: int) -> np.ndarray:
    """Normalised ADX code values to channel-dependent density, elementwise."""
    encoding = _encoding(bits)
    return (np.asarray(code, dtype=np.float64) * encoding.max_code - encoding.offset) / encoding.scale


def cdd_to_adx(cdd, bits: int) -> np.ndarray:
    """Channel-dependent density to normalised ADX code values, elementwise."""
    encoding = _encoding(bits)
    return (np.asarray(cdd, dtype=np.float64) * encoding.scale + encoding.offset) / encoding.max_code


def adx_to_aces(rgb, bits: int) -> np.ndarray:
    """ADX10 or ADX16 code values to ACES2065-1.

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        Normalised code values, ``code / (2**bits - 1)``.
    bits : {10, 16}
        The ADX encoding.

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        ACES2065-1 relative exposure, float64.

    References
    ----------
    ``ACEScsc.ADX10_to_ACES.ctl`` and ``ACEScsc.ADX16_to_ACES.ctl``
    (Academy, aces-dev 1.x); SMPTE ST 2065-3 (ADX).
    """
    cdd = adx_to_cdd(_rgb(rgb), bits)
    cid = _apply(CDD_TO_CID, cdd)
    exposure = 10.0 ** cid_to_log_exposure(cid)
    return _apply(EXP_TO_ACES, exposure)


def aces_to_adx(aces, bits: int) -> np.ndarray:
    """ACES2065-1 to ADX10 or ADX16 code values: the inverse of :func:`adx_to_aces`.

    The matrices are inverted and the log-exposure table is inverted by
    linear interpolation with its columns swapped (both columns are strictly
    increasing, so the inverse of a piecewise-linear map is piecewise
    linear). Relative exposures at or below ``1e-6``, and non-positive ones,
    have no unique density (the forward transform holds log exposure -6
    below density -0.19) and map to density -0.19.

    Parameters
    ----------
    aces : array_like, shape (..., 3)
        ACES2065-1 values.
    bits : {10, 16}
        The ADX encoding.

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        Normalised code values, unclamped and unquantised.

    References
    ----------
    Inverse of ``ACEScsc.ADX10_to_ACES.ctl`` / ``ACEScsc.ADX16_to_ACES.ctl``.
    """
    exposure = _apply(np.linalg.inv(EXP_TO_ACES), _rgb(aces))
    positive = exposure > 0.0
    log_e = np.where(positive, np.log10(np.where(positive, exposure, 1.0)), -np.inf)
    cid = log_exposure_to_cid(log_e)
    cdd = _apply(np.linalg.inv(CDD_TO_CID), cid)
    return cdd_to_adx(cdd, bits)
