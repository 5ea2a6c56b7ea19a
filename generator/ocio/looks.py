"""A spec's looks as OpenColorIO objects: the config's look list, its environment (the context
variables' defaults) and the search path that finds the looks' files in the build's folder."""

from __future__ import annotations

from pathlib import Path

import PyOpenColorIO as ocio

from generator.spec.looks import CDL_SUFFIXES, LOOK_FOLDER
from generator.spec.schema import Look, Spec

CDL_STYLES = {"asc": ocio.CDL_ASC, "no_clamp": ocio.CDL_NO_CLAMP}
INTERPOLATIONS = {"linear": ocio.INTERP_LINEAR, "tetrahedral": ocio.INTERP_TETRAHEDRAL}


def search_path(spec: Spec, lut_folder: str) -> str:
    """The config's search path: the LUT folder, then, with looks, the looks' folder."""
    return f"{lut_folder}:{LOOK_FOLDER}" if spec.looks else lut_folder


def look_transform(look: Look):
    """The transform of ``look``: a CDLTransform of its style, or a FileTransform OCIO reads from
    the looks folder (a CDL file by its CCC id), context variables left for OCIO to resolve."""
    if look.cdl is not None:
        c = look.cdl
        transform = ocio.CDLTransform(slope=list(c.slope), offset=list(c.offset), power=list(c.power), sat=c.saturation)
        transform.setStyle(CDL_STYLES[look.style])
        return transform
    transform = ocio.FileTransform(look.file)
    if Path(look.file).suffix.lower() not in CDL_SUFFIXES:
        transform.setInterpolation(INTERPOLATIONS[look.interpolation])
    if look.cccid:
        transform.setCCCId(look.cccid)
    return transform


def add_looks(spec: Spec, cfg, lut_folder: str) -> None:
    """The environment, search path and looks of ``spec`` into ``cfg``."""
    for name, default in spec.environment:
        cfg.addEnvironmentVar(name, default)
    if spec.looks:
        cfg.clearSearchPaths()
        for folder in search_path(spec, lut_folder).split(":"):
            cfg.addSearchPath(folder)
    for look in spec.looks:
        cfg.addLook(
            ocio.Look(
                name=look.name,
                processSpace=look.process_space,
                transform=look_transform(look),
                description=look.description,
            )
        )


def view_looks(display, view: str) -> str:
    """The ``looks`` a view of ``display`` carries in the config ("" for none)."""
    return ", ".join(display.view_looks(view))
