"""Derived matrices against the matrices their standards publish."""

import numpy as np
import pytest

from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import adaptation_matrix, apply_matrix, normalised_primary_matrix, rgb_to_rgb
from generator.tolerances import published_rounding

# (gamut, published RGB->XYZ, decimals, source)
PUBLISHED_NPM = [
    (
        "AP0",
        [[0.9525523959, 0.0, 0.0000936786], [0.3439664498, 0.7281660966, -0.0721325464], [0.0, 0.0, 1.0088251844]],
        10,
        "SMPTE ST 2065-1:2012, 4.1.2",
    ),
    (
        "AP1",
        [
            [0.6624541811, 0.1340042065, 0.1561876870],
            [0.2722287168, 0.6740817658, 0.0536895174],
            [-0.0055746495, 0.0040607335, 1.0103391003],
        ],
        10,
        "Academy S-2014-004, 4.1.2",
    ),
    (
        "Rec.709",
        [[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]],
        4,
        "IEC 61966-2-1:1999, 5.2",
    ),
]


@pytest.mark.parametrize("name, published, decimals, source", PUBLISHED_NPM, ids=[p[0] for p in PUBLISHED_NPM])
def test_normalised_primary_matrix_matches_standard(name, published, decimals, source):
    derived = gamuts()[name].rgb_to_xyz
    assert np.abs(derived - np.array(published)).max() <= published_rounding(decimals), source


def test_rec2020_luminance_row_matches_bt2020():
    # ITU-R BT.2020-2, Table 4: Y'C = 0.2627 R + 0.6780 G + 0.0593 B.
    row = gamuts()["Rec.2020"].rgb_to_xyz[1]
    assert np.abs(row - [0.2627, 0.6780, 0.0593]).max() <= published_rounding(4)


def test_ap0_to_ap1_matches_academy():
    # Academy S-2014-004, 4.1.3 (same white: no adaptation involved).
    published = [
        [1.4514393161, -0.2365107469, -0.2149285693],
        [-0.0765537734, 1.1762296998, -0.0996759264],
        [0.0083161484, -0.0060324498, 0.9977163014],
    ]
    derived = rgb_to_rgb(gamuts()["AP0"], gamuts()["AP1"])
    assert np.abs(derived - published).max() <= published_rounding(10)


def test_rec709_to_rec2020_matches_bt2087():
    # ITU-R BT.2087-0, equation (4).
    published = [[0.6274, 0.3293, 0.0433], [0.0691, 0.9195, 0.0114], [0.0164, 0.0880, 0.8956]]
    derived = rgb_to_rgb(gamuts()["Rec.709"], gamuts()["Rec.2020"])
    assert np.abs(derived - published).max() <= published_rounding(4)


def test_bradford_d65_to_d50_matches_lindbloom():
    # B. Lindbloom, "Chromatic Adaptation", Bradford D65 -> D50, with his whites
    # D65 = (0.95047, 1, 1.08883), D50 = (0.96422, 1, 0.82521).
    def xy(X, Z):
        return (X / (X + 1 + Z), 1 / (X + 1 + Z))

    published = [
        [1.0478112, 0.0228866, -0.0501270],
        [0.0295424, 0.9904844, -0.0170491],
        [-0.0092345, 0.0150436, 0.7521316],
    ]
    derived = adaptation_matrix(xy(0.95047, 1.08883), xy(0.96422, 0.82521), "Bradford")
    assert np.abs(derived - published).max() <= published_rounding(7)


def test_aces_to_rec709_bradford_matches_studio_config():
    # The AP0 -> linear Rec.709 matrix of OCIO's ACES studio config (Bradford, D60 -> D65),
    # printed there with 15 significant digits; ours must agree to float64 rounding of those digits.
    published = [
        [2.52168618674388, -1.13413098823972, -0.387555198504164],
        [-0.276479914229922, 1.37271908766826, -0.096239173438334],
        [-0.0153780649660342, -0.152975335867399, 1.16835340083343],
    ]
    derived = rgb_to_rgb(gamuts()["AP0"], gamuts()["Rec.709"], "Bradford")
    assert np.abs(derived - published).max() <= published_rounding(14)


@pytest.mark.parametrize("cat", ["Bradford", "CAT02", "CAT16", "von Kries", "XYZ scaling"])
def test_adaptation_maps_white_to_white(cat):
    d65, d50 = (0.3127, 0.3290), (0.3457, 0.3585)
    white = adaptation_matrix(d65, d50, cat) @ [d65[0] / d65[1], 1.0, (1 - sum(d65)) / d65[1]]
    assert np.allclose(white, [d50[0] / d50[1], 1.0, (1 - sum(d50)) / d50[1]], rtol=0, atol=1e-12)


def test_no_adaptation_is_identity_and_unknown_cat_is_refused():
    assert np.array_equal(adaptation_matrix((0.3127, 0.329), (0.32168, 0.33767), "none"), np.eye(3))
    with pytest.raises(ValueError, match="allowed"):
        adaptation_matrix((0.3127, 0.329), (0.3457, 0.3585), "Sharp")


def test_npm_maps_unit_rgb_to_white_with_unit_luminance():
    m = normalised_primary_matrix(((0.64, 0.33), (0.3, 0.6), (0.15, 0.06)), (0.3127, 0.329))
    assert np.allclose(m @ np.ones(3), [0.3127 / 0.329, 1.0, (1 - 0.3127 - 0.329) / 0.329], rtol=0, atol=1e-15)


