"""A view's baked LUT (:mod:`generator.luts.view`) as the config runs it: its OCIO
transform, and its errors measured through OCIO against the reference."""

from __future__ import annotations

import tempfile
from pathlib import Path

import PyOpenColorIO as ocio

from generator import reference
from generator.luts import probes
from generator.luts.curve1d import curve_file
from generator.luts.view import ViewLut
from generator.ocio.emit import display_steps, lut_steps, matrix_transform
from generator.spec.schema import Display, Spec


def view_transform(
    matrix,
    path: str,
    spec: Spec | None = None,
    display: Display | None = None,
    hsv_folder: str | None = None,
    bakes: dict | None = None,
):
    """:func:`lut_steps` as a GroupTransform; with ``spec`` and ``display``, for a LUT ending
    in display light, then the display's own encoding (from normalised display-linear RGB
    through CIE XYZ), whose baked curve files (a tabulated EOTF's, by name, for the search
    path to find) go into ``bakes`` as in the config."""
    steps = lut_steps(matrix, path, hsv_folder)
    if spec is not None and display is not None:
        steps += [
            matrix_transform(reference.normalised_display_to_xyz(spec, display)),
            *display_steps(spec, display, {} if bakes is None else bakes),
        ]
    return ocio.GroupTransform(steps)


def view_figures(lut: ViewLut) -> dict:
    """The errors of ``lut`` through OCIO on :mod:`generator.luts.probes` sets (drawn from
    the ACEScg gamut when the spec has it), the view as the config runs it (every file by
    name on the search path, the display's baked curve among them): set name to figures."""
    bakes: dict = {}
    transform = view_transform(
        lut.matrix,
        lut.filename,
        spec=lut.spec if lut.light else None,
        display=lut.display if lut.light else None,
        hsv_folder="" if lut.hsv else None,
        bakes=bakes,
    )
    files = {
        lut.filename: lut.data,
        **dict(lut.beside),
        **{filename: curve_file(baked) for filename, baked in bakes.items()},
    }
    with tempfile.TemporaryDirectory() as folder:
        for filename, content in files.items():
            (Path(folder) / filename).write_bytes(content)
        return probes.measure(
            lut.spec,
            None,
            lut.display,
            lut.method,
            probes.ocio_apply(transform, search_path=folder),
            gamut_source=_gamut_source(lut.spec),
        )


def _gamut_source(spec: Spec):
    try:
        return spec.space("ACEScg")
    except KeyError:
        return None
