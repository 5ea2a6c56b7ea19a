"""Names and plain values of a spec, checked where the spec gives them: each refusal a SpecError
naming the field, each accepted name one OpenColorIO carries as written."""

from __future__ import annotations

import tomllib
import unicodedata

import PyOpenColorIO as ocio
import pytest

from generator.spec import labels
from generator.spec.schema import SpecError

SOURCE = "show.toml"


def refusal(check, *args, **kwargs) -> SpecError:
    with pytest.raises(SpecError) as error:
        check(*args, **kwargs)
    assert error.value.source == SOURCE and "\n" not in str(error.value)
    return error.value


@pytest.mark.parametrize("name", ["ocioforge studio", "show.v2", "Show (2026)", "COM10", "CONSOLE", "lpt", "été"])
def test_a_name_that_can_name_a_folder_is_taken(name):
    assert labels.folder_name(name, SOURCE) == name


@pytest.mark.parametrize(
    "name, words",
    [
        ("", "cannot name a folder"),
        ("  ", "cannot name a folder"),
        (".", "not . or .."),
        ("..", "not . or .."),
        (" show", "spaces at either end"),
        ("a/b", "cannot name a folder"),
        ("a\\b", "cannot name a folder"),
        ("a:b", "cannot name a folder"),
        ('a"b', "cannot name a folder"),
        ("a\x7fb", "control characters"),
        # Microsoft, "Naming Files, Paths, and Namespaces": reserved device names, with any
        # extension and in any case, and no name ending in a dot.
        ("show.", "drops a final dot"),
        ("CON", "keeps it for a device"),
        ("con.ocio", "keeps it for a device"),
        ("Aux .x", "keeps it for a device"),
        ("com1", "keeps it for a device"),
        ("LPT9.cube", "keeps it for a device"),
        ("NUL", "keeps it for a device"),
    ],
)
def test_a_name_that_cannot_name_a_folder_is_refused(name, words):
    error = refusal(labels.folder_name, name, SOURCE)
    assert error.field == "name" and words in error.message


def test_control_characters_are_unicodes_category_cc():
    for code in range(0x10000):
        c = chr(code)
        assert labels.is_control(c) == (unicodedata.category(c) == "Cc"), hex(code)


def test_a_string_holds_no_control_character_but_a_texts_line_breaks_and_tabs():
    assert labels.string("a b", SOURCE, "f") == "a b"
    assert labels.string("line\n\tnext\r\n", SOURCE, "f", text=True) == "line\n\tnext\r\n"
    for value, text in (("a\nb", False), ("a\x00b", True), ("a\x85b", True)):
        error = refusal(labels.string, value, SOURCE, "description", text=text)
        assert error.field == "description" and "control character" in error.message
    assert "expected a string" in refusal(labels.string, 3, SOURCE, "f").message


def test_a_boolean_is_true_or_false_only():
    assert labels.boolean(False, SOURCE, "f") is False
    for value in (0, 1, "true", None):
        assert "expected true or false" in refusal(labels.boolean, value, SOURCE, "f").message


def test_strings_and_aliases_name_the_item_at_fault():
    assert labels.strings(["a", "b"], SOURCE, "views") == ("a", "b")
    assert "expected a list of strings" in refusal(labels.strings, "a", SOURCE, "views").message
    assert "expected a list of strings" in refusal(labels.strings, ["a", 2], SOURCE, "views").message
    assert refusal(labels.strings, ["a", "b\x00"], SOURCE, "views").field == "views[1]"
    assert labels.aliases(["lin_ap1", "ACES - ACEScg"], SOURCE, "aliases") == ("lin_ap1", "ACES - ACEScg")
    assert refusal(labels.aliases, ["a", "b,c"], SOURCE, "aliases").field == "aliases[1]"
    assert refusal(labels.aliases, ["", "b"], SOURCE, "aliases").field == "aliases[0]"
    assert refusal(labels.aliases, ["a$b"], SOURCE, "aliases").field == "aliases[0]"


def test_keys_are_checked_against_the_allowed_ones():
    labels.check_keys({"name": 1, "views": 2}, ("name", "views"), SOURCE, "display[0].")
    error = refusal(labels.check_keys, {"name": 1, "colour": 2}, ("name", "views"), SOURCE, "display[0].")
    assert error.field == "display[0].colour" and "allowed: name, views" in error.message
    error = refusal(labels.check_keys, [1], ("name",), SOURCE, "display[0].")
    assert error.field == "display[0]" and "expected a table of name" in error.message
    assert refusal(labels.check_keys, 3, ("name",), SOURCE, "").field == "-"


