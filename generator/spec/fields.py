"""Parsing of the spec's colorimetric fields: primaries, white points, transfer functions.

Each parser takes the raw TOML value and a ``where`` (source, field) pair for
errors, and returns a frozen record; a bad value raises
:class:`~generator.spec.schema.SpecError` naming the field and what is allowed.
"""

from __future__ import annotations

import csv
import difflib
import math
from pathlib import Path

import numpy as np

from generator import tolerances
from generator.colorimetry import transfer
from generator.colorimetry.curves import CURVES
from generator.files import not_readable
from generator.gamut.rgc import OCIO_RANGES, RGCParams
from generator.spec.schema import SpecError
from generator.tolerances import GAMUT_MIN_XY_AREA

TRANSFER_FAMILIES = {
    "linear": (),
    "gamma": ("exponent",),
    "piecewise_gamma": ("gamma", "offset"),
    "log_camera": (
        "base",
        "log_side_slope",
        "log_side_offset",
        "lin_side_slope",
        "lin_side_offset",
        "lin_side_break",
        "linear_slope",
    ),
    "tabulated": ("file",),
}
_OPTIONAL = {"lin_side_break", "linear_slope"}

#: Allowed values of the analytic families' parameters: (low, high, whether low itself is
#: excluded). Gamma's exponent decodes (linear = code ** exponent; the encoding raises scene
#: values to 1 / exponent): OCIO's ExponentTransform accepts 0.01 to 100, but beyond 0.2 to
#: 10 float32 evaluation leaves the range of the values verify probes (measured: at 0.11 the
#: encoding of 23160 overflows, at 50 the darkest ramp values underflow). piecewise_gamma's
#: are the bounds of OCIO's ExponentWithLinearTransform. log_camera's give an increasing
#: curve (OCIO only asks for non-zero slopes and a positive base other than 1).
PARAMETER_RANGES = {
    "gamma": {"exponent": (0.2, 10.0, False)},
    "piecewise_gamma": {"gamma": (1.0, 10.0, True), "offset": (0.0, 0.9, True)},
    "log_camera": {
        "base": (1.0, math.inf, True),
        "log_side_slope": (0.0, math.inf, True),
        "lin_side_slope": (0.0, math.inf, True),
        "linear_slope": (0.0, math.inf, True),
    },
}


def suggest(name: str, choices) -> str:
    """' (did you mean …?)' for close matches of ``name`` among ``choices``, or ''."""
    lowered = {c.lower(): c for c in choices}
    key = name.lower()
    close = [c for c in lowered if c.startswith(key)][:3] or difflib.get_close_matches(
        key, list(lowered), n=3, cutoff=0.6
    )
    return f" (did you mean {', '.join(repr(lowered[c]) for c in close)}?)" if close else ""


def number(value, source: str, field: str) -> float:
    """``value`` as a finite float; SpecError for a bool or anything else."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SpecError(source, field, f"expected a finite number, got {value!r}")
    return float(value)


def xy_pair(value, source: str, field: str, white: bool = False) -> tuple[float, float]:
    """A chromaticity [x, y]: a white needs y > 0; a primary may be imaginary (y < 0) but not y = 0."""
    if not isinstance(value, list) or len(value) != 2:
        raise SpecError(source, field, f"expected a chromaticity [x, y], got {value!r}")
    return plausible_xy(tuple(number(v, source, field) for v in value), source, field, white)


def plausible_xy(xy, source: str, field: str, white: bool = False, origin: str = "") -> tuple[float, float]:
    """``xy`` (typed, or derived from a spectrum as ``origin`` says) if it is a chromaticity a gamut can
    take; a white needs y > 0, a primary may be imaginary (y < 0) but not y = 0."""
    x, y = (float(v) for v in xy)
    if (white and y <= 0.0) or y == 0.0 or not (-1.0 < x < 2.0 and -1.0 < y < 2.0):
        need = "0 < y < 2" if white else "-1 < y < 2, y != 0"
        raise SpecError(source, field, f"{origin}chromaticity {[x, y]!r} is not plausible: need -1 < x < 2 and {need}")
    return (x, y)


def primaries(value, source: str, field: str) -> tuple:
    """Three xy chromaticities (red, green, blue) from ``[[x, y], [x, y], [x, y]]``."""
    if not isinstance(value, list) or len(value) != 3:
        raise SpecError(source, field, "expected three chromaticities [[xr, yr], [xg, yg], [xb, yb]]")
    return tuple(xy_pair(v, source, f"{field}[{i}]") for i, v in enumerate(value))


def _area(a, b, c) -> float:
    """Signed area of the xy triangle a, b, c (positive when counter-clockwise)."""
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))


def check_triangle(primaries: tuple, white: tuple, source: str, field: str, white_field: str) -> None:
    """The primaries must span a triangle and the white point lie inside it, each by at least
    :data:`~generator.tolerances.GAMUT_MIN_XY_AREA`, so the gamut's matrix is well conditioned."""
    area = _area(*primaries)
    if abs(area) < GAMUT_MIN_XY_AREA:
        raise SpecError(
            source,
            field,
            f"the primaries span no triangle (xy area {abs(area):.3g}: collinear or "
            f"repeated); allowed: three chromaticities enclosing an area of at least {GAMUT_MIN_XY_AREA:g}",
        )
    r, g, b = primaries
    shares = [_area(white, g, b), _area(r, white, b), _area(r, g, white)]
    if min(s * math.copysign(1.0, area) for s in shares) < GAMUT_MIN_XY_AREA:
        raise SpecError(
            source,
            white_field,
            f"white point ({white[0]:.5g}, {white[1]:.5g}) is outside the primaries' "
            "triangle or on its edge; allowed: a white inside it, making a triangle of xy area at least "
            f"{GAMUT_MIN_XY_AREA:g} with any two primaries",
        )


