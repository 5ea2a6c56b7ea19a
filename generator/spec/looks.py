"""A spec's looks (``[[look]]``), its context variables' defaults (``[environment]``) and the looks
its views apply (a ``views`` entry given as a table: ``{ view = "ACES 2.0", looks = "+Show Look" }``).

A look is an ASC CDL given inline (slope, offset, power, saturation) or a file the show provides:
a CDL file (.cc, .ccc, .cdl; by ``cccid`` where it holds several) or a 3D LUT (.cube, .spi3d),
each applied in its ``process_space``. A file's path, inside the spec's folder, and a CCC id may
name context variables (``$SHOT``), each with a default under ``[environment]``: studios point
them at a shot's grade. Files are checked here, for every value the variables' defaults give.
"""

from __future__ import annotations

import dataclasses
import glob
import hashlib
import re
from collections.abc import Mapping
from pathlib import Path, PurePosixPath
from typing import Any

from generator.colorimetry.cdl import STYLES, CdlFileError, Correction, correction_ids, read_cdl
from generator.colorimetry.library import SpaceDef
from generator.colorimetry.look_luts import INTERPOLATIONS, LutFileError, cached_lut3d
from generator.colorimetry.look_luts import SUFFIXES as LUT_SUFFIXES
from generator.spec import fields, labels
from generator.spec.schema import CONTEXT_VARIABLE, ColourSpace, Look, SpecError, context_variables, with_context

KEYS = (
    "name",
    "process_space",
    "description",
    "slope",
    "offset",
    "power",
    "saturation",
    "style",
    "file",
    "cccid",
    "interpolation",
)
CDL_KEYS = ("slope", "offset", "power", "saturation")
CDL_SUFFIXES = (".cc", ".ccc", ".cdl")
#: The folder of a build the looks' files are copied into, beside luts/.
LOOK_FOLDER = "looks"
VARIABLE_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
VIEW_KEYS = ("view", "looks")


def environment(value, source: str) -> tuple[tuple[str, str], ...]:
    """``[environment]``: each context variable's default, a name and a value a file name may hold."""
    if value is None:
        return ()
    if not isinstance(value, dict):
        raise SpecError(source, "environment", 'expected a table of NAME = "default value" ([environment])')
    out = []
    for name, default in value.items():
        field = f"environment.{labels.toml_key(name)}"
        if not VARIABLE_NAME.fullmatch(name):
            raise SpecError(source, field, "not a context variable's name; allowed: letters, digits and _")
        text = labels.string(default, source, field)
        if not text or "/" in text or "\\" in text or text in (".", "..") or CONTEXT_VARIABLE.search(text):
            raise SpecError(
                source, field, f"{text!r} cannot stand in a file name; allowed: a non-empty name without / or $"
            )
        out.append((name, text))
    return tuple(out)


def split_views(value, source: str, field: str) -> tuple[list, dict[int, str]]:
    """A display's ``views``: each entry's view (a name, or a table's ``view``), and for the tables
    that give ``looks``, that string by the entry's index."""
    if not isinstance(value, list):
        return value, {}
    names, looks = [], {}
    for i, entry in enumerate(value):
        if not isinstance(entry, dict):
            names.append(entry)
            continue
        labels.check_keys(entry, VIEW_KEYS, source, f"{field}[{i}].")
        if "view" not in entry:
            raise SpecError(source, f"{field}[{i}].view", "required: a view entry given as a table names its view")
        names.append(entry["view"])
        given = labels.string(entry.get("looks", ""), source, f"{field}[{i}].looks")
        if given.strip():
            looks[i] = given
    return names, looks


def look_names(given: str) -> tuple[str, ...]:
    """The looks a view's ``looks`` string names, in order ("+A, +B" or "A, B")."""
    return tuple(n.strip().lstrip("+").strip() for n in given.split(",") if n.strip())


