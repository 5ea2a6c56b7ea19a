"""Fitting a source-layout lattice's node values by least squares (see
:mod:`generator.luts.lattice`): tetrahedral interpolation at colours of the kinds the
probes measure, drawn from another seed, against the reference's values there, with
each node pulled toward its sampled value; then reweighted by each colour's error.
The solver is :mod:`generator.luts.solve`. :func:`source_lattice` lays out and fits the
lattice of a format that holds no matrix (.cube, .spi3d)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator import reference
from generator.colorimetry.transfer import Linear
from generator.luts import numbers, probes, solve
from generator.luts.lattice import CUBE_DECIMALS, SHAPER_DECIMALS, Lattice, coordinates, node_values, preimages
from generator.luts.source_axes import SOURCE_SHAPER_SIZES, shaper_domain, source_axis, source_domain
from generator.spec.schema import ColourSpace, Display, Spec

#: Colours per probe set in the least-squares fit of source-layout node values: fewer overfit
#: the sample, more bake slower for no gain (docs/luts.md gives the figures).
FIT_COUNT = 32768

#: Weight of in-gamut colours in the fit, against 1 for the other sets: an equal weight trades
#: in-gamut accuracy for out-of-gamut accuracy (in-gamut p99 56.6 codes at 1, 34.3 at 4).
FIT_IN_GAMUT_WEIGHT = 4.0

#: Least-squares passes after the first, each weighting a colour by its error in the previous one
#: (:func:`reweighted_fit`): one gains what two do.
FIT_REWEIGHTS = 1

#: Reweighting, with ``u`` a colour's error over its set's 99th percentile: weight ``FLOOR + u ** 2``
#: up to ``u = CUTOFF``, ``TAIL`` beyond, so colours near the percentile gain weight and those
#: no node values can bring under it lose theirs.
FIT_REWEIGHT_FLOOR, FIT_REWEIGHT_CUTOFF, FIT_REWEIGHT_TAIL = 0.5, 1.5, 0.3

#: Pull of each node toward its sampled value, in units of one colour's weight: nodes
#: few colours reach stay where they are.
FIT_REGULARISATION = 1.0

#: Relative residual at which the conjugate-gradient solve stops (per channel): the node values
#: settle long before the residual does, so 1e-3 fits as well as 1e-6 in a third of the products.
FIT_RTOL = 1e-3

#: Conjugate-gradient steps at most.
FIT_MAXITER = 500


def tetrahedra(index: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Flat node numbers and weights (4, m) of tetrahedral interpolation at fractional node
    indices ``index`` (3, m), ``[r, g, b]`` order, axis- and corner-major. The path from the cell's first corner steps along the axes by decreasing
    fraction (equal fractions in axis order); elementwise over the three axes (reductions
    along an axis of three are slow in numpy, see :func:`~generator.colorimetry.matrices.channel_max`)."""
    base = np.floor(index).astype(np.int64)
    np.clip(base, 0, size - 2, out=base)
    r, g, b = index - base
    nodes, weights = np.empty((4, *r.shape), dtype=np.int64), np.empty((4, *r.shape))  # filled in place
    upper, lower = np.maximum(r, g), np.minimum(r, g)
    high, low = np.maximum(upper, b), np.minimum(lower, b)
    middle = np.maximum(lower, np.minimum(upper, b))
    np.subtract(1.0, high, out=weights[0])
    np.subtract(high, middle, out=weights[1])
    np.subtract(middle, low, out=weights[2])
    weights[3] = low
    first = np.where(r == high, size * size, np.where(g == high, size, 1))  # the first of equal largest
    last = np.where(b == low, 1, np.where(g == low, size, size * size))  # the last of equal smallest
    origin = nodes[0]
    np.multiply(base[0], size, out=origin)
    origin += base[1]
    origin *= size
    origin += base[2]
    np.add(origin, first, out=nodes[1])
    np.add(origin, size * size + size + 1, out=nodes[3])
    np.subtract(nodes[3], last, out=nodes[2])
    return nodes, weights


