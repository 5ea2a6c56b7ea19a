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
from dataclasses import dataclass, field
from typing import Callable

import numpy as np


def _array(values) -> np.ndarray:
    return np.asarray(values, dtype=np.float64)


def _root(x: np.ndarray, exponent: float) -> np.ndarray:
    """``x ** exponent`` (``x >= 0``, ``exponent > 0``), the power evaluated only where ``x`` is
    neither 0 nor 1, which it leaves unchanged exactly: a lattice of clipped colours is mostly
    those (measured: 76% of a 65³ sRGB clip lattice's values, whose encoding then takes 10 ms, not 16)."""
    return np.power(x, exponent, out=np.array(x, dtype=np.float64), where=(x != 0.0) & (x != 1.0))


@dataclass(frozen=True)
class Linear:
    """The identity: the encoding is already linear."""

    def decode(self, code):
        return _array(code).copy()

    def encode(self, linear):
        return _array(linear).copy()


@dataclass(frozen=True)
class Power:
    """A pure power law, ``linear = code ** exponent``, mirrored for negatives.

    Expressed in OCIO as an ExponentTransform with the mirror negative style.
    """

    exponent: float

    def decode(self, code):
        c = _array(code)
        return np.sign(c) * np.abs(c) ** self.exponent

    def encode(self, linear):
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
        g, o = self.gamma, self.offset
        return (o * g / ((g - 1.0) * (1.0 + o))) ** g

    @property
    def slope(self) -> float:
        """Slope of the linear segment, linear over code."""
        return self.break_linear / self.break_code

    def decode(self, code):
        c = _array(code)
        if self.mirror:
            return np.sign(c) * PiecewisePower(self.gamma, self.offset).decode(np.abs(c))
        power = ((np.maximum(c, self.break_code) + self.offset) / (1.0 + self.offset)) ** self.gamma
        return np.where(c > self.break_code, power, c * self.slope)

    def encode(self, linear):
        v = _array(linear)
        if self.mirror:
            return np.sign(v) * PiecewisePower(self.gamma, self.offset).encode(np.abs(v))
        power = (1.0 + self.offset) * _root(np.maximum(v, self.break_linear), 1.0 / self.gamma) - self.offset
        return np.where(v > self.break_linear, power, v / self.slope)


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
        arg = self.lin_side_slope * self.lin_side_break + self.lin_side_offset
        return self.log_side_slope * self.lin_side_slope / (arg * math.log(self.base))

    def encode(self, linear):
        x = _array(linear)
        log = self._log(x)
        if self.lin_side_break is None:
            return log
        toe = self.toe_slope * (x - self.lin_side_break) + self.break_code
        return np.where(x > self.lin_side_break, log, toe)

    def decode(self, code):
        y = _array(code)
        lin = (self.base ** ((y - self.log_side_offset) / self.log_side_slope) - self.lin_side_offset) / self.lin_side_slope
        if self.lin_side_break is None:
            return lin
        toe = (y - self.break_code) / self.toe_slope + self.lin_side_break
        return np.where(y > self.break_code, lin, toe)

    def float32_departure(self, floor: float, samples: int = 4097) -> float:
        """Largest relative departure (``floor`` below which it is absolute) of the curve's formula
        evaluated in float32, as OCIO evaluates it, from float64: decoding codes 0 to 1 and
        encoding their light back. Extreme parameters (a huge base, a tiny slope, offsets far
        from the codes) lose the curve to float32 cancellation; +Inf where it overflows."""
        f = np.float32
        codes = np.linspace(0.0, 1.0, samples)
        b, s, o, ls, lo = (f(v) for v in (self.base, self.log_side_slope, self.log_side_offset, self.lin_side_slope,
                                           self.lin_side_offset))
        with np.errstate(all="ignore"):
            exact = self.decode(codes)
            y = codes.astype(f)
            lin = (b ** ((y - o) / s) - lo) / ls
            x = exact.astype(f)
            code = s * np.log(ls * x + lo) / f(math.log(self.base)) + o
            if self.lin_side_break is not None:
                bc, ts, lb = f(self.break_code), f(self.toe_slope), f(self.lin_side_break)
                lin = np.where(y > bc, lin, (y - bc) / ts + lb)
                code = np.where(x > lb, code, ts * (x - lb) + bc)
            shown = np.isfinite(exact)
            decoded = np.abs(lin.astype(np.float64) - exact) / np.maximum(np.abs(exact), floor)
            encoded = np.abs(code.astype(np.float64) - codes) / np.maximum(np.abs(codes), floor)
            worst = np.maximum(decoded, encoded)[shown]
        return float(np.nan_to_num(worst, nan=np.inf, posinf=np.inf).max(initial=0.0))


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
        rule = self.domain_rule
        return tuple(float(v) for v in (rule(self.encode) if callable(rule) else rule))

    def decode(self, code):
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return _array(self.decode_fn(_array(code)))

    def encode(self, linear):
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
        return (self.code[0], self.code[-1])

    def decode(self, code):
        return np.interp(_array(code), self.code, self.linear)

    def encode(self, linear):
        return np.interp(_array(linear), self.linear, self.code)


TransferFunction = Linear | Power | PiecewisePower | LogCamera | Function | Tabulated
