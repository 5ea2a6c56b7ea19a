"""The resolved spec stored beside a config: read back whole, anything malformed one SpecError naming its field."""

import copy
import json

import pytest

from generator.spec import load, resolved
from generator.spec.schema import SpecError

SPEC = (
    'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
    '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
    "[[custom_space]]\nname = 'Table'\ngamut = 'Rec.709'\ntransfer = { family = 'tabulated', file = 'c.csv' }\n"
)


@pytest.fixture(scope="module")
def stored(tmp_path_factory) -> dict:
    folder = tmp_path_factory.mktemp("stored")
    (folder / "c.csv").write_text("0,0\n0.5,0.2\n1,1\n")
    return json.loads(resolved.dumps(load.parse(SPEC, "show.toml", folder)))


def _set(data: dict, path: tuple, value):
    data = copy.deepcopy(data)
    target = data
    for key in path[:-1]:
        target = target[key]
    if value is KeyError:
        del target[path[-1]]
    else:
        target[path[-1]] = value
    return data


def test_a_build_that_wrote_an_inactive_space_by_its_alias_still_loads(stored):
    """Builds before inactive names were written as the space's own wrote them as given."""
    aliased = _set(stored, ("inactive",), [stored["colour_spaces"][1]["aliases"][0]])
    assert resolved.loads(json.dumps(aliased)).inactive == tuple(aliased["inactive"])


@pytest.mark.parametrize(
    "path, value, field, words",
    [
        (("roles",), {"scene_linear": "ACEScg"}, "roles", "expected a list"),
        (("roles", 0), "ACEScg", "roles[0]", "expected [role, colour space]"),
        (("roles", 0, 1), "Nope", "roles[0][1]", "'Nope' names nothing the spec defines"),
        (("colour_spaces",), [], "colour_spaces", "expected 1 entry or more"),
        (("colour_spaces", 0), 3, "colour_spaces[0]", "expected an object"),
        (
            ("colour_spaces", 1, "gamut", "primaries", 0, 0),
            float("nan"),
            "colour_spaces[1].gamut.primaries[0][0]",
            "expected a finite number, got nan",
        ),
        (
            ("colour_spaces", 1, "gamut", "primaries", 1),
            [0.713, 0.293],
            "colour_spaces[1].gamut.primaries",
            "span no triangle",
        ),
        (("colour_spaces", 1, "gamut", "whitepoint"), [0.3, 0.0], "colour_spaces[1].gamut.whitepoint", "not plausible"),
        (("colour_spaces", 1, "aliases"), 5, "colour_spaces[1].aliases", "expected a list"),
        (("colour_spaces", 1, "is_data"), "no", "colour_spaces[1].is_data", "expected true or false"),
        (("colour_spaces", 1, "gamut"), None, "colour_spaces[1].gamut", "a colour space that is not data has no gamut"),
        (("colour_spaces", 2, "curve", "family"), "Bogus", "colour_spaces[2].curve.family", "unknown family 'Bogus'"),
        (("colour_spaces", 2, "curve", "base"), "ten", "colour_spaces[2].curve.base", "expected a finite number"),
        (("colour_spaces", 2, "curve", "base"), 0.5, "colour_spaces[2].curve.base", "out of range; allowed: > 1"),
        (("colour_spaces", 2, "curve", "extra"), 1, "colour_spaces[2].curve.extra", "unknown key"),
        (("colour_spaces", 5, "curve", "linear", 1), 2.0, "colour_spaces[5].curve.linear", "not strictly increasing"),
        (
            ("colour_spaces", 3, "curve"),
            {"family": "Function", "name": "Nope"},
            "colour_spaces[3].curve.name",
            "unknown curve",
        ),
        (("displays", 0, "views"), [], "displays[0].views", "expected 1 entry or more"),
        (("displays", 0, "views", 0), "Filmic", "displays[0].views[0]", "unknown view"),
        (("displays", 0, "peak"), -1, "displays[0].peak", "not positive"),
        (("ocio_version",), [9, 9], "ocio_version", "not a version the installed OpenColorIO writes"),
        (("ocio_version",), "2.1", "ocio_version", "expected [major, minor]"),
        (("ocio_version", 1), True, "ocio_version[1]", "expected an integer"),
        (("chromatic_adaptation",), "Sharp", "chromatic_adaptation", "unknown chromatic adaptation 'Sharp'"),
        (("scene_reference",), "Nope", "scene_reference", "names nothing the spec defines"),
        (("inactive",), KeyError, "inactive", "missing"),
        (("inactive",), ["Nope"], "inactive[0]", "names nothing the spec defines"),
        (("file_rules", 0, "colour_space"), 5, "file_rules[0].colour_space", "expected a string"),
        (("file_rules", 0, "regex"), ".*", "file_rules[0].extension", "unknown key"),  # a regex rule has no glob
        (("file_rules", 0), {"name": "A", "colour_space": "ACEScg", "regex": ""}, "file_rules[0].regex", "empty"),
        (
            ("file_rules", 0),
            {"name": "A", "colour_space": "ACEScg", "regex": 5},
            "file_rules[0].regex",
            "expected a string",
        ),
        (("name",), 5, "name", "expected a string"),
        (("rgc", "power"), "x", "rgc.power", "expected a finite number"),
        # unhashable values had raised TypeError from the lookup of the adaptation's name
        (("colour_spaces", 1, "gamut", "adaptation"), [], "colour_spaces[1].gamut.adaptation", "expected a string"),
        (("chromatic_adaptation",), [1, 2], "chromatic_adaptation", "expected a string"),
        (("rgc", "power"), 0.5, "rgc", "power must be at least 1"),
        (("rgc", "limit_cyan"), KeyError, "rgc.limit_cyan", "missing"),
    ],
)
def test_a_malformed_stored_spec_is_one_error_naming_the_field(stored, path, value, field, words):
    assert resolved.loads(json.dumps(stored)) is not None
    with pytest.raises(SpecError) as error:
        resolved.loads(json.dumps(_set(stored, path, value)))
    assert (error.value.field, "\n" in str(error.value)) == (field, False)
    assert words in error.value.message


