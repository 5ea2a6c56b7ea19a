"""Error metrics, each named once: relative (value or colour), and ΔE ITP for HDR.

Layer: beside :mod:`generator.reference` (ΔE ITP decodes with its display EOTF), below
luts (whose fits are held to these metrics) and verify (which judges with them).
"""

from __future__ import annotations

import numpy as np

from generator import reference, tolerances
from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import channel_max, rgb_to_rgb


def relative_error(actual, expected) -> np.ndarray:
    """``|actual - expected|`` over ``|expected|``, the denominator at least RELATIVE_FLOOR."""
    expected = np.asarray(expected, dtype=np.float64)
    return np.abs(np.asarray(actual, dtype=np.float64) - expected) / np.maximum(
        np.abs(expected), tolerances.RELATIVE_FLOOR
    )


def colour_relative_error(actual, expected) -> np.ndarray:
    """Error of each colour (..., 3) relative to its largest component (floored): float32
    keeps 24 bits of the largest value of a triplet, so a channel far smaller than its
    neighbours cannot be held to a tighter relative bound after a matrix."""
    expected = np.asarray(expected, dtype=np.float64)
    scale = np.maximum(channel_max(np.abs(expected)), tolerances.RELATIVE_FLOOR)[..., None]
    return channel_max(np.abs(np.asarray(actual, dtype=np.float64) - expected) / scale)


def delta_e_itp(display, code_a, code_b) -> np.ndarray:
    """ΔE ITP (ITU-R BT.2124) between two sets of a display's code values.

    Both are decoded with the display's EOTF to light in cd/m², taken to BT.2020
    linear RGB through CIE XYZ, then to ICtCp (ITU-R BT.2100, PQ).
    """
    return delta_e_of_ictcp(ictcp_of_codes(display, code_a), ictcp_of_codes(display, code_b))


def ictcp_of_codes(display, code) -> np.ndarray:
    """ICtCp (ITU-R BT.2100, PQ) of a display's code values, as :func:`delta_e_itp` compares them."""
    to_2020 = rgb_to_rgb(display.gamut, gamuts()["Rec.2020"], "none")
    return ictcp_of_light(np.einsum("ij,...j->...i", to_2020, reference.display_decode(display, code) * 100.0))


def ictcp_of_light(rgb) -> np.ndarray:
    """ICtCp (ITU-R BT.2100, PQ) of BT.2020 linear RGB light in cd/m²."""
    import colour

    return np.asarray(colour.RGB_to_ICtCp(rgb), dtype=np.float64)


def delta_e_of_ictcp(ictcp_a, ictcp_b) -> np.ndarray:
    """ΔE ITP (ITU-R BT.2124) between two sets of ICtCp coordinates."""
    import colour

    return np.asarray(colour.delta_E(ictcp_a, ictcp_b, method="ITP"), dtype=np.float64)


def delta_e_itp_of_light(rgb_a, rgb_b) -> np.ndarray:
    """ΔE ITP (ITU-R BT.2124) between two sets of BT.2020 linear RGB light in cd/m²."""
    return delta_e_of_ictcp(ictcp_of_light(rgb_a), ictcp_of_light(rgb_b))


def dequantised(actual, expected, step: float | np.ndarray) -> np.ndarray:
    """``actual`` moved toward ``expected`` by up to half a quantisation ``step``.

    A value read back from an integer image file is the engine's result rounded
    to the file's step; removing that half step before any metric lets the
    metric judge the engine and not the file format (``step = 0`` changes nothing).
    """
    actual = np.asarray(actual, dtype=np.float64)
    expected = np.asarray(expected, dtype=np.float64)
    difference = actual - expected
    return expected + np.sign(difference) * np.maximum(np.abs(difference) - step / 2.0, 0.0)


def percentile_99(errors) -> float:
    """The 99th percentile of ``errors``, NaN left out (NaN when nothing is left)."""
    errors = np.asarray(errors, dtype=np.float64)
    kept = errors[~np.isnan(errors)]
    return float(np.percentile(kept, 99.0)) if kept.size else float("nan")
