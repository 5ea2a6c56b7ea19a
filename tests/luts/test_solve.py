"""The numpy least squares behind a .cube's fitted nodes (generator/luts/solve.py)."""

from __future__ import annotations

import numpy as np

from generator.luts import fit as fitting
from generator.luts import solve

RNG_SEED = 7


def _problem(size: int, count: int, rng):
    """Random colours in a size³ unit lattice: node numbers and weights (4, m), codes (3, m)."""
    nodes, weights = fitting.tetrahedra(np.ascontiguousarray(rng.random((3, count)) * (size - 1)), size)
    return nodes, weights, rng.random((3, count))


def _dense(nodes, weights, size):
    """The interpolation matrix, m by size³."""
    matrix = np.zeros((nodes.shape[1], size**3))
    for corner in range(nodes.shape[0]):
        np.add.at(matrix, (np.arange(nodes.shape[1]), nodes[corner]), weights[corner])
    return matrix


def test_interpolate_and_accumulate_are_the_matrix_and_its_transpose():
    rng = np.random.default_rng(RNG_SEED)
    nodes, weights, rows = _problem(4, 200, rng)
    matrix = _dense(nodes, weights, 4)
    values = rng.random((3, 64))
    assert np.allclose(solve.interpolate(nodes, weights, values), values @ matrix.T, rtol=0, atol=1e-12)
    assert np.allclose(solve.accumulate(nodes, weights, rows, 64), rows @ matrix, rtol=0, atol=1e-12)


def test_conjugate_gradient_solves_each_system_to_its_own_tolerance():
    rng = np.random.default_rng(RNG_SEED)
    basis = rng.random((30, 30))
    system = basis @ basis.T + np.eye(30)
    exact = rng.random((2, 30))
    right = exact @ system
    tolerance = np.array([1e-10, np.inf]) * np.linalg.norm(right, axis=1)  # the second stops at once
    start = np.zeros_like(right)
    solved = solve.conjugate_gradient(lambda v: v @ system, right, start, np.diag(system).copy(), tolerance, 500)
    assert np.linalg.norm(solved[0] @ system - right[0]) < tolerance[0]
    assert np.array_equal(solved[1], start[1])


def test_bands_are_the_normal_matrix():
    """The banded normal matrix applies A^T A, extrapolating rows (fractions beyond the cell) included."""
    rng = np.random.default_rng(RNG_SEED)
    for size in (2, 3, 5):
        index = rng.uniform(-0.3, size - 0.7, (3, 300))
        nodes, weights = fitting.tetrahedra(np.ascontiguousarray(index), size)
        matrix = _dense(nodes, weights, size)
        values = rng.random((3, size**3))
        banded = solve.banded(solve.bands(nodes, weights, size), size, values)
        assert np.allclose(banded, values @ (matrix.T @ matrix), rtol=0, atol=1e-10), size