def resolve_path(value, base: Path, source: str, field: str) -> Path:
    """``value``, a readable file, as an absolute path (a relative one is from ``base``)."""
    if not isinstance(value, str) or not value:
        raise SpecError(source, field, f"expected a file path, got {value!r}")

    path = (base / value).resolve() if not Path(value).is_absolute() else Path(value)
    why = not_readable(path)
    if why == "does not exist":
        raise SpecError(source, field, f"file {value!r} does not exist")
    if why is not None:
        raise SpecError(source, field, f"{value!r} {why}; allowed: a file's path")
    return path


def _csv(reader, path: Path, source: str, field: str):
    try:
        return reader(path)
    except UnicodeDecodeError:
        raise SpecError(source, field, f"{path.name}: not UTF-8 text; allowed: a UTF-8 CSV") from None
    except (ValueError, OSError, csv.Error) as error:
        raise SpecError(source, field, f"{path.name}: {error}") from None


def whitepoint(value, base: Path, source: str, field: str) -> tuple[float, float]:
    """A white point: [x, y], a named CIE illuminant, a CCT in kelvin, or an SPD CSV file."""
    from generator.colorimetry import spectral  # lazy: it imports colour-science (seconds)

    if isinstance(value, list):
        return xy_pair(value, source, field, white=True)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        cct = number(value, source, field)
        if not 1667.0 <= cct <= 25000.0:
            raise SpecError(source, field, f"CCT {cct:g} K is outside 1667 to 25000 K")
        x, y = spectral.whitepoint_from_cct(cct)
        return (float(x), float(y))
    if isinstance(value, str) and value.lower().endswith(".csv"):
        path = resolve_path(value, base, source, field)
        xy = _csv(lambda p: spectral.whitepoint_from_sd(spectral.read_spd_csv(p)), path, source, field)
        return plausible_xy(xy, source, field, white=True, origin=f"{path.name}: the spectrum's ")
    if isinstance(value, str):
        import colour

        illuminants = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]
        if value in illuminants:
            x, y = illuminants[value]
            return (float(x), float(y))
        raise SpecError(
            source,
            field,
            f"unknown illuminant {value!r}{suggest(value, illuminants)}; "
            "allowed: [x, y], a CIE illuminant name (D65, D60, A, E, ...), a CCT in K, or an SPD .csv",
        )
    raise SpecError(source, field, f"expected [x, y], an illuminant name, a CCT or an SPD .csv, got {value!r}")


def spectral_primaries(value, base: Path, source: str, field: str) -> tuple:
    """Three xy chromaticities from the red, green and blue spectra of a CSV file."""
    from generator.colorimetry import spectral  # lazy: it imports colour-science (seconds)

    path = resolve_path(value, base, source, field)
    xy = _csv(spectral.read_primaries_spectra_csv, path, source, field)
    return tuple(plausible_xy(p, source, field, origin=f"{path.name}: column {c}'s ") for c, p in zip("rgb", xy))


