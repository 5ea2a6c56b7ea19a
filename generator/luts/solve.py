"""Sparse least squares of tetrahedral interpolation, in numpy alone.

An interpolation matrix ``A`` has one row per colour and four non-zeros per
row: the node numbers ``nodes`` and ``weights`` of the colour's tetrahedron,
each of shape (4, m) (corner-major: gathering and summing one corner at a
time keeps memory access sequential). It is never formed: :func:`interpolate`
computes ``A v`` by gathering, :func:`accumulate` computes ``A^T r`` by
summing into the nodes. :func:`conjugate_gradient` solves the normal
equations for several right-hand sides at once (the three channels, one per
row of a (c, k) array), each on its own.
"""

from __future__ import annotations

import numpy as np


def interpolate(nodes: np.ndarray, weights: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``A v`` per channel: node ``values`` (c, k) interpolated at each row, shape (c, m)."""
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
