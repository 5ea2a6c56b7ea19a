"""An ACES view, from a source colour space to a display's code values, as a lattice.

The lattice's axes are :mod:`generator.luts.aces_axes`'; its values are the display's code
values of the view (the reference, :func:`~generator.reference.aces_view`),
fitted by least squares (:func:`generator.luts.fit.reweighted_fit`) to colours of the kinds
bench/aces_views.py measures (:mod:`generator.luts.aces_probes`, another seed); greys keep
their sampled values.

* Display layout (a CLF with ``--shaper auto``): the source's curve and the matrix to AP1 are
  exact operators, the Log operator and the Range after it are the view's own clamp (the
  lattice's faces are AP1's, and a colour outside lands on them as the view puts it there),
  then a 1D table to the :class:`~generator.luts.aces_axes.ViewAxis` coordinate. Where the
  view's last clamp is the display's own, the lattice holds the codes before it and a 1D
  table of two entries after it clamps exactly (:func:`light_before_clamp`).
* Source layout (.cube, .spi3d; a CLF with a named shaper): a 1D table uniform in the
  source's values takes them to the lattice coordinate
  (:class:`~generator.luts.aces_axes.SourceLogAxis`, or the named space's curve).
"""

from __future__ import annotations

import numpy as np

from generator import reference
from generator.colorimetry.matrices import settled
from generator.colorimetry.transfer import Linear
from generator.luts import aces_probes, numbers
from generator.luts.aces_axes import (
    ACES_TOE,
    SourceLogAxis,
    basis,
    basis_matrix,
    same_basis,
    source_range,
    thinning,
    view_axes,
)
from generator.luts.aces_lattice import ACES_FIT_RTOL, to_xyz
from generator.luts.axes import LogAxis
from generator.luts.fit import reweighted_fit, tetrahedra
from generator.luts.lattice import CUBE_DECIMALS, SHAPER_DECIMALS, Lattice, coordinates, grid, preimages
from generator.luts.solve import interpolate
from generator.luts.source_axes import shaper_domain
from generator.rendering import views
from generator.spec.schema import ColourSpace, Display, Spec

#: Colours per probe kind the lattice is fitted to (six kinds; more fit the nodes few colours
#: reach better, at a bake time linear in the count: measured at 65³, SDR Rec.709 on sRGB, from
#: ACEScct, p99 in ten-bit codes with 16384, 32768 and 65536: AP0 0..1 4.8, 4.7, 4.3; camera 33,
#: 33, 31; 0.9 s, 1.3 s, 3.1 s).
ACES_FIT_COUNT = 32768

#: Entries of the source layout's 1D table, for encoded and for linear sources (Resolve reads up
#: to 65536): a linear source's table is uniform in light up to
#: :func:`~generator.luts.aces_axes.linear_high`.
ACES_SHAPER_SIZES = (4096, 65536)


def training_sets(spec: Spec, display: Display, view) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """The fit's colours (ACES2065-1) per kind, with the view's display codes for them: the same
    for every source (:func:`~generator.luts.aces_probes.view_sets`)."""
    return aces_probes.view_sets(spec, display, view.name, aces_probes.TRAINING_SEED, ACES_FIT_COUNT)


def _training(spec: Spec, source: ColourSpace, display: Display, view, domain=None, training=None) -> dict:
    """The fit's colours: per kind, the source's code values and the view's display codes
    (of :func:`training_sets`, evaluated here unless given)."""
    training = training or training_sets(spec, display, view)
    return {name: aces_probes.held_in(spec, source, display, pair, domain) for name, pair in training.items()}


def _fitted(lat: Lattice, colours: dict, decimals: int) -> np.ndarray:
    return numbers.rounded(reweighted_fit(lat, colours, None, ACES_FIT_RTOL), decimals)


