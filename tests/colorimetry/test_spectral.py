"""Chromaticities derived from spectra against published values, and the CSV readers."""

from __future__ import annotations

import colour
import numpy as np
import pytest

from generator import tolerances
from generator.colorimetry import spectral

#: CIE 1931 RGB -> XYZ as published with the 1931 system:
#: ``XYZ = (1 / 0.17697) * M @ RGB``. Each row of ``M`` sums to 1, so
#: ``M`` alone maps equal-energy white RGB (1, 1, 1) to XYZ (1, 1, 1): it is
#: the normalised primary matrix (white Y = 1). The factor 1 / 0.17697 only
#: rescales it so that the red primary has unit luminance (white Y = 5.6508).
#: Rows 1 and 3 are printed to 2 decimals, row 2 to 5.
PUBLISHED_CIE_RGB_TO_XYZ = np.array(
    [
        [0.49, 0.31, 0.20],
        [0.17697, 0.81240, 0.01063],
        [0.00, 0.01, 0.99],
    ]
)
PUBLISHED_LUMINANCE_OF_RED = 0.17697

#: Published CIE xy of the CIE RGB primaries (700, 546.1, 435.8 nm), 5 decimals.
PUBLISHED_CIE_RGB_XY = np.array([[0.73469, 0.26531], [0.27368, 0.71743], [0.16654, 0.00888]])

#: Tabulated CIE xy (2 degree observer) of illuminants D65, A and D50.
TABULATED_XY = {"D65": (0.31270, 0.32900), "A": (0.44757, 0.40745), "D50": (0.34567, 0.35850)}


def test_cie_rgb_primaries_match_published_chromaticities():
    derived = spectral.cie_rgb_primaries()
    assert derived.shape == (3, 2)
    # Measured: within 4.8e-6 (half a unit of the 5th decimal is 5e-6).
    np.testing.assert_allclose(derived, PUBLISHED_CIE_RGB_XY, rtol=0, atol=tolerances.SPECTRAL_XY_ABSOLUTE)