def transfer_function(value, base: Path, source: str, field: str):
    """A transfer function: a library curve name, or a table with a ``family``."""
    if isinstance(value, str):
        for name, curve in CURVES.items():
            if name.lower() == value.lower():
                return name, curve
        raise SpecError(
            source,
            field,
            f"unknown curve {value!r}{suggest(value, CURVES)}; "
            "allowed: a library curve (ocioforge list --curves) or a table with 'family'",
        )
    if not isinstance(value, dict):
        raise SpecError(source, field, f"expected a curve name or a table, got {value!r}")
    if "family" not in value:
        raise SpecError(source, f"{field}.family", f"missing; allowed: {', '.join(TRANSFER_FAMILIES)}")
    family = value["family"]
    if not isinstance(family, str) or family not in TRANSFER_FAMILIES:
        what = f"unknown family {family!r}" if isinstance(family, str) else f"expected a string, got {family!r}"
        raise SpecError(source, f"{field}.family", f"{what}; allowed: {', '.join(TRANSFER_FAMILIES)}")
    allowed = set(TRANSFER_FAMILIES[family]) | {"family"}
    for key in value:
        if key not in allowed:
            raise SpecError(
                source, f"{field}.{key}", f"unknown key for family {family!r}; allowed: {', '.join(sorted(allowed))}"
            )
    missing = [k for k in TRANSFER_FAMILIES[family] if k not in value and k not in _OPTIONAL]
    if missing:
        raise SpecError(source, f"{field}.{missing[0]}", f"missing for family {family!r}")
    return _build_transfer(family, value, base, source, field)


def _build_transfer(family: str, value: dict, base: Path, source: str, field: str):
    label = f"custom {family}"
    if family == "linear":
        return "linear", transfer.Linear()
    if family == "tabulated":
        from generator.colorimetry import spectral  # lazy: it imports colour-science (seconds)

        path = resolve_path(value["file"], base, source, f"{field}.file")
        code, linear = _csv(spectral.read_curve_csv, path, source, f"{field}.file")
        return label, transfer.Tabulated(path.name, tuple(map(float, code)), tuple(map(float, linear)))
    params = {k: number(v, source, f"{field}.{k}") for k, v in value.items() if k != "family"}
    check_ranges(family, params, source, field)
    if family == "gamma":
        return label, transfer.Power(params["exponent"])
    if family == "piecewise_gamma":
        curve = transfer.PiecewisePower(params["gamma"], params["offset"])
        _check_float32(
            curve,
            family,
            source,
            field,
            "an offset of at least 1e-6, below which OCIO evaluates "
            "1e-6, and with a steep gamma one whose toe's slopes stay within float32",
        )
        if curve.break_code >= 1.0:
            raise SpecError(
                source,
                f"{field}.offset",
                f"the toe's break, offset / (gamma - 1) = {curve.break_code:.4g}, "
                f"lies at or above code 1, so no code reaches the power and code 1 decodes to "
                f"{float(curve.decode(1.0)):.4g}, not 1; allowed: an offset below gamma - 1 "
                f"({params['gamma'] - 1.0:.4g})",
            )
        return label, curve
    _check_log_break(params, source, field)
    log = transfer.LogCamera(**params)
    if log.lin_side_break is None:
        _check_black(log, source, field)
    _check_float32(
        log,
        family,
        source,
        field,
        "a base, slopes, offsets and break of a real camera curve: the library's are within 1.6e-6",
    )
    return label, log


def _check_float32(curve, family: str, source: str, field: str, hint: str) -> None:
    """OCIO evaluates the curve in float32 (transfer.float32_departure): it must follow the formula
    within CURVE_FLOAT32_RELATIVE wherever verify probes it."""
    departure = transfer.float32_departure(curve, tolerances.RELATIVE_FLOOR)
    if departure > tolerances.CURVE_FLOAT32_RELATIVE:
        low, high = transfer.PROBED_LINEAR
        raise SpecError(
            source,
            field,
            f"OCIO evaluates a {family} curve in float32, which departs {departure:.2g} "
            f"relative from this one on codes 0 to 1 and linear values ±{low:g} to {high:g}; allowed: "
            f"parameters it follows within {tolerances.CURVE_FLOAT32_RELATIVE:g} ({hint})",
        )


def check_ranges(family: str, params: dict, source: str, field: str) -> None:
    """The analytic ``family``'s ``params`` (those given) within :data:`PARAMETER_RANGES`."""
    for key, limits in PARAMETER_RANGES[family].items():
        if params.get(key) is not None and not _within(params[key], *limits):
            raise SpecError(source, f"{field}.{key}", f"{params[key]:g} is out of range; allowed: {_describe(*limits)}")


