"""Fitting a source-layout lattice's node values by least squares (see
:mod:`generator.luts.lattice`): tetrahedral interpolation at colours of the kinds the
probes measure, drawn from another seed, against the reference's values there, with
each node pulled toward its sampled value; then reweighted by each colour's error.
The solver is :mod:`generator.luts.solve`."""

from __future__ import annotations

import numpy as np

from generator.luts import numbers, probes, solve
from generator.luts.lattice import CUBE_DECIMALS, Lattice, coordinates

#: Colours per probe set in the least-squares fit of source-layout node values: fewer
#: overfit the sample (measured at 33³, clip, on the pairs of OCIOBAKELUT_P99, the smallest
#: ratio of ociobakelut's p99 to ours over pairs and sets: 1.96 with 16384 colours and three
#: reweighted passes, 2.24 with 32768 and one, 2.24 with 65536 and three, which bakes a 65³
#: .cube three times slower: 1.6 s against 0.56 s in-process, both with FIT_RTOL 1e-6).
FIT_COUNT = 32768

#: Weight of in-gamut colours in the fit, against 1 for the other sets: an equal weight
#: trades in-gamut accuracy for out-of-gamut accuracy (measured at 33³, clip, Linear
#: Rec.2020 to Gamma 2.6 P3, in-gamut / out-of-gamut p99 in ten-bit codes: 56.6 / 65.0 with
#: weight 1, 38.2 / 80.2 with 3, 34.3 / 84.3 with 4).
FIT_IN_GAMUT_WEIGHT = 4.0

#: Least-squares passes after the first, each weighting a colour by its error in the
#: previous one (:func:`reweighted_fit`; measured at 33³, clip, with FIT_COUNT colours, the
#: smallest ratio as there: 2.10 without, 2.24 with one, 2.24 with two).
FIT_REWEIGHTS = 1

#: Reweighting, with ``u`` a colour's error over its set's 99th percentile: weight
#: ``FLOOR + u ** 2`` up to ``u = CUTOFF``, ``TAIL`` beyond. The 99th percentile is set by
#: the colours near it, so they gain weight; those well above it, where a clipping plane
#: crosses a cell and no node values bring them under it, lose theirs (measured at 33³,
#: clip, the bench's pairs' p99 move by up to a tenth over floors 0.3 to 1, cut-offs 1.3 to
#: 2 and tails 0.05 to 0.5; a weight growing as ``u ** 2`` without a cut-off, as for an
#: L4 norm, takes ACEScg to sRGB's in-gamut p99 from 29 to 58).
FIT_REWEIGHT_FLOOR, FIT_REWEIGHT_CUTOFF, FIT_REWEIGHT_TAIL = 0.5, 1.5, 0.3

#: Pull of each node toward its sampled value, in units of one colour's weight: nodes
#: few colours reach stay where they are.
FIT_REGULARISATION = 1.0

#: Relative residual at which the conjugate-gradient solve stops (per channel): the node
#: values settle long before the residual does (measured at 33³, clip, on the pairs of
#: OCIOBAKELUT_P99, the smallest ratio of ociobakelut's p99 to ours: 2.24 at 1e-6 after 22
#: products, 2.245 at 1e-3 after 7, 2.25 at 3e-3, where PQ's dark set falls from 2.46 to
#: 2.28; a 65³ bake takes 0.53 s at 1e-6, 0.36 s at 1e-3).
FIT_RTOL = 1e-3

#: Conjugate-gradient steps at most.
FIT_MAXITER = 500


def tetrahedral_weights(index: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Flat node numbers (m, 4) and weights (m, 4) of tetrahedral interpolation at
    fractional node indices ``index`` (m, 3), ``[r, g, b]`` order."""
    base = np.clip(np.floor(index).astype(np.int64), 0, size - 2)
    fraction = index - base
    order = np.argsort(-fraction, axis=1, kind="stable")
    sorted_fraction = np.take_along_axis(fraction, order, axis=1)
    corner = base.copy()
    nodes, weights = [], []
    for k in range(4):
        if k:
            np.put_along_axis(corner, order[:, k - 1:k], np.take_along_axis(corner, order[:, k - 1:k], 1) + 1, 1)
        nodes.append((corner[:, 0] * size + corner[:, 1]) * size + corner[:, 2])
        upper = sorted_fraction[:, k - 1] if k else np.ones(len(index))
        lower = sorted_fraction[:, k] if k < 3 else np.zeros(len(index))
        weights.append(upper - lower)
    return np.stack(nodes, axis=1), np.stack(weights, axis=1)


def reweighted_fit(lat: Lattice, colours: dict, zero: int | None) -> np.ndarray:
    """:func:`fit` with each set's weight (:data:`FIT_IN_GAMUT_WEIGHT` for in-gamut
    colours, 1 for the others), then :data:`FIT_REWEIGHTS` times with every colour's
    weight scaled by its error in the probes' metric (ten-bit codes, ΔE ITP for HDR)
    relative to its set's 99th percentile (see :data:`FIT_REWEIGHT_FLOOR`)."""
    base = {name: np.full(len(code), FIT_IN_GAMUT_WEIGHT if name == "in_gamut" else 1.0)
            for name, (code, _) in colours.items()}
    corners = _corners(lat, colours)
    cube = fit(lat, colours, zero, base, corners)
    for _ in range(FIT_REWEIGHTS):
        weights = {}
        for name, (nodes, w) in corners.items():
            actual = np.einsum("mk,mkc->mc", w, cube.reshape(-1, 3)[nodes])
            error = probes.errors(lat.display, actual, np.nan_to_num(colours[name][1]))[0]
            u = error / max(float(np.percentile(error, 99)) if error.size else 1.0, 1e-12)
            scale = np.where(u > FIT_REWEIGHT_CUTOFF, FIT_REWEIGHT_TAIL, FIT_REWEIGHT_FLOOR + u**2)
            weights[name] = base[name] * scale
        cube = fit(lat, colours, zero, weights, corners)
    return cube