def check_view_looks(displays, looks: tuple[Look, ...], source: str, given: dict) -> None:
    """Each look a view applies is one the spec defines, applied forward; ``given``: display index
    -> entry index -> looks string as written."""
    known = {look.name for look in looks}
    for d, entries in given.items():
        for i, text in entries.items():
            field = f"display[{d}].views[{i}].looks"
            for part in (p.strip() for p in text.split(",")):
                if part.startswith(("-", "|")) or "|" in part or not part.lstrip("+").strip():
                    raise SpecError(
                        source,
                        field,
                        f"{part!r}: a view applies looks forward; allowed: look names, each optionally after '+', "
                        "separated by commas",
                    )
                name = part.lstrip("+").strip()
                if displays[d].views[i] == "Raw":
                    raise SpecError(source, field, "the Raw view shows data unchanged; allowed: looks on another view")
                if name not in known:
                    raise SpecError(
                        source,
                        field,
                        f"unknown look {name!r}{fields.suggest(name, known)}; allowed: "
                        f"{', '.join(sorted(known)) or 'a look the spec defines under [[look]] (it defines none)'}",
                    )
            if len(set(look_names(text))) != len(look_names(text)):
                raise SpecError(source, field, f"{text!r} names a look twice; allowed: each look once")


def tables(
    value, source: str, base: Path, spaces: Mapping[str, SpaceDef | ColourSpace], env: tuple
) -> tuple[Look, ...]:
    """The ``[[look]]`` tables; ``spaces``: lower-case name or alias -> the spec's colour space."""
    if value is None:
        return ()
    if not isinstance(value, list):
        raise SpecError(source, "look", f"expected an array of tables ([[look]]), got {value!r}")
    looks: list[Look] = []
    for i, table in enumerate(value):
        look = _look(table, source, f"look[{i}]", base, spaces, dict(env))
        if look.name in (earlier.name for earlier in looks):
            raise SpecError(source, f"look[{i}].name", f"{look.name!r} is defined twice; allowed: each look once")
        looks.append(look)
    return tuple(looks)


def _look(table, source: str, field: str, base: Path, spaces: Mapping[str, SpaceDef | ColourSpace], env: dict) -> Look:
    labels.check_keys(table, KEYS, source, f"{field}.")
    name = labels.table_name(table, source, field)
    if name.startswith(("+", "-")) or "|" in name:
        raise SpecError(
            source, f"{field}.name", "OCIO reads a leading + or - and | in a view's looks; allowed: a name without"
        )
    if "process_space" not in table:
        raise SpecError(source, f"{field}.process_space", "required: the colour space the look is applied in")
    given = labels.string(table["process_space"], source, f"{field}.process_space")
    space = spaces.get(given.lower())
    if space is None or space.is_data:
        raise SpecError(
            source,
            f"{field}.process_space",
            f"{given!r} is not among the spec's colour spaces{fields.suggest(given, [s.name for s in spaces.values()])}; "
            "allowed: a colour space of the spec that is not data (ACEScct, ACEScg, ...)",
        )
    inline = [k for k in CDL_KEYS if k in table]
    if bool(inline) == ("file" in table):
        raise SpecError(
            source, field, "give an ASC CDL (slope, offset, power, saturation) or a file, exactly one of them"
        )
    description = labels.string(table.get("description", ""), source, f"{field}.description", text=True)
    common: dict[str, Any] = dict(name=name, process_space=space.name, description=description)
    if inline:
        for key in ("cccid", "interpolation"):
            if key in table:
                raise SpecError(source, f"{field}.{key}", "belongs to a file look; allowed: with 'file'")
        return Look(
            **common, cdl=_correction(table, source, field), style=_choice(table, "style", STYLES, source, field)
        )
    return _file_look(table, source, field, base, env, common)


def _choice(table, key: str, allowed, source: str, field: str) -> str:
    value = labels.string(table.get(key, allowed[0]), source, f"{field}.{key}")
    if value not in allowed:
        raise SpecError(source, f"{field}.{key}", f"unknown {value!r}; allowed: {', '.join(allowed)}")
    return value


