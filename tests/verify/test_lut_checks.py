"""verify catches a broken config and names the broken item (PyOpenColorIO engines, small probe sets).

Each corruption is judged against the same config unbroken: exactly the broken
items must fail in addition to whatever fails there already."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.spec.schema import SpecError
from generator.verify.checks import FROM_REFERENCE, LUT, TO_REFERENCE, VIEW
from generator.verify.judge import FAIL
from generator.verify.run import verify
from tests.verify.conftest import dim_output_table

KINDS = (TO_REFERENCE, FROM_REFERENCE, VIEW, LUT)


def _failing_items(config_path, kinds) -> set[str]:
    result = verify(config_path, ("ocio",), density="quick", kinds=kinds)
    return {o.check.item for o in result.outcomes if o.verdict == FAIL}


def _rewrite(config_path, change) -> None:
    cfg = ocio.Config.CreateFromFile(str(config_path))
    change(cfg)
    config_path.write_text(cfg.serialize(), encoding="utf-8")


_BEFORE: dict[tuple, set[str]] = {}


def _newly_failing(config_path, corrupt, kinds=KINDS) -> set[str]:
    """The items that fail once ``corrupt(config_path)`` has run, and did not before
    (the unbroken copy is verified once per set of kinds)."""
    if kinds not in _BEFORE:
        _BEFORE[kinds] = _failing_items(config_path, kinds)
    corrupt(config_path)
    return _failing_items(config_path, kinds) - _BEFORE[kinds]


def _edit_space(name: str, edit):
    def change(cfg):
        space = cfg.getColorSpace(name)
        transform = space.getTransform(ocio.COLORSPACE_DIR_TO_REFERENCE)
        space.setTransform(edit(transform), ocio.COLORSPACE_DIR_TO_REFERENCE)
        cfg.addColorSpace(space)

    return change


def test_the_default_config_passes(config_copy):
    result = verify(config_copy, ("ocio",), density="quick")
    assert result.passed, [(o.check.title, o.engine, o.worst, o.note) for o in result.failures]


def test_a_matrix_entry_off_by_a_thousandth_is_named(config_copy):
    def nudge(matrix_transform):
        values = list(matrix_transform.getMatrix())
        values[0] += 1e-3
        matrix_transform.setMatrix(values)
        return matrix_transform

    corrupt = lambda path: _rewrite(path, _edit_space("Linear P3-D65", nudge))  # noqa: E731
    assert _newly_failing(config_copy, corrupt, (TO_REFERENCE, FROM_REFERENCE)) == {"Linear P3-D65"}


def test_a_wrong_exponent_is_named(config_copy):
    def steeper(group):
        exponent = group[0]
        exponent.setValue([2.25, 2.25, 2.25, 1.0])
        return group

    corrupt = lambda path: _rewrite(path, _edit_space("Gamma 2.2 Encoded Rec.709", steeper))  # noqa: E731
    assert _newly_failing(config_copy, corrupt, (TO_REFERENCE, FROM_REFERENCE)) == {"Gamma 2.2 Encoded Rec.709"}


def test_a_mislabelled_transfer_function_is_named(config_copy):
    def mislabel(cfg):
        srgb, video = cfg.getColorSpace("sRGB Encoded Rec.709 (sRGB)"), cfg.getColorSpace("Camera Rec.709")
        srgb.setTransform(video.getTransform(ocio.COLORSPACE_DIR_TO_REFERENCE), ocio.COLORSPACE_DIR_TO_REFERENCE)
        cfg.addColorSpace(srgb)

    corrupt = lambda path: _rewrite(path, mislabel)  # noqa: E731
    assert _newly_failing(config_copy, corrupt, (TO_REFERENCE, FROM_REFERENCE)) == {"sRGB Encoded Rec.709 (sRGB)"}


def test_swapped_lut_files_are_named(config_copy):
    def swap(path):
        first, second = (
            path.parent / "luts" / "canon_log_2_to_linear.spi1d",
            path.parent / "luts" / "canon_log_3_to_linear.spi1d",
        )
        a, b = first.read_bytes(), second.read_bytes()
        first.write_bytes(b)
        second.write_bytes(a)

    failing = _newly_failing(config_copy, swap, (TO_REFERENCE, FROM_REFERENCE, LUT))
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

    failing = _newly_failing(config_copy, swap, (VIEW, LUT))
    assert {
        "luts/view_srgb_display_desaturate_hsv19.clf",
        "luts/view_gamma_2_6_dci_p3_display_desaturate_hsv19.clf",
        "sRGB - Display / Desaturate",
        "Gamma 2.6 DCI-P3 - Display / Desaturate",
    } <= failing


def _nudge_nodes(clf, nodes, amount: float) -> None:
    """Add ``amount`` to every value at lattice ``nodes`` ((r, g, b) indices) of a 33³ CLF."""
    lines = clf.read_text(encoding="utf-8").splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if 'dim="33 33 33 3"' in line) + 1
    for r, g, b in nodes:
        row = start + (r * 33 + g) * 33 + b  # blue fastest
        lines[row] = " ".join(f"{float(v) + amount:.5f}" for v in lines[row].split()) + "\n"
    clf.write_text("".join(lines), encoding="utf-8")


@pytest.mark.parametrize("node", [(16, 16, 19), (30, 12, 12)])
def test_a_perceptual_node_nudged_by_a_tenth_of_a_code_is_named(config_copy, node):
    """A view defined by its lattice (Perceptual) is held to the mapping at every node and to
    the rebuilt lattice in every cell: one node of the sRGB file moved by a tenth of a ten-bit
    code fails the file, inside the display cube (nodes 12 to 20 span codes 0 to 1: (0.5, 0.5,
    0.875)) and far outside it (red 3 times the peak), where no other probe reaches."""

    def nudge(path):
        _nudge_nodes(path.parent / "luts" / "view_srgb_display_perceptual_33.clf", [node], 0.1 / 1023)

    failing = _newly_failing(config_copy, nudge, (LUT,))
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

    assert "luts/view_srgb_display_perceptual_33.clf" in _newly_failing(config_copy, nudge, (LUT,))


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

    assert _newly_failing(config_copy, nudge, (LUT,)) == {"luts/hsv_coordinates.clf"}


@pytest.mark.parametrize("entry", [37, 1500, 2700])
def test_an_entry_of_a_scale_files_output_table_nudged_is_named(config_copy, entry):
    """One entry of the sRGB Scale file's output table (coordinate to code) raised by a tenth of
    a ten-bit code: greys on every entry and between read it (random colours had read it only
    where they landed, and the quick probes passed it)."""

    def nudge(path):
        _raise_entry(path.parent / "luts" / "view_srgb_display_scale_17.clf", entry, 0.1 / 1023, 9)

    assert "luts/view_srgb_display_scale_17.clf" in _newly_failing(config_copy, nudge, (LUT,))


def test_a_scale_file_dimmed_by_half_a_code_is_named(config_copy):
    """The exact lattices (Scale, Desaturate) are held to the in-gamut target on every set, as
    Perceptual is to its lattice: the sRGB Scale file's output table scaled by 0.9995 (half a
    ten-bit code at white) fails its view and file; under the issue's every-set bound of a
    code, a file scaled by 0.9991 had passed."""

    def dim(path):
        dim_output_table(path.parent / "luts" / "view_srgb_display_scale_17.clf", 0.9995)

    failing = _newly_failing(config_copy, dim, (VIEW, LUT))
    assert failing == {"luts/view_srgb_display_scale_17.clf", "sRGB - Display / Scale"}


def test_a_perceptual_file_off_by_codes_fails_its_view(config_copy):
    """Node values a few codes off inside the cube fail the sRGB Perceptual view too, no other
    display's."""

    def nudge(path):
        _nudge_nodes(
            path.parent / "luts" / "view_srgb_display_perceptual_33.clf",
            [(r, g, b) for r in (14, 16, 18) for g in (14, 16, 18) for b in (14, 16, 18)],
            5 / 1023,
        )

    failing = _newly_failing(config_copy, nudge, (VIEW, LUT))
    assert failing >= {"luts/view_srgb_display_perceptual_33.clf", "sRGB - Display / Perceptual"}
    assert not {item for item in failing if "Perceptual" in item and "sRGB" not in item}


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
    assert "luts/view_srgb_display_perceptual_33.clf" in _failing_items(folder / "config.ocio", (LUT,))


