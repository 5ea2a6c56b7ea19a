"""Fitting a source-layout lattice's node values by least squares (generator/luts/fit.py)."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio

from generator import reference, tolerances
from generator.luts import bake, lattice, numbers, probes, source_axes
from generator.luts import fit as fitting

RNG_SEED = 7


def _request(spec, fmt, method="clip", size=17, source="ACEScct", display="sRGB - Display", shaper="auto"):
    return bake.request(spec, source, display, method, fmt, size, shaper)


def _write(tmp_path, req, name="lut"):
    files = bake.paths(bake.bake(req), tmp_path / f"{name}{bake.FORMATS[req.fmt].suffix}")
    bake.write(files)
    return list(files)


def _transform(paths):
    steps = [ocio.FileTransform(str(p), interpolation=ocio.INTERP_TETRAHEDRAL) for p in reversed(paths)]
    return steps[0] if len(steps) == 1 else ocio.GroupTransform(steps)


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
    kept = fitting.kept_nodes(size, 0)
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


def test_resolve_cube_keeps_greys_and_zero_channels(default_spec, tmp_path):
    """The fit leaves the diagonal and the nodes of a zero channel at their sampled values."""
    req = _request(default_spec, "resolve_cube", size=33, source="ACEScg")
    apply = probes.ocio_apply(_transform(_write(tmp_path, req)))
    rng = np.random.default_rng(3)
    grey = np.repeat(10.0 ** rng.uniform(-4, 1.2, (2000, 1)), 3, axis=1)
    expected = reference.mapped_view(
        default_spec, req.display, "clip", reference.to_reference(default_spec, req.source, grey)
    )
    assert np.abs(apply(grey) - expected).max() * 1023 <= tolerances.LUT_CUBE_GREY_CODES
    lat = bake.build_lattice(req)
    zero = source_axes.source_axis(default_spec, req.source, req.display, 33).zero
    linear = req.source.curve.decode(lattice.preimages(lat.size, lat.shaper, lat.domain))
    matrix = reference.scene_to_display_matrix(default_spec, req.display) @ reference.space_matrix(
        default_spec, req.source
    )
    sampled = lattice.node_values(req.display, "clip", linear, matrix, None)
    np.testing.assert_array_equal(lat.cube[zero], sampled[zero])
    np.testing.assert_array_equal(lat.cube[:, :, zero], sampled[:, :, zero])
    diagonal = np.arange(lat.size)
    np.testing.assert_array_equal(lat.cube[diagonal, diagonal, diagonal], sampled[diagonal, diagonal, diagonal])


def test_a_cube_from_a_display_encoded_source_is_exact_on_what_its_domain_holds(default_spec, tmp_path):
    """sRGB-encoded values through a .cube into the sRGB display (an identity in gamut): the
    fit leaves out colours beyond the file's domain (codes above 1, which the file clamps),
    which had pulled near-white nodes hundreds of codes off."""
    req = _request(default_spec, "resolve_cube", method="scale", size=33, source="sRGB Encoded Rec.709 (sRGB)")
    figures = probes.measure(
        default_spec, req.source, req.display, "scale", probes.ocio_apply(_transform(_write(tmp_path, req)))
    )
    assert max(figures[name].maximum for name in ("in_gamut", "dark")) <= tolerances.LUT_CLF_IN_GAMUT_CODES


def test_a_named_shaper_spaces_the_nodes_over_its_own_codes(default_spec):
    """--shaper ACEScct from ACEScg: the domain is the light ACEScct codes 0 to 1 hold (as
    ociobakelut's shaper space), so the table is ACEScct's code; the source's [-1, 16] range
    had put nine tenths of the nodes below 0 and mid grey 24 codes off."""
    acescct = default_spec.space("ACEScct")
    lat = bake.build_lattice(_request(default_spec, "resolve_cube", size=33, source="ACEScg", shaper="ACEScct"))
    np.testing.assert_allclose(lat.domain, acescct.curve.decode(np.array([0.0, 1.0])), rtol=1e-12)
    linear = np.linspace(*lat.domain, lat.shaper.size)
    np.testing.assert_allclose(lat.shaper, acescct.curve.encode(linear), rtol=0, atol=10.0**-lattice.SHAPER_DECIMALS)


def test_the_fit_leaves_out_colours_beyond_the_files_domain():
    """A colour with a channel outside the domain is clamped by a reader: it is not fitted."""
    code = np.array([[0.0, 0.5, 1.0], [0.2, 1.0000001, 0.3], [-1e-9, 0.5, 0.5], [0.25, 0.5, 0.75]])
    expected = np.arange(12.0).reshape(4, 3)
    held = fitting._held({"in_gamut": (code, expected)}, (0.0, 1.0))
    np.testing.assert_array_equal(held["in_gamut"][0], code[[0, 3]])
    np.testing.assert_array_equal(held["in_gamut"][1], expected[[0, 3]])


def test_without_a_shaper_the_greys_are_the_published_curves_through_the_mapping(default_spec):
    """ACEScct to sRGB with scale, no shaper: the cube spans the source's domain uniformly, and
    its greys (kept at their sampled values) are ACEScct decoded (S-2016-001) clipped to the
    peak and encoded by the display's curve, CLF's monCurveRev of 2.4 and 0.055 (S-2014-006),
    as colour-science has them."""
    import colour

    source, display = default_spec.space("ACEScct"), default_spec.displays[0]
    lat = fitting.source_lattice(default_spec, source, display, "scale", 9, "none")
    assert lat.shaper is None and lat.domain == source_axes.source_domain(source, display)
    code = np.linspace(*lat.domain, 9)
    light = np.clip(colour.models.log_decoding_ACEScct(code), 0.0, 1.0)
    expected = colour.models.exponent_function_monitor_curve(light, 2.4, 0.055, style="monCurveRev")
    diagonal = lat.cube[np.arange(9), np.arange(9), np.arange(9)]
    np.testing.assert_allclose(diagonal, np.repeat(expected[:, None], 3, axis=1), rtol=0, atol=1e-5)
    off = lat.cube.copy()
    off[np.arange(9), np.arange(9), np.arange(9)] = np.nan
    sampled = lattice.node_values(
        display,
        "scale",
        source.curve.decode(code),
        reference.scene_to_display_matrix(default_spec, display) @ reference.space_matrix(default_spec, source),
        None,
    )
    assert np.nanmax(np.abs(off - sampled)) > 10.0**-lattice.CUBE_DECIMALS  # the other nodes are fitted
