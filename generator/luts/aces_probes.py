"""Colours for fitting and measuring a baked ACES view: the six kinds of issue 21.

Each set is ACES2065-1 (n, 3), drawn from a seed so the same call gives the same colours:

* ``in_gamut``: the display's linear RGB uniform in [0, 1] (scene light at up to 100 cd/m²
  white, the display's primaries), taken to ACES2065-1 through CIE XYZ;
* ``ap0``: ACES2065-1 uniform in [0, 1];
* ``dark`` and ``bright``: hues (uniform RGB over its largest channel) scaled by 1e-4 to 0.1,
  and by 1 to 64, log-uniform;
* ``greys``: greys from 1e-4 to 100, log-uniform (fixed, not drawn);
* ``camera``: ARRI Wide Gamut 4 colours with a zero channel (its saturated edges) scaled by
  0.01 to 10, log-uniform: most lie outside AP1, whose faces the view clamps them to.

bench/aces_views.py draws the same kinds (seed 11, 20000 a set); the bake fits its node values
to colours from another seed (:data:`TRAINING_SEED`).
"""

from __future__ import annotations

import numpy as np

from generator import reference
from generator.colorimetry.gamuts import gamuts
from generator.luts.probes import held
from generator.spec.schema import ColourSpace, Display, Spec

SETS = ("in_gamut", "ap0", "dark", "bright", "greys", "camera")

#: What each set is called in tables.
LABELS = {
    "in_gamut": "in gamut",
    "ap0": "AP0 0..1",
    "dark": "dark",
    "bright": "bright",
    "greys": "greys",
    "camera": "camera",
}

#: Seed of the colours a bake fits its lattice to; :data:`PROBE_SEED` draws the ones it is measured on.
TRAINING_SEED, PROBE_SEED = 20250211, 20250212

#: Colours per set in the measurements of the pack and the tests.
PROBE_COUNT = 8192

#: Greys per decade of :func:`sets`' grey ramp (1e-4 to 100: 2001 greys at the default, bench/aces_views.py's).
GREYS_PER_DECADE = 1000 / 3


def _to_ap0(name: str) -> np.ndarray:
    ap0 = gamuts()["AP0"]
    return np.linalg.inv(ap0.rgb_to_xyz) @ gamuts()[name].rgb_to_xyz


def sets(display: Display, seed: int, count: int) -> dict[str, np.ndarray]:
    """The six sets of ``count`` ACES2065-1 colours each (the greys: a fixed ramp)."""
    return sets_in(display.gamut.rgb_to_xyz, seed, count)


def sets_in(rgb_to_xyz: np.ndarray, seed: int, count: int) -> dict[str, np.ndarray]:
    """:func:`sets`, the in-gamut colours those of the gamut whose RGB to CIE XYZ matrix is ``rgb_to_xyz``."""
    rng = np.random.default_rng(seed)
    ap0 = gamuts()["AP0"]
    hue = rng.random((count, 3))
    hue /= hue.max(axis=1, keepdims=True)
    edge = rng.random((count, 3))
    edge[np.arange(count), rng.integers(0, 3, count)] = 0.0
    edge /= edge.max(axis=1, keepdims=True)
    in_gamut = rng.random((count, 3)) @ (np.linalg.inv(ap0.rgb_to_xyz) @ rgb_to_xyz).T
    return {
        "in_gamut": in_gamut,
        "ap0": rng.random((count, 3)),
        "dark": hue * 10 ** rng.uniform(-4, -1, (count, 1)),
        "bright": hue * 10 ** rng.uniform(0, np.log10(64), (count, 1)),
        "greys": np.repeat(10 ** np.linspace(-4, 2, round(6 * GREYS_PER_DECADE) + 1)[:, None], 3, axis=1),
        "camera": (edge * 10 ** rng.uniform(-2, 1, (count, 1))) @ _to_ap0("ARRI Wide Gamut 4").T,
    }


def view_sets(
    spec: Spec, display: Display, view: str, seed: int, count: int
) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each of :func:`sets`' sets with the view's display code values for it (the reference,
    :func:`~generator.reference.aces_view`): the same for every source, so a pack evaluates them
    once per view (:func:`held_in` takes a source's share)."""
    from_aces = np.linalg.inv(reference.to_aces_matrix(spec))
    return {
        name: (aces, reference.aces_view(spec, display, view, reference.apply_matrix(from_aces, aces)))
        for name, aces in sets(display, seed, count).items()
    }


def _source_codes(
    spec: Spec, source: ColourSpace, display: Display, aces: np.ndarray, domain: tuple[float, float] | None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Scene-reference values of ACES2065-1 colours, ``source``'s code values for them and which
    of them the source holds (:func:`~generator.luts.probes.held`) within ``domain``, if given."""
    ref = reference.apply_matrix(np.linalg.inv(reference.to_aces_matrix(spec)), aces)
    with np.errstate(all="ignore"):
        code = reference.from_reference(spec, source, ref)
        keep = held(spec, source, display, ref, code)
        if domain is not None:
            keep &= np.all((code >= domain[0]) & (code <= domain[1]), axis=-1)
    return ref, code, keep


def in_source(
    spec: Spec,
    source: ColourSpace,
    display: Display,
    view: str,
    aces: np.ndarray,
    domain: tuple[float, float] | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """ACES2065-1 colours as ``source``'s code values and the view's display code values for them
    (the reference, :func:`~generator.reference.aces_view`), keeping the colours the
    source's encoding holds (:func:`~generator.luts.probes.held`) and, given a ``domain``, whose
    codes lie in it."""
    ref, code, keep = _source_codes(spec, source, display, aces, domain)
    return code[keep], reference.aces_view(spec, display, view, ref[keep])


def held_in(
    spec: Spec,
    source: ColourSpace,
    display: Display,
    pair: tuple[np.ndarray, np.ndarray],
    domain: tuple[float, float] | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`in_source` of a set of :func:`view_sets` (its colours and their display codes)."""
    aces, expected = pair
    _, code, keep = _source_codes(spec, source, display, aces, domain)
    return code[keep], expected[keep]
