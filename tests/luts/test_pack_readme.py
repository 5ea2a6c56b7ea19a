"""The README of a LUT pack, assembled from the blocks its files call for
(generator/luts/pack_readme.py)."""

from __future__ import annotations

import pytest

from generator.luts import pack_readme

FIGURES = {"ocio": "2.4.2", "count": 4096, "shaper_steps": 1000}


def _table_width(text: str, first: str) -> tuple[int, int]:
    """Cells of a Markdown table's header row (the line starting ``first``) and of its rule."""
    lines = text.splitlines()
    at = next(i for i, line in enumerate(lines) if line.startswith(first))
    return lines[at].count("|") - 1, lines[at + 1].count("|") - 1


def test_sizes_are_said_once_each_in_order():
    assert pack_readme.joined_sizes([33]) == "33"
    assert pack_readme.joined_sizes([33, 17, 33]) == "17³ or 33"


def test_a_pack_of_clf_files_says_nothing_of_cubes():
    text = pack_readme.gamut_head(["clip", "scale"], ["clf"], [], [17], **FIGURES)
    assert "a 17³ lattice uniform in\n  the logarithm of display light" in text
    assert "* `.cube`: DaVinci Resolve format" not in text and "Prefer the `.clf`" not in text
    assert text.index("Gamut mapping: **clip** ") < text.index("Gamut mapping: **scale** ")
    assert "Gamut mapping: **desaturate**" not in text
    assert "through OpenColorIO 2.4.2" in text and "on 4096 random probes" in text


def test_a_pack_with_cubes_explains_them_and_prefers_the_clf():
    text = pack_readme.gamut_head(["scale"], ["resolve_cube", "clf", "spi3d"], [33, 65], [17, 33], **FIGURES)
    assert "then a 33³ or 65³ lattice whose nodes" in text and "a 17³ or 33³ lattice uniform" in text
    assert "steps by 1/1000 of its range" in text and "Prefer the `.clf`" in text
    assert pack_readme.OTHER_NOTES["spi3d"] in text and pack_readme.OTHER_NOTES["iridas_cube"] not in text
    assert text.index(pack_readme.CUBE_NOTE[:20]) < text.index(pack_readme.CLF_NOTE[:20])


@pytest.mark.parametrize("method", sorted(pack_readme.METHOD_NOTES))
def test_each_method_is_explained_in_a_paragraph_of_its_own(method):
    text = pack_readme.gamut_head([method], ["clf"], [], [33], **FIGURES)
    assert f"Gamut mapping: **{method}** (" in text and pack_readme.METHOD_NOTES[method] in text


def test_the_error_tables_header_and_rule_have_as_many_cells():
    text = pack_readme.gamut_head(["clip"], ["clf"], [], [17], **FIGURES)
    assert _table_width(text, "| File |") == (11, 11)


def test_the_readme_holds_only_the_sections_with_rows():
    gamut, aces = "GAMUT HEAD\n", "ACES HEAD\n"
    assert pack_readme.readme(gamut, [], aces, []) == pack_readme.TITLE
    assert pack_readme.readme(gamut, ["| a |\n"], aces, []) == pack_readme.TITLE + gamut + "| a |\n"
    both = pack_readme.readme(gamut, ["| a |\n"], aces, ["| b |\n", "| c |\n"])
    assert both == pack_readme.TITLE + gamut + "| a |\n" + aces + "| b |\n| c |\n"
