"""Transfer functions as declarative families.

Every family is a frozen record with two pure, vectorised methods:
``decode(code) -> linear`` and ``encode(linear) -> code``, float64 throughout,
acting elementwise over arrays of any shape. These are the reference
evaluation: the OCIO emitter expresses the same records as transforms, the
baker samples them and the verifier compares against them.

Linear is scene-referred (0.18 = mid grey) for camera and working encodings,
and display-relative (1.0 = 100 cd/m², the reference white) for display EOTFs.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np


def _array(values) -> np.ndarray:
    return np.asarray(values, dtype=np.float64)


#: Linear magnitudes verify probes a scene space's curve with, either sign and 0, beside its codes
#: 0 to 1 (generator.verify.probes: noise around black from 1e-12, over-range neutrals to half-float
#: max): the float32 checks of the analytic families cover them and the codes they encode to.
PROBED_LINEAR = (1e-12, 65504.0)

#: OCIO's moncurve (ExponentWithLinearTransform) evaluates max(gamma, 1 + EPS) and max(offset, EPS)
#: (OpenColorIO ops/gamma/GammaOpUtils.cpp, EPS = 1e-6), so a smaller offset is a different curve.
OCIO_MONCURVE_EPS = 1e-6


def probed_values(curve, samples: int) -> tuple[np.ndarray, np.ndarray]:
    """Codes and linear values where verify probes ``curve``, float32 exactly (engines see float32):
    codes 0 to 1 and those of the linear values; linear ±PROBED_LINEAR, 0 and those of the codes."""
    magnitudes = np.geomspace(*PROBED_LINEAR, samples)
    ramp = np.linspace(0.0, 1.0, samples)
    with np.errstate(all="ignore"):
        light = np.concatenate([-magnitudes, [0.0], magnitudes, curve.decode(ramp)])
        codes = np.concatenate([ramp, curve.encode(light)])
        codes, light = (v[np.isfinite(v)].astype(np.float32) for v in (codes, light))
    return tuple(v[np.isfinite(v)].astype(np.float64) for v in (codes, light))


def _relative(approximate: np.ndarray, exact: np.ndarray, floor: float, slack=0.0) -> np.ndarray:
    """(|approximate - exact| less ``slack``, the part no float32 evaluation avoids) / max(|exact|,
    floor) where ``exact`` is finite (+Inf where the approximation is not)."""
    shown = np.isfinite(exact)
    slack = np.broadcast_to(slack, exact.shape)[shown]
    error = np.maximum(np.abs(approximate[shown].astype(np.float64) - exact[shown]) - slack, 0.0)
    return np.nan_to_num(error / np.maximum(np.abs(exact[shown]), floor), nan=np.inf, posinf=np.inf)


def float32_departure(curve, floor: float, samples: int = 4097) -> float:
    """Largest relative departure (``floor`` below which it is absolute) of ``curve`` evaluated as
    OCIO does (its ``float32(codes, light)``: decoded codes and encoded light, in float32) from its
    float64 formula, over the values verify probes (:func:`probed_values`); +Inf where it overflows.
    An encoding's error is counted beyond what float32 rounding of a log's argument alone brings
    (``curve.argument_rounding``): near the log's pole it is unbounded, and whether a curve passed
    had depended on how close a sample fell (Cineon's, 1.6e-5 with 4097 samples)."""
    codes, light = probed_values(curve, samples)
    with np.errstate(all="ignore"):
        decoded, encoded = curve.float32(codes.astype(np.float32), light.astype(np.float32))
        slack = curve.argument_rounding(light) if hasattr(curve, "argument_rounding") else 0.0
        worst = np.concatenate(
            [_relative(decoded, curve.decode(codes), floor), _relative(encoded, curve.encode(light), floor, slack)]
        )
    return float(worst.max(initial=0.0))


def _root(x: np.ndarray, exponent: float) -> np.ndarray:
    """``x ** exponent`` (``x >= 0``, ``exponent > 0``), the power evaluated only where ``x`` is
    neither 0 nor 1, which it leaves unchanged exactly: a lattice of clipped colours is mostly
    those (measured: 76% of a 65³ sRGB clip lattice's values, whose encoding then takes 10 ms, not 16)."""
    return np.power(x, exponent, out=np.array(x, dtype=np.float64), where=(x != 0.0) & (x != 1.0))


@dataclass(frozen=True)
class Linear:
    """The identity: the encoding is already linear."""

    def decode(self, code):
        """Linear values of ``code``: a float64 copy."""
        return _array(code).copy()

    def encode(self, linear):
        """Code values of ``linear``: a float64 copy."""
        return _array(linear).copy()


@dataclass(frozen=True)
class Power:
    """A pure power law, ``linear = code ** exponent``, mirrored for negatives.

    Expressed in OCIO as an ExponentTransform with the mirror negative style.
    """

    exponent: float

    def decode(self, code):
        """Linear values of ``code``: ``|code| ** exponent``, sign kept."""
        c = _array(code)
        return np.sign(c) * np.abs(c) ** self.exponent

    def encode(self, linear):
        """Code values of ``linear``: ``|linear| ** (1 / exponent)``, sign kept."""
        v = _array(linear)
        return np.sign(v) * _root(np.abs(v), 1.0 / self.exponent)


@dataclass(frozen=True)
class PiecewisePower:
    """A power law with a linear segment near black (the "moncurve" family).

    ``linear = ((code + offset) / (1 + offset)) ** gamma`` above the break and a
    straight line through the origin below it, the break and slope chosen so the
    curve and its first derivative are continuous (IEC 61966-2-1 for sRGB with
    gamma 2.4, offset 0.055; ITU-R BT.709 with gamma 1/0.45, offset 0.099).
    The linear segment continues below zero, or with ``mirror`` the curve is
    mirrored there (``f(-x) = -f(x)``, the extended sRGB of EDR displays). This
    is exactly OCIO's ExponentWithLinearTransform (negative style linear or mirror).
    """

    gamma: float
    offset: float
    mirror: bool = False

    @property
    def break_code(self) -> float:
        """Code value where the power segment meets the linear one."""
        return self.offset / (self.gamma - 1.0)

    @property
    def break_linear(self) -> float:
        """The linear value where the linear toe meets the power segment."""
        g, o = self.gamma, self.offset
        return (o * g / ((g - 1.0) * (1.0 + o))) ** g

    @property
    def slope(self) -> float:
        """Slope of the linear segment, linear over code."""
        return self.break_linear / self.break_code

    def decode(self, code):
        """Linear values of ``code``: the toe below the break, the power segment above."""
        c = _array(code)
        if self.mirror:
            return np.sign(c) * PiecewisePower(self.gamma, self.offset).decode(np.abs(c))
        power = ((np.maximum(c, self.break_code) + self.offset) / (1.0 + self.offset)) ** self.gamma
        return np.where(c > self.break_code, power, c * self.slope)

    def encode(self, linear):
        """Code values of ``linear``: the toe below the break, the power segment above."""
        v = _array(linear)
        if self.mirror:
            return np.sign(v) * PiecewisePower(self.gamma, self.offset).encode(np.abs(v))
        power = (1.0 + self.offset) * _root(np.maximum(v, self.break_linear), 1.0 / self.gamma) - self.offset
        return np.where(v > self.break_linear, power, v / self.slope)

    def float32(self, codes: np.ndarray, light: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``codes`` decoded and ``light`` encoded as OCIO's CPU renderer evaluates the curve
        (ops/gamma/GammaOpCPU.cpp): OCIO_MONCURVE_EPS's clamps, then float32 parameters and
        arithmetic; with ``mirror``, on magnitudes, the sign put back."""
        f = np.float32
        g, o = max(self.gamma, 1.0 + OCIO_MONCURVE_EPS), max(self.offset, OCIO_MONCURVE_EPS)
        knee = o * g / ((g - 1.0) * (1.0 + o))
        fwd = [f(v) for v in (1.0 / (1.0 + o), o / (1.0 + o), g, o / (g - 1.0), (g - 1.0) / o * knee**g)]
        rev = [f(v) for v in (1.0 + o, o, 1.0 / g, knee**g, ((g - 1.0) / o) ** (g - 1.0) * ((1.0 + o) / g) ** g)]
        sign = (np.sign(codes), np.sign(light)) if self.mirror else (f(1.0), f(1.0))
        x, y = (np.abs(v) if self.mirror else v for v in (codes, light))
        scale, offset, gamma, knot, slope = fwd
        decoded = np.where(x <= knot, x * slope, np.power(x * scale + offset, gamma))
        scale, offset, gamma, knot, slope = rev
        encoded = np.where(y <= knot, y * slope, np.power(y, gamma) * scale - offset)
        return sign[0] * decoded, sign[1] * encoded


@dataclass(frozen=True)
class LogCamera:
    """A logarithm of an affine function of linear, with a linear segment below a break.

    ``code = log_side_slope * log_base(lin_side_slope * x + lin_side_offset) + log_side_offset``
    for ``x > lin_side_break``; below it a straight line that meets the log
    segment at the break, with slope ``linear_slope`` or, when that is None,
    the slope that makes the derivative continuous. Without a break the log
    segment is used everywhere (and is NaN where its argument is not
    positive). This is exactly OCIO's LogCameraTransform (LogAffineTransform
    when there is no break).
    """

    base: float
    log_side_slope: float
    log_side_offset: float
    lin_side_slope: float
    lin_side_offset: float
    lin_side_break: float | None = None
    linear_slope: float | None = None

    def _log(self, x):
        with np.errstate(invalid="ignore", divide="ignore"):
            arg = self.lin_side_slope * x + self.lin_side_offset
            return self.log_side_slope * np.log(arg) / math.log(self.base) + self.log_side_offset

    @property
    def break_code(self) -> float:
        """The code value at the linear break."""
        return float(self._log(self.lin_side_break))

    @property
    def code_constant(self) -> float:
        """Magnitude, in code values, of the constant a float32 evaluation of the decoding
        carries: the log segment's offset, which the code is taken from, and from which
        OCIO derives the linear segment (OCIO's ACEScct decode sits 3.4e-9 below the exact
        linear segment at code 0.073: 0.6 units of 2**-24 in code, where the code's own
        rounding is 0.07 and the offset's 0.55)."""
        return abs(self.log_side_offset)

    @property
    def toe_slope(self) -> float:
        """Slope of the linear segment, code over linear."""
        if self.linear_slope is not None:
            return self.linear_slope
        if self.lin_side_break is None:
            raise ValueError("a LogCamera without a break has no linear segment")
        arg = self.lin_side_slope * self.lin_side_break + self.lin_side_offset
        return self.log_side_slope * self.lin_side_slope / (arg * math.log(self.base))

    def encode(self, linear):
        """Code values of ``linear``: the log segment, the straight line below the break."""
        x = _array(linear)
        log = self._log(x)
        if self.lin_side_break is None:
            return log
        toe = self.toe_slope * (x - self.lin_side_break) + self.break_code
        return np.where(x > self.lin_side_break, log, toe)

    def decode(self, code):
        """Linear values of ``code``: the inverse of :meth:`encode`."""
        y = _array(code)
        lin = (
            self.base ** ((y - self.log_side_offset) / self.log_side_slope) - self.lin_side_offset
        ) / self.lin_side_slope
        if self.lin_side_break is None:
            return lin
        toe = (y - self.break_code) / self.toe_slope + self.lin_side_break
        return np.where(y > self.break_code, lin, toe)

    def float32(self, codes: np.ndarray, light: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``codes`` decoded and ``light`` encoded with the curve's formula in float32, as OCIO
        evaluates it. Extreme parameters (a huge base, a tiny slope, offsets far from the codes, a
        break far above black) lose the curve to float32 cancellation or overflow."""
        f = np.float32
        b, s, o, ls, lo = (
            f(v)
            for v in (self.base, self.log_side_slope, self.log_side_offset, self.lin_side_slope, self.lin_side_offset)
        )
        lin = (b ** ((codes - o) / s) - lo) / ls
        code = s * np.log(ls * light + lo) / f(math.log(self.base)) + o
        if self.lin_side_break is not None:
            bc, ts, lb = f(self.break_code), f(self.toe_slope), f(self.lin_side_break)
            lin = np.where(codes > bc, lin, (codes - bc) / ts + lb)
            code = np.where(light > lb, code, ts * (light - lb) + bc)
        return lin, code

    def argument_rounding(self, light: np.ndarray) -> np.ndarray:
        """The code error float32 rounding of the log's argument alone brings to encoding
        ``light`` (the product and the sum each rounded: within float32's epsilon times
        ``|lin_side_slope * x| + |lin_side_offset|``), times the log's slope there; 0 on the toe.
        Near the log's pole the argument cancels and this grows without bound: no float32
        engine encodes those values better."""
        eps = float(np.finfo(np.float32).eps)
        product = np.abs(self.lin_side_slope * light)
        with np.errstate(divide="ignore", invalid="ignore"):
            arg = np.abs(self.lin_side_slope * light + self.lin_side_offset)
            slack = self.log_side_slope / math.log(self.base) * eps * (product + abs(self.lin_side_offset)) / arg
        return slack if self.lin_side_break is None else np.where(light > self.lin_side_break, slack, 0.0)


@dataclass(frozen=True)
class Function:
    """A curve given by a pair of published functions (colour-science or ours).

    ``name`` is the curve's registry name (see :mod:`generator.colorimetry.curves`);
    OCIO expresses it with a builtin where the target version has one, and as a
    baked 1D LUT over ``domain`` (code values) otherwise. Codes outside the
    domain are clamped to it when baked.
    """

    name: str
    decode_fn: Callable = field(compare=False, repr=False)
    encode_fn: Callable = field(compare=False, repr=False)
    #: The code-value domain, or a rule computing it from the encoding function
    #: (evaluated when asked, so colour-science is imported only when needed).
    domain_rule: tuple[float, float] | Callable = field(default=(0.0, 1.0), compare=False, repr=False)
    #: Code values where the published formula itself jumps (segments that do not meet).
    discontinuities: tuple[float, ...] = ()

    @property
    def domain(self) -> tuple[float, float]:
        """The code-value domain a baked LUT covers: the rule's result, or the given pair."""
        rule = self.domain_rule
        lo, hi = rule(self.encode) if callable(rule) else rule
        return (float(lo), float(hi))

    def decode(self, code):
        """Linear values of ``code`` through ``decode_fn``, float64, warnings silenced."""
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return _array(self.decode_fn(_array(code)))

    def encode(self, linear):
        """Code values of ``linear`` through ``encode_fn``, float64, warnings silenced."""
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return _array(self.encode_fn(_array(linear)))


@dataclass(frozen=True)
class Tabulated:
    """A curve tabulated in a CSV file: code values and the linear values they decode to.

    Linear interpolation between rows; the table must be strictly increasing in
    both columns (so it can be inverted). Values outside the table are clamped to
    its ends, as OCIO clamps a 1D LUT's input to its domain.
    """

    source: str
    code: tuple[float, ...]
    linear: tuple[float, ...]

    @property
    def domain(self) -> tuple[float, float]:
        """The first and last code values of the table."""
        return (self.code[0], self.code[-1])

    def decode(self, code):
        """Linear values of ``code``, interpolated linearly in the table (clamped at its ends)."""
        return np.interp(_array(code), self.code, self.linear)

    def encode(self, linear):
        """Code values of ``linear``, interpolated linearly in the table (clamped at its ends)."""
        return np.interp(_array(linear), self.linear, self.code)


TransferFunction = Linear | Power | PiecewisePower | LogCamera | Function | Tabulated
