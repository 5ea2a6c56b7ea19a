"""Probe colours: what the verifier feeds every engine, each family named.

Code families sample one colour space's encoding directly: neutral ramps over
its code range, a 3D lattice at the centres of n equal cells (between the nodes
of an (n+1)-node LUT; the centre code 0.5 of an odd n is a node of 17-, 33- and
65-node LUTs), random codes, and for a baked curve its LUT's
nodes and the points between them. Scene families are colours given in the
scene reference, encoded into whichever space a check starts from: the
ColorChecker computed from reflectance spectra (ISO 17321-1) under D65 and
under illuminant A (CIE 1931 2° observer; the A-lit chart is not adapted, so it
stays a warm, chromatic set), monochromatic light from 380 to 780 nm (outside
every display's gamut), the primaries and secondaries of every camera gamut of
the spec, negatives, noise around black, over-range values up to half-float max,
and NaN / ±Inf.

Every value is rounded to float32 when the family is made: engines see float32,
and the reference is evaluated on exactly what they see. Random families use
fixed seeds, so a run is repeatable.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from generator import reference
from generator.colorimetry.curves import HALF_MAX
from generator.colorimetry.matrices import apply_matrix
from generator.spec.schema import Spec

NON_FINITE = "non-finite"
SEED = 20240601
OBSERVER = "CIE 1931 2 Degree Standard Observer"
COLORCHECKER = "ISO 17321-1"


@dataclass(frozen=True)
class Sizes:
    """How densely the families sample: ``full`` for verify, ``quick`` for tests."""

    ramp: int
    lattice: int
    random: int
    wavelength_step: float


SIZES = {"full": Sizes(1025, 17, 4096, 1.0), "quick": Sizes(33, 4, 128, 20.0)}


def _f32(values) -> np.ndarray:
    return np.asarray(values, dtype=np.float32).astype(np.float64).reshape(-1, 3)


@dataclass(frozen=True, eq=False)
class Family:
    """A named set of probe colours, (n, 3) float64, with optional per-sample notes."""

    name: str
    values: np.ndarray
    notes: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "values", _f32(self.values))


@dataclass(frozen=True, eq=False)
class Probes:
    """The families a check feeds an engine, concatenated in order."""

    families: tuple[Family, ...]

    @cached_property
    def values(self) -> np.ndarray:
        """Every family's values, concatenated: (n, 3)."""
        return np.concatenate([f.values for f in self.families]) if self.families else np.zeros((0, 3))

    @cached_property
    def family_index(self) -> np.ndarray:
        """For each sample, the index of its family."""
        return np.repeat(np.arange(len(self.families)), [len(f.values) for f in self.families])

    @property
    def finite(self) -> np.ndarray:
        """Samples outside the non-finite family (those compared with the reference)."""
        special = np.array([f.name == NON_FINITE for f in self.families], dtype=bool)
        return ~special[self.family_index] if self.families else np.zeros(0, dtype=bool)

    def describe(self, index: int) -> str:
        """The sample at ``index``: its family, position, note and value, to the 9 digits that give
        back its float32 exactly (fewer can land a probe on a steep toe far from the one judged)."""
        family = self.families[int(self.family_index[index])]
        start = sum(len(f.values) for f in self.families[: int(self.family_index[index])])
        note = f" {family.notes[index - start]}" if family.notes else ""
        rgb = ", ".join(f"{v:.9g}" for v in self.values[index])
        return f"{family.name}[{index - start}]{note} ({rgb})"


def code_families(lo: float, hi: float, sizes: Sizes, lut: tuple[int, float] | None = None) -> list[Family]:
    """Ramps, offset lattice and random codes over [lo, hi]; for a baked curve whose
    LUT has ``lut = (nodes, shaper)``, its nodes and the midpoints between them."""
    ramp = np.linspace(lo, hi, sizes.ramp)
    zeros = np.zeros_like(ramp)
    ramps = [np.stack([ramp] * 3, axis=-1)] + [
        np.stack(list(np.roll([ramp, zeros, zeros], k, axis=0)), -1) for k in range(3)
    ]
    n = sizes.lattice
    axis = lo + (hi - lo) * (np.arange(n) + 0.5) / n
    lattice = np.stack(np.meshgrid(axis, axis, axis, indexing="ij"), axis=-1).reshape(-1, 3)
    rng = np.random.default_rng(SEED)
    out = [
        Family("ramp", np.concatenate(ramps)),
        Family("lattice", lattice),
        Family("random", rng.uniform(lo, hi, (sizes.random, 3))),
    ]
    if lut is not None:
        nodes, shaper = lut
        u = np.arange(2 * nodes - 1) / (2.0 * (nodes - 1))
        out.append(Family("LUT nodes and midpoints", np.repeat((lo + (hi - lo) * u**shaper)[:, None], 3, axis=1)))
    return out


def colorchecker(spec: Spec, illuminant: str) -> Family:
    """The ColorChecker's 24 patches lit by ``illuminant`` ("D65" or "A"), XYZ relative to the
    illuminant (Y = 1 for a perfect white), taken as XYZ-D65 into the scene reference."""
    import colour  # seconds to import: only when scene families are made, not when convert starts

    cmfs = colour.MSDS_CMFS[OBSERVER]
    light = colour.SDS_ILLUMINANTS[illuminant]
    patches = colour.SDS_COLOURCHECKERS[COLORCHECKER]
    xyz = np.array([colour.sd_to_XYZ(sd, cmfs, light, method="Integration") for sd in patches.values()]) / 100.0
    to_ref = np.linalg.inv(reference.scene_to_display_reference(spec))
    return Family(f"ColorChecker {illuminant}", apply_matrix(to_ref, xyz), tuple(patches))


