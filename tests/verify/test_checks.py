"""What verify checks: coverage from the spec; a space or view broken in the config is named
(against the unbroken config); a baked table's steep rise carried as float32 rounding."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.verify import checks
from generator.verify.checks import FROM_REFERENCE, LUT, TO_REFERENCE, VIEW
from generator.verify.run import verify
from tests.verify.conftest import newly_failing, nudge_nodes, rewrite, scale_view_matrix


@pytest.fixture(scope="module")
def built(spec):
    return checks.build_checks(spec, "quick")


def test_every_space_is_checked_both_ways(spec, built):
    to_ref = {c.item for c in built if c.kind == checks.TO_REFERENCE}
    from_ref = {c.item for c in built if c.kind == checks.FROM_REFERENCE}
    names = {s.name for s in spec.colour_spaces} | {d.name for d in spec.displays}
    assert names <= to_ref and names <= from_ref
    assert {f"Colorimetric - {d.name}" for d in spec.displays} <= from_ref


def test_every_view_is_checked_from_three_inputs(spec, built):
    views = [c for c in built if c.kind == checks.VIEW]
    sources = {c.src for c in views}
    assert sources == {"ACEScg", "ACEScct", spec.displays[0].name}
    assert len(views) == 3 * sum(len(d.views) for d in spec.displays)


def test_a_table_rising_steeply_between_two_rows_verifies(tmp_path):
    """A 10-bit table whose top row flags a clip (20 to 100 over one step) is baked on its rows,
    and verify carries the float32 rounding of the codes times that slope (1.04e-4 of the value
    at the top row, over 1e-4, which no float32 engine can do better than)."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    rows = "".join(f"{i / 1023:.9f},{20 * (i / 1023) ** 2.4:.9g}\n" for i in range(1023))
    (tmp_path / "clip.csv").write_text("code,linear\n" + rows + "1,100\n")
    (tmp_path / "show.toml").write_text(
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
        '[[custom_space]]\nname = "Clip"\ngamut = "Rec.709"\ntransfer = { family = "tabulated", file = "clip.csv" }\n'
        '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
    )
    folder = tmp_path / "show"
    build(for_folder(load.load(tmp_path / "show.toml"), folder, (2, 1)), folder)
    result = verify(folder / "config.ocio", ("ocio",), density="quick", only="Clip")
    assert result.outcomes and result.passed, [(o.check.title, o.engine, o.worst) for o in result.failures]


def _edit_space(name: str, edit):
    """A change replacing colour space ``name``'s transform to the reference by ``edit`` of it."""

    def change(cfg):
        space = cfg.getColorSpace(name)
        transform = space.getTransform(ocio.COLORSPACE_DIR_TO_REFERENCE)
        space.setTransform(edit(transform), ocio.COLORSPACE_DIR_TO_REFERENCE)
        cfg.addColorSpace(space)

    return change


def test_a_matrix_entry_off_by_a_thousandth_is_named(config_copy):
    def nudge(matrix_transform):
        values = list(matrix_transform.getMatrix())
        values[0] += 1e-3
        matrix_transform.setMatrix(values)
        return matrix_transform

    corrupt = lambda path: rewrite(path, _edit_space("Linear P3-D65", nudge))  # noqa: E731
    assert newly_failing(config_copy, corrupt, (TO_REFERENCE, FROM_REFERENCE)) == {"Linear P3-D65"}


def test_a_wrong_exponent_is_named(config_copy):
    def steeper(group):
        exponent = group[0]
        exponent.setValue([2.25, 2.25, 2.25, 1.0])
        return group

    corrupt = lambda path: rewrite(path, _edit_space("Gamma 2.2 Encoded Rec.709", steeper))  # noqa: E731
    assert newly_failing(config_copy, corrupt, (TO_REFERENCE, FROM_REFERENCE)) == {"Gamma 2.2 Encoded Rec.709"}


