"""Names and plain values of a spec: strings OCIO carries as they are written, checked
where the spec gives them (each check a SpecError naming the field and what is allowed)."""

from __future__ import annotations

import json
import re

from generator.spec.schema import SpecError

#: Characters a config's name may not hold: it names the default output folder, configs/<name>,
#: on any system a show's files travel to.
NAME_FORBIDDEN = '/\\:*?"<>|'

#: Names Windows keeps for devices, with any extension ("CON.ocio" too), in any case.
WINDOWS_DEVICES = ("CON", "PRN", "AUX", "NUL", *(f"{port}{n}" for port in ("COM", "LPT") for n in range(10)))


def folder_name(name: str, source: str) -> str:
    """The spec's ``name`` as the default output folder's (``configs/<name>``); SpecError when
    it cannot name one."""
    if (
        not name.strip()
        or name.strip(".") == ""
        or name != name.strip()
        or any(c in NAME_FORBIDDEN or is_control(c) for c in name)
    ):
        raise SpecError(
            source,
            "name",
            f"{name!r} cannot name a folder (a build's default output is "
            f"configs/<name>); allowed: a name without {' '.join(NAME_FORBIDDEN)}, control characters "
            "or spaces at either end, and not . or ..",
        )
    if name.endswith(".") or name.split(".")[0].rstrip().upper() in WINDOWS_DEVICES:
        raise SpecError(
            source,
            "name",
            f"{name!r} cannot name a folder on Windows (a build's default output is "
            f"configs/<name>), which {'drops a final dot' if name.endswith('.') else 'keeps it for a device'}"
            f"; allowed: a name not ending in a dot, and none of {', '.join(WINDOWS_DEVICES[:4])}, "
            "COM0-9 or LPT0-9 before a dot",
        )
    return name


def check_keys(table: dict, allowed, source: str, prefix: str) -> None:
    """SpecError unless ``table`` is a table whose keys are all among ``allowed``."""
    if not isinstance(table, dict):
        raise SpecError(
            source,
            prefix.rstrip(".") or "-",
            f"expected a table of {', '.join(allowed)} (key = value lines under its [[header]]), got {table!r}",
        )
    for key in table:
        if key not in allowed:
            raise SpecError(source, f"{prefix}{key}", f"unknown key; allowed: {', '.join(allowed)}")


#: Control characters a description may hold (a multi-line TOML string's line breaks).
TEXT_CONTROLS = "\t\n\r"


def is_control(c: str) -> bool:
    """Unicode's control characters (category Cc): C0, DEL and C1."""
    return ord(c) < 0x20 or 0x7F <= ord(c) < 0xA0


def string(value, source: str, field: str, text: bool = False) -> str:
    """A string without control characters (C0, DEL, C1: OCIO's C strings end at NUL, which merges
    two names into one); a description (``text``) may hold tabs and line breaks."""
    if not isinstance(value, str):
        raise SpecError(source, field, f"expected a string, got {value!r}")
    control = next((c for c in value if is_control(c) and not (text and c in TEXT_CONTROLS)), None)
    if control is not None:
        allowed = "tabs and line breaks but no other control characters" if text else "no control characters"
        raise SpecError(
            source,
            field,
            f"{value!r} holds the control character {control!r} (OCIO ends a string at "
            f"NUL and writes the others as they are); allowed: {allowed}",
        )
    return value


def boolean(value, source: str, field: str) -> bool:
    """``value``, which must be true or false."""
    if not isinstance(value, bool):
        raise SpecError(source, field, f"expected true or false, got {value!r}")
    return value


def strings(value, source: str, field: str) -> tuple[str, ...]:
    """``value``, a list of strings, as a tuple."""
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise SpecError(source, field, f"expected a list of strings, got {value!r}")
    return tuple(string(v, source, f"{field}[{i}]") for i, v in enumerate(value))