def monochromatic(spec: Spec, step: float) -> Family:
    """Monochromatic light of unit radiance every ``step`` nm from 380 to 780 nm (Y = ȳ(λ))."""
    import colour

    wavelengths = np.arange(380.0, 780.0 + step / 2, step)
    xyz = colour.MSDS_CMFS[OBSERVER][wavelengths]
    to_ref = np.linalg.inv(reference.scene_to_display_reference(spec))
    return Family("monochromatic", apply_matrix(to_ref, xyz), tuple(f"{w:g} nm" for w in wavelengths))


def camera_gamut(spec: Spec) -> Family:
    """Primaries and secondaries, at 0.18 and 1.0, of every distinct gamut of the spec's spaces."""
    corners = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 1, 1], [1, 0, 1], [1, 1, 0]], dtype=np.float64)
    labels = ("red", "green", "blue", "cyan", "magenta", "yellow")
    gamuts = {s.gamut.name: s.gamut for s in spec.colour_spaces if s.gamut is not None}
    values, notes = [], []
    for name, gamut in gamuts.items():
        matrix = reference.gamut_matrix(spec, gamut)
        for level in (0.18, 1.0):
            values.append(apply_matrix(matrix, corners * level))
            notes += [f"{name} {label} x{level:g}" for label in labels]
    return Family("camera gamut", np.concatenate(values), tuple(notes))


def display_faces(spec: Spec, count: int) -> Family:
    """Colours on the faces of each display's light cube, ``count`` a display: one channel
    exactly 0 (where a power law's toe is steepest and float32 rounding shows most) or exactly
    the peak (where clipping starts), the others random within [0, peak]."""
    rng = np.random.default_rng(SEED + 2)
    values, notes = [], []
    for display in spec.displays:
        light = rng.random((count, 3)) * display.clip_high
        row, channel = np.arange(count), rng.integers(0, 3, count)
        light[row, channel] = np.where(row % 2 == 0, 0.0, display.clip_high)
        values.append(apply_matrix(np.linalg.inv(reference.scene_to_display_matrix(spec, display)), light))
        notes += [f"{display.name} {'RGB'[c]} = {'0' if r % 2 == 0 else 'peak'}" for r, c in zip(row, channel)]
    return Family("display faces", np.concatenate(values) if values else np.zeros((0, 3)), tuple(notes))


def negatives(count: int) -> Family:
    """Negative scene colours: a quarter all negative, the rest mixed (seeded)."""
    rng = np.random.default_rng(SEED + 1)
    all_negative = rng.uniform(-0.5, 0.0, (count // 4, 3))
    mixed = rng.uniform(-0.5, 1.0, (count - count // 4, 3))
    return Family("negative", np.concatenate([all_negative, mixed]))


def near_black(count: int) -> Family:
    """Render noise around black: channels of either sign, 1e-12 to 1e-5 in size (a few
    float32 or half-float steps from 0, where a table over half floats reads the entries
    of +0, -0 and the smallest subnormals), and -0 itself."""
    rng = np.random.default_rng(SEED + 3)
    sign = rng.choice([-1.0, 1.0], (count, 3))
    noise = sign * rng.random((count, 3)) * 10.0 ** rng.uniform(-12.0, -5.0, (count, 1))
    return Family("near black", np.concatenate([noise, [[-0.0, -0.0, -0.0], [0.0, 0.0, -0.0]]]))


def over_range(checker: Family) -> Family:
    """Neutrals from 1 to half-float max, and the ColorChecker scaled by 2**4, 2**8, 2**12."""
    neutral = np.repeat(np.geomspace(1.0, HALF_MAX, 33)[:, None], 3, axis=1)
    scaled = np.concatenate([checker.values * 2.0**k for k in (4, 8, 12)])
    return Family("over-range", np.concatenate([neutral, scaled]))


def non_finite() -> Family:
    """NaN, +Inf and -Inf in each channel beside mid grey, and in all three."""
    values, notes = [], []
    for special, label in ((np.nan, "NaN"), (np.inf, "+Inf"), (-np.inf, "-Inf")):
        for channel in range(3):
            rgb = np.full(3, 0.18)
            rgb[channel] = special
            values.append(rgb)
            notes.append(f"{label} in channel {channel}")
        values.append(np.full(3, special))
        notes.append(f"{label} in every channel")
    return Family(NON_FINITE, np.array(values), tuple(notes))


def scene_families(spec: Spec, sizes: Sizes) -> tuple[Family, ...]:
    """The scene-referred families, in the scene reference (non-finite last)."""
    checker = colorchecker(spec, "D65")
    return (
        checker,
        colorchecker(spec, "A"),
        monochromatic(spec, sizes.wavelength_step),
        camera_gamut(spec),
        display_faces(spec, max(8, sizes.random // 16)),
        negatives(max(16, sizes.random // 16)),
        near_black(max(16, sizes.random // 16)),
        over_range(checker),
        non_finite(),
    )