def test_cie_rgb_matrix_matches_the_published_1931_matrix():
    """The normalised primary matrix (white E, Y = 1) is the published matrix
    without its 1 / 0.17697 factor.

    Row 2 (Y, 5 decimals) agrees within PUBLISHED_MATRIX_ABSOLUTE (measured
    8.0e-5: the 1931 matrix came from the Wright-Guild data, the 1 nm CMFs
    were smoothed later). Rows 1 and 3 were printed to 2 decimals, so the
    honest comparison is equality after rounding to 2 decimals (measured
    deviation before rounding 2.0e-4).
    """
    npm = colour.normalised_primary_matrix(spectral.cie_rgb_primaries(), spectral.CIE_RGB_WHITEPOINT)
    np.testing.assert_allclose(PUBLISHED_CIE_RGB_TO_XYZ.sum(axis=1), 1.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(npm[1], PUBLISHED_CIE_RGB_TO_XYZ[1], rtol=0, atol=tolerances.PUBLISHED_MATRIX_ABSOLUTE)
    np.testing.assert_array_equal(np.round(npm[[0, 2]], 2), PUBLISHED_CIE_RGB_TO_XYZ[[0, 2]])
    # In the published scaling, Y of the red primary is 1.
    scaled = npm / PUBLISHED_LUMINANCE_OF_RED
    np.testing.assert_allclose(
        scaled[1],
        PUBLISHED_CIE_RGB_TO_XYZ[1] / PUBLISHED_LUMINANCE_OF_RED,
        rtol=0,
        atol=tolerances.PUBLISHED_MATRIX_ABSOLUTE / PUBLISHED_LUMINANCE_OF_RED,
    )


def test_cie_rgb_matches_project_matrix_helper():
    from generator.colorimetry.matrices import normalised_primary_matrix

    primaries = spectral.cie_rgb_primaries()
    expected = colour.normalised_primary_matrix(primaries, spectral.CIE_RGB_WHITEPOINT)
    np.testing.assert_allclose(normalised_primary_matrix(primaries, spectral.CIE_RGB_WHITEPOINT), expected, atol=1e-12)


def test_monochromatic_700nm_is_a_tabulated_point():
    cmfs = colour.MSDS_CMFS[spectral.CIE_1931_2_DEGREE]
    x, y, z = cmfs[700.0]
    np.testing.assert_allclose(
        spectral.monochromatic_primaries_xy([700.0])[0], [x / (x + y + z), y / (x + y + z)], atol=1e-15
    )


def test_monochromatic_rejects_wavelengths_outside_the_cmfs():
    with pytest.raises(ValueError, match="360-830 nm"):
        spectral.monochromatic_primaries_xy([350.0, 546.1, 435.8])


def test_colour_datasets_are_not_mutated():
    cmfs = colour.MSDS_CMFS[spectral.CIE_1931_2_DEGREE]
    interpolator, shape = cmfs.interpolator, cmfs.shape
    spectral.cie_rgb_primaries()
    spectral.whitepoint_from_sd(colour.SDS_ILLUMINANTS["D65"])
    assert cmfs.interpolator is interpolator and cmfs.shape == shape


@pytest.mark.parametrize("name", sorted(TABULATED_XY))
def test_whitepoint_from_sd_matches_tabulated(name):
    # Measured: D65 2.7e-5, A 1.8e-5, D50 1.3e-5 (largest coordinate).
    xy = spectral.whitepoint_from_sd(colour.SDS_ILLUMINANTS[name])
    np.testing.assert_allclose(xy, TABULATED_XY[name], rtol=0, atol=tolerances.SPECTRAL_XY_ABSOLUTE)


def test_daylight_6504K_is_d65():
    # Measured: |dx| 1.4e-5, |dy| 1.19e-4 against (0.31270, 0.32900).
    np.testing.assert_allclose(
        spectral.whitepoint_from_cct(6504.0), TABULATED_XY["D65"], rtol=0, atol=tolerances.DAYLIGHT_LOCUS_XY_ABSOLUTE
    )


def test_planckian_2856K_is_illuminant_a():
    # Illuminant A is a blackbody at 2856 K (c2 = 1.4388e-2 m K); measured 3.1e-5.
    np.testing.assert_allclose(
        spectral.whitepoint_from_cct(2856.0), TABULATED_XY["A"], rtol=0, atol=tolerances.SPECTRAL_XY_ABSOLUTE
    )


def test_whitepoint_from_cct_branches_and_shape():
    cct = np.array([[3000.0, 4000.0], [5003.0, 25000.0]])
    xy = spectral.whitepoint_from_cct(cct)
    assert xy.shape == (2, 2, 2)
    np.testing.assert_allclose(xy[0, 1], colour.temperature.CCT_to_xy_CIE_D(4000.0), atol=1e-15)
    cmfs = colour.MSDS_CMFS[spectral.CIE_1931_2_DEGREE]  # the full 360-830 nm table
    planck = colour.UCS_uv_to_xy(colour.temperature.CCT_to_uv_Planck1900(3000.0, cmfs))
    np.testing.assert_allclose(xy[0, 0], planck, atol=1e-12)
    with pytest.raises(ValueError, match="1000-25000 K"):
        spectral.whitepoint_from_cct(30000.0)


def test_named_whitepoint_is_a_copy():
    d65 = spectral.named_whitepoint("D65")
    d65[0] = 0.0
    np.testing.assert_allclose(spectral.named_whitepoint("D65"), (0.3127, 0.3290))
    with pytest.raises(ValueError, match="unknown illuminant 'D66'"):
        spectral.named_whitepoint("D66")


# --------------------------------------------------------------------- CSV --


def _write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _d65_csv(tmp_path):
    sd = colour.SDS_ILLUMINANTS["D65"]
    rows = [f"{w:g},{v:.6f}" for w, v in zip(sd.wavelengths, sd.values) if w >= 360]
    return _write(tmp_path, "d65.csv", "# CIE D65\nwavelength,power\n" + "\n".join(rows) + "\n")


def test_read_spd_csv_round_trips_d65(tmp_path):
    sd = spectral.read_spd_csv(_d65_csv(tmp_path))
    assert sd.wavelengths[0] == 360 and sd.wavelengths[-1] == 780
    np.testing.assert_allclose(
        spectral.whitepoint_from_sd(sd), TABULATED_XY["D65"], rtol=0, atol=tolerances.SPECTRAL_XY_ABSOLUTE
    )


def test_read_primaries_spectra_csv_narrow_band_primaries(tmp_path):
    # Gaussians of 1 nm standard deviation, centred on the CIE RGB wavelengths.
    w = np.arange(360.0, 830.25, 0.5)
    columns = [np.exp(-0.5 * (w - c) ** 2) for c in spectral.CIE_RGB_WAVELENGTHS]
    rows = "\n".join(",".join(f"{v:.9g}" for v in row) for row in zip(w, *columns))
    xy = spectral.read_primaries_spectra_csv(_write(tmp_path, "rgb.csv", "wavelength,r,g,b\n" + rows + "\n"))
    assert xy.shape == (3, 2)
    np.testing.assert_allclose(xy, spectral.cie_rgb_primaries(), rtol=0, atol=1e-3)


def test_read_curve_csv(tmp_path):
    code, linear = spectral.read_curve_csv(_write(tmp_path, "curve.csv", "code,linear\n0,0\n0.5,0.2\n\n1,1\n"))
    assert code == (0.0, 0.5, 1.0) and linear == (0.0, 0.2, 1.0)


@pytest.mark.parametrize(
    "text, message",
    [
        ("0,0\n0.5,0.2\n0.5,0.3\n", r"line 3: code value 0.5 is not greater than the previous 0.5"),
        ("0,0\n0.5,0.2\n0.7,0.1\n", r"line 3: linear value 0.1 is not greater than the previous 0.2"),
        ("0,0\n0.5,abc\n", r"line 2: 'abc' is not a number; expected 2 comma-separated numbers \(code, linear\)"),
        ("0,0\n0.5,0.2,9\n", r"line 2: 3 field\(s\); expected 2"),
        ("0,0\n0.5,nan\n", r"line 2: 'nan' is not finite"),
        ("code,linear\n0,0\n", r"1 data row\(s\); expected at least 2"),
    ],
)
def test_read_curve_csv_errors(tmp_path, text, message):
    path = _write(tmp_path, "bad.csv", text)
    with pytest.raises(ValueError, match=message) as error:
        spectral.read_curve_csv(path)
    assert str(path) in str(error.value)


@pytest.mark.parametrize(
    "rows, message",
    [
        (["350,1", "380,1", "780,1"], r"line 1: wavelength 350 nm is outside 360-830 nm"),
        (["380,1", "600,1", "600,1", "780,1"], r"line 3: wavelength 600 is not greater than the previous 600"),
        (["400,1", "780,1"], r"span 400-780 nm; they must cover at least 380-780 nm"),
        (["380,1", "600,-0.5", "780,1"], r"line 2: value -0.5 is negative"),
        (["380,0", "780,0"], r"column 'value' is zero throughout"),
    ],
)
def test_read_spd_csv_errors(tmp_path, rows, message):
    path = _write(tmp_path, "bad.csv", "\n".join(rows) + "\n")
    with pytest.raises(ValueError, match=message) as error:
        spectral.read_spd_csv(path)
    assert str(path) in str(error.value)


def test_read_primaries_spectra_csv_errors(tmp_path):
    path = _write(tmp_path, "bad.csv", "wavelength,r,g,b\n380,1,1,1\n780,1,1\n")
    with pytest.raises(ValueError, match=r"line 3: 3 field\(s\); expected 4 comma-separated numbers"):
        spectral.read_primaries_spectra_csv(path)
    path = _write(tmp_path, "dark.csv", "380,1,0,1\n780,1,0,1\n")
    with pytest.raises(ValueError, match="column 'g' is zero throughout"):
        spectral.read_primaries_spectra_csv(path)


@pytest.mark.parametrize("step, within", [(5, 1e-6), (10, 3e-5)])
def test_narrow_primaries_sampled_every_5_or_10_nm_keep_their_chromaticity(tmp_path, step, within):
    """Gaussian emitters (632, 525 and 462 nm; deviations 9, 15 and 10 nm), as an LED wall's
    spectroradiometer tabulates them: interpolated linearly between rows, green came out 4.7e-3
    off in xy at 10 nm; CIE 167's Sprague interpolation keeps every primary to a few 1e-6."""
    import colour

    peaks = ((632.0, 9.0), (525.0, 15.0), (462.0, 10.0))
    rows = np.arange(380, 781, step)
    lines = ["wavelength,r,g,b"] + [
        f"{w}," + ",".join(f"{np.exp(-0.5 * ((w - c) / s) ** 2):.10f}" for c, s in peaks) for w in rows
    ]
    got = spectral.read_primaries_spectra_csv(_write(tmp_path, "wall.csv", "\n".join(lines) + "\n"))
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].trim(colour.SpectralShape(380, 780, 1))
    nm = cmfs.wavelengths
    for (centre, deviation), xy in zip(peaks, got):
        XYZ = cmfs.values.T @ np.exp(-0.5 * ((nm - centre) / deviation) ** 2)
        np.testing.assert_allclose(xy, XYZ[:2] / XYZ.sum(), rtol=0, atol=within)


