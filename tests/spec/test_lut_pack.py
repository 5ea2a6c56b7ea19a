"""The [[lut_pack]] tables of a spec: their keys' shapes and names, checked when the spec loads."""

from __future__ import annotations

from pathlib import Path

import pytest

from generator.gamut import METHODS
from generator.luts.pack import GAMUT_NAME, VIEW_NAME
from generator.spec import load, lut_pack
from generator.spec.allowed import LUT_FORMATS
from generator.spec.schema import LutPack, SpecError

SOURCE = "show.toml"
#: Two tables before the one a test adds, which is then lut_pack[2].
SPEC = """
colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]
[[display]]
name = "sRGB - Display"
[[lut_pack]]
sources = ["ACEScct"]
displays = ["sRGB - Display"]
formats = ["clf"]
[[lut_pack]]
sources = ["ACEScct"]
displays = ["sRGB - Display"]
views = ["ACES 2.0"]
formats = ["clf"]
"""
SPACES = {"aces2065-1", "acescg", "lin_ap1", "acescct"}
DISPLAYS = {"srgb - display", "srgb_display"}


def bad(text: str) -> SpecError:
    with pytest.raises(SpecError) as caught:
        load.parse(SPEC + text, SOURCE, Path("."))
    assert "\n" not in str(caught.value)
    return caught.value


def table(**keys) -> LutPack:
    return lut_pack.tables(
        [{"sources": ["ACEScg"], "displays": ["sRGB - Display"], "formats": ["clf"], **keys}], SOURCE, SPACES, DISPLAYS
    )[0]


def refused(**keys) -> SpecError:
    with pytest.raises(SpecError) as caught:
        table(**keys)
    assert caught.value.source == SOURCE
    return caught.value


@pytest.mark.parametrize(
    "table, field, words",
    [
        ('colour = 1\nsources = ["ACEScg"]', "lut_pack[2].colour", "allowed: sources"),
        ('sources = ["ACEScg"]\nformats = ["clf"]', "lut_pack[2].displays", "required"),
        ('sources = ["Nope"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]', "lut_pack[2].sources[0]", "not in"),
        ('sources = ["ACEScg"]\ndisplays = ["sRGB - Display"]\nformats = ["tiff"]', "lut_pack[2].formats[0]", "clf"),
        (
            'sources = ["ACEScg"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]\nsize = 500',
            "lut_pack[2].size",
            "2 to 129",
        ),
        (
            'sources = ["ACEScg"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]\ngamut_maps = ["squash"]',
            "lut_pack[2].gamut_maps[0]",
            "allowed: clip",
        ),
        (
            'sources = ["ACEScg"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]\nviews = ["ACES 2.0"]\n'
            'gamut_maps = ["clip"]',
            "lut_pack[2].views",
            "exclude each other",
        ),
        (
            'sources = ["ACEScg"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]\nfile_name = "{camera}"',
            "lut_pack[2].file_name",
            "{source}",
        ),
        (
            'sources = ["ACEScg"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]\ndecimals = 3',
            "lut_pack[2].decimals",
            "with views",
        ),
    ],
)
def test_bad_keys_are_named_when_loaded(table, field, words):
    error = bad(f"[[lut_pack]]\n{table}\n")
    assert error.field == field and words in error.message


def test_a_spec_without_tables_has_none_and_tables_must_be_an_array():
    assert lut_pack.tables(None, SOURCE, SPACES, DISPLAYS) == ()
    with pytest.raises(SpecError, match=r"expected an array of tables \(\[\[lut_pack\]\]\)"):
        lut_pack.tables({"sources": ["ACEScg"]}, SOURCE, SPACES, DISPLAYS)
    assert [len(p.sources) for p in load.parse(SPEC, SOURCE, Path(".")).lut_packs] == [1, 1]


def test_a_table_keeps_its_names_as_written_and_takes_the_bakes_defaults():
    pack = table(sources=["lin_ap1", "ACEScct"], displays=["SRGB_DISPLAY"], formats=["clf", "spi3d"])
    assert pack == LutPack(
        sources=("lin_ap1", "ACEScct"), displays=("SRGB_DISPLAY",), formats=("clf", "spi3d"), sizes=(None, None)
    )
    assert (pack.shaper, pack.file_name, pack.linear_source_formats, pack.decimals, pack.shaper_entries) == (
        "auto",
        "",
        None,
        None,
        None,
    )


