"""Probe colours and OpenColorIO runners shared by the ACES 2.0 tests."""

from __future__ import annotations

from functools import cache

import colour
import numpy as np
import PyOpenColorIO as ocio

from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import apply_matrix, normalised_primary_matrix, rgb_to_rgb
from generator.rendering.aces2 import ACES2Params, tables
from generator.rendering.aces2_presets import D65, PRESETS, REC2020

#: Cameras whose gamut edges (saturated colours beyond AP1 in places) are probed.
CAMERAS = ("ARRI Wide Gamut 4", "S-Gamut3")
#: Exposures of those edges (1.0 = the gamut's cube at 1).
EXPOSURES = (0.01, 0.05, 0.18, 1.0, 4.0, 16.0)
#: An LED wall measured by a show: primaries, white and peak (cd/m²).
LED_WALL = ACES2Params(1500, ((0.70, 0.29), (0.17, 0.75), (0.135, 0.045)), (0.3127, 0.3290))


def float32(values) -> np.ndarray:
    """``values`` as OCIO receives them: rounded to float32, held in float64."""
    return np.asarray(values, dtype=np.float32).astype(np.float64)


def cube_edges(samples: int = 41) -> np.ndarray:
    """The twelve edges of the unit RGB cube: a gamut's most saturated colours."""
    t = np.linspace(0.0, 1.0, samples)
    edges = []
    for fixed in range(3):
        for free in range(3):
            if free != fixed:
                for other in (0.0, 1.0):
                    edge = np.full((samples, 3), other)
                    edge[:, fixed] = 1.0 - other
                    edge[:, free] = t
                    edges.append(edge)
    return np.concatenate(edges)


@cache
def probe_sets() -> dict[str, np.ndarray]:
    """ACES2065-1 probes, float32-representable: greys 1e-4..100 and on to 65504, random AP0
    in [0, 1], camera gamuts' edges, bright (1..64) and dark (1e-4..0.1) colours."""
    rng = np.random.default_rng(2025)
    to_ap0 = {
        name: rgb_to_rgb(gamuts()[name], gamuts()["AP0"], gamuts()[name].adaptation or "Bradford") for name in CAMERAS
    }
    edges = cube_edges()
    return {
        "grey": float32(np.geomspace(1e-4, 65504.0, 1201)[:, None] * np.ones(3)),
        "random": float32(rng.uniform(0.0, 1.0, (6000, 3))),
        "camera": float32(np.concatenate([apply_matrix(m, edges * e) for m in to_ap0.values() for e in EXPOSURES])),
        "bright": float32(rng.uniform(1.0, 64.0, (3000, 3))),
        "dark": float32(rng.uniform(1e-4, 0.1, (3000, 3))),
    }


@cache
def preset_tables(view: str):
    return tables(PRESETS[view].params)


def ocio_apply(transform, colours) -> np.ndarray:
    """``colours`` (..., 3) through an OCIO transform on the CPU (float32), back in float64."""
    cpu = ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()
    pixels = np.ascontiguousarray(colours, dtype=np.float32).reshape(-1, 3).copy()
    cpu.applyRGB(pixels)
    return pixels.astype(np.float64).reshape(np.shape(colours))


def builtin(style: str, inverse: bool = False) -> ocio.BuiltinTransform:
    transform = ocio.BuiltinTransform(style)
    transform.setDirection(ocio.TRANSFORM_DIR_INVERSE if inverse else ocio.TRANSFORM_DIR_FORWARD)
    return transform


def fixed_function(params: ACES2Params, inverse: bool = False) -> ocio.FixedFunctionTransform:
    """OCIO's ACES2_OutputTransform fixed function with ``params``' peak and limiting gamut."""
    values = [params.peak_luminance, *np.ravel(params.limiting_primaries), *params.limiting_white]
    transform = ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_ACES_OUTPUT_TRANSFORM_20, values)
    transform.setDirection(ocio.TRANSFORM_DIR_INVERSE if inverse else ocio.TRANSFORM_DIR_FORWARD)
    return transform


def is_sdr(params: ACES2Params) -> bool:
    return params.peak_luminance * params.linear_scale <= 100.0


def sdr_codes(xyz, params: ACES2Params) -> np.ndarray:
    """Ten-bit codes of display XYZ (1.0 = 100 cd/m²) on an SDR display of the encoding gamut,
    encoded with IEC 61966-2-1's piecewise curve. A pure power's infinite slope at black would
    judge float32's rounding of OCIO's XYZ output instead (a channel at 1e-8 is 0.47 codes of a
    2.4 power), which the display's own float32 matrix then adds in any case."""
    to_encoding = np.linalg.inv(normalised_primary_matrix(params.encoding_primaries, params.encoding_white))
    linear = np.clip(apply_matrix(to_encoding, xyz) / params.linear_scale, 0.0, 1.0)
    return 1023.0 * colour.cctf_encoding(linear, function="sRGB")


def code_error(a, b, params: ACES2Params) -> np.ndarray:
    """Largest channel difference in :func:`sdr_codes`."""
    return np.max(np.abs(sdr_codes(a, params) - sdr_codes(b, params)), axis=-1)


def delta_e_itp(a, b) -> np.ndarray:
    """ΔE ITP (ITU-R BT.2124) between display XYZ (1.0 = 100 cd/m²), through BT.2020 in cd/m²."""
    to_2020 = np.linalg.inv(normalised_primary_matrix(REC2020, D65))

    def ictcp(xyz):
        return colour.RGB_to_ICtCp(np.maximum(apply_matrix(to_2020, xyz) * 100.0, 0.0))

    return np.asarray(colour.difference.delta_E_ITP(ictcp(a), ictcp(b)), dtype=np.float64)


def display_error(a, b, params: ACES2Params) -> np.ndarray:
    """Ten-bit sRGB codes for an SDR preset, ΔE ITP for an HDR one."""
    return code_error(a, b, params) if is_sdr(params) else delta_e_itp(a, b)
