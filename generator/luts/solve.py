"""Sparse least squares of tetrahedral interpolation, in numpy alone.

An interpolation matrix ``A`` has one row per colour and four non-zeros per
row: the node numbers ``nodes`` and ``weights`` of the colour's tetrahedron,
each of shape (4, m) (corner-major: gathering and summing one corner at a
time keeps memory access sequential). It is never formed: :func:`interpolate`
computes ``A v`` by gathering, :func:`accumulate` computes ``A^T r`` by
summing into the nodes. The normal matrix ``A^T A`` of a lattice's colours is
banded (:func:`bands`): the corners of a tetrahedron differ by one of seven
offsets, so it is held as eight bands and :func:`banded` applies it in a
small fraction of the time ``A`` takes. :func:`conjugate_gradient` solves the
normal equations for several right-hand sides at once (the three channels, one
per row of a (c, k) array), each on its own.
"""

from __future__ import annotations

import numpy as np


def interpolate(nodes: np.ndarray, weights: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``A v`` per channel: node ``values`` (c, k) interpolated at each row, shape (c, m). A
    channel not contiguous (a transposed table's) is copied once here: numpy's take copies it
    whole at every gather otherwise."""
    values = np.ascontiguousarray(values)
    out = np.empty((values.shape[0], nodes.shape[1]))
    for row, channel in zip(out, values):
        np.multiply(weights[0], np.take(channel, nodes[0]), out=row)
        for corner in range(1, nodes.shape[0]):
            row += weights[corner] * np.take(channel, nodes[corner])
    return out


def accumulate(nodes: np.ndarray, weights: np.ndarray, rows: np.ndarray, size: int) -> np.ndarray:
    """``A^T r`` per channel: per-row values ``rows`` (c, m) summed into ``size`` nodes, shape (c, size)."""
    flat = nodes.ravel()
    return np.stack([np.bincount(flat, weights=(weights * row).ravel(), minlength=size) for row in rows])


def offsets(size: int) -> np.ndarray:
    """The node-number differences of two corners of a tetrahedron in a size³ lattice, 0 first:
    the steps along one, two or three axes ([r, g, b] order, b fastest)."""
    return np.array([r * size * size + g * size + b for r in (0, 1) for g in (0, 1) for b in (0, 1)])


def band_keys(nodes: np.ndarray, size: int) -> np.ndarray:
    """Where each product of two corners of a row lands in :func:`bands`' flat array, per pair of
    corners (6, m): the same for every weighting of the rows, so a fit's passes compute it once."""
    steps = offsets(size)
    band = np.zeros(steps[-1] + 1, dtype=np.intp)  # band of each difference (a lookup, not a search)
    band[steps] = np.arange(steps.size)
    keys = np.empty((len(_PAIRS), nodes.shape[1]), dtype=np.intp)
    for row, (a, b) in enumerate(_PAIRS):
        np.take(band, nodes[b] - nodes[a], out=keys[row])
        keys[row] += nodes[a] * steps.size
    return keys


#: The pairs of a tetrahedron's four corners.
_PAIRS = [(a, b) for a in range(4) for b in range(a + 1, 4)]


def bands(nodes: np.ndarray, weights: np.ndarray, size: int, keys: np.ndarray | None = None) -> np.ndarray:
    """``A^T A`` of the rows ``nodes``, ``weights`` (4, m; node numbers ascending along each
    tetrahedron's corners, as :func:`generator.luts.fit.tetrahedra` gives them) in a size³
    lattice: band ``k`` (8, size³) holds the entries ``[i, i + offsets(size)[k]]``. ``keys``:
    the rows' :func:`band_keys`, computed here if not given."""
    keys = band_keys(nodes, size) if keys is None else keys
    values = np.empty(keys.shape)
    for row, (a, b) in enumerate(_PAIRS):
        np.multiply(weights[a], weights[b], out=values[row])
    count = offsets(size).size
    flat = np.bincount(keys.ravel(), weights=values.ravel(), minlength=count * size**3)
    out = np.ascontiguousarray(flat.reshape(size**3, count).T)
    out[0] = np.bincount(nodes.ravel(), weights=(weights * weights).ravel(), minlength=size**3)
    return out


def banded(matrix: np.ndarray, size: int, values: np.ndarray) -> np.ndarray:
    """The symmetric matrix of :func:`bands` ``matrix`` applied to node ``values`` (c, size³)."""
    out = matrix[0] * values
    for band, step in zip(matrix[1:], offsets(size)[1:]):
        upper = band[:-step]
        out[:, :-step] += upper * values[:, step:]
        out[:, step:] += upper * values[:, :-step]
    return out


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.einsum("ck,ck->c", a, b)


def conjugate_gradient(
    matvec, right: np.ndarray, start: np.ndarray, diagonal: np.ndarray, tolerance: np.ndarray, maxiter: int
) -> np.ndarray:
    """Jacobi-preconditioned conjugate gradients for ``M x = right``: ``M`` symmetric
    positive definite, applied to (c, k) arrays by ``matvec``, with main diagonal
    ``diagonal`` (k,); one system per row of ``right`` (c, k), from ``start``.
    A system stops once its residual's norm falls below its ``tolerance`` (c,),
    or after ``maxiter`` steps."""
    x = np.array(start, dtype=np.float64)
    residual = right - matvec(x)
    inverse = 1.0 / diagonal
    direction = np.zeros_like(x)
    rho_previous = np.ones(x.shape[0])
    for _ in range(maxiter):
        norm = np.sqrt(_dot(residual, residual))
        active = (norm >= tolerance) & (norm > 0.0)
        if not active.any():
            break
        z = residual * inverse
        rho = _dot(residual, z)
        beta = np.where(active, rho / np.where(active, rho_previous, 1.0), 0.0)
        direction = z + direction * beta[:, None]
        product = matvec(direction)
        alpha = np.where(active, rho / np.where(active, _dot(direction, product), 1.0), 0.0)
        x += alpha[:, None] * direction
        residual -= alpha[:, None] * product
        rho_previous = np.where(active, rho, rho_previous)
    return x
