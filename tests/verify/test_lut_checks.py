"""verify's checks of a config's LUT files on their own: every baked file is checked, under its
own name, and one broken anywhere a probe could miss (a node, a shaper entry, an output table's
entry, the shared HSV table) is named; the unbroken config is the baseline (PyOpenColorIO engines,
small probe sets)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.verify import checks, lut_checks
from generator.verify.checks import FROM_REFERENCE, LUT, TO_REFERENCE, VIEW
from generator.verify.judge import FAIL, PASS, Output, judge
from generator.verify.probes import SIZES
from generator.verify.run import verify
from tests.verify.conftest import failing_items, newly_failing, nudge_nodes


def test_swapped_lut_files_are_named(config_copy):
    def swap(path):
        first, second = (
            path.parent / "luts" / "canon_log_2_to_linear.spi1d",
            path.parent / "luts" / "canon_log_3_to_linear.spi1d",
        )
        a, b = first.read_bytes(), second.read_bytes()
        first.write_bytes(b)
        second.write_bytes(a)

    failing = newly_failing(config_copy, swap, (TO_REFERENCE, FROM_REFERENCE, LUT))
    assert {"luts/canon_log_2_to_linear.spi1d", "luts/canon_log_3_to_linear.spi1d"} <= failing
    assert {"CanonLog2 CinemaGamut D55", "CanonLog3 CinemaGamut D55"} <= failing


def test_swapped_desaturate_files_are_named(config_copy):
    """The desaturate views' files (lattices in OCIO's HSV) of two displays swapped: their
    luminance weights differ, and verify names both files and both views."""

    def swap(path):
        luts = path.parent / "luts"
        first, second = (
            luts / "view_srgb_display_desaturate_hsv19.clf",
            luts / "view_gamma_2_6_dci_p3_display_desaturate_hsv19.clf",
        )
        a, b = first.read_bytes(), second.read_bytes()
        first.write_bytes(b)
        second.write_bytes(a)

    failing = newly_failing(config_copy, swap, (VIEW, LUT))
    assert {
        "luts/view_srgb_display_desaturate_hsv19.clf",
        "luts/view_gamma_2_6_dci_p3_display_desaturate_hsv19.clf",
        "sRGB - Display / Desaturate",
        "Gamma 2.6 DCI-P3 - Display / Desaturate",
    } <= failing


@pytest.mark.parametrize("node", [(16, 16, 19), (30, 12, 12)])
def test_a_perceptual_node_nudged_by_a_tenth_of_a_code_is_named(config_copy, node):
    """A view defined by its lattice (Perceptual) is held to the mapping at every node and to
    the rebuilt lattice in every cell: one node of the sRGB file moved by a tenth of a ten-bit
    code fails the file, inside the display cube (nodes 12 to 20 span codes 0 to 1: (0.5, 0.5,
    0.875)) and far outside it (red 3 times the peak), where no other probe reaches."""

    def nudge(path):
        nudge_nodes(path.parent / "luts" / "view_srgb_display_perceptual_33.clf", [node], 0.1 / 1023)

    failing = newly_failing(config_copy, nudge, (LUT,))
    assert failing == {"luts/view_srgb_display_perceptual_33.clf"}


def _raise_entry(clf, entry: int, by: float, decimals: int) -> None:
    """Raise entry ``entry`` of the first LUT1D of the single-column CLF ``clf`` by ``by``."""
    lines = clf.read_text(encoding="utf-8").splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if line.startswith("<LUT1D")) + 2  # after <Array>
    lines[start + entry] = f"{float(lines[start + entry]) + by:.{decimals}f}\n"
    clf.write_text("".join(lines), encoding="utf-8")


@pytest.mark.parametrize("entry", [20, 460])
def test_a_perceptual_shaper_entry_nudged_is_named(config_copy, entry):
    """One entry of a Perceptual file's shaper table moved by 1e-3 of a coordinate (far below
    black, far above the peak: entries no display-code or scene probe reaches) fails the file."""

    def nudge(path):
        _raise_entry(path.parent / "luts" / "view_srgb_display_perceptual_33.clf", entry, 1e-3, 6)

    assert "luts/view_srgb_display_perceptual_33.clf" in newly_failing(config_copy, nudge, (LUT,))


@pytest.mark.parametrize("half, column", [(0x0CBA, 0), (0x0B5B, 2), (0x0010, 1)])
def test_an_entry_of_the_shared_hsv_table_is_named(config_copy, half, column):
    """Every entry of the shared HSV table is read (a hue near 3e-4, a value near 2e-4, a
    saturation 2**-20 from OCIO HSV's cone, a subnormal half: narrow bands no scene colour of
    the quick probes reaches), and one moved is named."""

    def nudge(path):
        clf = path.parent / "luts" / "hsv_coordinates.clf"
        lines = clf.read_text(encoding="utf-8").splitlines(keepends=True)
        start = next(i for i, line in enumerate(lines) if line.startswith("<LUT1D")) + 2  # after <Array>
        values = [float(v) for v in lines[start + half].split()]
        values[column] = values[column] * 1.5 + 1e-3
        lines[start + half] = " ".join(f"{v:.9g}" for v in values) + "\n"
        clf.write_text("".join(lines), encoding="utf-8")

    assert newly_failing(config_copy, nudge, (LUT,)) == {"luts/hsv_coordinates.clf"}


@pytest.mark.parametrize("entry", [37, 1500, 2700])
def test_an_entry_of_a_scale_files_output_table_nudged_is_named(config_copy, entry):
    """One entry of the sRGB Scale file's output table (coordinate to code) raised by a tenth of
    a ten-bit code: greys on every entry and between read it (random colours had read it only
    where they landed, and the quick probes passed it)."""

    def nudge(path):
        _raise_entry(path.parent / "luts" / "view_srgb_display_scale_17.clf", entry, 0.1 / 1023, 9)

    assert "luts/view_srgb_display_scale_17.clf" in newly_failing(config_copy, nudge, (LUT,))


def test_a_perceptual_lattice_assembled_wrongly_is_named(tmp_path, monkeypatch):
    """A generator that assembled a Perceptual lattice wrongly (red and green swapped), for the
    file it writes and for the lattice verify rebuilds alike, is still caught: every node is
    held to the mapping itself."""
    import dataclasses

    from generator.luts import view
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    made = view.view_lattice.__wrapped__

    def swapped(spec, display, method):
        lat = made(spec, display, method)
        return dataclasses.replace(lat, cube=np.ascontiguousarray(lat.cube.transpose(1, 0, 2, 3)))

    monkeypatch.setattr(view, "view_lattice", swapped)
    text = load.default_text().split("[[display]]")[0] + (
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Perceptual", "Raw"]\n'
    )
    folder = tmp_path / "swapped"
    build(for_folder(load.parse(text, "swapped.toml", tmp_path), folder), folder)
    assert "luts/view_srgb_display_perceptual_33.clf" in failing_items(folder / "config.ocio", (LUT,))


def test_every_baked_lut_file_is_checked(build_config, spec):
    on_disk = {f"luts/{p.name}" for p in (build_config((2, 1)).parent / "luts").iterdir()}
    assert {c.lut for c in checks.build_checks(spec, "quick", kinds=(LUT,))} == on_disk


def test_custom_curves_are_checked_under_their_files_names_and_as_code_values(tmp_path):
    """A custom tabulated curve is baked under its space's or display's name, and verify checks
    that file on its own (a display's was only read through its views);
    a gamma-encoded space labelled scene-linear is still judged as code values, with the
    float32 limit of its steep power (it failed by colour relative error before)."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    (tmp_path / "curve.csv").write_text("code,linear\n0,0\n0.25,0.02\n0.5,0.12\n0.75,0.45\n1,1\n")
    text = (
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", '
        '"CIE XYZ-D65 - Scene-referred"]\n'
        '[[custom_space]]\nname = "Tab"\ngamut = "P3-D65"\ntransfer = { family = "tabulated", file = "curve.csv" }\n'
        '[[custom_space]]\nname = "Warm"\nencoding = "scene-linear"\nprimaries = [[0.70, 0.30], [0.17, 0.80], '
        '[0.13, 0.04]]\nwhite = 5000\ntransfer = { family = "gamma", exponent = 2.2 }\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
        '[[display]]\nname = "Tab Monitor"\ngamut = "Rec.709"\neotf = { family = "tabulated", file = "curve.csv" }\n'
        'views = ["Colorimetric", "Raw"]\n'
    )
    (tmp_path / "show.toml").write_text(text)
    folder = tmp_path / "show"
    build(for_folder(load.load(tmp_path / "show.toml"), folder, (2, 1)), folder)
    files = {"luts/tab_to_linear.spi1d", "luts/tab_monitor_to_linear.spi1d"}
    assert {f"luts/{p.name}" for p in (folder / "luts").iterdir()} == files
    result = verify(
        folder / "config.ocio",
        ("ocio",),
        density="quick",
        kinds=(TO_REFERENCE, FROM_REFERENCE, LUT),
    )
    assert files <= {o.check.item for o in result.outcomes}
    assert result.passed, [(o.check.title, o.engine, o.worst, o.note) for o in result.failures]


def test_verify_checks_each_space_against_its_own_curve_file(slugging_alike):
    """Spaces whose names slug alike (one as a library curve's) each have a file; verify
    checks every one, and each space through its own (they shared one file before, and
    verify failed the spaces decoding with another's curve)."""

    _spec, folder = slugging_alike
    result = verify(
        folder / "config.ocio",
        ("ocio",),
        density="quick",
        kinds=(TO_REFERENCE, FROM_REFERENCE, LUT),
    )
    files = {f"luts/{p.name}" for p in (folder / "luts").iterdir()}
    assert len(files) == 4 and files <= {o.check.item for o in result.outcomes}
    assert result.passed, [(o.check.title, o.engine, o.worst, o.note) for o in result.failures]


def test_a_baked_curves_file_is_read_on_every_node_and_between_and_a_node_off_is_named(build_config, spec, tmp_path):
    """N-Log's file through OCIO's FileTransform: the check reads every node (every fourth probe)
    and the quarters between, expecting N-Log's own decoding there, and passes the file the
    build wrote; one node raised by 1e-3 of its value fails, naming that node's probe."""
    nlog = tuple(s for s in spec.colour_spaces if s.name == "N-Log N-Gamut")
    (check,) = lut_checks.lut_checks(replace(spec, colour_spaces=nlog, displays=()), SIZES["quick"])
    assert check.lut == "luts/n_log_to_linear.spi1d" and check.interpolation == "linear"
    file = build_config((2, 1)).parent / check.lut
    rows = file.read_text(encoding="utf-8").splitlines()
    first = rows.index("{") + 1
    nodes = int(next(row for row in rows if row.startswith("Length")).split()[1])
    u = check.probes.values[: 4 * (nodes - 1) + 1, 0]
    np.testing.assert_allclose(u * 4 * (nodes - 1), np.arange(4 * (nodes - 1) + 1), atol=1e-3)
    np.testing.assert_allclose(
        check.expected[: len(u) : 4, 0], [float(v) for v in rows[first : first + nodes]], rtol=1e-6
    )

    def through(path):
        transform = ocio.FileTransform(src=str(path), interpolation=ocio.INTERP_LINEAR)
        cpu = ocio.Config.CreateRaw().getProcessor(transform).getDefaultCPUProcessor()
        pixels = np.ascontiguousarray(check.probes.values, dtype=np.float32)
        cpu.applyRGB(pixels)
        return Output(pixels.astype(np.float64))

    assert judge(check, "ocio", through(file)).verdict == PASS
    rows[first + 700] = f"{float(rows[first + 700]) * 1.001:.9g}"
    broken = tmp_path / "n_log_to_linear.spi1d"
    broken.write_text("\n".join(rows) + "\n", encoding="utf-8")
    outcome = judge(check, "ocio", through(broken))
    assert outcome.verdict == FAIL and outcome.worst_input.startswith("LUT nodes and between[2800] ")