def aliases(value, source: str, field: str) -> tuple[str, ...]:
    """``value``, a list of aliases (labels without commas), as a tuple."""
    aliases = strings(value, source, field)
    for i, alias in enumerate(aliases):
        label(alias, source, f"{field}[{i}]")
        no_comma(alias, source, f"{field}[{i}]")
    return aliases


def repeated(names) -> tuple[int, int] | None:
    """The index of the first name that repeats an earlier one (OCIO's names ignore case) and
    the earlier one's index, or None."""
    first: dict[str, int] = {}
    for i, name in enumerate(names):
        if name.lower() in first:
            return i, first[name.lower()]
        first[name.lower()] = i
    return None


def owners(listed, customs, indexed: bool):
    """(name, field, owner) for every name and alias of the spec's colour spaces, in order: a library
    space's field is its entry in colour_spaces (``indexed``: the list names them one by one), a custom
    space's the name or alias itself."""
    for i, space in enumerate(listed):
        field = f"colour_spaces[{i}]" if indexed else "colour_spaces"
        for name in (space.name, *space.aliases):
            yield name, field, f"the library colour space {space.name!r} of {field}"
    for i, space in enumerate(customs):
        for key, name in (("name", space.name), *((f"aliases[{j}]", a) for j, a in enumerate(space.aliases))):
            yield name, f"custom_space[{i}].{key}", f"custom_space[{i}] {space.name!r}"


def distinct(named, source: str) -> None:
    """Each name or alias names one colour space (OCIO compares names without case): a repeat is
    the error of the field that brings it second."""
    first: dict[str, str] = {}
    for name, field, owner in named:
        if name.lower() in first:
            raise SpecError(
                source,
                field,
                f"{name!r} already names {first[name.lower()]} (OCIO compares names "
                "without case); allowed: a name no other colour space has",
            )
        first[name.lower()] = owner


def table_name(table: dict, source: str, field: str) -> str:
    """The ``name`` of a table: a label without commas."""
    name = label(table.get("name", ""), source, f"{field}.name")
    no_comma(name, source, f"{field}.name")
    return name


#: Characters OCIO reads as the start of a context variable in the names of colour spaces and
#: roles (and refuses there with an exception).
CONTEXT_TOKENS = "$%"


def label(value, source: str, field: str, context: bool = True) -> str:
    """A name the config carries (a colour space's, an alias, a display's, a role's; a file rule's
    with ``context`` False): a string of a visible character, without control characters, without
    spaces at either end (OCIO trims them from names it reads, so the config's name would not be the
    spec's) and, where OCIO resolves context variables, without $ or %."""
    name = string(value, source, field)
    if not name.strip():
        raise SpecError(source, field, f"{name!r} is blank; required: a name with a visible character")
    if name != name.strip():
        raise SpecError(
            source,
            field,
            f"{name!r} has a space at either end, which OCIO trims from names; allowed: the name without them",
        )
    token = next((c for c in name if context and c in CONTEXT_TOKENS), None)
    if token is not None:
        raise SpecError(
            source,
            field,
            f"{name!r} holds {token!r}, which OCIO reads as a context variable in the "
            f"names of colour spaces and roles; allowed: a name without {' or '.join(CONTEXT_TOKENS)}",
        )
    return name


def toml_key(key: str) -> str:
    """``key`` as TOML writes it in a dotted field name: bare, or quoted when it holds other
    characters than letters, digits, '-' and '_' (an empty key among them)."""
    return key if re.fullmatch(r"[A-Za-z0-9_-]+", key) else json.dumps(key, ensure_ascii=False)


def no_comma(name: str, source: str, field: str) -> None:
    """OCIO's lists of names (active displays, inactive spaces) are split at commas."""
    if "," in name:
        raise SpecError(
            source,
            field,
            f"{name!r} holds a comma, at which OCIO splits its lists of names (active "
            "displays, inactive spaces); allowed: a name without commas",
        )