@dataclass(frozen=True, eq=False)
class _System:
    """The fit's colours in the corner-major layout of :mod:`generator.luts.solve`, with
    what every pass shares: ``nodes`` and tetrahedral ``weights`` (4, m), ``expected``
    codes (3, m), each set's rows (``sets``, name to slice), the ``unknown`` nodes (flat
    mask), their numbering ``columns`` (4, m; 0 where the node is kept), ``free``, the
    weights on unknown nodes, the rows with a kept node (``touching``, their numbers, and
    ``kept``, their weights on kept nodes: every other row's are 0), ``rest``, per
    channel, the squared right-hand side of the free nodes no colour reaches (the
    regularisation times their sampled values: the same whatever the colours' weights),
    and ``keys``, the rows' :func:`~generator.luts.solve.band_keys` where the solve forms
    ``A^T A`` (at least as many rows as nodes), else None."""

    nodes: np.ndarray
    weights: np.ndarray
    expected: np.ndarray
    sets: dict
    unknown: np.ndarray
    columns: np.ndarray
    free: np.ndarray
    touching: np.ndarray
    kept: np.ndarray
    rest: np.ndarray
    keys: np.ndarray | None


def _system(lat: Lattice, colours: dict, zero: int | None) -> _System:
    """The fit's rows of ``colours`` (set name to (input values, expected codes)) in ``lat``'s
    source layout: :func:`_node_system` with the nodes :func:`_kept` keeps."""
    index = {
        name: coordinates(lat, np.ascontiguousarray(code.T)).T * (lat.size - 1) for name, (code, _) in colours.items()
    }
    return system_at(
        lat.cube, {name: (index[name], expected) for name, (_, expected) in colours.items()}, kept_nodes(lat.size, zero)
    )


def system_at(cube: np.ndarray, colours: dict, kept: np.ndarray) -> _System:
    """The fit's rows of ``colours`` (set name to (fractional node indices (m, 3), expected
    values)) on ``cube`` (n, n, n, 3): the unknowns are the nodes neither ``kept`` (flat mask)
    nor unreached by every colour."""
    size = cube.shape[0]
    index = np.concatenate([index for index, _ in colours.values()]).T
    nodes, weights = tetrahedra(np.ascontiguousarray(index), size)
    expected = np.ascontiguousarray(np.concatenate([np.nan_to_num(codes) for _, codes in colours.values()]).T)
    ends = np.cumsum([0, *(len(index) for index, _ in colours.values())])
    sets = {name: slice(a, b) for name, a, b in zip(colours, ends[:-1], ends[1:])}
    # A free node no colour reaches has the equation FIT_REGULARISATION * (x - start) = 0 alone:
    # it keeps its sampled value, and the unknowns are the free nodes the colours reach.
    free = ~kept
    unknown = free & (np.bincount(nodes.ravel(), minlength=size**3) > 0)
    reached = unknown[nodes]
    columns = np.where(reached, (np.cumsum(unknown) - 1)[nodes], 0)
    touching = np.flatnonzero(~reached.all(axis=0))
    start = np.ascontiguousarray(cube.reshape(-1, 3).T)
    rest = FIT_REGULARISATION**2 * (start**2 @ (free & ~unknown).astype(np.float64))
    return _System(
        nodes,
        weights,
        expected,
        sets,
        unknown,
        columns,
        weights * reached,
        touching,
        weights[:, touching] * ~reached[:, touching],
        rest,
        # A^T A's bands cost a pass over the nodes a product, A itself a pass over the colours
        solve.band_keys(nodes, size) if nodes.shape[1] >= size**3 else None,
    )


def reweighted_fit(lat: Lattice, colours: dict, zero: int | None, rtol: float | None = None) -> np.ndarray:
    """:func:`fit` with each set's weight (:data:`FIT_IN_GAMUT_WEIGHT` for in-gamut
    colours, 1 for the others), then :data:`FIT_REWEIGHTS` times with every colour's
    weight scaled by its error in the probes' metric (ten-bit codes, ΔE ITP for HDR)
    relative to its set's 99th percentile (see :data:`FIT_REWEIGHT_FLOOR`); ``rtol`` as
    :func:`fit`'s."""
    return reweighted_nodes(
        lat.cube, _system(lat, colours, zero), lambda a, e: probes.errors(lat.display, a, e)[0], rtol
    )


