"""The baked ACES 2.0 view: OCIO runs the file as its float64 evaluation says."""

import tempfile
from pathlib import Path

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import reference
from generator.luts import aces_lattice, aces_probes, probes
from generator.luts.plain import plain_recipe
from generator.ocio.emit import matrix_transform
from generator.rendering import views

#: OCIO's float32 run of the file against its float64 evaluation, display light relative
#: to the peak, with its lossless flags: float32 alone (measured 1.8e-6; OCIO's default flags add
#: their fast log2 and power, generator.tolerances.ACES_LATTICE_FILE_RELATIVE).
FILE_RELATIVE = 1e-5

#: OCIO's CPU evaluates a power with a fast approximation (measured 2.5e-5 relative, monCurve of
#: gamma 2.4 on 200,000 codes from -1 to 1.5).
OCIO_POWER_RELATIVE = 3e-5


def test_ocio_runs_the_file_as_its_float64_evaluation():
    view = views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"]
    lat = aces_lattice.bake(view, 17)
    steps = [
        matrix_transform(views.tables(view).ap0_to_ap1),
        ocio.RangeTransform(minInValue=0.0, maxInValue=lat.upper, minOutValue=0.0, maxOutValue=lat.upper),
    ]
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / "v.ctf").write_bytes(aces_lattice.ocio_file(lat))
        cfg = ocio.Config.CreateRaw()
        cfg.setSearchPath(folder)
        group = ocio.GroupTransform(
            [
                *steps,
                ocio.FileTransform("v.ctf", interpolation=ocio.INTERP_TETRAHEDRAL),
                ocio.RangeTransform(minInValue=0.0, maxInValue=1.0, minOutValue=0.0, maxOutValue=1.0),
                matrix_transform(aces_lattice.to_xyz(view)),
            ]
        )
        rgb = np.random.default_rng(3).random((4000, 3)) * np.array([[1.0], [8.0]]).repeat(2000, 0)
        out = rgb.astype(np.float32)
        cfg.getProcessor(group).getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS).applyRGB(out)
    expected = aces_lattice.evaluate(lat, rgb)
    assert np.max(np.abs(out - expected)) < FILE_RELATIVE