def _triple(table, key: str, default, source: str, field: str, low: float, strict: bool) -> tuple:
    value = table.get(key, list(default))
    if not isinstance(value, list) or len(value) != 3:
        raise SpecError(source, f"{field}.{key}", f"expected three numbers [r, g, b], got {value!r}")
    numbers = tuple(fields.number(v, source, f"{field}.{key}[{j}]") for j, v in enumerate(value))
    bad = next((v for v in numbers if v < low or (strict and v == low)), None)
    if bad is not None and low > float("-inf"):
        raise SpecError(
            source,
            f"{field}.{key}",
            f"{bad:g} is out of range; allowed: numbers {'above' if strict else 'from'} {low:g}",
        )
    return numbers


def _correction(table, source: str, field: str) -> Correction:
    """An inline ASC CDL: slope at least 0, any offset, power above 0, saturation at least 0."""
    saturation = fields.number(table.get("saturation", 1.0), source, f"{field}.saturation")
    if saturation < 0.0:
        raise SpecError(source, f"{field}.saturation", f"{saturation:g} is out of range; allowed: 0 or more")
    return Correction(
        slope=_triple(table, "slope", (1.0, 1.0, 1.0), source, field, 0.0, False),
        offset=_triple(table, "offset", (0.0, 0.0, 0.0), source, field, float("-inf"), False),
        power=_triple(table, "power", (1.0, 1.0, 1.0), source, field, 0.0, True),
        saturation=saturation,
    )


def _file_look(table, source: str, field: str, base: Path, env: dict, common: dict) -> Look:
    path = labels.string(table["file"], source, f"{field}.file")
    pure = PurePosixPath(path)
    if not path or pure.is_absolute() or ".." in pure.parts or "\\" in path:
        raise SpecError(
            source,
            f"{field}.file",
            f"{path!r} leaves the spec's folder; allowed: a path inside it, with / (the build copies it "
            f"into its {LOOK_FOLDER} folder)",
        )
    suffix = pure.suffix.lower()
    if suffix not in CDL_SUFFIXES + LUT_SUFFIXES:
        raise SpecError(
            source,
            f"{field}.file",
            f"a {suffix or 'suffix-less'} file; allowed: {', '.join(CDL_SUFFIXES + LUT_SUFFIXES)} "
            "(a CLF's reference evaluation needs a CLF reader colour-science lacks)",
        )
    cccid = labels.string(table.get("cccid", ""), source, f"{field}.cccid")
    if cccid and suffix not in CDL_SUFFIXES:
        raise SpecError(
            source, f"{field}.cccid", f"names a correction in a CDL file; allowed: with {', '.join(CDL_SUFFIXES)}"
        )
    if "style" in table:
        raise SpecError(
            source,
            f"{field}.style",
            "a CDL file is applied as OCIO reads it (CDL_NO_CLAMP); allowed: with an inline CDL",
        )
    interpolation = "linear"
    if suffix in LUT_SUFFIXES:
        interpolation = _choice(table, "interpolation", INTERPOLATIONS, source, field)
    elif "interpolation" in table:
        raise SpecError(source, f"{field}.interpolation", "belongs to a LUT file; allowed: with .cube or .spi3d")
    for key, text in (("file", path), ("cccid", cccid)):
        missing = next((v for v in context_variables(text) if v not in env), None)
        if missing:
            raise SpecError(
                source,
                f"{field}.{key}",
                f"names the context variable {missing!r}, which has no default; allowed: a default under "
                f'[environment] ({missing} = "...") or a name without it',
            )
    look = Look(**common, file=path, cccid=cccid, interpolation=interpolation)
    check_file(look, base, env, source, field)
    files = tuple((name, digest(base / name)) for name in copied_files(look, base))
    return dataclasses.replace(look, files=files)


def digest(path: Path) -> str:
    """The SHA-256 of the file at ``path``, in hex."""
    return hashlib.sha256(path.read_bytes()).hexdigest()