@pytest.mark.parametrize("cat", ["Bradford", "CAT02", "CAT16", "von Kries", "XYZ scaling"])
def test_cone_matrices_are_colour_sciences_and_adaptation_agrees(cat):
    """The cone matrices held as data are colour-science's, value for value, and the
    adaptation built from them is its von Kries transform, bit for bit."""
    from colour.adaptation import CHROMATIC_ADAPTATION_TRANSFORMS, matrix_chromatic_adaptation_VonKries

    from generator.colorimetry.matrices import CATS, CONE_MATRICES, xy_to_XYZ

    assert np.array_equal(np.array(CONE_MATRICES[cat]), CHROMATIC_ADAPTATION_TRANSFORMS[CATS[cat]])
    whites = [(0.3127, 0.329), (0.32168, 0.33767), (0.3457, 0.3585), (1 / 3, 1 / 3), (0.314, 0.351)]
    for source in whites:
        for target in whites:
            if source != target:
                theirs = matrix_chromatic_adaptation_VonKries(xy_to_XYZ(source), xy_to_XYZ(target), transform=CATS[cat])
                assert np.array_equal(adaptation_matrix(source, target, cat), theirs)


def test_shared_primaries_give_exact_zeros_and_ones_as_written():
    """Rec.709 and P3-D65 share blue, so blue's column of the conversion is (0, 0, s) exactly,
    and P3's red lies on x + y = 1, so its Z is 0: float64 leaves those 1e-17 to 1e-15 off, and
    what is written (config, CLF, ``ocioforge matrix``) holds the exact values."""
    from generator.colorimetry.matrices import settled

    g = gamuts()
    to_p3 = settled(rgb_to_rgb(g["Rec.709"], g["P3-D65"]))
    assert to_p3[0, 2] == 0.0 and to_p3[1, 2] == 0.0 and not np.signbit(to_p3[0, 2])
    assert np.array_equal(settled(rgb_to_rgb(g["Rec.2020"], g["Rec.2020"])), np.eye(3))
    assert settled(normalised_primary_matrix(g["P3-D65"].primaries, g["P3-D65"].whitepoint))[2, 0] == 0.0
    raw = rgb_to_rgb(g["AP0"], g["P3-D65"])
    np.testing.assert_array_equal(settled(raw), raw)  # nothing else moves


def test_written_matrices_hold_no_float_residue(build_config):
    """Every MatrixTransform of the default config is exact where its derivation is: no entry
    is a residue below 1e-12 (a reader sees 0, not -3.96e-17)."""
    import PyOpenColorIO as ocio

    from generator.ocio.write import leaf_transforms

    config = ocio.Config.CreateFromFile(str(build_config((2, 1))))
    entries = [v for _, t in leaf_transforms(config) if isinstance(t, ocio.MatrixTransform) for v in t.getMatrix()]
    entries = np.array(entries)
    assert entries.size > 100
    residue = entries[(entries != 0.0) & (np.abs(entries) < 1e-12)]
    assert residue.size == 0, residue


def test_von_kries_of_tristimulus_whites_is_colour_sciences():
    """The one adaptation path takes whites as tristimulus values too (the perceptual mapping's
    display white to Oklab's, whose Y is not 1), bit for bit as colour-science's."""
    from colour.adaptation import matrix_chromatic_adaptation_VonKries

    from generator.colorimetry.matrices import von_kries

    source, target = np.array([0.9505, 1.0, 1.089]), np.array([0.95047, 0.99999, 1.08883])
    theirs = matrix_chromatic_adaptation_VonKries(source, target, transform="CAT02")
    assert np.array_equal(von_kries(source, target, "CAT02"), theirs)


def test_remembered_matrices_are_each_callers_own():
    """Derived once per chromaticities, a matrix changed by one caller is not what the next gets;
    lists and arrays (unhashable) are derived too, to the same values."""
    primaries, white = ((0.64, 0.33), (0.30, 0.60), (0.15, 0.06)), (0.3127, 0.3290)
    first = normalised_primary_matrix(primaries, white)
    first[0, 0] = 99.0
    again = normalised_primary_matrix(primaries, white)
    assert again[0, 0] != 99.0
    assert np.array_equal(again, normalised_primary_matrix(np.array(primaries), list(white)))
    adapted = adaptation_matrix(white, (0.32168, 0.33767), "CAT02")
    adapted[:] = 0.0
    assert np.array_equal(
        adaptation_matrix(white, (0.32168, 0.33767), cat="CAT02"),
        adaptation_matrix(list(white), [0.32168, 0.33767], "CAT02"),
    )
    assert adaptation_matrix(white, (0.32168, 0.33767), "CAT02").any()


def test_a_matrix_gives_the_same_bits_whatever_the_colours_layout():
    """Contiguous, strided and transposed colours of the same values: the same bits (einsum
    summed strided colours in another order), within 1e-15 of a float64 product."""
    rng = np.random.default_rng(5)
    matrix = rgb_to_rgb(gamuts()["AP0"], gamuts()["Rec.709"])
    colours = rng.normal(size=(4096, 3)) * 100.0
    strided = np.repeat(colours, 2, axis=1)[:, ::2]
    transposed = np.ascontiguousarray(colours.T).T
    out = apply_matrix(matrix, colours)
    for layout in (strided, transposed, colours.reshape(16, 256, 3)):
        assert np.array_equal(apply_matrix(matrix, layout).reshape(-1, 3), out)
    assert np.allclose(out, colours @ matrix.T, rtol=1e-15, atol=1e-12)
    assert np.array_equal(apply_matrix(matrix, colours[7]), out[7])
    with pytest.raises(ValueError, match="3x3 matrix and colours"):
        apply_matrix(matrix, colours[:, :2])
