"""The resolved spec as JSON, written beside each built config and read back by later commands.

Every number the reference evaluation needs is in it (primaries, white points,
curve parameters, tabulated curves); named published curves are stored by
name and restored from the library. Keys are sorted and floats written with
``repr``, so the same spec always gives the same bytes.
"""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path
from typing import ClassVar

import numpy as np

from generator.colorimetry import transfer
from generator.colorimetry.curves import CURVES
from generator.colorimetry.matrices import CATS, Gamut
from generator.files import not_readable
from generator.gamut.rgc import RGCParams
from generator.rendering.views import is_aces_name
from generator.spec import fields, looks
from generator.spec.allowed import COLORIMETRIC_ALIASES, OCIO_MIN_VERSION, VIEWS, newest_ocio_version
from generator.spec.namespace import DISPLAY_REFERENCE, colour_spaces, generated
from generator.spec.schema import ColourSpace, Display, FileRule, Spec, SpecError

FILENAME = "ocioforge-spec.json"
_CURVE_TYPES = {
    cls.__name__: cls
    for cls in (transfer.Linear, transfer.Power, transfer.PiecewisePower, transfer.LogCamera, transfer.Tabulated)
}


def _curve_to_json(curve) -> dict:
    if isinstance(curve, transfer.Function):
        return {"family": "Function", "name": curve.name}
    return {"family": type(curve).__name__, **dataclasses.asdict(curve)}


def _record(obj) -> dict:
    """A ColourSpace or Display as a plain dict (curve and gamut expanded)."""
    out = {}
    for f in dataclasses.fields(obj):
        value = getattr(obj, f.name)
        if f.name == "looks" and not value:  # a display's views' looks, recorded when there are any
            continue
        if f.name in ("curve", "eotf"):
            out[f.name] = _curve_to_json(value)
        elif isinstance(value, Gamut):
            out[f.name] = dataclasses.asdict(value)
        else:
            out[f.name] = value
    return out


def _rule_record(rule: FileRule) -> dict:
    """A file rule as it matches: by ``regex`` alone, or by ``pattern`` and ``extension``."""
    keys = ("name", "colour_space", "regex") if rule.regex else ("name", "colour_space", "pattern", "extension")
    return {key: getattr(rule, key) for key in keys}


def dumps(spec: Spec) -> str:
    """``spec`` as the JSON a build writes beside its config."""
    data = {f.name: getattr(spec, f.name) for f in dataclasses.fields(spec) if f.metadata.get("resolved", True)}
    data["colour_spaces"] = [_record(s) for s in spec.colour_spaces]
    data["displays"] = [_record(d) for d in spec.displays]
    data["file_rules"] = [_rule_record(r) for r in spec.file_rules]
    data["rgc"] = dataclasses.asdict(spec.rgc)
    data.update(looks.records(spec))
    return json.dumps(data, indent=1, sort_keys=True) + "\n"


def loads(text: str, source: str = FILENAME) -> Spec:
    """The spec stored in ``text``; anything malformed (a shape, a type, a number that is not
    finite, a name nothing defines) is a SpecError naming its field."""
    try:
        data = json.loads(text)
    except ValueError as error:
        raise SpecError(source, "-", f"not JSON ({error}); allowed: the file a build writes") from None
    return _Reader(source).spec(data)


