"""Chromaticities derived from spectra: monochromatic primaries, white points,
and the CSV files a spec may point at.

Colorimetry follows CIE 015:2018 (tristimulus values by summation of the
spectral power distribution weighted by the colour-matching functions) with
colour-science's CIE 1931 2 degree observer tabulated at 1 nm, 360-830 nm.
colour-science's datasets are copied before any change, never mutated.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import colour
import numpy as np

#: The observer every derivation here uses unless told otherwise.
CIE_1931_2_DEGREE = "CIE 1931 2 Degree Standard Observer"

#: Wavelengths (nm) of the CIE 1931 RGB primaries: a red at the long end of
#: the spectrum and the mercury lines at 546.1 and 435.8 nm (CIE 1931).
CIE_RGB_WAVELENGTHS = (700.0, 546.1, 435.8)

#: CIE RGB is balanced to the equal-energy stimulus E.
CIE_RGB_WHITEPOINT = (1.0 / 3.0, 1.0 / 3.0)

#: CCT range of the CIE daylight locus (CIE 015:2018, 4000 K to 25 000 K);
#: below it :func:`whitepoint_from_cct` uses the Planckian locus.
DAYLIGHT_CCT_RANGE = (4000.0, 25000.0)

#: Lowest CCT :func:`whitepoint_from_cct` accepts (Planckian locus).
MINIMUM_CCT = 1000.0

#: Wavelengths a spectral CSV may hold: the tabulated domain of the CIE CMFs.
CSV_WAVELENGTH_DOMAIN = (360.0, 830.0)

#: Span a spectral CSV must cover: the visible range CIE 015 integrates over
#: when nothing wider is available.
CSV_REQUIRED_SPAN = (380.0, 780.0)


def _cmfs(name: str) -> colour.MultiSpectralDistributions:
    if name not in colour.MSDS_CMFS:
        raise ValueError(f"unknown colour-matching functions {name!r}; allowed: {', '.join(sorted(colour.MSDS_CMFS))}")
    return colour.MSDS_CMFS[name].copy()


def monochromatic_primaries_xy(wavelengths_nm, cmfs: str = CIE_1931_2_DEGREE) -> np.ndarray:
    """Chromaticities of monochromatic stimuli, read off the colour-matching functions.

    The chromaticity of a monochromatic stimulus at wavelength λ is that of
    the colour-matching functions themselves, ``x = x̄ / (x̄ + ȳ + z̄)``
    (CIE 015:2018, spectral locus). Between the 1 nm tabulated wavelengths
    the functions are interpolated with the Sprague (1880) quintic, the
    method CIE 167:2005 recommends for uniformly spaced spectral data; at
    546.1 nm it reproduces the chromaticities CIE publishes for the CIE RGB
    primaries to within 5e-6.

    Parameters
    ----------
    wavelengths_nm : array_like, shape (n,)
        Wavelengths in nm, inside the colour-matching functions' domain.
    cmfs : str
        Key of ``colour.MSDS_CMFS``.

    Returns
    -------
    numpy.ndarray, shape (n, 2)
        CIE xy of each wavelength, float64.
    """
    wavelengths = np.atleast_1d(np.asarray(wavelengths_nm, dtype=np.float64))
    observer = _cmfs(cmfs)
    low, high = observer.shape.start, observer.shape.end
    if wavelengths.ndim != 1 or np.any((wavelengths < low) | (wavelengths > high)):
        raise ValueError(f"wavelengths must be a 1-D sequence within {low:g}-{high:g} nm, got {wavelengths_nm!r}")
    observer.interpolator = colour.SpragueInterpolator
    return np.asarray(colour.XYZ_to_xy(observer[wavelengths]), dtype=np.float64)


def cie_rgb_primaries() -> np.ndarray:
    """The CIE 1931 RGB primaries, 700, 546.1 and 435.8 nm, as CIE xy (3, 2).

    Derived from the CIE 1931 2 degree colour-matching functions with
    :func:`monochromatic_primaries_xy`; the white point is equal-energy E,
    :data:`CIE_RGB_WHITEPOINT`.
    """
    return monochromatic_primaries_xy(CIE_RGB_WAVELENGTHS, CIE_1931_2_DEGREE)


def whitepoint_from_sd(sd: colour.SpectralDistribution, cmfs: str = CIE_1931_2_DEGREE) -> np.ndarray:
    """CIE xy of a spectral power distribution.

    The distribution is evaluated (with its own interpolator) at the 1 nm
    wavelengths of the colour-matching functions that lie within its
    domain, and colour-science's summation (``sd_to_XYZ``, method
    "Integration", equal-energy weighting: the distribution is the
    stimulus) gives XYZ (CIE 015:2018, section 7); a distribution with rows
    closer than 1 nm is summed at its rows too (:func:`_fine_XYZ`). Nothing
    is extrapolated beyond the distribution's own wavelengths.

    Parameters
    ----------
    sd : colour.SpectralDistribution
        Relative spectral power, wavelengths in nm.
    cmfs : str
        Key of ``colour.MSDS_CMFS``.

    Returns
    -------
    numpy.ndarray, shape (2,)
    """
    observer = _cmfs(cmfs)
    wavelengths = observer.wavelengths
    start = max(math.ceil(float(sd.wavelengths[0])), observer.shape.start)
    end = min(math.floor(float(sd.wavelengths[-1])), observer.shape.end)
    if end - start < 1:
        raise ValueError(f"{sd.name!r} does not overlap the colour-matching functions' {observer.shape}")
    rows = np.asarray(sd.wavelengths, dtype=np.float64)
    if rows.size > 1 and np.diff(rows).min() < 1.0:
        XYZ = _fine_XYZ(sd, observer, rows[(rows >= start) & (rows <= end)], start, end)
    else:
        shape = colour.SpectralShape(start, end, 1)
        inside = (wavelengths >= start) & (wavelengths <= end)
        values = _peak_1(sd[wavelengths[inside]])
        aligned = colour.SpectralDistribution(values, wavelengths[inside], name=sd.name)
        XYZ = colour.sd_to_XYZ(aligned, observer.trim(shape), illuminant=colour.sd_ones(shape), method="Integration")
    if not np.sum(XYZ) > 0.0:
        raise ValueError(f"{sd.name!r} has no positive tristimulus sum; it has no chromaticity")
    return np.asarray(colour.XYZ_to_xy(XYZ), dtype=np.float64)


def _peak_1(values: np.ndarray) -> np.ndarray:
    """Scaled to a peak of 1 (the chromaticity is the spectrum's shape): a finite spectrum of
    huge values would overflow in the sums."""
    return values / np.max(values) if np.max(values) > 0.0 else values


def _fine_XYZ(sd, observer, rows: np.ndarray, start: float, end: float) -> np.ndarray:
    """XYZ (up to scale) of a distribution tabulated finer than 1 nm: summed over the union of
    its own rows and the observer's whole nanometres, each weighted by the trapezoid rule (half
    its two intervals), the colour-matching functions interpolated there with the Sprague
    quintic. At whole nanometres alone, a laser's line 0.5 nm wide (rows every 0.1 nm) falls
    between them: its white came out 0.006 off in u'v', and a line off the whole nanometres
    lost all its power."""
    grid = np.union1d(np.arange(start, end + 1.0), rows)
    weights = np.zeros_like(grid)
    weights[1:] += np.diff(grid) / 2.0
    weights[:-1] += np.diff(grid) / 2.0
    observer.interpolator = colour.SpragueInterpolator
    return (_peak_1(sd[grid]) * weights) @ np.asarray(observer[grid], dtype=np.float64)


def whitepoint_from_cct(cct, cmfs: str = CIE_1931_2_DEGREE) -> np.ndarray:
    """CIE xy of a white given by its correlated colour temperature (K).

    At or above 4000 K: the CIE daylight locus (CIE 015:2018, equations for
    the D series, valid 4000-25 000 K), through colour-science's
    ``CCT_to_xy_CIE_D``. Below 4000 K: the Planckian locus, a blackbody at
    that temperature (c2 = 1.4388e-2 m K) integrated with the
    colour-matching functions (``CCT_to_uv_Planck1900``). The two loci do
    not meet: the daylight locus lies above the Planckian one, so xy jumps at
    4000 K. The daylight polynomial places CIE D65 (6504 K) about 1e-4 above
    the chromaticity of its tabulated SPD in y, a known consequence of
    the rounding in CIE's D-series tables.

    Parameters
    ----------
    cct : array_like
        Temperature in kelvin, 1000-25 000.
    cmfs : str
        Observer of the Planckian branch (the daylight polynomial is
        defined for the 2 degree observer only).

    Returns
    -------
    numpy.ndarray, shape (..., 2)
    """
    t = np.asarray(cct, dtype=np.float64)
    if np.any(~np.isfinite(t) | (t < MINIMUM_CCT) | (t > DAYLIGHT_CCT_RANGE[1])):
        raise ValueError(f"CCT must be within {MINIMUM_CCT:g}-{DAYLIGHT_CCT_RANGE[1]:g} K, got {cct!r}")
    flat = np.atleast_1d(t).ravel()
    xy = np.empty((flat.size, 2))
    daylight = flat >= DAYLIGHT_CCT_RANGE[0]
    if np.any(daylight):
        xy[daylight] = colour.temperature.CCT_to_xy_CIE_D(flat[daylight])
    if np.any(~daylight):
        uv = colour.temperature.CCT_to_uv_Planck1900(flat[~daylight], _cmfs(cmfs))
        xy[~daylight] = colour.UCS_uv_to_xy(uv)
    return xy.reshape(*t.shape, 2)


def named_whitepoint(name: str) -> np.ndarray:
    """CIE xy of a named illuminant for the CIE 1931 2 degree observer.

    Looked up in ``colour.CCS_ILLUMINANTS`` (values from CIE 015 and the
    standards colour-science cites); a copy is returned.
    """
    table = colour.CCS_ILLUMINANTS[CIE_1931_2_DEGREE]
    if name not in table:
        raise ValueError(f"unknown illuminant {name!r}; allowed: {', '.join(sorted(table))}")
    return np.array(table[name], dtype=np.float64)


# --------------------------------------------------------------------- CSV --


def _number(path, line: int, text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{path}, line {line}: {text!r} is not a number; expected {what}") from None
    if not math.isfinite(value):
        raise ValueError(f"{path}, line {line}: {text!r} is not finite; expected {what}")
    return value


def _is_header(fields: list[str]) -> bool:
    try:
        [float(f) for f in fields]
    except ValueError:
        return True
    return False


def _read_table(path, names: tuple[str, ...]) -> tuple[np.ndarray, list[int]]:
    """Rows of ``len(names)`` numbers, with their line numbers.

    Blank lines and lines starting with ``#`` are skipped; the first other
    line may be a header (any non-numeric field makes it one).
    """
    what = f"{len(names)} comma-separated numbers ({', '.join(names)})"
    rows, lines, first = [], [], True
    with open(path, newline="", encoding="utf-8-sig") as handle:
        reader = csv.reader(handle)
        for fields in reader:
            fields = [f.strip() for f in fields]
            if not any(fields) or fields[0].startswith("#"):
                continue
            if len(fields) != len(names):
                raise ValueError(f"{path}, line {reader.line_num}: {len(fields)} field(s); expected {what}")
            if first and _is_header(fields):
                first = False
                continue
            first = False
            rows.append([_number(path, reader.line_num, f, what) for f in fields])
            lines.append(reader.line_num)
    if len(rows) < 2:
        raise ValueError(f"{path}: {len(rows)} data row(s); expected at least 2 rows of {what}")
    return np.array(rows, dtype=np.float64), lines


def _check_increasing(path, column: np.ndarray, lines: list[int], name: str) -> None:
    bad = np.flatnonzero(np.diff(column) <= 0.0)
    if bad.size:
        i = int(bad[0]) + 1
        raise ValueError(
            f"{path}, line {lines[i]}: {name} {column[i]:g} is not greater than the previous "
            f"{column[i - 1]:g}; {name} must be strictly increasing"
        )


def _check_wavelengths(path, wavelengths: np.ndarray, lines: list[int]) -> None:
    _check_increasing(path, wavelengths, lines, "wavelength")
    low, high = CSV_WAVELENGTH_DOMAIN
    outside = np.flatnonzero((wavelengths < low) | (wavelengths > high))
    if outside.size:
        i = int(outside[0])
        raise ValueError(
            f"{path}, line {lines[i]}: wavelength {wavelengths[i]:g} nm is outside {low:g}-{high:g} nm, "
            "the domain of the CIE colour-matching functions"
        )
    need_low, need_high = CSV_REQUIRED_SPAN
    if wavelengths[0] > need_low or wavelengths[-1] < need_high:
        raise ValueError(
            f"{path}: wavelengths span {wavelengths[0]:g}-{wavelengths[-1]:g} nm; "
            f"they must cover at least {need_low:g}-{need_high:g} nm"
        )


#: Smallest peak a spectrum's column may have: the smallest normal float64. Below it every value
#: is subnormal, with fewer significant bits the smaller it is (5e-324 has one), so the spectrum's
#: shape, and with it the chromaticity, is lost before it is integrated.
MINIMUM_PEAK_POWER = float(np.finfo(np.float64).tiny)


def _check_power(path, values: np.ndarray, lines: list[int], name: str) -> None:
    negative = np.flatnonzero(values < 0.0)
    if negative.size:
        i = int(negative[0])
        raise ValueError(f"{path}, line {lines[i]}: {name} {values[i]:g} is negative; spectral power must be >= 0")
    if not np.any(values > 0.0):
        raise ValueError(f"{path}: column {name!r} is zero throughout; a spectrum needs some positive power")
    if values.max() < MINIMUM_PEAK_POWER:
        raise ValueError(
            f"{path}: column {name!r} peaks at {values.max():g}, below the smallest normal float "
            f"({MINIMUM_PEAK_POWER:g}), where values lose their digits; allowed: the spectrum scaled up "
            "(only its shape sets the chromaticity)"
        )


def _check_float32(path, values: np.ndarray, lines: list[int], name: str) -> None:
    """A curve's values become a LUT's float32 entries: each must be finite in float32."""
    with np.errstate(over="ignore"):
        beyond = np.flatnonzero(~np.isfinite(values.astype(np.float32)))
    if beyond.size:
        i = int(beyond[0])
        raise ValueError(
            f"{path}, line {lines[i]}: {name} {values[i]:g} is beyond float32's range "
            f"(±{float(np.finfo(np.float32).max):.4g}), in which OCIO's LUTs hold their values; "
            "allowed: values within it"
        )


#: Rows a distribution needs for the Sprague quintic (colour-science's minimum).
CURVED_ROWS = 6


def _sd(wavelengths: np.ndarray, values: np.ndarray, name: str) -> colour.SpectralDistribution:
    """The distribution, interpolated as CIE 167:2005 recommends: the Sprague (1880) quintic
    for rows evenly spaced in wavelength, a cubic spline otherwise. Linear interpolation
    of a narrow emitter sampled every 10 nm (a Gaussian of 15 nm deviation) put its
    chromaticity 4.7e-3 off in xy; Sprague puts it 5e-6 off, at 5 nm 1e-7. Fewer than
    :data:`CURVED_ROWS` rows, which neither takes, interpolate linearly."""
    steps = np.diff(wavelengths)
    even = np.allclose(steps, steps[0], rtol=0.0, atol=1e-9 * max(1.0, float(steps[0])))
    interpolator = (
        colour.LinearInterpolator
        if len(wavelengths) < CURVED_ROWS
        else colour.SpragueInterpolator
        if even
        else colour.CubicSplineInterpolator
    )
    return colour.SpectralDistribution(values, wavelengths, interpolator=interpolator, name=name)


def read_spd_csv(path) -> colour.SpectralDistribution:
    """Read a spectral power distribution from a two-column CSV file.

    Columns: wavelength (nm), relative power. Wavelengths strictly
    increasing, within 360-830 nm (the tabulated domain of the CIE
    colour-matching functions) and covering at least 380-780 nm; power
    finite and non-negative. An optional header line, blank lines and
    ``#`` comment lines are allowed. The distribution interpolates between rows as
    :func:`_sd` says (irregular spacing is allowed).

    Raises
    ------
    ValueError
        Naming the file, the line and what is allowed.
    """
    table, lines = _read_table(path, ("wavelength nm", "value"))
    _check_wavelengths(path, table[:, 0], lines)
    _check_power(path, table[:, 1], lines, "value")
    return _sd(table[:, 0], table[:, 1], Path(path).stem)


def read_primaries_spectra_csv(path, cmfs: str = CIE_1931_2_DEGREE) -> np.ndarray:
    """Chromaticities of three primaries from their measured spectra.

    Columns: wavelength (nm), then the spectral power of the red, green and
    blue primaries, with the wavelength and power rules of
    :func:`read_spd_csv`. Each spectrum is integrated with the
    colour-matching functions by :func:`whitepoint_from_sd`.

    Returns
    -------
    numpy.ndarray, shape (3, 2)
        CIE xy of red, green and blue.

    Raises
    ------
    ValueError
        Naming the file, the line and what is allowed.
    """
    table, lines = _read_table(path, ("wavelength nm", "r", "g", "b"))
    _check_wavelengths(path, table[:, 0], lines)
    stem = Path(path).stem
    xy = []
    for column, name in enumerate(("r", "g", "b"), start=1):
        _check_power(path, table[:, column], lines, name)
        xy.append(whitepoint_from_sd(_sd(table[:, 0], table[:, column], f"{stem} {name}"), cmfs))
    return np.array(xy)


def read_curve_csv(path) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """Read a transfer curve sampled as (code value, linear value) rows.

    Both columns must be strictly increasing (the curve is invertible) and
    finite; an optional header line, blank lines and ``#`` comment lines are
    allowed.

    Returns
    -------
    tuple of (tuple of float, tuple of float)
        Code values and linear values.

    Raises
    ------
    ValueError
        Naming the file, the line and what is allowed.
    """
    table, lines = _read_table(path, ("code", "linear"))
    for column, name in enumerate(("code value", "linear value")):
        _check_float32(path, table[:, column], lines, name)
        _check_increasing(path, table[:, column], lines, name)
    return tuple(table[:, 0].tolist()), tuple(table[:, 1].tolist())