def _corners(lat: Lattice, colours: dict) -> dict:
    """Set name to the tetrahedral node numbers and weights (m, 4) of its colours."""
    return {name: tetrahedral_weights(coordinates(lat, code) * (lat.size - 1), lat.size)
            for name, (code, _) in colours.items()}


def _fit_rows(colours: dict, weights: dict, corners: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Node numbers (4, m), weights (4, m) and expected codes (3, m) of the fit's
    colours, each row scaled by the square root of its colour's weight."""
    nodes, rows, expected = [], [], []
    for name, (_, codes) in colours.items():
        scale = np.sqrt(weights[name])[:, None]
        corner, w = corners[name]
        nodes.append(corner)
        rows.append(w * scale)
        expected.append(np.nan_to_num(codes) * scale)
    return tuple(np.ascontiguousarray(np.concatenate(part).T) for part in (nodes, rows, expected))


def _kept(size: int, zero: int | None) -> np.ndarray:
    """Flat mask of the nodes the fit keeps: the diagonal's, and with ``zero`` those of a zero channel."""
    kept = np.zeros(size**3, dtype=bool)
    kept[np.arange(size) * (size * size + size + 1)] = True
    if zero is not None:
        grid = kept.reshape(size, size, size)
        grid[zero, :, :] = grid[:, zero, :] = grid[:, :, zero] = True
    return kept


def fit(lat: Lattice, colours: dict, zero: int | None, weights: dict, corners: dict | None = None) -> np.ndarray:
    """Node values minimising the weighted squared error of tetrahedral interpolation
    on ``colours`` (set name to (input values, expected codes); ``weights``, set name
    to a weight per colour; ``corners``, :func:`_corners` if already computed), plus
    :data:`FIT_REGULARISATION` times the squared change of each node. The
    diagonal's nodes (greys) and, with ``zero``, the nodes of a zero channel are
    kept at their sampled values; the others solve the normal equations."""
    total = lat.size**3
    nodes, weights, expected = _fit_rows(colours, weights, corners or _corners(lat, colours))
    kept = _kept(lat.size, zero)
    start = np.ascontiguousarray(lat.cube.reshape(total, 3).T)
    # A free node no colour reaches has the equation FIT_REGULARISATION * (x - start) = 0 alone:
    # it keeps its sampled value, and the unknowns are the free nodes the colours reach.
    unknown = ~kept & (np.bincount(nodes.ravel(), minlength=total) > 0)
    reached = unknown[nodes]
    columns = np.where(reached, (np.cumsum(unknown) - 1)[nodes], 0)
    free_weights = np.where(reached, weights, 0.0)
    count = int(np.count_nonzero(unknown))
    residual = expected - solve.interpolate(nodes, weights - free_weights, start)
    right = solve.accumulate(columns, free_weights, residual, count) + FIT_REGULARISATION * start[:, unknown]
    # The stopping rule is relative to the whole right-hand side, unreached free nodes included.
    rest = FIT_REGULARISATION**2 * (start**2 @ (~kept & ~unknown).astype(np.float64))
    whole = np.sqrt(np.einsum("ck,ck->c", right, right) + rest)
    diagonal = np.bincount(columns.ravel(), weights=(free_weights**2).ravel(), minlength=count) + FIT_REGULARISATION

    def normal(v):
        return solve.accumulate(columns, free_weights, solve.interpolate(columns, free_weights, v), count) + \
            FIT_REGULARISATION * v

    values = start.copy()
    values[:, unknown] = solve.conjugate_gradient(normal, right, start[:, unknown], diagonal, FIT_RTOL * whole,
                                                  FIT_MAXITER)
    return numbers.rounded(values.T.reshape(lat.cube.shape), CUBE_DECIMALS)