def display_lattice(
    spec: Spec,
    source: ColourSpace,
    display: Display,
    view,
    size: int,
    decimals: int = CUBE_DECIMALS,
    values: np.ndarray | None = None,
) -> Lattice:
    """The display layout (a CLF): decoding and the matrix to the basis exact, the Log operator of
    :func:`view_axes` and its Range (the view's clamp), its 1D table, a lattice of fitted display
    codes (``values``, else :func:`display_values`); or, where the view's last clamp is the
    display's (:func:`light_before_clamp`), of the display's codes of the light before that
    clamp, which a 1D table of two entries after the lattice applies exactly (the clamp bends
    the codes where the lattice cannot)."""
    log, _, table = view_axes(view)
    matrix = settled(basis_matrix(spec, source, view))
    before = light_before_clamp(spec, display, view)
    post = None if before is None else unclamped_codes(display, *before)[0]
    cube = display_values(spec, display, view, size, decimals) if values is None else values
    return Lattice(source, display, view.name, source.curve, matrix, log, (0.0, 1.0), table, cube, post, decimals)


def display_values(
    spec: Spec, display: Display, view, size: int, decimals: int = CUBE_DECIMALS, training=None
) -> np.ndarray:
    """The display layout's lattice values (size, size, size, 3), written with ``decimals``
    decimals: the same for every source, as the layout's lattice starts at the view's basis.
    Sampled at the nodes, then fitted to the training colours (:func:`training_sets`, evaluated
    here unless given) taken to the basis directly."""
    log, _, table = view_axes(view)
    nodes = grid(log.position(preimages(size, table, (0.0, 1.0)))).reshape(-1, 3)
    to_aces = np.linalg.inv(basis(view).from_aces)
    before = light_before_clamp(spec, display, view)
    if before is None:
        post, values = None, lambda ref: reference.aces_view(spec, display, view.name, ref)
    else:
        post, values = unclamped_codes(display, *before)
    from_aces = np.linalg.inv(reference.to_aces_matrix(spec))
    cube = numbers.rounded(values(reference.apply_matrix(from_aces @ to_aces, nodes)), CUBE_DECIMALS)
    lat = Lattice(None, display, view.name, None, None, log, (0.0, 1.0), table, cube.reshape(size, size, size, 3), post)
    if before is None:  # the lattice holds the view's codes: the training's own
        pairs = training or training_sets(spec, display, view)
    else:
        aces_sets = aces_probes.sets(display, aces_probes.TRAINING_SEED, ACES_FIT_COUNT)
        pairs = {name: (aces, values(reference.apply_matrix(from_aces, aces))) for name, aces in aces_sets.items()}
    colours = {}
    for name, (aces, expected) in pairs.items():
        with np.errstate(all="ignore"):
            coordinate = log.coordinate(reference.apply_matrix(basis(view).from_aces, aces))
        colours[name] = (coordinate, expected)
    return _fitted(lat, colours, decimals)


def light_before_clamp(spec: Spec, display: Display, view):
    """Where the view's last clamp is the display's own (per channel in its linear RGB, before an
    encoding CLF's 1D table can follow, so not HLG): the function giving the view's normalised
    display light before that clamp for scene-reference colours (n, 3), and the clamp's top
    (1, or lower for an ACES 2.0 white scaling); None elsewhere. ACES 1.3's output ends in XYZ
    before its display's clamp; ACES 2.0 clamps its limiting RGB, the display's own when they
    share primaries and white."""
    if display.eotf_name == "HLG":
        return None
    to_display = reference.display_matrix(spec, display) / display.clip_high
    to_aces = reference.to_aces_matrix(spec)
    if view.version != "2.0":
        return (
            lambda ref: reference.apply_matrix(to_display, views.evaluate(view, reference.apply_matrix(to_aces, ref))),
            1.0,
        )
    product = to_display @ to_xyz(view)
    d = float(product[0, 0])
    if not np.allclose(product, d * np.eye(3), rtol=0, atol=1e-9 * d):
        return None
    b = basis(view)

    def light(ref):
        clamped = np.clip(reference.apply_matrix(b.from_aces @ to_aces, ref), 0.0, b.upper)
        return (
            views.output_rgb(view, reference.apply_matrix(np.linalg.inv(b.from_aces), clamped))
            / (view.peak / 100.0)
            * d
        )

    return light, min(d, 1.0)