def test_a_mislabelled_transfer_function_is_named(config_copy):
    def mislabel(cfg):
        srgb, video = cfg.getColorSpace("sRGB Encoded Rec.709 (sRGB)"), cfg.getColorSpace("Camera Rec.709")
        srgb.setTransform(video.getTransform(ocio.COLORSPACE_DIR_TO_REFERENCE), ocio.COLORSPACE_DIR_TO_REFERENCE)
        cfg.addColorSpace(srgb)

    corrupt = lambda path: rewrite(path, mislabel)  # noqa: E731
    assert newly_failing(config_copy, corrupt, (TO_REFERENCE, FROM_REFERENCE)) == {"sRGB Encoded Rec.709 (sRGB)"}


def test_a_perceptual_file_off_by_codes_fails_its_view(config_copy):
    """Node values a few codes off inside the cube fail the sRGB Perceptual view too, no other
    display's."""

    def nudge(path):
        nudge_nodes(
            path.parent / "luts" / "view_srgb_display_perceptual_33.clf",
            [(r, g, b) for r in (14, 16, 18) for g in (14, 16, 18) for b in (14, 16, 18)],
            5 / 1023,
        )

    failing = newly_failing(config_copy, nudge, (VIEW, LUT))
    assert failing >= {"luts/view_srgb_display_perceptual_33.clf", "sRGB - Display / Perceptual"}
    assert not {item for item in failing if "Perceptual" in item and "sRGB" not in item}


def test_a_wrong_view_transform_fails_every_colorimetric_view(config_copy):
    nudge = scale_view_matrix("Colorimetric", ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE, 5, 1.001)
    failing = newly_failing(config_copy, lambda path: rewrite(path, nudge), (VIEW,))
    displays = ocio.Config.CreateFromFile(str(config_copy)).getDisplays()
    assert {f"{d} / Colorimetric" for d in displays} <= failing
    assert all(" / " in item for item in failing)


def test_the_view_checks_are_those_of_one_process_whoever_built_each(spec, monkeypatch):
    """The forked worker builds views from the first, this process from the last, until they
    meet (here the worker stops after two): together, in config order, the checks one process
    builds alone, with the same values."""
    from generator.verify import paths, probes

    claim = checks._claim
    monkeypatch.setattr(
        checks, "_claim", lambda claims, first: None if first and claims[0] >= 2 else claim(claims, first)
    )
    built = checks.build_checks(spec, "quick", kinds=(VIEW,))
    sizes = probes.SIZES["quick"]
    alone = checks.view_checks(spec, paths.endpoints(spec), probes.scene_families(spec, sizes), sizes)
    views = [c for c in built if c.kind == VIEW]
    assert [(c.title, c.src) for c in views] == [(c.title, c.src) for c in alone]
    for a, b in zip(views, alone):
        for field in ("expected", "allowance", "keep"):
            x, y = getattr(a, field), getattr(b, field)
            assert (x is None and y is None) or np.array_equal(x, y, equal_nan=True), (a.title, a.src, field)


def test_claims_from_both_ends_meet_once():
    """Each unit is claimed once, from the first or the last, whichever comes first."""
    import multiprocessing

    claims = multiprocessing.get_context("fork").Array("i", [0, 7])
    got = [checks._claim(claims, first) for first in (True, False, False, True, True, False, True, False, True)]
    assert got == [0, 6, 5, 1, 2, 4, 3, None, None]


def test_a_conversion_through_a_view_is_judged_as_verify_judges_the_view(spec, built):
    """``convert``'s check of a frame through a view (:func:`checks.conversion_check`) is verify's
    own check of that view from that source: the same expectation, allowance, samples kept,
    metric and tolerance (every seventh view check of the default config, ACES views among them)."""
    from generator.verify import paths

    ends = paths.endpoints(spec)
    views = [c for c in built if c.kind == VIEW][::7]
    assert any(c.view.startswith("ACES 2.0") for c in views) and any(c.view.startswith("ACES 1.") for c in views)
    for check in views:
        again = checks.conversion_check(spec, ends, check.probes, check.src, display=check.display, view=check.view)
        assert (again.title, again.output, again.metric, again.tolerance, again.problem) == (
            check.title,
            check.output,
            check.metric,
            check.tolerance,
            check.problem,
        )
        for field in ("expected", "allowance", "keep"):
            x, y = getattr(again, field), getattr(check, field)
            assert (x is None and y is None) or np.array_equal(x, y, equal_nan=True), (check.title, check.src, field)
