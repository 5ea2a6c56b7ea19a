"""Probe colours for measuring a baked LUT against the reference, and the error figures.

Four sets, each in the LUT's input (source code values), drawn from a fixed
seed so the same call always gives the same colours:

* ``in_gamut``: display-linear RGB uniform in the display cube [0, peak];
* ``dark``: in-gamut colours whose largest channel is 1e-4 to 1e-2 of
  display white (100 cd/m²), log-uniform;
* ``out_of_gamut``: source-gamut colours (source linear RGB uniform in [0, 1]
  times display white) that the display cannot show, a channel below 0;
* ``over_range``: source-gamut colours scaled by 1 to 16 times the display's
  peak, log-uniform, whose largest display channel exceeds the peak.

Colours the source encoding cannot hold (they do not decode back to themselves: a
tabulated curve's clamp beyond its table, a curve with no negative values; or their
codes pass the top of a capped code range, as S-Log3's brightest codes fall short of 16
times a 1000 cd/m² peak) are left out of both, as a file in that encoding never holds them.

Errors are ten-bit code values (largest channel difference times 1023) for SDR
displays and ΔE ITP (ITU-R BT.2124, as :func:`~generator.metrics.delta_e_itp`)
for HDR ones; each set reports its maximum and 99th percentile.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator import reference, tolerances
from generator.colorimetry.matrices import channel_max, channel_min
from generator.colorimetry.transfer import Linear
from generator.luts.source_axes import code_range
from generator.metrics import colour_relative_error, delta_e_of_ictcp, ictcp_of_codes
from generator.spec.schema import ColourSpace, Display, Spec

SETS = ("in_gamut", "dark", "out_of_gamut", "over_range")

#: Probes per set.
COUNT = 4096

#: Over-range probes reach this multiple of the display's peak.
OVER_RANGE = 16.0

SEED = 20240601

#: Seed of :func:`training`: colours drawn as the probes but never the probes themselves.
TRAINING_SEED = 20250117


@dataclass(frozen=True)
class Figures:
    """Largest and 99th-percentile error of one probe set, in ``unit``."""

    maximum: float
    p99: float
    unit: str


def _display_linear(spec: Spec, source: ColourSpace, display: Display, rng, count: int) -> dict[str, np.ndarray]:
    high = display.clip_high
    to_display = reference.scene_to_display_matrix(spec, display) @ reference.space_matrix(spec, source)
    sets = {"in_gamut": rng.random((count, 3)) * high}
    dark = rng.random((count, 3))
    sets["dark"] = dark / channel_max(dark)[:, None] * 10.0 ** rng.uniform(-4, -2, (count, 1))
    wide = rng.random((8 * count, 3))
    sets["out_of_gamut"] = _first(
        count, lambda rgb: channel_min(rgb) < 0, lambda rows: reference.apply_matrix(to_display, rows), wide
    )
    exponent = rng.uniform(0, np.log10(OVER_RANGE), (8 * count, 1))
    bright = rng.random((8 * count, 3))
    sets["over_range"] = _first(
        count,
        lambda rgb: channel_max(rgb) > high,
        lambda rows, e: reference.apply_matrix(to_display, rows * (high * 10.0**e)),
        bright,
        exponent,
    )
    return sets


def _first(count: int, keep, make, *drawn: np.ndarray) -> np.ndarray:
    """The first ``count`` colours ``make(*rows)`` for which ``keep`` holds, the rows of the
    arrays ``drawn`` (equally long) taken ``2 * count`` at a time: the candidates past the
    ``count``-th kept one are drawn (the generator's sequence stays the same) but never made."""
    block, found, total = max(2 * count, 1), [], 0
    for start in range(0, len(drawn[0]), block):
        made = make(*(d[start : start + block] for d in drawn))
        found.append(made[keep(made)][: count - total])
        total += len(found[-1])
        if total >= count:
            break
    return np.concatenate(found) if found else np.empty((0, 3))


def representable(spec: Spec, source: ColourSpace, ref: np.ndarray, code: np.ndarray | None = None) -> np.ndarray:
    """Which scene-reference colours ``ref`` (n, 3) the encoding of ``source`` holds: their
    codes (``code``, computed if not given) decode back to them within float64 rounding
    (REPRESENTABLE_RELATIVE of the largest component). Every colour, for a linear source."""
    if isinstance(source.curve, Linear):
        return np.ones(len(ref), dtype=bool)
    with np.errstate(all="ignore"):
        code = reference.from_reference(spec, source, ref) if code is None else code
        return (
            colour_relative_error(reference.to_reference(spec, source, code), ref) <= tolerances.REPRESENTABLE_RELATIVE
        )


def held(spec: Spec, source: ColourSpace, display: Display, ref: np.ndarray, code: np.ndarray) -> np.ndarray:
    """:func:`representable` colours whose codes also lie within the source's code range where
    the curve caps it (S-Log3's and an sRGB encoding's codes end at 1, below the brightest
    over-range probes of a 1000 cd/m² display): no file of the source holds the others."""
    keep = representable(spec, source, ref, code)
    _low, high, capped = code_range(source, display)
    if capped:
        with np.errstate(invalid="ignore"):
            keep &= np.all(code <= high, axis=-1)
    return keep


def probes(
    spec: Spec, source: ColourSpace, display: Display, count: int = COUNT, gamut_source: ColourSpace | None = None
) -> dict[str, np.ndarray]:
    """The probe sets as scene-reference linear RGB, shape (n, 3) each.

    ``gamut_source`` (default ``source``) is the space whose gamut the
    out-of-gamut and over-range sets are drawn from."""
    rng = np.random.default_rng(SEED)
    sets = _display_linear(spec, gamut_source or source, display, rng, count)
    to_reference = np.linalg.inv(reference.scene_to_display_matrix(spec, display))
    return {name: reference.apply_matrix(to_reference, linear) for name, linear in sets.items()}


def training(
    spec: Spec,
    source: ColourSpace,
    display: Display,
    method: str,
    count: int,
    params=None,
    gamut_source: ColourSpace | None = None,
) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Colours of the four kinds the probes measure, from another seed: per set, the
    source code values (n, 3) and the reference's display code values (n, 3)."""
    rng = np.random.default_rng(TRAINING_SEED)
    sets = _display_linear(spec, gamut_source or source, display, rng, count)
    to_reference = np.linalg.inv(reference.scene_to_display_matrix(spec, display))
    out = {}
    for name, linear in sets.items():
        ref = reference.apply_matrix(to_reference, linear)
        with np.errstate(all="ignore"):
            code = reference.from_reference(spec, source, ref)
            keep = held(spec, source, display, ref, code)
            out[name] = (code[keep], reference.mapped_view(spec, display, method, ref[keep], params))
    return out


def errors(display: Display, actual, expected) -> tuple[np.ndarray, str]:
    """Per-colour error of code values ``actual`` against ``expected``, and its unit."""
    return errors_against(display, actual, target(display, expected))


def target(display: Display, expected) -> np.ndarray:
    """What :func:`errors_against` compares a reading with: the ``expected`` code values, or
    for an HDR display their ICtCp, computed once for all the readings of a file."""
    expected = np.asarray(expected, dtype=np.float64)
    if not display.is_hdr:
        return expected
    with np.errstate(all="ignore"):
        return ictcp_of_codes(display, expected)


def errors_against(display: Display, actual, wanted: np.ndarray) -> tuple[np.ndarray, str]:
    """:func:`errors` of code values ``actual`` against a :func:`target` ``wanted``."""
    actual = np.asarray(actual, dtype=np.float64)
    if display.is_hdr:
        with np.errstate(all="ignore"):
            return np.nan_to_num(delta_e_of_ictcp(ictcp_of_codes(display, actual), wanted)), "ΔE ITP"
    return channel_max(np.abs(actual - wanted)) * 1023.0, "10-bit codes"


def targets(display: Display, sets: dict) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """:func:`reference_sets`' ``sets`` with each expected value its :func:`target`."""
    return {name: (code, target(display, expected)) for name, (code, expected) in sets.items()}


def reference_sets(
    spec: Spec,
    source: ColourSpace | None,
    display: Display,
    method: str,
    gamut_source: ColourSpace | None = None,
    count: int = COUNT,
) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each set's input values (source code values; ``source`` None: scene-reference linear RGB)
    and the reference's display code values for them. A set with no colours (no out-of-gamut
    colours when the source gamut is the display's, no over-range ones a bounded source holds)
    is left out."""
    space = source or spec.reference
    out = {}
    for name, ref in probes(spec, space, display, count, gamut_source).items():
        code = ref if source is None else reference.from_reference(spec, source, ref)
        if source is not None:
            keep = held(spec, source, display, ref, code)
            ref, code = ref[keep], code[keep]
        if not len(ref):
            continue
        with np.errstate(all="ignore"):
            expected = reference.mapped_view(
                spec, display, method, ref, reference.method_params(spec, method, None, source, display)
            )
        out[name] = (code, expected)
    return out


def errors_on(display: Display, wanted: dict, apply) -> tuple[dict[str, np.ndarray], str]:
    """Per-colour errors of ``apply`` (input values (n, 3) -> display code values) on the
    :func:`targets` ``wanted`` of :func:`reference_sets`, and their unit ("" without a set)."""
    result, unit = {}, ""
    for name, (code, goal) in wanted.items():
        result[name], unit = errors_against(display, apply(code), goal)
    return result, unit


def figures(sets: dict[str, np.ndarray], unit: str) -> dict[str, Figures]:
    """Largest error and p99 of each set's per-colour errors."""
    return {name: Figures(float(e.max()), float(np.percentile(e, 99)), unit) for name, e in sets.items()}


def measure(
    spec: Spec,
    source: ColourSpace | None,
    display: Display,
    method: str,
    apply,
    gamut_source: ColourSpace | None = None,
    count: int = COUNT,
) -> dict[str, Figures]:
    """Figures of ``apply`` (source code values (n, 3) -> display code values) on every set of
    :func:`reference_sets`."""
    sets = reference_sets(spec, source, display, method, gamut_source, count)
    return figures(*errors_on(display, targets(display, sets), apply))


def ocio_apply(transform, interpolation=None, search_path: str = "", optimization: str = "OPTIMIZATION_DEFAULT"):
    """A function applying an OCIO transform (e.g. a FileTransform) in float32 on the CPU,
    optimised with the flags named by ``optimization`` (OCIO's default, what hosts run, takes
    fast approximations of pow, log and exp; ``"OPTIMIZATION_LOSSLESS"`` evaluates the file as
    written); files named by a relative path are looked up on ``search_path``.

    OCIO caches files by path; the cache is cleared first so a file rewritten at
    the same path is read anew."""
    import PyOpenColorIO as ocio

    ocio.ClearAllCaches()
    if interpolation is not None:
        transform.setInterpolation(interpolation)
    config = ocio.Config.CreateRaw()
    config.setSearchPath(search_path)
    processor = config.getProcessor(transform).getOptimizedCPUProcessor(getattr(ocio, optimization))

    def apply(code):
        pixels = np.ascontiguousarray(np.asarray(code, dtype=np.float32))
        processor.applyRGB(pixels)
        return pixels.astype(np.float64)

    return apply