class _Reader:
    """Reads the stored JSON back into records, every value checked as it is read."""

    KINDS: ClassVar[dict] = {
        str: "a string",
        bool: "true or false",
        int: "an integer",
        float: "a finite number",
        list: "a list",
        dict: "an object",
    }

    def __init__(self, source: str):
        self.source = source

    def fail(self, field: str, message: str) -> SpecError:
        """A SpecError on the stored spec's ``field``."""
        return SpecError(self.source, field, f"{message}; allowed: the value a build writes (build again)")

    def typed(self, value, kind, field: str):
        """``value`` if it is of ``kind`` (a bool is no number; a float is finite)."""
        if kind is float:
            if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value):
                return float(value)
        elif isinstance(value, kind) and not (kind is int and isinstance(value, bool)):
            return value
        raise self.fail(field, f"expected {self.KINDS[kind]}, got {value!r}")

    def table(self, data, keys, field: str) -> dict:
        """``data`` an object holding exactly ``keys``."""
        self.typed(data, dict, field or "-")
        odd = next((k for k in (*keys, *data) if (k in keys) != (k in data)), None)
        if odd is not None:
            raise self.fail(_join(field, odd), "missing" if odd in keys else "unknown key")
        return data

    def items(self, value, field: str, read, least: int = 0) -> tuple:
        """A list of at least ``least`` values, each read by ``read(value, field)``."""
        values = self.typed(value, list, field)
        if len(values) < least:
            raise self.fail(
                field, f"expected {least} {'entry' if least == 1 else 'entries'} or more, got {len(values)}"
            )
        return tuple(read(v, f"{field}[{i}]") for i, v in enumerate(values))

    def strings(self, value, field: str) -> tuple[str, ...]:
        """A list of strings, as a tuple."""
        return self.items(value, field, lambda v, f: self.typed(v, str, f))

    def xy(self, value, field: str) -> tuple[float, float]:
        """A chromaticity ``[x, y]``."""
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(field, f"expected a chromaticity [x, y], got {value!r}")
        return tuple(self.typed(v, float, f"{field}[{i}]") for i, v in enumerate(value))

    def gamut(self, data, field: str) -> Gamut:
        """A gamut record."""
        keys = ("name", "primaries", "whitepoint", "adapting_white", "citation", "adaptation")
        d = self.table(data, keys, field)
        primaries = self.items(d["primaries"], f"{field}.primaries", self.xy, 3)
        if len(primaries) != 3:
            raise self.fail(f"{field}.primaries", "expected three chromaticities")
        white = self.white(d["whitepoint"], f"{field}.whitepoint")
        fields.check_triangle(primaries, white, self.source, f"{field}.primaries", f"{field}.whitepoint")
        if d["adaptation"] is not None and self.typed(d["adaptation"], str, f"{field}.adaptation") not in CATS:
            raise self.fail(f"{field}.adaptation", f"unknown {d['adaptation']!r}")
        adapting = None if d["adapting_white"] is None else self.white(d["adapting_white"], f"{field}.adapting_white")
        gamut = Gamut(
            self.typed(d["name"], str, f"{field}.name"),
            primaries,
            white,
            adapting,
            self.typed(d["citation"], str, f"{field}.citation"),
            d["adaptation"],
        )
        with np.errstate(all="ignore"):
            if not np.all(np.isfinite(gamut.rgb_to_xyz)):  # a primary at y = 0 is XYZ's alone
                raise self.fail(f"{field}.primaries", "they give no RGB to XYZ matrix")
        return gamut

    def white(self, value, field: str) -> tuple[float, float]:
        """A white point: a plausible chromaticity."""
        return fields.plausible_xy(self.xy(value, field), self.source, field, white=True)

    def curve(self, data, field: str):
        """A transfer function record: a library curve by name, or a family's parameters."""
        family = self.typed(self.typed(data, dict, field).get("family"), str, f"{field}.family")
        if family == "Function":
            name = self.table(data, ("family", "name"), field)["name"]
            if name not in CURVES:
                raise self.fail(f"{field}.name", f"unknown curve {name!r}")
            return CURVES[name]
        if family not in _CURVE_TYPES:
            raise self.fail(f"{field}.family", f"unknown family {family!r} ({', '.join(['Function', *_CURVE_TYPES])})")
        cls = _CURVE_TYPES[family]
        d = self.table(data, ("family", *(f.name for f in dataclasses.fields(cls))), field)
        values = {
            f.name: self.field_value(d[f.name], str(f.type), f"{field}.{f.name}") for f in dataclasses.fields(cls)
        }
        if family in _SPEC_FAMILIES:
            fields.check_ranges(_SPEC_FAMILIES[family], values, self.source, field)
        column = next((k for k in ("code", "linear") if k in values and not np.all(np.diff(values[k]) > 0.0)), None)
        if column:
            raise self.fail(f"{field}.{column}", "not strictly increasing")
        return cls(**values)

    def field_value(self, value, annotation: str, field: str):
        """A curve record's field, by its annotation: a number (or None), a flag, a name, a table's column."""
        if value is None and annotation.endswith("| None"):
            return None
        if annotation.startswith("tuple"):
            return self.items(value, field, lambda v, f: self.typed(v, float, f), 2)
        return self.typed(value, {"bool": bool, "str": str}.get(annotation, float), field)

    def space(self, data, field: str) -> ColourSpace:
        """A colour space record."""
        d = self.table(data, [f.name for f in dataclasses.fields(ColourSpace)], field)
        gamut = None if d["gamut"] is None else self.gamut(d["gamut"], f"{field}.gamut")
        special = self.typed(d["special"], str, f"{field}.special")
        is_data = self.typed(d["is_data"], bool, f"{field}.is_data")
        if gamut is None and not (is_data or special):
            raise self.fail(f"{field}.gamut", "a colour space that is not data has no gamut")
        return ColourSpace(
            name=self.typed(d["name"], str, f"{field}.name"),
            gamut=gamut,
            curve=self.curve(d["curve"], f"{field}.curve"),
            curve_name=self.typed(d["curve_name"], str, f"{field}.curve_name"),
            aliases=self.strings(d["aliases"], f"{field}.aliases"),
            family=self.typed(d["family"], str, f"{field}.family"),
            encoding=self.typed(d["encoding"], str, f"{field}.encoding"),
            description=self.typed(d["description"], str, f"{field}.description"),
            is_data=is_data,
            special=special,
        )

    def display(self, data, field: str) -> Display:
        """A display record."""
        keys = [f.name for f in dataclasses.fields(Display) if f.name != "looks" or "looks" in data]
        d = self.table(data, keys, field)
        views = self.items(d["views"], f"{field}.views", lambda v, f: self.typed(v, str, f), 1)
        unknown = next(
            (
                i
                for i, v in enumerate(views)
                if v not in VIEWS and v not in COLORIMETRIC_ALIASES and not is_aces_name(v)
            ),
            None,
        )
        if unknown is not None:
            raise self.fail(f"{field}.views[{unknown}]", f"unknown view {views[unknown]!r}")
        peak = self.typed(d["peak"], float, f"{field}.peak")
        if peak <= 0.0:
            raise self.fail(f"{field}.peak", f"{peak:g} is not positive")
        return Display(
            self.typed(d["name"], str, f"{field}.name"),
            self.gamut(d["gamut"], f"{field}.gamut"),
            self.curve(d["eotf"], f"{field}.eotf"),
            self.typed(d["eotf_name"], str, f"{field}.eotf_name"),
            views,
            self.strings(d["aliases"], f"{field}.aliases"),
            peak,
            self.typed(d["encoding"], str, f"{field}.encoding"),
            self.typed(d["description"], str, f"{field}.description"),
            self.typed(d["absolute"], bool, f"{field}.absolute"),
            tuple(self.items(d.get("looks", []), f"{field}.looks", self.pair)),
        )

    def pair(self, value, field: str) -> tuple[str, str]:
        """A role record ``[role, colour space]``."""
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(field, f"expected [role, colour space], got {value!r}")
        return tuple(self.typed(v, str, f"{field}[{i}]") for i, v in enumerate(value))

    def rule(self, value, field: str) -> FileRule:
        """A file rule record."""
        keys = [
            "name",
            "colour_space",
            *(["regex"] if isinstance(value, dict) and "regex" in value else ["pattern", "extension"]),
        ]
        d = {k: self.typed(v, str, f"{field}.{k}") for k, v in self.table(value, keys, field).items()}
        if "regex" in d and not d["regex"]:
            raise self.fail(f"{field}.regex", "empty")
        return FileRule(**d, **({"pattern": "", "extension": ""} if "regex" in d else {}))

    def rgc(self, value):
        """RGC parameters as :func:`dumps` records them (field by field), ACES 1.3's if absent."""
        if value is None:
            return RGCParams()
        names = [f.name for f in dataclasses.fields(RGCParams)]
        d = {k: self.typed(v, float, f"rgc.{k}") for k, v in self.table(value, names, "rgc").items()}
        try:
            return RGCParams(**d)
        except ValueError as error:
            raise self.fail("rgc", str(error)) from None

    def version(self, value) -> tuple[int, int]:
        """The OCIO version ``[major, minor]``, one the installed OpenColorIO writes."""
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail("ocio_version", f"expected [major, minor], got {value!r}")
        version = tuple(self.typed(v, int, f"ocio_version[{i}]") for i, v in enumerate(value))
        if not OCIO_MIN_VERSION <= version <= newest_ocio_version():
            raise self.fail("ocio_version", f"{value!r} is not a version the installed OpenColorIO writes")
        return version

    def spec(self, data) -> Spec:
        """The whole stored spec."""
        keys = [f.name for f in dataclasses.fields(Spec) if f.metadata.get("resolved", True) and f.name != "rgc"]
        # Builds before the spec held RGC parameters recorded none: they used ACES 1.3's.
        data = dict(data) if isinstance(data, dict) else data
        rgc = self.rgc(data.pop("rgc", None) if isinstance(data, dict) else None)
        spec_looks, environment = looks.read_records(self, data) if isinstance(data, dict) else ((), ())
        d = self.table(data, keys, "")
        if self.typed(d["chromatic_adaptation"], str, "chromatic_adaptation") not in CATS:
            raise self.fail("chromatic_adaptation", f"unknown chromatic adaptation {d['chromatic_adaptation']!r}")
        spec = Spec(
            name=self.typed(d["name"], str, "name"),
            description=self.typed(d["description"], str, "description"),
            ocio_version=self.version(d["ocio_version"]),
            scene_reference=self.typed(d["scene_reference"], str, "scene_reference"),
            chromatic_adaptation=d["chromatic_adaptation"],
            colour_spaces=self.items(d["colour_spaces"], "colour_spaces", self.space, 1),
            displays=self.items(d["displays"], "displays", self.display, 1),
            roles=self.items(d["roles"], "roles", self.pair),
            file_rules=self.items(d["file_rules"], "file_rules", self.rule),
            display_view_spaces=self.typed(d["display_view_spaces"], bool, "display_view_spaces"),
            inactive=self.strings(d["inactive"], "inactive"),
            source=self.typed(d["source"], str, "source"),
            rgc=rgc,
            looks=spec_looks,
            environment=environment,
        )
        self.check_names(spec)
        return spec

    def check_names(self, spec: Spec) -> None:
        """Every name the spec refers to is one it defines: the scene reference among its colour
        spaces, the inactive spaces among the config's (generated ones too; by name or alias, as
        builds before names were written as the space's own wrote them),
        the roles' targets among the spec's, its displays and the display reference, the file
        rules' among those and the roles."""
        spaces = {n.lower() for n in spec.space_names}
        targets = (
            spaces | {n.lower() for d in spec.displays for n in (d.name, *d.aliases)} | {DISPLAY_REFERENCE.lower()}
        )
        refers = [("scene_reference", spec.scene_reference, spaces)]
        taken = generated(spec.displays, spec.display_view_spaces, (), self.source)
        every = set(colour_spaces(spec.colour_spaces, taken))  # aliases too (older builds)
        refers += [(f"inactive[{i}]", name, every) for i, name in enumerate(spec.inactive)]
        refers += [(f"roles[{i}][1]", target, targets) for i, (_, target) in enumerate(spec.roles)]
        refers += [
            (f"file_rules[{i}].colour_space", r.colour_space, targets | {role for role, _ in spec.roles})
            for i, r in enumerate(spec.file_rules)
        ]
        for field, name, names in refers:
            if name.lower() not in names:
                raise self.fail(field, f"{name!r} names nothing the spec defines")