def test_a_size_is_one_for_every_format_or_one_per_format():
    formats = ["clf", "resolve_cube", "spi3d"]
    assert table(formats=formats, size=33).sizes == (33, 33, 33)
    assert table(formats=formats, size={"spi3d": 17, "clf": 65}).sizes == (65, None, 17)
    assert table(size=2).sizes == (2,) and table(size=129).sizes == (129,)
    for size in (1, 130, True, 33.0, "33"):
        assert refused(size=size).field == "lut_pack[0].size"
    assert refused(formats=formats, size={"clf": 0}).field == "lut_pack[0].size.clf"
    assert refused(formats=["clf"], size={"spi3d": 17}).field == "lut_pack[0].size.spi3d"


@pytest.mark.parametrize(
    "keys, field, words",
    [
        (dict(sources=[]), "lut_pack[0].sources", "empty; allowed: one name or more"),
        (dict(sources="ACEScg"), "lut_pack[0].sources", "expected a list of strings"),
        (dict(sources=["ACEScg", "acescg"]), "lut_pack[0].sources[1]", "listed twice"),
        (dict(displays=["Rec.1886 Rec.709 - Display"]), "lut_pack[0].displays[0]", "not in the spec"),
        (dict(formats=["clf", "CLF"]), "lut_pack[0].formats[1]", "listed twice"),
        (dict(gamut_maps=["clip", "Clip"]), "lut_pack[0].gamut_maps[1]", "listed twice"),
        (dict(linear_source_formats=["spi3d"]), "lut_pack[0].linear_source_formats[0]", "allowed: clf"),
        (dict(shaper_entries=256), "lut_pack[0].shaper_entries", "with views"),
        (dict(views=["ACES 2.0"], decimals=10), "lut_pack[0].decimals", "1 to 9"),
        (dict(views=["ACES 2.0"], decimals=True), "lut_pack[0].decimals", "1 to 9"),
        (dict(views=["ACES 2.0"], shaper_entries=1), "lut_pack[0].shaper_entries", "2 to 65536"),
        (dict(shaper="a\x00b"), "lut_pack[0].shaper", "control character"),
    ],
)
def test_bad_keys_name_the_field(keys, field, words):
    error = refused(**keys)
    assert error.field == field and words in error.message


def test_the_ends_of_the_ranges_are_taken():
    views = ["ACES 2.0"]
    assert table(views=views, decimals=1, shaper_entries=2).decimals == 1
    assert table(views=views, decimals=9, shaper_entries=65536).shaper_entries == 65536
    assert table(formats=["clf", "spi3d"], linear_source_formats=["clf"]).linear_source_formats == ("clf",)


@pytest.mark.parametrize(
    "pattern",
    ["{source}_{display}_{format}", "{source}-{gamut_map}-{size}", "show {view}", "plain", GAMUT_NAME, VIEW_NAME],
)
def test_a_file_name_pattern_of_the_name_fields_is_taken(pattern):
    assert table(file_name=pattern).file_name == pattern


@pytest.mark.parametrize(
    "pattern, words",
    [
        ("luts/{source}", "names a folder or a hidden file"),
        ("luts\\{source}", "names a folder or a hidden file"),
        (".{source}", "names a folder or a hidden file"),
        ("{source!r}", "unknown field {source}"),
        ("{size:03d}", "unknown field {size}"),
        ("{0}", "unknown field {0}"),
        ("{}", "unknown field {}"),
        ("{source", "expected '}'"),
        ("a}b", "Single '}'"),
    ],
)
def test_a_file_name_pattern_that_python_cannot_fill_or_that_names_a_folder_is_refused(pattern, words):
    error = refused(file_name=pattern)
    assert error.field == "lut_pack[0].file_name" and words in error.message


def test_the_gamut_maps_and_formats_are_the_bakes():
    assert set(lut_pack.GAMUT_MAPS) == set(METHODS) and len(lut_pack.GAMUT_MAPS) == len(METHODS)
    for name in LUT_FORMATS:
        assert table(formats=[name]).formats == (name,)
    unknown = refused(colour=1)
    assert unknown.field == "lut_pack[0].colour" and f"allowed: {', '.join(lut_pack.KEYS)}" in unknown.message
