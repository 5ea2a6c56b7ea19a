"""The ASC Color Decision List (ASC CDL v1.2): slope, offset, power and saturation.

A standard as data and two small functions: :func:`asc_cdl` evaluates a correction in
float64, :func:`read_cdl` reads one from the XML files the ASC defines (.cc: one
ColorCorrection; .ccc: a ColorCorrectionCollection; .cdl: a ColorDecisionList), by id where
the file holds several. Styles are OpenColorIO's: ``asc`` (its CDL_ASC, the v1.2 formula with
its clamps) and ``no_clamp`` (its CDL_NO_CLAMP, negatives passed through the power).
"""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass
from pathlib import Path

import numpy as np

#: ASC CDL v1.2's saturation weights: Rec.709 luma (ITU-R BT.709, as the ASC specifies them).
LUMA_WEIGHTS = (0.2126, 0.7152, 0.0722)

#: The styles a correction is evaluated in: OpenColorIO's CDL_ASC and CDL_NO_CLAMP.
STYLES = ("asc", "no_clamp")


@dataclass(frozen=True)
class Correction:
    """One ASC CDL correction: per-channel slope, offset and power, and a saturation."""

    slope: tuple[float, float, float] = (1.0, 1.0, 1.0)
    offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    power: tuple[float, float, float] = (1.0, 1.0, 1.0)
    saturation: float = 1.0


def asc_cdl(rgb, correction: Correction, style: str = "asc") -> np.ndarray:
    """``rgb`` (..., 3) through ``correction``, in float64.

    ASC CDL v1.2: ``out = clamp(in * slope + offset) ** power`` with the clamp to [0, 1] before
    the power, then saturation about Rec.709 luma, clamped to [0, 1] again (the ``asc`` style,
    OpenColorIO's CDL_ASC). ``no_clamp`` (CDL_NO_CLAMP) clamps nowhere and passes values below 0
    through the power unchanged.

    >>> asc_cdl([0.5, 0.5, 0.5], Correction(slope=(2.0, 1.0, 1.0)))
    array([1. , 0.5, 0.5])
    """
    rgb = np.asarray(rgb, dtype=np.float64)
    sop = rgb * np.asarray(correction.slope) + np.asarray(correction.offset)
    if style == "asc":
        sop = np.clip(sop, 0.0, 1.0)
        powered = sop ** np.asarray(correction.power)
    else:
        with np.errstate(invalid="ignore"):
            powered = np.where(sop >= 0.0, np.abs(sop) ** np.asarray(correction.power), sop)
    luma = powered @ np.asarray(LUMA_WEIGHTS)
    out = luma[..., None] + correction.saturation * (powered - luma[..., None])
    return np.clip(out, 0.0, 1.0) if style == "asc" else out


class CdlFileError(ValueError):
    """A CDL file that cannot be read, or holds no correction of the id asked for."""


def read_cdl(path: str | Path, cccid: str = "") -> Correction:
    """The correction in the CDL file at ``path`` (.cc, .ccc or .cdl): the one of id ``cccid``,
    or with none given the file's first (as OpenColorIO reads a FileTransform without one)."""
    try:
        root = ElementTree.parse(path).getroot()
    except (OSError, ElementTree.ParseError) as error:
        raise CdlFileError(f"cannot read it as CDL XML ({error})") from None
    corrections = [e for e in root.iter() if _local(e.tag) == "ColorCorrection"]
    if not corrections:
        raise CdlFileError("holds no ColorCorrection")
    if cccid:
        chosen = [e for e in corrections if e.get("id") == cccid]
        if not chosen:
            ids = [i for e in corrections if (i := e.get("id"))]
            raise CdlFileError(f"holds no ColorCorrection of id {cccid!r} (its ids: {', '.join(ids) or 'none'})")
        corrections = chosen
    return _correction(corrections[0])


def correction_ids(path: str | Path) -> tuple[str, ...]:
    """The ids of the ColorCorrections in the CDL file at ``path``, in file order."""
    root = ElementTree.parse(path).getroot()
    return tuple(i for e in root.iter() if _local(e.tag) == "ColorCorrection" and (i := e.get("id")))


def _local(tag: str) -> str:
    """An element's name without its XML namespace."""
    return tag.rsplit("}", 1)[-1]


def _numbers(element, name: str, count: int, default: tuple[float, ...]) -> tuple[float, ...]:
    found = next((e for e in element.iter() if _local(e.tag) == name), None)
    if found is None or not (text := found.text or "").strip():
        return default
    try:
        values = tuple(float(v) for v in text.split())
    except ValueError:
        raise CdlFileError(f"its {name} {text.strip()!r} is not {count} numbers") from None
    if len(values) != count or not np.all(np.isfinite(values)):
        raise CdlFileError(f"its {name} {text.strip()!r} is not {count} finite numbers")
    return values


def _rgb(element, name: str, default: float) -> tuple[float, float, float]:
    r, g, b = _numbers(element, name, 3, (default,) * 3)
    return (r, g, b)


def _correction(element) -> Correction:
    return Correction(
        slope=_rgb(element, "Slope", 1.0),
        offset=_rgb(element, "Offset", 0.0),
        power=_rgb(element, "Power", 1.0),
        saturation=_numbers(element, "Saturation", 1, (1.0,))[0],
    )
