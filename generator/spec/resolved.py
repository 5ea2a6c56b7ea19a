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

import numpy as np

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
    data = {f.name: getattr(spec, f.name) for f in dataclasses.fields(spec) if f.metadata.get("resolved", True)}
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
    spec = Spec(**{**data, "ocio_version": tuple(data["ocio_version"]), "colour_spaces": spaces, "displays": displays,
                   "roles": tuple(tuple(r) for r in data["roles"]), "inactive": tuple(data["inactive"]),
                   "file_rules": tuple(FileRule(**r) for r in data["file_rules"])})
    return _checked(spec)


def _checked(spec: Spec) -> Spec:
    """What later commands take for granted, checked as the file is read (an edited file raised
    deep inside them): a known adaptation, a version of integers, the scene reference among the
    spaces, and every gamut's matrix (ValueError, KeyError, TypeError or LinAlgError otherwise)."""
    from generator.colorimetry.matrices import CATS

    if spec.chromatic_adaptation not in CATS:
        raise ValueError(f"unknown chromatic adaptation {spec.chromatic_adaptation!r}")
    if len(spec.ocio_version) != 2 or not all(isinstance(v, int) for v in spec.ocio_version):
        raise TypeError(f"ocio_version {spec.ocio_version!r} is not two integers")
    spec.reference  # noqa: B018 (a KeyError when the reference is not among the spaces)
    for space in spec.colour_spaces:
        if space.gamut is None and not (space.is_data or space.special):
            raise ValueError(f"{space.name!r} has no gamut")
    for gamut in {s.gamut for s in spec.colour_spaces if s.gamut is not None} | {d.gamut for d in spec.displays}:
        gamut.rgb_to_xyz  # noqa: B018 (derives the matrix: LinAlgError or ValueError when degenerate)
    return spec


def read_beside(config_path: str | Path) -> Spec:
    """The resolved spec stored beside a built config."""
    path = Path(config_path).parent / FILENAME
    try:
        return loads(path.read_text(encoding="utf-8"))
    except OSError:
        raise SpecError(str(path), "-", "no resolved spec beside the config; build it with ocioforge build") from None
    except (ValueError, KeyError, TypeError, IndexError, np.linalg.LinAlgError) as error:
        raise SpecError(str(path), "-", f"not a resolved ocioforge spec: {type(error).__name__} {error}") from None