def reweighted_nodes(
    cube: np.ndarray, system: _System, error, rtol: float | None = None, decimals: int | None = CUBE_DECIMALS
) -> np.ndarray:
    """:func:`reweighted_fit` of ``cube``'s node values on a built ``system``, ``error``
    giving per-colour errors (m,) of actual against expected values (m, 3); the values are
    rounded to ``decimals`` (None: not rounded)."""
    base = {
        name: np.full(rows.stop - rows.start, FIT_IN_GAMUT_WEIGHT if name == "in_gamut" else 1.0)
        for name, rows in system.sets.items()
    }
    fitted = _solved(cube, base, system, rtol, decimals)
    for _ in range(FIT_REWEIGHTS):
        actual = solve.interpolate(system.nodes, system.weights, np.ascontiguousarray(fitted.reshape(-1, 3).T))
        weights = {}
        for name, rows in system.sets.items():
            error_ = error(actual[:, rows].T, system.expected[:, rows].T)
            # beyond the cut-off a colour's weight is the tail's whatever u is; capped, u**2 cannot overflow
            u = np.minimum(error_ / max(_percentile_99(error_) if error_.size else 1.0, 1e-12), 2 * FIT_REWEIGHT_CUTOFF)
            scale = np.where(u > FIT_REWEIGHT_CUTOFF, FIT_REWEIGHT_TAIL, FIT_REWEIGHT_FLOOR + u**2)
            weights[name] = base[name] * scale
        fitted = _solved(cube, weights, system, rtol, decimals)
    return fitted


def _percentile_99(values: np.ndarray) -> float:
    """``np.percentile(values, 99)`` (its linear method, the same arithmetic) of a non-empty
    1D array, by one partition: np.percentile imports numpy.ma on first use, a tenth of
    the start-up of numpy itself."""
    index = (values.size - 1) * 0.99
    low = int(index)
    if low >= values.size - 1:
        return float(values.max())
    a, b = np.partition(values, (low, low + 1))[low : low + 2]
    t, diff = index - low, b - a
    return float(b - diff * (1 - t) if t >= 0.5 else a + diff * t)


def kept_nodes(size: int, zero: int | None) -> np.ndarray:
    """Flat mask of the nodes the fit keeps: the diagonal's, and with ``zero`` those of a zero channel."""
    kept = np.zeros(size**3, dtype=bool)
    kept[np.arange(size) * (size * size + size + 1)] = True
    if zero is not None:
        grid = kept.reshape(size, size, size)
        grid[zero, :, :] = grid[:, zero, :] = grid[:, :, zero] = True
    return kept


def fit(
    lat: Lattice,
    colours: dict,
    zero: int | None,
    weights: dict,
    system: _System | None = None,
    rtol: float | None = None,
) -> np.ndarray:
    """Node values minimising the weighted squared error of tetrahedral interpolation
    on ``colours`` (set name to (input values, expected codes); ``weights``, set name
    to a weight per colour; ``system``, :func:`_system` if already built), plus
    :data:`FIT_REGULARISATION` times the squared change of each node. The
    diagonal's nodes (greys) and, with ``zero``, the nodes of a zero channel are
    kept at their sampled values; the others solve the normal equations, to a residual of
    ``rtol`` (:data:`FIT_RTOL`) relative to the right-hand side."""
    return _solved(lat.cube, weights, system or _system(lat, colours, zero), rtol)


