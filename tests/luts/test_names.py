"""File names of written LUTs: slugs, unique within a folder."""

from __future__ import annotations

import pytest

from generator.luts.names import add_file, file_stems, slug


def test_slug_keeps_letters_and_digits():
    assert slug("Rec.2100-PQ - Display") == "rec_2100_pq_display"
    assert slug('Ünïcode: "quoted"') == "unicode_quoted"


def test_a_name_slugging_apart_keeps_its_slug():
    assert file_stems(["sRGB - Display", "Rec.2100-PQ - Display"]) == {
        "sRGB - Display": "srgb_display", "Rec.2100-PQ - Display": "rec_2100_pq_display"}


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