def test_a_repeat_is_found_without_case():
    assert labels.repeated(["A", "b", "a", "B"]) == (2, 0)
    assert labels.repeated(["A", "b", "c"]) is None
    assert labels.repeated([]) is None


def test_each_name_or_alias_names_one_space_and_the_second_is_at_fault():
    class Space:
        def __init__(self, name, aliases=()):
            self.name, self.aliases = name, aliases

    listed = [Space("ACES2065-1", ("aces",)), Space("ACEScg", ("lin_ap1",))]
    named = list(labels.owners(listed, [Space("Wall", ("wall_lin",))], indexed=True))
    assert [field for _, field, _ in named] == [
        "colour_spaces[0]",
        "colour_spaces[0]",
        "colour_spaces[1]",
        "colour_spaces[1]",
        "custom_space[0].name",
        "custom_space[0].aliases[0]",
    ]
    labels.distinct(named, SOURCE)
    clash = list(labels.owners(listed, [Space("Wall", ("LIN_AP1",))], indexed=False))
    error = refusal(labels.distinct, clash, SOURCE)
    assert error.field == "custom_space[0].aliases[0]"
    assert "'LIN_AP1' already names the library colour space 'ACEScg' of colour_spaces" in error.message


#: Names OCIO's YAML could misread if they were written unquoted.
NAMES = ["ACEScg", "a: b", "#x", "'q'", '"q"', "[x]", "{y}", "- z", "été 2", "Show Look", "50%off"]


@pytest.mark.parametrize("name", NAMES)
def test_an_accepted_name_is_carried_by_ocio_as_written(name):
    """Written into a config and read back, the colour space keeps the name the spec gave; where
    OCIO resolves context variables ($ and %), the name is refused as OCIO refuses it."""
    config = ocio.Config.CreateRaw()
    try:
        accepted = labels.label(name, SOURCE, "name") == name
    except SpecError:
        accepted = False
    try:
        config.addColorSpace(ocio.ColorSpace(name=name))
    except ocio.Exception:
        assert not accepted and labels.label(name, SOURCE, "name", context=False) == name
        return
    assert accepted
    read = ocio.Config.CreateFromStream(config.serialize())
    assert name in [space.getName() for space in read.getColorSpaces()]


@pytest.mark.parametrize(
    "name, words",
    [
        ("", "blank"),
        (" \t", "control character"),
        (" A", "space at either end"),
        ("A ", "space at either end"),
        ("A$B", "holds '$'"),
        ("a%b", "holds '%'"),
    ],
)
def test_a_label_ocio_cannot_carry_is_refused(name, words):
    assert words in refusal(labels.label, name, SOURCE, "display[0].name").message


def test_a_tables_name_is_a_label_without_commas():
    assert labels.table_name({"name": "Show Look"}, SOURCE, "look[0]") == "Show Look"
    assert refusal(labels.table_name, {"name": "A, B"}, SOURCE, "look[0]").field == "look[0].name"
    assert "blank" in refusal(labels.table_name, {}, SOURCE, "look[0]").message


def test_a_comma_is_refused_where_ocio_splits_lists_at_it():
    config = ocio.Config.CreateRaw()
    for name in ("a", "b", "a,b"):
        config.addColorSpace(ocio.ColorSpace(name=name))
    config.setInactiveColorSpaces("a,b")
    inactive = config.getColorSpaces(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_INACTIVE)
    assert sorted(space.getName() for space in inactive) == ["a", "b"]
    labels.no_comma("a;b", SOURCE, "inactive[0]")
    assert refusal(labels.no_comma, "a,b", SOURCE, "inactive[0]").field == "inactive[0]"


@pytest.mark.parametrize("key", ["scene_linear", "a-b_9", "", "a.b", "a b", "été", 'a"b', "a\\b", "1.2"])
def test_a_toml_key_reads_back_as_the_key(key):
    written = labels.toml_key(key)
    assert tomllib.loads(f"{written} = 1") == {key: 1}
    assert (written == key) == (key != "" and all(c.isascii() and (c.isalnum() or c in "-_") for c in key))
