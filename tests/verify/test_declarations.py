"""verify refuses a config whose declarations are not what its stored spec builds, naming the edit."""

from __future__ import annotations

import PyOpenColorIO as ocio
import pytest

from generator.spec import resolved
from generator.spec.schema import SpecError
from generator.verify import declarations
from generator.verify.run import load


def _move_alias(cfg):
    """The alias lin_rec2020 moved from Linear Rec.2020 onto Linear Rec.709 (sRGB)."""
    source, target = cfg.getColorSpace("Linear Rec.2020"), cfg.getColorSpace("Linear Rec.709 (sRGB)")
    source.removeAlias("lin_rec2020")
    target.addAlias("lin_rec2020")
    cfg.addColorSpace(source)
    cfg.addColorSpace(target)


def _exr_as_log(cfg):
    rules = cfg.getFileRules()
    rules.setColorSpace(rules.getIndexForRule("OpenEXR"), "ACEScct")
    cfg.setFileRules(rules)


def _raw_first(cfg):
    views = list(cfg.getViews(ocio.VIEW_DISPLAY_DEFINED, "sRGB - Display"))
    moved = ["Raw", *[v for v in views if v != "Raw"]]
    entries = [
        (v, cfg.getDisplayViewTransformName("sRGB - Display", v), cfg.getDisplayViewColorSpaceName("sRGB - Display", v))
        for v in views
    ]
    for view in views:
        cfg.removeDisplayView("sRGB - Display", view)
    by_name = {v: (t, s) for v, t, s in entries}
    for view in moved:
        transform, space = by_name[view]
        if transform:
            cfg.addDisplayView("sRGB - Display", view, transform, space, "", "", "")
        else:
            cfg.addDisplayView("sRGB - Display", view, space)


def _edit_space(cfg, name, change):
    space = cfg.getColorSpace(name)
    change(space)
    cfg.addColorSpace(space)  # replaces the one of that name


def _shared_view(cfg):
    """A shared view listed on sRGB: hosts offer it after the display's own."""
    cfg.addSharedView("Extra", "Scale (Display P3 - Display)", "<USE_DISPLAY_NAME>", "", "", "")
    cfg.addDisplaySharedView("sRGB - Display", "Extra")


def _viewing_rule(cfg):
    """A viewing rule on sRGB's Colorimetric view: an ACEScg image no longer defaults to it."""
    rules = ocio.ViewingRules()
    rules.insertRule(0, "logonly")
    rules.addColorSpace(0, "ACEScct")
    cfg.setViewingRules(rules)


def _named_transform(cfg):
    transform = ocio.NamedTransform()
    transform.setName("Darker")
    transform.setTransform(ocio.ExponentTransform([2.0, 2.0, 2.0, 1.0]), ocio.TRANSFORM_DIR_FORWARD)
    cfg.addNamedTransform(transform)