def test_the_tables_rows_are_the_codes_ocio_writes():
    """The file's 3D table holds, row for row, the 16-bit codes OCIO writes for the same table
    (OCIO pads them to six characters: the whitespace alone differs)."""
    from generator.luts import transforms

    lat = aces_lattice.bake(views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"], 9)
    assert lat.cube.min() < 0.0 and lat.cube.max() > 1.0  # codes of either sign and past the range
    table = transforms.lut3d(lat.cube)
    table.setFileOutputBitDepth(ocio.BIT_DEPTH_UINT16)
    text = ocio.GroupTransform([table]).write("Color Transform Format", ocio.Config.CreateRaw())
    theirs = text.partition('<Array dim="9 9 9 3">')[2].partition("</Array>")[0].split()
    ours = aces_lattice.ocio_file(lat).decode().partition('<Array dim="9 9 9 3">')[2].partition("</Array>")[0]
    assert ours.strip().splitlines() == aces_lattice.table_rows(lat.cube).splitlines()
    assert ours.split() == theirs


def test_greys_land_on_the_tables_nodes_and_black_is_kept():
    """A grey at a node of the luminance axis reads that node (its chromaticity is a node's of p
    and q, to the 1D table's six decimals); black, every chromaticity at luminance 0, keeps the
    view's black."""
    view = views.catalogue()["ACES 2.0 - HDR 1000 nits (P3 D65)"]
    lat = aces_lattice.bake(view, 17)
    p, q = lat.axes.grey_nodes(17)
    ap1 = lat.value(np.linspace(0.0, 1.0, 17))[1:, None].repeat(3, 1)
    coordinate = lat.coordinate(ap1) * 16
    assert np.max(np.abs(coordinate - np.stack([np.full(16, p), np.full(16, q), np.arange(1, 17)], axis=1))) < 1e-4
    aces = ap1 @ views.tables(view).ap1_to_ap0.T
    assert np.allclose(
        aces_lattice.evaluate(lat, aces),
        aces_lattice.mon_decode(lat.cube[p, q, 1:], lat.curve).clip(0, 1) @ aces_lattice.to_xyz(view).T,
        rtol=0,
        atol=1e-5,
    )
    assert not np.any(lat.cube[:, :, 0])


def test_the_tables_empty_half_holds_the_views_clamp():
    """No colour reaches q > p; a node there holds what the table gives its colour with AP1's red
    clamped to 0, so that whatever input OCIO's inverse of the table finds renders as asked."""
    lat = aces_lattice.bake(views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"], 17)
    node = np.array([[3, 9, 12]]) / 16.0
    clamped = np.minimum(lat.axes.values(node), lat.upper)
    assert clamped[0, 0] == 0.0 and clamped[0, 1] > 0.0 and clamped[0, 2] > 0.0
    expected = aces_lattice.mon_encode(aces_lattice.file_output(lat, clamped), lat.curve)[0]
    # the node and the nodes it was read from are each rounded to half a 16-bit code
    assert np.max(np.abs(lat.cube[3, 9, 12] - expected)) <= 1.0 / aces_lattice.CODE_STEPS
    rng = np.random.default_rng(4)
    u = lat.coordinate(rng.random((20000, 3)) * np.array([1.0, 8.0, 64.0]))
    assert np.all(u[:, 1] <= u[:, 0] + 1e-12)


def test_bake_all_keeps_each_views_lattice_as_bake_makes_it():
    """Baked side by side in workers, each lattice is the one a bake here makes, kept so that
    :func:`bake` returns it; what ran meanwhile comes back."""
    chosen = [views.catalogue()[n] for n in ("ACES 2.0 - SDR 100 nits (P3 D65)", "ACES 2.0 - HDR 500 nits (P3 D65)")]
    assert aces_lattice.bake_all(chosen, lambda: "meanwhile") == "meanwhile"
    for view in chosen:
        kept = aces_lattice.bake(view)
        assert kept is aces_lattice.bake(view)
        np.testing.assert_array_equal(kept.cube, aces_lattice.baked(view).cube)
        np.testing.assert_array_equal(kept.axes.chroma, aces_lattice.baked(view).axes.chroma)


@pytest.mark.parametrize(
    "name, display_name",
    [
        ("ACES 2.0 - SDR 100 nits (Rec.709)", "sRGB - Display"),
        ("ACES 2.0 - SDR 100 nits (P3 D65)", "Display P3 - Display"),
        ("ACES 2.0 - HDR 1000 nits (P3 D65)", "Rec.2100-PQ - Display"),
        ("ACES 2.0 - HDR 500 nits (Rec.2020)", "Rec.2100-PQ - Display"),
        ("ACES 2.0 - HDR 108 nits (P3 D65)", "ST2084-P3-D65 - Display"),
    ],
)
def test_the_baked_view_errs_less_than_the_plain_recipe(default_spec, name, display_name):
    """p99 against the float64 view on each probe kind (8192 a kind, the probe seed), in ten-bit
    codes or ΔE ITP: below the plain recipe's on every kind. The SDR views' greys had erred more
    with the axis thinning above 64 (0.44 against 0.40 codes), the HDR views' bright colours with
    toe 2^-10 and gamma 3 (1.97 against 1.62 ΔE ITP at 1000 nits)."""
    view = views.catalogue()[name]
    display = next(d for d in default_spec.displays if d.name == display_name)
    lat, plain = aces_lattice.bake(view), plain_recipe(default_spec, display, view)
    worse = {}
    for kind, aces in aces_probes.sets(display, aces_probes.PROBE_SEED, aces_probes.PROBE_COUNT).items():
        truth = reference.display_xyz_encode(default_spec, display, views.evaluate(view, aces))
        ours = reference.display_xyz_encode(default_spec, display, aces_lattice.evaluate(lat, aces))
        p99 = [float(np.percentile(probes.errors(display, codes, truth)[0], 99)) for codes in (ours, plain(aces))]
        if p99[0] >= p99[1]:
            worse[kind] = p99
    assert not worse, worse


#: Issue 21's goal for a baked view, in ten-bit codes (SDR) or ΔE ITP (HDR): p99 and largest
#: error per probe kind.
GOAL_P99, GOAL_MAX = 1.0, 10.0

#: Every probe kind.
ALL_KINDS = aces_probes.SETS


@pytest.mark.parametrize(
    "name, display_name, kinds",
    [
        ("ACES 2.0 - SDR 100 nits (Rec.709)", "sRGB - Display", ("in_gamut", "dark", "greys")),
        ("ACES 2.0 - SDR 100 nits (P3 D65)", "Display P3 - Display", ("in_gamut", "ap0", "dark", "greys")),
        ("ACES 2.0 - HDR 1000 nits (P3 D65)", "Rec.2100-PQ - Display", ALL_KINDS),
        ("ACES 2.0 - HDR 1000 nits (Rec.2020)", "Rec.2100-PQ - Display", ALL_KINDS),
        ("ACES 2.0 - HDR 500 nits (Rec.2020)", "Rec.2100-PQ - Display", ALL_KINDS),
        ("ACES 2.0 - HDR 500 nits (P3 D65)", "Rec.2100-PQ - Display", ALL_KINDS),
        ("ACES 2.0 - HDR 108 nits (P3 D65)", "ST2084-P3-D65 - Display", ALL_KINDS),
    ],
)
def test_the_baked_views_meet_the_goal(default_spec, name, display_name, kinds):
    """On the probe kinds given (8192 a kind, the probe seed): p99 at most 1 ten-bit code or ΔE
    ITP, largest error at most 10. At 81 nodes a side the SDR Rec.709 view's in-gamut colours
    measured 1.40 codes p99 (max 15.3), the SDR P3 view's 1.13, and the Rec.2020-limited HDR
    views' bright ones 1.13 and 1.04; with the luminance toe of 2^-9 the 108 nit view's camera
    colours measured 1.02."""
    view = views.catalogue()[name]
    display = next(d for d in default_spec.displays if d.name == display_name)
    lat = aces_lattice.bake(view)
    missed = {}
    for kind, aces in aces_probes.sets(display, aces_probes.PROBE_SEED, aces_probes.PROBE_COUNT).items():
        if kind not in kinds:
            continue
        truth = reference.display_xyz_encode(default_spec, display, views.evaluate(view, aces))
        ours = reference.display_xyz_encode(default_spec, display, aces_lattice.evaluate(lat, aces))
        error = probes.errors(display, ours, truth)[0]
        if np.percentile(error, 99) > GOAL_P99 or error.max() > GOAL_MAX:
            missed[kind] = (float(np.percentile(error, 99)), float(error.max()))
    assert not missed, missed