@pytest.mark.parametrize("text", ["[1, 2]", "{", "null"])
def test_a_stored_spec_that_is_no_json_object_is_an_error(tmp_path, text):
    (tmp_path / resolved.FILENAME).write_text(text)
    with pytest.raises(SpecError) as error:
        resolved.read_beside(tmp_path / "config.ocio")
    assert error.value.source == str(tmp_path / resolved.FILENAME) and "\n" not in str(error.value)


def test_verify_of_a_config_whose_stored_spec_is_malformed_exits_2_with_one_line(tmp_path, capsys, stored):
    """verify read the roles as pairs of characters and raised inside its declaration check."""
    from generator.cli import main
    from generator.ocio.write import build, for_folder

    folder = tmp_path / "show"
    (tmp_path / "c.csv").write_text("0,0\n0.5,0.2\n1,1\n")
    build(for_folder(load.parse(SPEC, "show.toml", tmp_path), folder, (2, 1)), folder)
    (folder / resolved.FILENAME).write_text(json.dumps(_set(stored, ("roles",), {"scene_linear": "ACEScg"})))
    with pytest.raises(SystemExit) as exit_:
        main(["verify", str(folder / "config.ocio"), "--quick", "--engines", "ocio"])
    err = capsys.readouterr().err
    assert exit_.value.code == 2 and err.count("\n") == 1 and ":roles: expected a list" in err


def test_the_rgc_parameters_round_trip_and_a_build_before_them_reads_aces_13s(stored, tmp_path):
    from generator.gamut import RGCParams

    spec = load.parse("[rgc]\nlimits = [1.5, 1.4, 1.3]\npower = 1.5", "show.toml", tmp_path)
    assert resolved.loads(resolved.dumps(spec)).rgc == spec.rgc == RGCParams(1.5, 1.4, 1.3, power=1.5)
    assert resolved.loads(json.dumps(_set(stored, ("rgc",), KeyError))).rgc == RGCParams()
