"""The reference evaluation of a spec's looks, in float64: an ASC CDL (inline or read from its
file) or a show's 3D LUT, each in its process space, in a context (the context variables' values
that choose a shot's file or CCC id).

Beside :mod:`generator.reference`, whose colour-space conversions it uses; the verifier compares
the config's looks, and its views that apply them, against these functions.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from generator import reference
from generator.colorimetry.cdl import CdlFileError, asc_cdl, read_cdl
from generator.colorimetry.look_luts import apply_lut3d, cached_lut3d
from generator.spec.looks import CDL_SUFFIXES
from generator.spec.schema import Look, Spec, SpecError, with_context

Evaluate = Callable[[np.ndarray], np.ndarray]

#: The style OpenColorIO (2.1 to 2.6) applies a CDL file's correction in: its FileTransform reads
#: .cc, .ccc and .cdl as CDL_NO_CLAMP (OCIO's CDLOp tests' no-clamp values, measured here too).
FILE_CDL_STYLE = "no_clamp"


def context_of(spec: Spec, given: dict[str, str] | None = None) -> dict[str, str]:
    """The context variables' values: the spec's defaults, then ``given``'s."""
    return {**dict(spec.environment), **(given or {})}


def look_file(spec: Spec, look: Look, context: dict[str, str]) -> Path:
    """The file ``look`` reads in ``context``."""
    return Path(spec.look_folder) / with_context(look.file, context)


def look_function(spec: Spec, look: Look, context: dict[str, str]) -> Evaluate:
    """``look`` on values of its process space: its CDL, or its file's (CDL or 3D LUT) read in ``context``."""
    cdl = look.cdl
    if cdl is not None:
        return lambda rgb: asc_cdl(rgb, cdl, look.style)
    path = look_file(spec, look, context)
    if Path(look.file).suffix.lower() in CDL_SUFFIXES:
        try:
            correction = read_cdl(path, with_context(look.cccid, context))
        except CdlFileError as error:
            raise SpecError(str(path), "cccid" if look.cccid else "file", f"look {look.name!r}: {error}") from None
        return lambda rgb: asc_cdl(rgb, correction, FILE_CDL_STYLE)
    lut = cached_lut3d(path)
    return lambda rgb: apply_lut3d(lut, rgb, look.interpolation)


def in_reference(spec: Spec, look: Look, context: dict[str, str]) -> Evaluate:
    """``look`` on scene-reference values: into its process space, the look, back."""
    space = spec.space(look.process_space)
    fn = look_function(spec, look, context)
    return lambda ref: reference.to_reference(spec, space, fn(reference.from_reference(spec, space, ref)))


def looks_in_reference(spec: Spec, names: tuple[str, ...], context: dict[str, str]) -> Evaluate:
    """The looks ``names``, in order, on scene-reference values (as a view applies them)."""
    chain = [in_reference(spec, next(k for k in spec.looks if k.name == n), context) for n in names]

    def apply(ref):
        for fn in chain:
            ref = fn(ref)
        return ref

    return apply