def unclamped_codes(display: Display, light, top_light: float):
    """The 1D table after a lattice of unclamped codes (``[0, top]``: it clamps what it reads to
    [0, 1]) and the function giving the lattice's values of scene-reference colours: the display's
    codes of ``light`` (normalised display light before the clamp at ``top_light``), mirrored
    below 0, over ``top``, the code of the clamp."""
    top = float(
        numbers.rounded(reference.display_encode(display, np.full(3, top_light * display.clip_high))[0], CUBE_DECIMALS)
    )

    def values(ref):
        rgb = light(ref) * display.clip_high
        return np.sign(rgb) * reference.display_encode(display, np.abs(rgb)) / top

    return np.array([0.0, top]), values


def _log_coordinate(lat: Lattice, code) -> np.ndarray:
    """A display layout's Log operator after its decoding and matrix: the 1D table's input."""
    if not isinstance(lat.pre, LogAxis) or lat.decode is None:
        raise TypeError("a display layout has a decoding and a LogAxis")
    with np.errstate(all="ignore"):
        return lat.pre.coordinate(
            reference.apply_matrix(lat.matrix, lat.decode.decode(np.asarray(code, dtype=np.float64)))
        )


def _display_codes(spec: Spec, display: Display, view, rgb: np.ndarray, to_aces: np.ndarray) -> np.ndarray:
    """The view's display codes of colours ``rgb`` (n, 3), ``to_aces`` taking them to ACES2065-1."""
    ref = reference.apply_matrix(np.linalg.inv(reference.to_aces_matrix(spec)) @ to_aces, rgb)
    return numbers.rounded(reference.aces_view(spec, display, view.name, ref), CUBE_DECIMALS)


def source_lattice(
    spec: Spec,
    source: ColourSpace,
    display: Display,
    view,
    size: int,
    shaper: str | ColourSpace = "auto",
    decimals: int = CUBE_DECIMALS,
    entries: int | None = None,
    training=None,
) -> Lattice:
    """The source layout: a 1D table uniform in source values (``shaper`` "auto": to the
    :class:`SourceLogAxis` coordinate; a colour space: its curve over its codes 0 to 1; "none":
    no table, the lattice uniform in source values), a lattice of fitted display codes, written
    with ``decimals`` decimals; the table has ``entries`` entries (default
    :data:`ACES_SHAPER_SIZES`); fitted to ``training`` (:func:`training_sets`) if given."""
    low, high = source_range(spec, source, display, view)
    with np.errstate(all="ignore"):
        lo, hi = source.curve.encode(np.array([low, high]))
    domain = (float(lo), float(hi))
    if isinstance(shaper, ColourSpace):
        domain = shaper_domain(source, shaper, display)
    table = None if shaper == "none" else _table(source, shaper, size, domain, (low, high), entries, thinning(view))
    codes = preimages(size, table, domain)
    with np.errstate(all="ignore"):
        linear = source.curve.decode(codes)
    nodes = grid(linear).reshape(-1, 3)
    to_aces = reference.to_aces_matrix(spec) @ reference.space_matrix(spec, source)
    cube = _display_codes(spec, display, view, nodes, to_aces).reshape(size, size, size, 3)
    lat = Lattice(source, display, view.name, None, None, None, domain, table, cube)
    # Beyond the domain the file clamps each channel: the view's own clamp where the source is its basis.
    held = None if same_basis(spec, source, view) and shaper == "auto" else domain
    return Lattice(
        source,
        display,
        view.name,
        None,
        None,
        None,
        domain,
        table,
        _fitted(lat, _training(spec, source, display, view, held, training), decimals),
        decimals=decimals,
    )


