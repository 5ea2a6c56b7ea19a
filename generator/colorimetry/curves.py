"""The named transfer functions: canonical curve name to transfer record.

Conventions, for every curve (matching the OCIO ACES studio config builtins):

* code is the full-range normalised code value (10-bit code / 1023), never
  legal range or IRE;
* linear is scene-linear with 0.18 = mid grey (an 18 % reflector), except for
  the display EOTFs (sRGB, Rec.709 inverse, the gamma curves, ST 2084) where
  1.0 = 100 cd/m², and HLG, whose linear is BT.2100's normalised scene light
  E in [0, 1] (OCIO's "CURVE - HLG-OETF-INVERSE" returns 3 E instead).

A vendor curve that is exactly "log of an affine function of linear, with a
straight line below a break" is a :class:`LogCamera` whose parameters are
computed here from the constants the vendor prints; everything else is a
:class:`Function` over colour-science's implementation or ours
(:mod:`generator.colorimetry.vendor`).

The LogCamera curves are in :mod:`generator.colorimetry.camera_logs`.
"""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from generator.colorimetry import vendor
from generator.colorimetry.camera_logs import (
    acescct,
    arri_logc3_ei800,
    arri_logc4,
    blackmagic_film_gen5,
    davinci_intermediate,
    dji_dlog,
    filmlight_tlog,
    filmlight_tloge,
    fujifilm_flog,
    fujifilm_flog2,
    jplog2,
    leica_llog,
    panasonic_vlog,
    red_log3g10,
    sony_slog3,
)
from generator.colorimetry.transfer import (
    Function,
    Linear,
    PiecewisePower,
    Power,
    TransferFunction,
)

#: Largest finite half float: the top of the linear range a LUT domain must reach.
HALF_MAX = 65504.0


class _ColourModel:
    """colour.models.<name> with ``kwargs``; colour-science is imported at the first call,
    not with this module (it takes a second to import). A class, not a closure, so that a
    curve pickles (verify builds checks in a forked worker)."""

    def __init__(self, name: str, **kwargs):
        self.name, self.kwargs = name, kwargs

    def __call__(self, values):
        import colour.models

        return getattr(colour.models, self.name)(values, **self.kwargs)


def _colour_models(name: str, **kwargs) -> _ColourModel:
    """:class:`_ColourModel` of colour.models.<name> with ``kwargs``."""
    return _ColourModel(name, **kwargs)


#: Where SMPTE ST 2084 is defined: codes 0 to 1, light 0 to 10000 cd/m² (100 in units of 100 cd/m²).
PQ_CODE_DOMAIN = (0.0, 1.0)
PQ_PEAK = 100.0


def _pq_decode(code):
    """SMPTE ST 2084 EOTF, in units of 100 cd/m² (1.0 = 100 cd/m², 100.0 = 10000); codes
    outside the signal range are clamped to it (the formula decodes codes above about 1.99
    to negative light, and negative codes to 0)."""
    return _colour_models("eotf_ST2084")(np.clip(code, *PQ_CODE_DOMAIN)) / 100.0


def _pq_encode(linear):
    """SMPTE ST 2084 inverse EOTF from units of 100 cd/m²; light outside 0 to 10000 cd/m² is
    clamped to it (the formula encodes negative light to codes far above 1)."""
    return _colour_models("eotf_inverse_ST2084")(np.clip(np.asarray(linear, dtype=np.float64), 0.0, PQ_PEAK) * 100.0)


class _Quiet:
    """``fn`` with floating-point warnings off: colour-science evaluates every branch of a
    piecewise curve and discards the invalid ones with np.where. A class, so it pickles."""

    def __init__(self, fn):
        self.fn = fn
        self.__doc__ = fn.__doc__

    def __call__(self, values):
        with np.errstate(all="ignore"):
            return self.fn(values)


def _quiet(fn) -> _Quiet:
    """:class:`_Quiet` of ``fn``."""
    return _Quiet(fn)


def _function(name: str, decode, encode, domain=None, discontinuities=()) -> Function:
    """A :class:`Function` over ``decode``/``encode``; ``domain`` may be a rule computing
    it from the encoding (see :func:`_lut_domain`), evaluated when first asked."""
    decode, encode = _quiet(decode), _quiet(encode)
    return Function(name, decode, encode, (0.0, 1.0) if domain is None else domain, tuple(discontinuities))


#: N-Log's published segments do not meet at code 452/1023: the cube-root toe ends at
#: linear 0.32876 (before reflection scaling) and the log segment starts at 0.32846,
#: so decoding steps down there and is not monotonic within two 10-bit codes of it
#: (Nikon, "N-Log Specification Document", version 1.0.0).
NLOG_BREAK = 452.0 / 1023.0


def _lut_domain(encode) -> tuple[float, float]:
    """From code 0, or lower if linear -0.05 encodes below it, to code 1, or lower
    if half-float max encodes below it."""
    return (min(0.0, float(encode(-0.05))), min(1.0, float(encode(HALF_MAX))))


