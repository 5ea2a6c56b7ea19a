"""Which OpenColorIO known hosts run, as data: a config of a newer profile version does not load
in them (OCIO refuses it: "not able to load that config version").

The VFX Reference Platform names one OpenColorIO per calendar year (vfxplatform.com; OCIO's own
release notes say which year takes each: 2.3 is CY2024's); Debian 12's packages and the pip
wheel of OpenImageIO were measured (``oiiotool --help``, ``ldd``).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Host:
    """A host and the OpenColorIO (major, minor) it runs: the newest config version it loads.
    ``platform``: the VFX Reference Platform year whose hosts it stands for (0: one program)."""

    name: str
    ocio: tuple[int, int]
    platform: int = 0


HOSTS = (
    Host("Debian 12's Blender 3.4, ocioconvert and oiiotool", (2, 1)),
    Host("CY2022", (2, 1), platform=2022),
    Host("CY2023", (2, 2), platform=2023),
    Host("CY2024", (2, 3), platform=2024),
    Host("CY2025", (2, 4), platform=2025),
    Host("pip's OpenImageIO 3.2 oiiotool", (2, 5)),
)


def _version(version: tuple[int, int]) -> str:
    return ".".join(map(str, version))


def not_loading(version: tuple[int, int], hosts: tuple[Host, ...] = HOSTS) -> str:
    """The hosts of ``hosts`` that will not load a config of profile ``version``, in one phrase
    (the VFX Reference Platform's years as one range); "" when every one loads it."""
    older = [h for h in hosts if h.ocio < version]
    programs = [f"{h.name} (OCIO {_version(h.ocio)})" for h in older if not h.platform]
    years = [h for h in older if h.platform]
    if years:
        first, last = years[0], years[-1]
        span = first.name if first is last else f"{first.name}–{last.name}"
        runs = _version(first.ocio) if first is last else f"{_version(first.ocio)}–{_version(last.ocio)}"
        programs.append(f"hosts of VFX Reference Platform {span} (OCIO {runs})")
    return ", ".join(programs)
