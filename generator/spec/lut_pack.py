"""The ``[[lut_pack]]`` tables of a spec: the show's standalone LUTs, baked by ``ocioforge pack``.

Each key mirrors an option of ``ocioforge bake``: ``sources`` (``--from``), ``displays``
(``--to``), ``gamut_maps`` (``--gamut-map``) or ``views`` (``--view``), ``formats``
(``--format``), ``size`` (``--size``, one for all formats or a table per format) and
``shaper`` (``--shaper``). Here the keys' shapes and names are checked; what depends on the
bake (a size too small for a layout, a view a display cannot show) is checked when the pack
is planned (:mod:`generator.luts.pack`), with the same field names.
"""

from __future__ import annotations

import string as _string

from generator.spec import labels
from generator.spec.allowed import LUT_FORMATS, VIEW_METHODS
from generator.spec.schema import LutPack, SpecError

KEYS = (
    "sources",
    "displays",
    "gamut_maps",
    "views",
    "formats",
    "size",
    "shaper",
    "file_name",
    "linear_source_formats",
    "decimals",
    "shaper_entries",
)

#: The gamut mappings a table may name (``ocioforge bake --gamut-map``).
GAMUT_MAPS = tuple(dict.fromkeys(VIEW_METHODS.values()))

#: Fields a file name pattern may hold, each replaced by the name's slug.
NAME_FIELDS = ("source", "display", "gamut_map", "view", "format", "size")

#: Lattice nodes a side OpenColorIO reads (a layout's own minimum is checked when planned).
SIZE_RANGE = (2, 129)
DECIMALS_RANGE = (1, 9)
SHAPER_ENTRIES_RANGE = (2, 65536)


def tables(value, source: str, spaces: set[str], displays: set[str]) -> tuple[LutPack, ...]:
    """The ``[[lut_pack]]`` tables; ``spaces`` and ``displays`` hold every lower-case name and
    alias the spec defines."""
    if value is None:
        return ()
    if not isinstance(value, list):
        raise SpecError(source, "lut_pack", f"expected an array of tables ([[lut_pack]]), got {value!r}")
    return tuple(_table(t, source, f"lut_pack[{i}]", spaces, displays) for i, t in enumerate(value))


def _table(table, source: str, field: str, spaces: set[str], displays: set[str]) -> LutPack:
    labels.check_keys(table, KEYS, source, f"{field}.")
    sources = _names(table, "sources", source, field, spaces, "a colour space of the spec ('ocioforge list --spec')")
    shown = _names(table, "displays", source, field, displays, "a display of the spec ('ocioforge list --spec')")
    if "gamut_maps" in table and "views" in table:
        raise SpecError(
            source,
            f"{field}.views",
            "views and gamut_maps exclude each other (an ACES view maps its own gamut); allowed: one of them",
        )
    maps = _list(table, "gamut_maps", source, field, required=False)
    for i, name in enumerate(maps):
        if name not in GAMUT_MAPS:
            raise SpecError(
                source, f"{field}.gamut_maps[{i}]", f"unknown gamut mapping {name!r}; allowed: {', '.join(GAMUT_MAPS)}"
            )
    views = _list(table, "views", source, field, required=False)
    formats = _formats(table, "formats", source, field, LUT_FORMATS)
    linear = (
        _formats(table, "linear_source_formats", source, field, formats) if "linear_source_formats" in table else None
    )
    aces_only = [k for k in ("decimals", "shaper_entries") if k in table and not views]
    if aces_only:
        raise SpecError(
            source, f"{field}.{aces_only[0]}", "applies to an ACES view's lattice; allowed: with views, not gamut_maps"
        )
    return LutPack(
        sources=sources,
        displays=shown,
        formats=formats,
        gamut_maps=maps,
        views=views,
        sizes=_sizes(table.get("size"), formats, source, f"{field}.size"),
        shaper=labels.string(table.get("shaper", "auto"), source, f"{field}.shaper"),
        file_name=_pattern(table.get("file_name", ""), source, f"{field}.file_name"),
        linear_source_formats=linear,
        decimals=_integer(table, "decimals", source, field, DECIMALS_RANGE),
        shaper_entries=_integer(table, "shaper_entries", source, field, SHAPER_ENTRIES_RANGE),
    )


def _list(table: dict, key: str, source: str, field: str, required: bool = True) -> tuple[str, ...]:
    if key not in table:
        if required:
            raise SpecError(source, f"{field}.{key}", "missing; allowed: a list of names (required)")
        return ()
    values = labels.strings(table[key], source, f"{field}.{key}")
    if not values:
        raise SpecError(source, f"{field}.{key}", "empty; allowed: one name or more")
    twice = labels.repeated([v.lower() for v in values])
    if twice:
        raise SpecError(source, f"{field}.{key}[{twice[0]}]", f"{values[twice[0]]!r} is listed twice; allowed: once")
    return values


def _names(table: dict, key: str, source: str, field: str, known: set[str], what: str) -> tuple[str, ...]:
    values = _list(table, key, source, field)
    for i, name in enumerate(values):
        if name.lower() not in known:
            raise SpecError(source, f"{field}.{key}[{i}]", f"{name!r} is not in the spec; allowed: {what}")
    return values


def _formats(table: dict, key: str, source: str, field: str, allowed) -> tuple[str, ...]:
    values = _list(table, key, source, field)
    for i, name in enumerate(values):
        if name not in allowed:
            raise SpecError(
                source, f"{field}.{key}[{i}]", f"{name!r} is not allowed here; allowed: {', '.join(allowed)}"
            )
    return values


def _size(value, source: str, field: str) -> int:
    low, high = SIZE_RANGE
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        raise SpecError(
            source, field, f"got {value!r}; allowed: a whole number of lattice nodes a side, {low} to {high}"
        )
    return value


def _sizes(value, formats: tuple[str, ...], source: str, field: str) -> tuple[int | None, ...]:
    """One size per format: ``size = 33`` for all, ``size = { clf = 17 }`` per format (a format
    left out takes the bake's default)."""
    if value is None:
        return (None,) * len(formats)
    if not isinstance(value, dict):
        return (_size(value, source, field),) * len(formats)
    for key in value:
        if key not in formats:
            raise SpecError(source, f"{field}.{key}", f"not among the table's formats; allowed: {', '.join(formats)}")
    return tuple(None if f not in value else _size(value[f], source, f"{field}.{f}") for f in formats)


def _integer(table: dict, key: str, source: str, field: str, bounds: tuple[int, int]) -> int | None:
    if key not in table:
        return None
    value, (low, high) = table[key], bounds
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        raise SpecError(source, f"{field}.{key}", f"got {value!r}; allowed: a whole number, {low} to {high}")
    return value


def _pattern(value, source: str, field: str) -> str:
    """A file name pattern: text and ``{field}`` names of :data:`NAME_FIELDS`, no folders."""
    text = labels.string(value, source, field)
    allowed = f"allowed: text and {', '.join('{' + f + '}' for f in NAME_FIELDS)}, no '/'"
    if "/" in text or "\\" in text or text.startswith("."):
        raise SpecError(source, field, f"{text!r} names a folder or a hidden file; {allowed}")
    try:
        parts = [(name, spec, conversion) for _, name, spec, conversion in _string.Formatter().parse(text)]
    except ValueError as error:
        raise SpecError(source, field, f"{text!r}: {error}; {allowed}") from None
    for name, spec, conversion in parts:
        if name is not None and (name not in NAME_FIELDS or spec or conversion):
            raise SpecError(source, field, f"unknown field {{{name}}}; {allowed}")
    return text