@pytest.mark.parametrize("view", ["Scale", "Desaturate"])
def test_a_view_read_back_wrongly_is_named(config_copy, view):
    """A "<view> - <display>" space read into the scene (a display-referred image brought into
    a comp) is checked against the display's decoding: its view transform's inverse matrix
    off by a tenth in one entry fails that space alone."""
    change = _scale_view_matrix(f"{view} (sRGB - Display)", ocio.VIEWTRANSFORM_DIR_TO_REFERENCE, 0, 1.1)
    failing = _newly_failing(config_copy, lambda path: _rewrite(path, change), (TO_REFERENCE,))
    assert failing == {f"{view} - sRGB - Display"}


def _scale_view_matrix(name: str, direction, entry: int, factor: float):
    """A change multiplying one entry of view transform ``name``'s matrix in ``direction``."""

    def change(cfg):
        vt = cfg.getViewTransform(name)
        matrix = vt.getTransform(direction)
        values = list(matrix.getMatrix())
        values[entry] *= factor
        matrix.setMatrix(values)
        vt.setTransform(matrix, direction)
        cfg.addViewTransform(vt)

    return change


def test_a_missing_lut_file_is_named_not_a_traceback(config_copy):
    missing = config_copy.parent / "luts" / "mi_log_to_linear.spi1d"
    assert _newly_failing(config_copy, lambda path: missing.unlink(), (TO_REFERENCE, LUT)) == {
        "Mi-Log Rec.2020",
        "luts/mi_log_to_linear.spi1d",
    }
    result = verify(config_copy, ("ocio",), density="quick", kinds=(TO_REFERENCE, LUT), only="Mi-Log")
    notes = {o.check.item: o.note for o in result.failures}
    assert notes and all("mi_log_to_linear.spi1d" in note for note in notes.values())
    result = verify(config_copy, ("ocio",), density="quick", kinds=(LUT,), only="mi_log")
    assert {o.note for o in result.failures} == {"FileNotFoundError: missing LUT file luts/mi_log_to_linear.spi1d"}


def test_a_wrong_view_transform_fails_every_colorimetric_view(config_copy):
    nudge = _scale_view_matrix("Colorimetric", ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE, 5, 1.001)
    failing = _newly_failing(config_copy, lambda path: _rewrite(path, nudge), (VIEW,))
    displays = ocio.Config.CreateFromFile(str(config_copy)).getDisplays()
    assert {f"{d} / Colorimetric" for d in displays} <= failing
    assert all(" / " in item for item in failing)


@pytest.mark.parametrize("missing", ["config.ocio", "ocioforge-spec.json"])
def test_a_missing_file_is_a_clear_error(config_copy, missing):
    (config_copy.parent / missing).unlink()
    with pytest.raises(SpecError, match="no such config file|no resolved spec here"):
        verify(config_copy, ("ocio",), density="quick")
