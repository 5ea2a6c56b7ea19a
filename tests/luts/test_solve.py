"""The numpy least squares behind a .cube's fitted nodes, and the text of LUT tables."""

from __future__ import annotations

import numpy as np

from generator.luts import fit as fitting
from generator.luts import lattice, numbers, solve

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


def test_tetrahedra_step_along_the_axes_by_decreasing_fraction_equal_ones_in_axis_order():
    """Every corner path of a cell, ties included (fractions on a coarse grid): the corners are
    the cell's first corner plus unit steps taken largest fraction first, the weights the
    differences of the sorted fractions, and they interpolate a linear function exactly."""
    size, rng = 5, np.random.default_rng(RNG_SEED)
    index = rng.integers(0, size - 1, (2000, 3)) + rng.integers(0, 4, (2000, 3)) / 4.0
    index[::7] = size - 1  # the last node: the cell below it
    nodes, weights = (a.T for a in fitting.tetrahedra(np.ascontiguousarray(index.T), size))
    base = np.clip(np.floor(index), 0, size - 2).astype(np.int64)
    fraction = index - base
    order = np.argsort(-fraction, axis=1, kind="stable")
    steps = np.zeros((len(index), 4, 3), dtype=np.int64)
    for k in range(1, 4):
        steps[:, k] = steps[:, k - 1]
        steps[np.arange(len(index)), k, order[:, k - 1]] += 1
    corners = base[:, None, :] + steps
    assert np.array_equal(nodes, (corners[..., 0] * size + corners[..., 1]) * size + corners[..., 2])
    ordered = np.concatenate([np.ones((len(index), 1)), -np.sort(-fraction, axis=1), np.zeros((len(index), 1))], 1)
    assert np.array_equal(weights, ordered[:, :-1] - ordered[:, 1:])
    linear = np.arange(size**3).reshape(size, size, size).astype(np.float64)  # r * size² + g * size + b
    assert np.allclose((weights * linear.ravel()[nodes]).sum(axis=1), index @ [size * size, size, 1.0])


def test_the_percentile_of_the_reweighting_is_numpys():
    rng = np.random.default_rng(RNG_SEED)
    for size in (1, 2, 99, 100, 101, 4097):
        values = rng.random(size) * 50.0
        values[::3] = np.round(values[::3])  # ties
        assert fitting._percentile_99(values.copy()) == float(np.percentile(values, 99)), size


def test_coordinates_interpolate_the_shaper_table_uniform_over_the_domain():
    rng = np.random.default_rng(RNG_SEED)
    shaper = np.concatenate([[0.0, 0.0], np.sort(rng.random(60)), [1.0, 1.0]])  # flat runs at both ends
    lat = lattice.Lattice(None, None, "clip", None, None, None, (-0.5, 3.0), shaper, np.zeros((2, 2, 2, 3)))
    code = np.concatenate([rng.uniform(-2.0, 5.0, 5000), np.linspace(-0.5, 3.0, shaper.size), [np.nan]])
    expected = np.interp(np.clip(code, -0.5, 3.0), np.linspace(-0.5, 3.0, shaper.size), shaper)
    got = lattice.coordinates(lat, code)
    assert np.allclose(got, expected, rtol=0, atol=1e-15, equal_nan=True)
    assert np.isnan(got[-1])


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


def test_fit_is_the_regularised_least_squares_solution_with_kept_nodes(monkeypatch):
    """Solved to a tight tolerance, the fit is the exact solution (to the written decimals);
    at FIT_RTOL, the normal equations' residual is within the documented stopping rule."""
    size, rng = 4, np.random.default_rng(RNG_SEED)
    cube = rng.random((size, size, size, 3))
    lat = lattice.Lattice(None, None, "clip", None, None, None, (0.0, 1.0), None, cube)
    colours = {name: (rng.random((150, 3)), rng.random((150, 3))) for name in ("in_gamut", "out_of_gamut")}
    colour_weights = {name: rng.uniform(0.3, 4.0, 150) for name in colours}
    loose, rtol = fitting.fit(lat, colours, 0, colour_weights).reshape(-1, 3), fitting.FIT_RTOL
    monkeypatch.setattr(fitting, "FIT_RTOL", 1e-12)
    fitted = fitting.fit(lat, colours, 0, colour_weights).reshape(-1, 3)
    matrix, expected = [], []
    for name, (code, codes) in colours.items():
        scale = np.sqrt(colour_weights[name])[:, None]
        nodes, weights = fitting.tetrahedra(np.ascontiguousarray(code.T * (size - 1)), size)
        matrix.append(_dense(nodes, weights, size) * scale)
        expected.append(codes * scale)
    matrix, expected = np.concatenate(matrix), np.concatenate(expected)
    start = cube.reshape(-1, 3)
    kept = fitting._kept(size, 0)
    free = matrix[:, ~kept]
    normal = free.T @ free + fitting.FIT_REGULARISATION * np.eye(free.shape[1])
    right = free.T @ (expected - matrix[:, kept] @ start[kept]) + fitting.FIT_REGULARISATION * start[~kept]
    exact = start.copy()
    exact[~kept] = np.linalg.solve(normal, right)
    assert np.array_equal(fitted[kept], numbers.rounded(start[kept], lattice.CUBE_DECIMALS))
    step = 10.0**-lattice.CUBE_DECIMALS  # rounding as written, and the solver's stopping point within it
    assert np.abs(fitted - exact).max() <= step
    residual = normal @ loose[~kept] - right  # the written values: rounding adds up to half a step per node
    rounding = np.abs(normal).sum(axis=1)[:, None] * step / 2
    allowed = rtol * np.linalg.norm(right, axis=0) + np.linalg.norm(rounding, axis=0)
    assert np.all(np.linalg.norm(residual, axis=0) <= allowed)
    assert np.abs(loose - exact).max() > step  # the loose stop is not the exact solution here


def _reference_text(value: float, decimals: int) -> str:
    q = round(value * 10**decimals)
    text = f"{abs(q) / 10**decimals:.{decimals}f}".rstrip("0").rstrip(".")
    return ("-" if q < 0 else "") + text


def test_table_text_drops_trailing_zeros_and_spans_blocks():
    rng = np.random.default_rng(RNG_SEED)
    rows = numbers.TABLE_BLOCK + 300
    values = rng.uniform(-9.99, 9.99, (rows, 3))
    values[::7] = np.round(values[::7], 2)
    values[::11, 0] = 0.0
    values[::13, 1] = -1e-9  # rounds to zero: written without a sign
    values[::17, 2] = 1.0
    for decimals in (5, 6, 7):
        lines = numbers.table(values, decimals).decode("ascii").splitlines()
        assert len(lines) == rows
        rounded = numbers.rounded(values, decimals)
        assert lines == [" ".join(_reference_text(v, decimals) for v in row) for row in rounded]
