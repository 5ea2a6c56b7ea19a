"""The README of a LUT pack, assembled from the blocks its files call for
(generator/luts/pack_readme.py)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from generator.luts import bake, pack_readme

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


def _aces_head() -> str:
    """The ACES section's head as generator.luts.pack formats it."""
    return pack_readme.ACES_HEAD.format(
        size="33", decimals="5", entries="4096", count=4096, ocio="2.4.2", labels="Greys p99 / max", rule=" --- |"
    )


def _pack_readme(formats: list[str]) -> str:
    """The README of a pack holding a gamut-mapped file and an ACES view's file of each of ``formats``."""
    suffixes = dict.fromkeys(bake.FORMATS[f].suffix for f in formats)
    gamut = pack_readme.gamut_head(["clip"], formats, [33], [17], **FIGURES)
    gamut_rows = [f"| acescg_to_srgb{s} | ACEScg | sRGB - Display | clip | 33³ |\n" for s in suffixes]
    aces_rows = [f"| acescct_sdr{s} | ACEScct | ACES 2.0 | sRGB - Display | 33³ |\n" for s in suffixes]
    return pack_readme.readme(gamut, gamut_rows, _aces_head(), aces_rows)


def test_a_clf_only_packs_readme_never_mentions_cubes_or_spi3d():
    """Not in the notes, the errors' text, nor the ACES section: each format's sentences go
    with its files."""
    text = _pack_readme(["clf"])
    assert ".cube" not in text and ".spi3d" not in text
    assert "move a CLF's decoding curve and its Log\noperator" in text and "rows below).\n" in text
    assert "err more.\nOn a CLF for a pure-power display (Rec.1886, Gamma 2.6) that is up to a few codes" in text
    assert "* `.clf`: the source's curve and the matrix to AP1 exact" in text


def test_a_pack_with_cubes_still_speaks_of_them_in_every_section():
    text = _pack_readme(["resolve_cube", "clf"])
    assert "rows below); a `.cube` holds only tables and reads the same either way." in text
    assert "err more. On an SDR `.cube` between" in text and "below; on a CLF for a pure-power display" in text
    assert "* `.cube` (encoded sources only)" in text and "* `.clf`: the source's curve" in text


def test_a_pack_without_clf_files_says_nothing_of_clf():
    for formats in (["resolve_cube"], ["spi3d"], ["iridas_cube", "spi3d"]):
        text = _pack_readme(formats)
        assert ".clf" not in text and "CLF" not in text, formats
        assert "hosts run it: a `" in text and "holds only tables and reads the same either way." in text
    text = _pack_readme(["spi3d", "resolve_cube"])
    assert "a `.spi3d` or `.cube` holds only tables" in text and "On an SDR `.spi3d` or `.cube` between" in text
    assert "A `.cube` holds no matrix: its lattice" in text and "Prefer the `.clf`" not in text


def test_the_committed_packs_head_is_what_its_formats_give():
    """The repository's pack (luts/: .cube and .clf files, scale) keeps its README's text, word
    for word, with the figures it was written with."""
    text = (Path(__file__).parents[2] / "luts" / "README.md").read_text()
    figures = {
        "ocio": re.search(r"through OpenColorIO (\S+) \(CPU", text).group(1),
        "count": int(re.search(r"on (\d+) random probes", text).group(1)),
        "shaper_steps": int(re.search(r"steps by 1/(\d+) of", text).group(1)),
    }
    head = pack_readme.gamut_head(["scale"], ["resolve_cube", "clf"], [33], [17], **figures)
    assert text.startswith(pack_readme.TITLE + head)


def test_the_format_notes_are_one_list_then_a_blank_line():
    text = pack_readme.gamut_head(["clip"], ["clf", "spi3d"], [], [17], **FIGURES)
    assert "(tetrahedral).\n* `.spi3d`" in text and "applied first.\n\nErrors:" in text


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