def _absolute_file(cfg):
    """The sRGB Scale view reads its file by an absolute path: a copied build reads the original's."""
    name = "Scale (sRGB - Display)"
    view = cfg.getViewTransform(name)
    group = view.getTransform(ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
    for t in group:
        if isinstance(t, ocio.FileTransform):
            t.setSrc("/mnt/shows/other/luts/" + t.getSrc())
    view.setTransform(group, ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)
    cfg.addViewTransform(view)


EDITS = {
    # what a build never writes and a host acts on
    "shared view": (_shared_view, "sRGB - Display also lists the shared views ['Extra']"),
    "viewing rule": (_viewing_rule, "viewing rules ['logonly'] choose views per image"),
    "named transform": (_named_transform, "named transforms ['Darker']"),
    "environment": (lambda cfg: cfg.addEnvironmentVar("SHOT", "a"), "environment variables ['SHOT']"),
    "file by path": (_absolute_file, "view transform 'Scale (sRGB - Display)' reads '/mnt/shows/other/luts/"),
    "version": (lambda cfg: cfg.setMinorVersion(3), "the config is OCIO 2.3, the spec's 2.1"),
    "extra alias": (
        lambda cfg: _edit_space(cfg, "ACEScg", lambda cs: cs.addAlias("cg")),
        "ACEScg has the aliases ['cg'], which the spec does not give it",
    ),
    "role": (lambda cfg: cfg.setRole("scene_linear", "ACES2065-1"), "role scene_linear is 'ACES2065-1'"),
    "file rule": (_exr_as_log, "file rule 1 is ('OpenEXR', '*', 'exr', '', 'ACEScct')"),
    "inactive": (lambda cfg: cfg.setInactiveColorSpaces("ACEScct, Linear Rec.2020"), "inactive spaces are"),
    "active views": (lambda cfg: cfg.setActiveViews("Colorimetric, Raw"), "active views are ['Colorimetric', 'Raw']"),
    "active displays": (
        lambda cfg: cfg.setActiveDisplays("Rec.2100-PQ - Display, sRGB - Display"),
        "active displays are ['Rec.2100-PQ - Display', 'sRGB - Display']",
    ),
    "default view": (_raw_first, "sRGB - Display's views are ['Raw', "),
    "alias": (_move_alias, "alias 'lin_rec2020' names 'Linear Rec.709 (sRGB)', the spec's 'Linear Rec.2020'"),
    "search path": (
        lambda cfg: cfg.setSearchPath("/mnt/shows/other/luts"),
        "the search path is '/mnt/shows/other/luts', the build's 'luts'",
    ),
    "encoding": (
        lambda cfg: _edit_space(cfg, "ACEScg", lambda cs: cs.setEncoding("log")),
        "ACEScg's family, encoding, data flag and categories are ('ACES', 'log', False, ",
    ),
    "categories": (
        lambda cfg: _edit_space(cfg, "sRGB - Display", lambda cs: cs.clearCategories()),
        "sRGB - Display's family, encoding, data flag and categories are ('Display', 'sdr-video', False, [])",
    ),
    # the spaces the build writes beside the spec's (a host's Write node lists them): they had gone unchecked
    "view space family": (
        lambda cfg: _edit_space(cfg, "Scale - sRGB - Display", lambda cs: cs.setFamily("Hacked")),
        "Scale - sRGB - Display's family, encoding, data flag, categories and aliases are ('Hacked', ",
    ),
    "view space categories": (
        lambda cfg: _edit_space(
            cfg, "Perceptual - sRGB - Display", lambda cs: (cs.clearCategories(), cs.addCategory("working-space"))
        ),
        "Perceptual - sRGB - Display's family, encoding, data flag, categories and aliases are "
        "('Display-View', 'sdr-video', False, ['working-space'], [])",
    ),
    "display reference aliases": (
        lambda cfg: _edit_space(cfg, "CIE XYZ-D65 - Display-referred", lambda cs: cs.clearAliases()),
        "CIE XYZ-D65 - Display-referred's family, encoding, data flag, categories and aliases "
        "are ('', 'display-linear', False, ['file-io'], [])",
    ),
}


def test_the_built_config_declares_what_its_spec_builds(config_copy):
    assert (
        declarations.differences(ocio.Config.CreateFromFile(str(config_copy)), resolved.read_beside(config_copy)) == []
    )


@pytest.mark.parametrize("edit", sorted(EDITS))
def test_an_edited_declaration_is_named(config_copy, edit):
    change, words = EDITS[edit]
    cfg = ocio.Config.CreateFromFile(str(config_copy))
    change(cfg)
    config_copy.write_text(cfg.serialize(), encoding="utf-8")
    with pytest.raises(SpecError, match="declares what its stored spec does not build") as raised:
        load(config_copy)
    assert words in str(raised.value) and "\n" not in str(raised.value)


@pytest.mark.parametrize("version", [(2, 1), (2, 6)])
def test_a_custom_build_declares_what_its_spec_builds(tmp_path, version):
    """Custom spaces and displays with aliases, inactive spaces named by alias (written by their
    own names: OCIO hides no space its alias names), roles in any case, file rules of their own
    (globs and a regex), no display-view spaces: nothing a build writes is refused."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    text = (
        'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw", '
        '"Linear Rec.2020"]\ninactive = ["lin_rec2020", "Cam Log", "cie_xyz_d65_display"]\n'
        "display_view_spaces = false\n"
        '[[custom_space]]\nname = "Cam Log"\naliases = ["cam_log"]\ngamut = "Rec.2020"\n'
        'transfer = { family = "log_camera", base = 10, log_side_slope = 0.25, log_side_offset = 0.6, '
        "lin_side_slope = 5.0, lin_side_offset = 0.05 }\n"
        '[[display]]\nname = "Wall"\naliases = ["wall_display"]\ngamut = "P3-D65"\neotf = "gamma 2.4"\n'
        'views = ["Raw", "Colorimetric"]\n[[display]]\nname = "sRGB - Display"\n'
        '[roles]\nCompositing_Log = "cam_log"\n'
        '[[file_rule]]\nname = "Plates"\npattern = "*plate*"\nextension = "dpx"\ncolour_space = "ACEScct"\n'
        '[[file_rule]]\nname = "Renders"\nregex = \'.*_acescg_v\\d{3}\\.\\d{4}\\.exr$\'\ncolour_space = "ACEScg"\n'
        '[[file_rule]]\nname = "Default"\ncolour_space = "default"\n'
    )
    folder = tmp_path / "show"
    build(for_folder(load.parse(text, "show.toml", tmp_path), folder, version), folder)
    config = folder / "config.ocio"
    cfg = ocio.Config.CreateFromFile(str(config))
    assert declarations.differences(cfg, resolved.read_beside(config)) == []
    active = set(cfg.getColorSpaceNames(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ACTIVE))
    assert not {"Linear Rec.2020", "Cam Log", "CIE XYZ-D65 - Display-referred"} & active
    assert {"ACEScg", "Wall", "sRGB - Display"} <= active
    assert cfg.getColorSpaceFromFilepath("/show/sh010_acescg_v012.1001.exr")[0] == "ACEScg"  # the whole path matches
    assert cfg.getColorSpaceFromFilepath("/show/sh010_acescg_v12.1001.exr")[0] == "default"
    rules = cfg.getFileRules()
    rules.removeRule(rules.getIndexForRule("Renders"))
    rules.insertRule(1, "Renders", "ACEScg", r".*_acescg_v\d{2}\.\d{4}\.exr$")
    cfg.setFileRules(rules)
    assert declarations.differences(cfg, resolved.read_beside(config)) == [
        "file rule 2 is ('Renders', '', '', '.*_acescg_v\\\\d{2}\\\\.\\\\d{4}\\\\.exr$', 'ACEScg'), the spec's "
        "('Renders', '', '', '.*_acescg_v\\\\d{3}\\\\.\\\\d{4}\\\\.exr$', 'ACEScg')"
    ]