def _within(value: float, low: float, high: float, open_low: bool) -> bool:
    return (value > low if open_low else value >= low) and value <= high


def _describe(low: float, high: float, open_low: bool) -> str:
    if high == math.inf:
        return f"> {low:g}" if open_low else f">= {low:g}"
    return f"> {low:g} and <= {high:g}" if open_low else f"{low:g} to {high:g}"


def _check_black(curve, source: str, field: str) -> None:
    """A log_camera curve without a toe keeps black off the log's pole: float32's rounding of
    linear 0 (a unit in the last place of 1, what a matrix leaves in a channel at 0) moves
    black's code by at most the verifier's ANALYTIC_RELATIVE (floor RELATIVE_FLOOR)."""
    if curve.lin_side_offset <= 0.0:
        raise SpecError(
            source,
            f"{field}.lin_side_offset",
            f"{curve.lin_side_offset:g} leaves black without a code "
            "(the log of lin_side_offset at linear 0); allowed: > 0, or a lin_side_break where a linear "
            "toe takes over",
        )
    black, rounded = curve.encode(np.array([0.0, tolerances.FLOAT32_UNIT_ROUNDOFF]))
    moved = abs(rounded - black) / max(abs(black), tolerances.RELATIVE_FLOOR)
    if moved > tolerances.ANALYTIC_RELATIVE:
        raise SpecError(
            source,
            f"{field}.lin_side_offset",
            f"{curve.lin_side_offset:g} puts black so near the log's "
            f"pole that float32's rounding of linear 0 moves its code by {moved:.2g} (relative); allowed: "
            f"a lin_side_offset large enough that it moves by at most {tolerances.ANALYTIC_RELATIVE:g}, or "
            "a lin_side_break where a linear toe takes over",
        )


def _check_log_break(params: dict, source: str, field: str) -> None:
    """A log_camera's linear segment starts at lin_side_break, where the log segment must be
    defined (its argument positive); linear_slope is that segment's slope, so needs the break."""
    if "lin_side_break" not in params:
        if "linear_slope" in params:
            raise SpecError(source, f"{field}.linear_slope", "needs lin_side_break, where the linear segment starts")
        return
    lowest = -params["lin_side_offset"] / params["lin_side_slope"]
    if params["lin_side_break"] <= lowest:
        raise SpecError(
            source,
            f"{field}.lin_side_break",
            f"at {params['lin_side_break']:g} the log segment is undefined "
            f"(lin_side_slope * lin_side_break + lin_side_offset <= 0); allowed: > {lowest:g}",
        )


#: The keys of a spec's [rgc] table, each as RGCParams holds it.
RGC_KEYS = ("limits", "thresholds", "power")


def rgc_params(value, source: str):
    """The spec's [rgc] table (limits and thresholds as [cyan, magenta, yellow], power), each
    key defaulting to ACES 1.3's value, within what OpenColorIO's fixed function accepts."""
    defaults = RGCParams()
    if value is None:
        return defaults
    if not isinstance(value, dict):
        raise SpecError(
            source, "rgc", f"expected a table of {', '.join(RGC_KEYS)} (under an [rgc] header), got {value!r}"
        )
    for key in value:
        if key not in RGC_KEYS:
            raise SpecError(source, f"rgc.{key}", f"unknown key; allowed: {', '.join(RGC_KEYS)}")
    chosen: dict[str, tuple[float, ...]] = {
        "limits": defaults.limits,
        "thresholds": defaults.thresholds,
        "power": (defaults.power,),
    }
    for key, given in value.items():
        if key == "power":
            numbers = [("rgc.power", number(given, source, "rgc.power"))]
        else:
            if not isinstance(given, list) or len(given) != 3:
                raise SpecError(source, f"rgc.{key}", f"expected three numbers [cyan, magenta, yellow], got {given!r}")
            numbers = [(f"rgc.{key}[{i}]", number(v, source, f"rgc.{key}[{i}]")) for i, v in enumerate(given)]
        low, high = OCIO_RANGES[key]
        for field, v in numbers:
            if not low <= v <= high:
                raise SpecError(
                    source,
                    field,
                    f"{v!r} is outside what OpenColorIO's ACES_GAMUT_COMP_13 takes; allowed: {low:g} to {high:g}",
                )
        chosen[key] = tuple(v for _, v in numbers)
    return RGCParams(*chosen["limits"], *chosen["thresholds"], *chosen["power"])