def _join(field: str, key: str) -> str:
    return f"{field}.{key}" if field else key


#: The spec's transfer family each stored analytic curve is, whose parameter ranges it keeps.
_SPEC_FAMILIES = {"Power": "gamma", "PiecewisePower": "piecewise_gamma", "LogCamera": "log_camera"}


def read_beside(config_path: str | Path) -> Spec:
    """The resolved spec stored beside a built config."""
    return read(Path(config_path).parent / FILENAME)


def read(path: Path) -> Spec:
    """The resolved spec stored at ``path``."""
    why = not_readable(path)
    if why not in (None, "does not exist"):
        raise SpecError(str(path), "-", f"{why}; allowed: the {FILENAME} a build writes beside its config.ocio")
    try:
        text = path.read_text(encoding="utf-8")
    except OSError:
        raise SpecError(
            str(path),
            "-",
            "no resolved spec here; allowed: a build's config.ocio or the "
            f"{FILENAME} beside it (ocioforge build writes both)",
        ) from None
    except UnicodeDecodeError:
        raise SpecError(str(path), "-", "not UTF-8 text; allowed: the file a build writes (build again)") from None
    spec = loads(text, str(path))
    return (
        dataclasses.replace(spec, look_folder=str(path.parent.absolute() / looks.LOOK_FOLDER)) if spec.looks else spec
    )
