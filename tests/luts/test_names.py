"""File names of written LUTs: slugs, unique within a folder."""

from __future__ import annotations

import pytest

from generator.luts.names import STEM_MAX, add_file, file_stems, slug


def test_slug_keeps_letters_and_digits():
    assert slug("Rec.2100-PQ - Display") == "rec_2100_pq_display"
    assert slug('Ünïcode: "quoted"') == "unicode_quoted"


def test_a_name_slugging_apart_keeps_its_slug():
    assert file_stems(["sRGB - Display", "Rec.2100-PQ - Display"]) == {
        "sRGB - Display": "srgb_display",
        "Rec.2100-PQ - Display": "rec_2100_pq_display",
    }


def test_names_slugging_alike_get_distinct_stems_independent_of_order():
    names = ["Tab Log", "Tab-Log", "tab log", "Other"]
    stems = file_stems(names)
    assert len(set(stems.values())) == len(names) and stems["Other"] == "other"
    assert all(stems[n].startswith("tab_log_") for n in names[:3])
    assert file_stems(reversed(names)) == stems
    assert file_stems(["Tab Log", "Tab-Log"])["Tab Log"] == stems["Tab Log"]


def test_a_stem_taken_or_empty_is_told_apart():
    assert file_stems(["Canon Log 2"], taken=["canon_log_2"])["Canon Log 2"].startswith("canon_log_2_")
    stems = file_stems(["日本", "中国"])
    assert len(set(stems.values())) == 2 and all(stems.values())


def test_a_different_file_under_a_name_already_recorded_is_an_error():
    files = {}
    add_file(files, "a.clf", b"1")
    add_file(files, "a.clf", b"1")
    with pytest.raises(ValueError, match="a.clf"):
        add_file(files, "a.clf", b"2")


def test_a_slug_takes_accents_off_and_drops_other_scripts():
    assert slug("Écran LED (Plateau n°2)") == "ecran_led_plateau_n_2"
    assert slug("カメラ") == ""


def test_a_name_ending_in_another_names_digest_gets_a_longer_one():
    """ "Wall X 155a6b9c" slugs to the stem "Wall X" takes beside "wall-x" (its slug and digest):
    both move on to longer digests, the same whatever the order."""
    names = ["Wall X", "wall-x", "Wall X 155a6b9c"]
    stems = file_stems(names)
    assert stems["Wall X"].startswith("wall_x_155a6b9c") and len(set(stems.values())) == 3
    assert file_stems(reversed(names)) == stems


def test_a_long_name_is_cut_and_told_apart_by_its_digest():
    """A slug up to STEM_MAX is kept whole (names earlier builds wrote keep their files); a
    longer one is cut to fit with its digest, so no file name passes 255 bytes."""
    kept, first, second = "Stage " + "x" * 220, "Wall " + "x" * 300, "Wall " + "x" * 299 + "y"
    stems = file_stems([kept, first, second, "Wall"])
    assert stems["Wall"] == "wall" and stems[kept] == slug(kept) and len(slug(kept)) <= STEM_MAX
    assert stems[first] != stems[second] and stems[first].startswith(slug(first)[:200])
    assert all(len(stems[n]) <= STEM_MAX for n in (first, second))
    assert len(f"view_{stems[first]}_desaturate_hsv19.clf".encode()) <= 255
    clashing = file_stems([kept, kept.upper() + "!"])
    assert all(len(stem) <= STEM_MAX for stem in clashing.values()) and len(set(clashing.values())) == 2


def test_a_spec_whose_names_slug_alike_or_run_long_builds_distinct_short_files(tmp_path):
    """Displays whose names slug alike, one ending in another's digest, and one of 240
    characters: each view gets a file of its own, its name within the 255 bytes file
    systems allow (the build had stopped on a traceback, then on 'File name too long')."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    display = (
        '[[display]]\nname = "{}"\nprimaries = [[0.70, 0.29], [0.17, 0.78], [0.13, 0.04]]\nwhite = "D65"\n'
        'eotf = "Gamma 2.4"\nviews = ["Colorimetric", "Scale"]\n'
    )
    names = ["LED Wall", "led-wall", "LED Wall 507756a0", "Wall " + "x" * 235]
    text = 'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n' + "".join(
        display.format(n) for n in names
    )
    folder = tmp_path / "show"
    build(for_folder(load.parse(text, "show.toml", tmp_path), folder, (2, 1)), folder)
    views = sorted(p.name for p in (folder / "luts").iterdir() if p.name.startswith("view_"))
    assert len(views) == len(names) and max(len(v.encode()) for v in views) <= 255, views