def _table(source: ColourSpace, shaper, size: int, domain, reach, entries: int | None, thin) -> np.ndarray:
    """The 1D table: lattice coordinates at ``entries`` entries uniform over ``domain`` (source
    values), thinning out as ``thin`` (:func:`~generator.luts.aces_axes.thinning`) says."""
    count = entries or ACES_SHAPER_SIZES[isinstance(source.curve, Linear)]
    with np.errstate(all="ignore"):
        linear = source.curve.decode(np.linspace(domain[0], domain[1], count))
        if isinstance(shaper, ColourSpace):
            encoded = shaper.curve.encode(linear)
            coordinate = (encoded - encoded[0]) / (encoded[-1] - encoded[0])
        else:
            coordinate = SourceLogAxis.layout(size, reach[0], reach[1], thin).coordinate(linear)
    return numbers.rounded(coordinate, SHAPER_DECIMALS)


def file_output(lat: Lattice, code) -> np.ndarray:
    """A lattice's file evaluated in float64 as OCIO runs it: source code values (n, 3) to display
    code values (n, 3): the display layout's decoding, matrix and Log operator, the 1D table
    (linear), the lattice (tetrahedral) and the table after it (linear, clamped to its input range)."""
    code = np.asarray(code, dtype=np.float64).reshape(-1, 3)
    with np.errstate(all="ignore"):
        u = coordinates(lat, _log_coordinate(lat, code) if isinstance(lat.pre, LogAxis) else code)
    nodes, weights = tetrahedra(np.ascontiguousarray(np.nan_to_num(u).T * (lat.size - 1)), lat.size)
    out = interpolate(nodes, weights, lat.cube.reshape(-1, 3).T).T
    return out if lat.post is None else np.interp(out, np.linspace(0.0, 1.0, lat.post.size), lat.post)


def notes(lat: Lattice, view, shaper) -> list[str]:
    """Comment lines after the title: what the file's input is, what its lattice holds, its output."""
    b = basis(view)
    display, source = lat.display, lat.source
    if source is None:
        raise ValueError("an ACES view lattice reads a source colour space")
    top = float(reference.display_encode(display, np.full(3, display.clip_high))[0])
    output = f"Output: {display.name} code values (full range, 0 to {top:.6g}), as the view and the display encode."
    fitted = (
        "Node values are fitted by least squares to colours of six kinds (in the display's gamut, ACES2065-1 "
        "0 to 1, dark, bright, greys, saturated camera colours); greys keep the sampled values. "
        "Interpolate tetrahedrally."
    )
    level, density = thinning(view)
    if isinstance(lat.pre, LogAxis):
        log, axis, _ = view_axes(view)
        clamp = (
            " The lattice holds the codes before the display's clamp, which the 1D table after it applies."
            if lat.post is not None
            else ""
        )
        return [
            f"Input: {source.name} values, decoded and taken to {b.name} exactly, clamped to [0, {b.upper:.9g}] "
            f"(the view's own clamp); a 1D table spaces the nodes uniformly in log2({b.name} + {log.toe:.9g}), "
            f"{density:.3g} times as densely above {axis.light:.6g}.{clamp}",
            output,
            fitted,
        ]
    lo, hi = lat.domain
    spacing = (
        "uniformly in the source's values"
        if lat.shaper is None
        else f"by {shaper.name}'s curve of the decoded values"
        if isinstance(shaper, ColourSpace)
        else f"uniformly in log2(x + {ACES_TOE:g}) of the decoded values x (mirrored below 0), "
        f"{density:.3g} times as densely above {level:g}"
    )
    low, high = float(lat.cube.min()), float(lat.cube.max())
    return [
        f"Input: {source.name} values, sampled over [{lo:.9g}, {hi:.9g}] (clamped outside); nodes spaced {spacing}.",
        output[:-1] + f"; the fitted node values range from {low:.6g} to {high:.6g}.",
        fitted,
    ]