def check_file(look: Look, folder: Path, context: dict, source: str, field: str) -> None:
    """The file ``look`` reads in ``context`` (under ``folder``) exists and holds what it needs."""
    path = folder / with_context(look.file, context)
    shown = with_context(look.file, context)
    if not path.is_file():
        raise SpecError(
            source,
            f"{field}.file",
            f"{shown} does not exist{_in(look, context)}; allowed: a file inside the spec's folder",
        )
    try:
        if Path(look.file).suffix.lower() in CDL_SUFFIXES:
            read_cdl(path, with_context(look.cccid, context))
        else:
            cached_lut3d(path)
    except (CdlFileError, LutFileError) as error:
        key = "cccid" if look.cccid and "no ColorCorrection of id" in str(error) else "file"
        raise SpecError(source, f"{field}.{key}", f"{shown}{_in(look, context)} {error}") from None


def _in(look: Look, context: dict) -> str:
    used = [f"{v}={context[v]}" for v in look.variables if v in context]
    return f" (with {', '.join(used)})" if used else ""


def copied_files(look: Look, folder: Path) -> list[str]:
    """The files of ``folder`` (relative paths) a build copies for ``look``: its file, or with
    context variables every file its path matches with each variable standing for any name."""
    if not look.file:
        return []
    if not look.variables:
        return [look.file]
    pattern = CONTEXT_VARIABLE.sub("*", glob.escape(look.file).replace("[$]", "$"))
    return sorted(str(PurePosixPath(p.relative_to(folder).as_posix())) for p in folder.glob(pattern) if p.is_file())


def ccc_ids(look: Look, folder: Path, context: dict) -> tuple[str, ...]:
    """The correction ids of the CDL file ``look`` reads in ``context``."""
    return correction_ids(folder / with_context(look.file, context))


def records(spec) -> dict:
    """The looks and environment as the resolved spec records them: absent when there are none,
    so a spec without looks gives the bytes it gave before looks existed."""
    out: dict[str, list] = {}
    if spec.looks:
        out["looks"] = [dataclasses.asdict(look) for look in spec.looks]
    if spec.environment:
        out["environment"] = [list(pair) for pair in spec.environment]
    return out


def read_records(reader, data: dict) -> tuple[tuple[Look, ...], tuple[tuple[str, str], ...]]:
    """The looks and environment :func:`records` wrote, taken out of ``data`` and checked by
    ``reader`` (:class:`generator.spec.resolved._Reader`)."""
    env = reader.items(data.pop("environment", []), "environment", lambda v, f: _pair(reader, v, f))
    found = reader.items(data.pop("looks", []), "looks", lambda v, f: _read_look(reader, v, f))
    return found, env


def _pair(reader, value, field: str) -> tuple[str, str]:
    if not isinstance(value, list) or len(value) != 2:
        raise reader.fail(field, f"expected [name, default], got {value!r}")
    return tuple(reader.typed(v, str, f"{field}[{i}]") for i, v in enumerate(value))


def _read_look(reader, value, field: str) -> Look:
    d = reader.table(value, [f.name for f in dataclasses.fields(Look)], field)
    text = {k: reader.typed(d[k], str, f"{field}.{k}") for k in d if k not in ("cdl", "files")}
    files = reader.items(d["files"], f"{field}.files", lambda v, f: _pair(reader, v, f))
    cdl = None
    if d["cdl"] is not None:
        c = reader.table(d["cdl"], [f.name for f in dataclasses.fields(Correction)], f"{field}.cdl")
        triple = {
            k: reader.items(c[k], f"{field}.cdl.{k}", lambda v, f: reader.typed(v, float, f), 3)
            for k in ("slope", "offset", "power")
        }
        if any(len(v) != 3 for v in triple.values()):
            raise reader.fail(f"{field}.cdl", "expected three numbers for each of slope, offset, power")
        cdl = Correction(**triple, saturation=reader.typed(c["saturation"], float, f"{field}.cdl.saturation"))
    if (cdl is None) == (not text["file"]):
        raise reader.fail(field, "a look holds a CDL or a file, exactly one")
    for key, allowed in (("style", STYLES), ("interpolation", INTERPOLATIONS)):
        if text[key] not in allowed:
            raise reader.fail(f"{field}.{key}", f"unknown {text[key]!r}")
    return Look(**text, cdl=cdl, files=files)