#: Canon Log v1.2 (Canon's current formulas), full-range normalised code,
#: scene reflectance (colour-science's 0.9 "reflection" scaling on).
_CANON_DECODE = {"bit_depth": 10, "in_normalised_code_value": True, "out_reflection": True, "method": "v1.2"}
_CANON_ENCODE = {"bit_depth": 10, "out_normalised_code_value": True, "in_reflection": True, "method": "v1.2"}
_NLOG_DECODE = {"bit_depth": 10, "in_normalised_code_value": True, "out_reflection": True}
_NLOG_ENCODE = {"bit_depth": 10, "out_normalised_code_value": True, "in_reflection": True}


def _functions() -> dict[str, Function]:
    """The curves that are not LogCamera, with their LUT domains.

    Domains are code 0 to 1 unless noted. ACEScc spans its whole range, from
    the code of linear 0 (it clamps below) to that of half-float max.
    Canon Log 2 extends below code 0 down to linear -0.05 (Canon's mirrored
    toe); Canon Log 3's code 0 is already linear -0.074. Apple Log, Mi-Log and
    Samsung Log clamp below code 0, and N-Log's cube-root toe is defined only
    down to code 0 (linear -0.0075). ST 2084 and HLG cover their signal range.
    """
    functions = (
        _function(
            "ACEScc",
            _colour_models("log_decoding_ACEScc"),
            _colour_models("log_encoding_ACEScc"),
            lambda f: (float(f(0.0)), float(f(HALF_MAX))),
        ),
        _function(
            "Canon Log 2",
            _colour_models("log_decoding_CanonLog2", **_CANON_DECODE),
            _colour_models("log_encoding_CanonLog2", **_CANON_ENCODE),
            _lut_domain,
        ),
        _function(
            "Canon Log 3",
            _colour_models("log_decoding_CanonLog3", **_CANON_DECODE),
            _colour_models("log_encoding_CanonLog3", **_CANON_ENCODE),
            _lut_domain,
        ),
        _function(
            "Apple Log", _colour_models("log_decoding_AppleLogProfile"), _colour_models("log_encoding_AppleLogProfile")
        ),
        _function(
            "N-Log",
            _colour_models("log_decoding_NLog", **_NLOG_DECODE),
            _colour_models("log_encoding_NLog", **_NLOG_ENCODE),
            discontinuities=(NLOG_BREAK,),
        ),
        _function("Samsung Log", vendor.samsung_log_decode, vendor.samsung_log_encode),
        _function("Mi-Log", _colour_models("log_decoding_MiLog"), _colour_models("log_encoding_MiLog")),
        _function("ST 2084", _pq_decode, _pq_encode),
        _function("HLG", _colour_models("oetf_inverse_BT2100_HLG"), _colour_models("oetf_BT2100_HLG")),
    )
    return {f.name: f for f in functions}


def _curves() -> dict[str, TransferFunction]:
    functions = _functions()
    return {
        "linear": Linear(),
        "sRGB": PiecewisePower(2.4, 0.055),
        # Extended sRGB (EDR): mirrored below zero and unbounded above one.
        "sRGB extended": PiecewisePower(2.4, 0.055, mirror=True),
        # BT.709 OETF as a moncurve: break 0.01795 and slope 4.514 from continuity (BT.709 prints 0.018, 4.5).
        "Rec.709": PiecewisePower(1.0 / 0.45, 0.099),
        "Gamma 1.8": Power(1.8),
        "Gamma 2.2": Power(2.2),
        # Adobe RGB (1998) Color Image Encoding, 2005, section 4.3.1.2: 2 51/256, as the ACES studio config (v5).
        "Adobe RGB (1998)": Power(563.0 / 256.0),
        "Gamma 2.4": Power(2.4),
        "Gamma 2.6": Power(2.6),
        "ACEScct": acescct(),
        "ACEScc": functions["ACEScc"],
        "ARRI LogC3 (EI800)": arri_logc3_ei800(),
        "ARRI LogC4": arri_logc4(),
        "S-Log3": sony_slog3(),
        "Log3G10": red_log3g10(),
        "Canon Log 2": functions["Canon Log 2"],
        "Canon Log 3": functions["Canon Log 3"],
        "V-Log": panasonic_vlog(),
        "BMDFilm Gen5": blackmagic_film_gen5(),
        "DaVinci Intermediate": davinci_intermediate(),
        "Apple Log": functions["Apple Log"],
        "D-Log": dji_dlog(),
        "F-Log": fujifilm_flog(),
        "F-Log2": fujifilm_flog2(),
        "L-Log": leica_llog(),
        "N-Log": functions["N-Log"],
        "Samsung Log": functions["Samsung Log"],
        "Mi-Log": functions["Mi-Log"],
        "T-Log": filmlight_tlog(),
        "T-LogE": filmlight_tloge(),
        "JPLog2": jplog2(),
        "ST 2084": functions["ST 2084"],
        "HLG": functions["HLG"],
    }


CURVES = MappingProxyType(_curves())
"""Canonical curve name to transfer record (read-only)."""
