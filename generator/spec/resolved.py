"""The resolved spec as JSON, written beside each built config and read back by later commands.

Every number the reference evaluation needs is in it (primaries, white points,
curve parameters, tabulated curves); named published curves are stored by
name and restored from the library. Keys are sorted and floats written with
``repr``, so the same spec always gives the same bytes.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

from generator.colorimetry import transfer
from generator.colorimetry.matrices import Gamut
from generator.spec.schema import ColourSpace, Display, FileRule, Spec, SpecError

FILENAME = "ocioforge-spec.json"
_CURVE_TYPES = {cls.__name__: cls for cls in (transfer.Linear, transfer.Power, transfer.PiecewisePower,
                                              transfer.LogCamera, transfer.Tabulated)}


def _curve_to_json(curve) -> dict:
    if isinstance(curve, transfer.Function):
        return {"family": "Function", "name": curve.name}
    return {"family": type(curve).__name__, **dataclasses.asdict(curve)}


def _curve_from_json(data: dict):
    from generator.colorimetry.curves import CURVES

    data = dict(data)
    family = data.pop("family")
    if family == "Function":
        return CURVES[data["name"]]
    if family == "Tabulated":
        data = {**data, "code": tuple(data["code"]), "linear": tuple(data["linear"])}
    return _CURVE_TYPES[family](**data)


def _gamut_from_json(data):
    if data is None:
        return None
    return Gamut(data["name"], tuple(tuple(p) for p in data["primaries"]), tuple(data["whitepoint"]),
                 tuple(data["adapting_white"]) if data["adapting_white"] else None, data["citation"],
                 data.get("adaptation"))


def _record(obj) -> dict:
    """A ColourSpace or Display as a plain dict (curve and gamut expanded)."""
    out = {}
    for f in dataclasses.fields(obj):
        value = getattr(obj, f.name)
        if f.name in ("curve", "eotf"):
            out[f.name] = _curve_to_json(value)
        elif isinstance(value, Gamut):
            out[f.name] = dataclasses.asdict(value)
        else:
            out[f.name] = value
    return out


def dumps(spec: Spec) -> str:
    data = {f.name: getattr(spec, f.name) for f in dataclasses.fields(spec)}
    data["colour_spaces"] = [_record(s) for s in spec.colour_spaces]
    data["displays"] = [_record(d) for d in spec.displays]
    data["file_rules"] = [dataclasses.asdict(r) for r in spec.file_rules]
    return json.dumps(data, indent=1, sort_keys=True) + "\n"


def loads(text: str) -> Spec:
    data = json.loads(text)
    spaces = tuple(ColourSpace(**{**s, "gamut": _gamut_from_json(s["gamut"]), "curve": _curve_from_json(s["curve"]),
                                  "aliases": tuple(s["aliases"])}) for s in data["colour_spaces"])
    displays = tuple(Display(**{**d, "gamut": _gamut_from_json(d["gamut"]), "eotf": _curve_from_json(d["eotf"]),
                                "aliases": tuple(d["aliases"]), "views": tuple(d["views"])}) for d in data["displays"])
    return Spec(**{**data, "ocio_version": tuple(data["ocio_version"]), "colour_spaces": spaces, "displays": displays,
                   "roles": tuple(tuple(r) for r in data["roles"]), "inactive": tuple(data["inactive"]),
                   "file_rules": tuple(FileRule(**r) for r in data["file_rules"])})


def read_beside(config_path: str | Path) -> Spec:
    """The resolved spec stored beside a built config."""
    path = Path(config_path).parent / FILENAME
    try:
        return loads(path.read_text(encoding="utf-8"))
    except OSError:
        raise SpecError(str(path), "-", "no resolved spec beside the config; build it with ocioforge build") from None
    except (ValueError, KeyError, TypeError) as error:
        raise SpecError(str(path), "-", f"not a resolved ocioforge spec: {error}") from None