def _solved(
    cube: np.ndarray, weights: dict, system: _System, rtol: float | None = None, decimals: int | None = CUBE_DECIMALS
) -> np.ndarray:
    """:func:`fit` from ``cube``'s sampled values on a built ``system``, rounded to ``decimals``."""
    scale = np.sqrt(np.concatenate([weights[name] for name in system.sets]))
    free, columns, unknown = system.free * scale, system.columns, system.unknown
    count = int(np.count_nonzero(unknown))
    start = np.ascontiguousarray(cube.reshape(-1, 3).T)
    residual = system.expected * scale
    touching = system.touching
    residual[:, touching] -= solve.interpolate(system.nodes[:, touching], system.kept * scale[touching], start)
    right = solve.accumulate(columns, free, residual, count) + FIT_REGULARISATION * start[:, unknown]
    # The stopping rule is relative to the whole right-hand side, unreached free nodes included.
    whole = np.sqrt(np.einsum("ck,ck->c", right, right) + system.rest)
    size = cube.shape[0]
    if system.keys is not None:
        matrix = solve.bands(system.nodes, free, size, system.keys)
        diagonal = matrix[0][unknown] + FIT_REGULARISATION
        every = np.zeros((3, size**3))

        def normal(v):
            every[:, unknown] = v
            return solve.banded(matrix, size, every)[:, unknown] + FIT_REGULARISATION * v

    else:
        diagonal = np.bincount(columns.ravel(), weights=(free**2).ravel(), minlength=count) + FIT_REGULARISATION

        def normal(v):
            return solve.accumulate(columns, free, solve.interpolate(columns, free, v), count) + FIT_REGULARISATION * v

    values = start.copy()
    rtol = FIT_RTOL if rtol is None else rtol  # read when called: FIT_RTOL is the one default
    values[:, unknown] = solve.conjugate_gradient(normal, right, start[:, unknown], diagonal, rtol * whole, FIT_MAXITER)
    values = values.T.reshape(cube.shape)
    return values if decimals is None else numbers.rounded(values, decimals)


def _shaper_table(spec: Spec, source: ColourSpace, display: Display, size: int, shaper, domain) -> np.ndarray | None:
    if shaper == "none":
        return None
    count = SOURCE_SHAPER_SIZES[isinstance(source.curve, Linear)]
    with np.errstate(all="ignore"):
        linear = source.curve.decode(np.linspace(domain[0], domain[1], count))
        if shaper == "auto":
            coordinate = source_axis(spec, source, display, size).coordinate(linear / display.clip_high)
        else:
            encoded = shaper.curve.encode(linear)
            coordinate = (encoded - encoded[0]) / (encoded[-1] - encoded[0])
    return numbers.rounded(coordinate, SHAPER_DECIMALS)


def source_lattice(
    spec: Spec,
    source: ColourSpace,
    display: Display,
    method: str,
    size: int,
    shaper: str | ColourSpace = "auto",
    params=None,
) -> Lattice:
    """The source layout. ``shaper``: "auto" (:class:`SourceAxis` on the decoded source),
    "none" (the cube directly over the source domain) or a colour space whose
    curve, applied to the decoded source values, spaces the nodes. ``params`` None takes
    the spec's (:func:`~generator.reference.method_params`)."""
    params = reference.method_params(spec, method, params, source, display)

    domain = (
        shaper_domain(source, shaper, display) if isinstance(shaper, ColourSpace) else source_domain(source, display)
    )
    table = _shaper_table(spec, source, display, size, shaper, domain)
    codes = preimages(size, table, domain)
    with np.errstate(all="ignore"):
        linear = source.curve.decode(codes)
    matrix = reference.scene_to_display_matrix(spec, display) @ reference.space_matrix(spec, source)
    cube = node_values(display, method, linear, matrix, params)
    lat = Lattice(source, display, method, None, None, None, domain, table, cube)
    axis = source_axis(spec, source, display, size) if shaper == "auto" else None
    zero = axis.zero if axis is not None and axis.values[axis.zero] == 0.0 else None
    colours = _held(probes.training(spec, source, display, method, FIT_COUNT, params), domain)
    return Lattice(source, display, method, None, None, None, domain, table, reweighted_fit(lat, colours, zero))


def _held(colours: dict, domain: tuple[float, float]) -> dict:
    """The training colours whose source values the file's domain holds: one beyond it is
    clamped there, and fitting its mapped colour at the clamped input would pull the
    domain's edge nodes off (an sRGB-encoded source, whose domain ends at code 1, put
    near-white colours hundreds of codes off through an identity)."""
    lo, hi = domain
    out = {}
    for name, (code, expected) in colours.items():
        inside = np.all((code >= lo) & (code <= hi), axis=-1)
        out[name] = (code[inside], expected[inside])
    return out