def _locus(nm: np.ndarray, spectrum: np.ndarray) -> np.ndarray:
    """xy of ``spectrum`` summed at ``nm``, the CIE 1931 functions Sprague-interpolated there."""
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy()
    cmfs.interpolator = colour.SpragueInterpolator
    XYZ = spectrum @ cmfs[nm]
    return XYZ[:2] / XYZ.sum()


def test_lines_narrower_than_a_nanometre_keep_their_chromaticity(tmp_path):
    """A laser projector's white, three lines 0.2 nm deviation measured every 0.1 nm: read at
    whole nanometres only, it came out green, (0.259, 0.637) for (0.273, 0.332); summed at its
    rows it is the lines' own colour, as a 0.01 nm sum of the exact lines gives."""
    lines = ((465.5, 0.2, 0.9), (532.0, 0.2, 1.0), (639.3, 0.2, 1.2))

    def power(nm):
        return sum(w * np.exp(-0.5 * ((nm - c) / s) ** 2) for c, s, w in lines)

    rows = np.round(np.arange(3800, 7801) * 0.1, 1)
    text = "wavelength,power\n" + "".join(f"{w:.1f},{power(w):.12f}\n" for w in rows)
    got = spectral.whitepoint_from_sd(spectral.read_spd_csv(_write(tmp_path, "laser.csv", text)))
    fine = np.linspace(380.0, 780.0, 40001)
    np.testing.assert_allclose(got, _locus(fine, power(fine)), rtol=0, atol=2e-6)


def test_a_line_between_whole_nanometres_is_not_lost(tmp_path):
    """Rows every 0.5 nm, power in one of them only, 467.5 nm, and zero at every whole nanometre:
    the chromaticity is the spectral locus's there (read at whole nanometres, it had been derived
    from interpolation noise, 4e-16 of the peak, and came out (0.1266, 0.0533))."""
    rows = np.arange(760, 1561) * 0.5
    text = "".join(f"{w:.1f},{1.0 if w == 467.5 else 0.0}\n" for w in rows)
    got = spectral.whitepoint_from_sd(spectral.read_spd_csv(_write(tmp_path, "line.csv", text)))
    np.testing.assert_allclose(got, spectral.monochromatic_primaries_xy([467.5])[0], rtol=0, atol=1e-4)
