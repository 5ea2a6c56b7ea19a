"""An ACES 2.0 view baked for configs whose OCIO cannot run it (2.1 to 2.3).

The view runs, in the config::

    Matrix (scene reference -> AP1) -> Range clamp [0, upper] -> this CTF -> Range [0, 1]
    -> Matrix (limiting RGB at the peak -> CIE XYZ)

where the clamp is the view's own AP1 clamp (upper: the tone scale's forward limit) and the
CTF holds the operators placing AP1 on the table's axes (chromaticity and luminance:
:mod:`generator.luts.aces_chroma`), a 3D table (tetrahedral) of the rendering's limiting RGB
over its peak, encoded by a mirrored power with a linear toe (CLF's monCurve), and the Exponent
undoing that encoding. It is a CTF, OCIO's superset of CLF, as CLF has no XYZ_TO_xyY. The
table's values are fitted by least squares to colours of the kinds bench/aces_views.py measures
(:func:`fitted`). What is linear (the matrices) and what is a clamp stays outside the table, so
the table holds the rendering unclamped. One file per view, whatever displays show it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from functools import cached_property
from typing import TypeVar

import numpy as np

from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import channel_max
from generator.colorimetry.transfer import PiecewisePower
from generator.luts import aces_probes, numbers
from generator.luts.aces_axes import HDR_LOW_PEAK
from generator.luts.aces_chroma import (
    BLACK_OFFSET,
    CHROMA_LOG_OFFSET,
    CHROMA_LOG_SPAN,
    HDR_WARP,
    SDR_WARP,
    ChromaAxes,
    chroma_axes,
)
from generator.luts.fit import reweighted_nodes, system_at, tetrahedra
from generator.luts.pool import Pool
from generator.luts.solve import interpolate
from generator.metrics import delta_e_itp_of_light
from generator.rendering import views
from generator.rendering.aces2_params import triangle_area
from generator.rendering.aces2_presets import P3 as P3_PRIMARIES
from generator.rendering.views import ACESView

T = TypeVar("T")

#: Nodes a side: SDR views, HDR views, HDR views of a wide limiting gamut (:data:`WIDE_AREA`).
#: Colours fill the half of a table where q <= p (:mod:`~generator.luts.aces_chroma`): n (n + 1) / 2 * n
#: nodes. SDR views bend most; of the sizes 97 to 129, 117 and 129 put greys' error lowest, and 129
#: makes 35 MB files. The default 2.1 config's seven files hold 105 MB, below the 133 MB of the plain
#: recipe's eighteen 65³ files (docs/aces-views.md).
SDR_LATTICE_SIZE, HDR_LATTICE_SIZE, HDR_WIDE_LATTICE_SIZE = 117, 81, 93

#: An HDR view whose limiting gamut's xy area is this many times P3's takes
#: :data:`HDR_WIDE_LATTICE_SIZE` nodes (Rec.2020's is 1.39 times). At 81 nodes the Rec.2020-limited
#: views' bright colours measured 1.19 (1000 nits) and 1.04 (500 nits) ΔE ITP p99.
WIDE_AREA = 1.1

#: The luminance axis's toe (AP1 linear) for SDR views, HDR views, and HDR views peaking below
#: :data:`~generator.luts.aces_axes.HDR_LOW_PEAK`: the axis is log2(L + toe), so black sits on a
#: node. 2^-8.5 brought the 108 nit view's camera colours under 1 ΔE ITP p99 on three draws (0.91
#: to 1.02 at 2^-9), where the 1000 nit view's darks and greys rose (docs/aces-views.md).
SDR_TOE, HDR_TOE, HDR_LOW_TOE = 2.0**-7, 2.0**-9, 2.0**-8.5

#: Colours per probe kind a view's table is fitted to (:func:`fitted`).
VIEW_FIT_COUNT = 16384

#: The fit's stopping rule for an ACES view's table, here and in ``bake --view``
#: (:func:`generator.luts.fit.fit`'s ``rtol``): the default's 1e-3 stops a 65³ fit after a few
#: steps, as its right-hand side is dominated by the nodes' own values (SDR Rec.709 in-gamut
#: p99 2.32 ten-bit codes at 1e-3, 2.14 at 1e-6, in the same time).
ACES_FIT_RTOL = 1e-6

#: The table's output encoding (gamma, offset of CLF's monCurve). A larger gamma or a smaller
#: offset keeps nodes for the darks, a smaller one for the brights. SDR: below sRGB's (2.4, 0.055),
#: which bright and camera colours erred more with, at the same darks, greys and in-gamut colours;
#: HDR: steeper, as PQ is (bench/aces_views.py, docs/aces-views.md).
SDR_CURVE, HDR_CURVE = (2.1, 0.035), (2.8, 0.025)

#: The table's values are whole 16-bit codes of the encoded range, as the file holds them:
#: 0.008 ten-bit codes at most, in two fifths of the text of float32 values.
CODE_STEPS = 65535.0


@dataclass(frozen=True)
class AcesLattice:
    """A baked ACES 2.0 view: AP1 in [0, ``upper``] on the ``axes``, and the table (n, n, n, 3)
    indexed [p, q, luminance] holding the ``curve`` (gamma, offset) encoding of limiting RGB over
    the peak."""

    view: ACESView
    upper: float
    axes: ChromaAxes
    curve: tuple[float, float]
    cube: np.ndarray

    @property
    def size(self) -> int:
        """Nodes along each axis of the cube."""
        return self.cube.shape[0]

    @cached_property
    def planes(self) -> np.ndarray:
        """The table's values channel by channel (3, n³), each contiguous: numpy's take copies a
        strided channel whole before gathering from it (1.6 ms a call at 117³)."""
        return np.ascontiguousarray(self.cube.reshape(-1, 3).T)

    def coordinate(self, ap1) -> np.ndarray:
        """AP1 colours (m, 3; clamped to [0, ``upper``]) to lattice coordinates (m, 3) in [0, 1],
        as OCIO reads the file."""
        ap1 = np.nan_to_num(np.asarray(ap1, dtype=np.float64).reshape(-1, 3))
        return self.axes.coordinate(np.clip(ap1, 0.0, self.upper))

    def value(self, u) -> np.ndarray:
        """The AP1 grey at luminance coordinates ``u``: on a node of the table's grey line where
        ``u`` is one's."""
        return self.axes.grey(u)


def mon_decode(code, curve: tuple[float, float]) -> np.ndarray:
    """Code to linear as CLF's monCurveMirrorFwd: the piecewise power (gamma, offset), mirrored
    for negative codes."""
    code = np.asarray(code, dtype=np.float64)
    return np.sign(code) * PiecewisePower(*curve).decode(np.abs(code))


def mon_encode(linear, curve: tuple[float, float]) -> np.ndarray:
    """Linear to code, :func:`mon_decode`'s inverse (CLF's monCurveMirrorRev)."""
    linear = np.asarray(linear, dtype=np.float64)
    return np.sign(linear) * PiecewisePower(*curve).encode(np.abs(linear))


def lattice_size(view: ACESView) -> int:
    """Nodes a side of ``view``'s table."""
    if not view.is_hdr:
        return SDR_LATTICE_SIZE
    wide = abs(triangle_area(*view.limiting)) > WIDE_AREA * abs(triangle_area(*P3_PRIMARIES))
    return HDR_WIDE_LATTICE_SIZE if wide else HDR_LATTICE_SIZE


def bake(view: ACESView, size: int | None = None) -> AcesLattice:
    """The lattice of ACES 2.0 view ``view`` (``size`` nodes a side, default :func:`lattice_size`):
    sampled from the float64 reference, then fitted (kept: this process bakes each view once)."""
    key = (view, size or lattice_size(view))
    if key not in _BAKED:
        _keep(key, baked(*key))
    return _BAKED[key]


#: The lattices this process baked or adopted (:func:`bake_all`), by (view, size); the oldest go first.
_BAKED: dict[tuple[ACESView, int], AcesLattice] = {}
_BAKED_MAX = 32


def _keep(key: tuple[ACESView, int], lat: AcesLattice) -> None:
    _BAKED[key] = lat
    while len(_BAKED) > _BAKED_MAX:
        _BAKED.pop(next(iter(_BAKED)))


def bake_all(views, meanwhile: Callable[[], T]) -> T:
    """:func:`bake` each of ``views`` not baked yet, in worker processes, kept here; ``meanwhile()``
    runs here as they bake, and its result is returned."""
    missing = [v for v in dict.fromkeys(views) if (v, lattice_size(v)) not in _BAKED]
    with Pool() as pool:
        for view in missing:
            pool.submit(view, baked, view)
        out = meanwhile()
        for view in missing:
            _keep((view, lattice_size(view)), pool.result(view, baked, view))
    return out


def baked(view: ACESView, size: int | None = None) -> AcesLattice:
    """The lattice of ACES 2.0 view ``view`` baked now (:func:`bake` keeps it)."""
    size = size or lattice_size(view)
    curve, toe, shape = (HDR_CURVE, HDR_TOE, HDR_WARP) if view.is_hdr else (SDR_CURVE, SDR_TOE, SDR_WARP)
    if view.is_hdr and view.peak < HDR_LOW_PEAK:
        toe = HDR_LOW_TOE
    axes, top = chroma_axes(view, size, toe, shape), upper(view)
    # the half colours reach (q <= p), sampled; the other is filled after the fit (:func:`_clamped_half`)
    nodes = np.linspace(0.0, 1.0, size)
    reached = np.tril(np.ones((size, size), dtype=bool))
    p, q = np.nonzero(reached)
    cube = np.zeros((size, size, size, 3))
    ap1 = axes.node_values(np.stack([nodes[p], nodes[q]], axis=1), nodes)
    cube[reached] = _encoded(view, np.minimum(ap1, top), curve).reshape(-1, size, 3)
    lat = AcesLattice(view, top, axes, curve, cube)
    cube = _clamped_half(replace(lat, cube=fitted(lat)))
    # + 0.0: no negative zero, which OCIO would write as "-0"
    return AcesLattice(view, top, axes, curve, np.round(cube * CODE_STEPS) / CODE_STEPS + 0.0)


def _clamped_half(lat: AcesLattice) -> np.ndarray:
    """``lat``'s table with its other half (q > p), which no colour reaches, holding what the
    table gives the node's colour clamped as the view clamps it (R < 0 to 0, on the plane p = q).
    Whatever input OCIO's inverse of the table finds for a display colour, the view's clamp then
    takes it to a colour the view renders as that display colour (a linear continuation instead
    sent display cyan back as (0.65, 0.95, 1))."""
    n = lat.size
    p, q = np.triu_indices(n, 1)
    index = (np.repeat(p, n), np.repeat(q, n), np.tile(np.arange(n), p.size))
    ap1 = lat.axes.node_values(np.stack([p, q], axis=1) / (n - 1.0), np.arange(n) / (n - 1.0))
    u = lat.coordinate(np.minimum(ap1, lat.upper)) * (n - 1)
    out = lat.cube.copy()
    out[index] = interpolate(*tetrahedra(np.ascontiguousarray(u.T), n), lat.planes).T
    return out


def _encoded(view: ACESView, ap1, curve: tuple[float, float]) -> np.ndarray:
    """The table's values of AP1 colours (m, 3): limiting RGB over the peak, encoded by ``curve``."""
    rgb = views.output_rgb(view, ap1 @ views.tables(view).ap1_to_ap0.T) / (view.render_peak / 100.0)
    return mon_encode(rgb, curve)


def fitted(lat: AcesLattice) -> np.ndarray:
    """``lat``'s table fitted by least squares (:func:`~generator.luts.fit.reweighted_nodes`) to
    colours of the six kinds bench/aces_views.py measures, from another seed; greys and the
    black cell keep their sampled values. A colour's error is in ten-bit codes of the encoded
    values for SDR views, ΔE ITP for HDR ones."""
    t = views.tables(lat.view)
    colours = {}
    for name, aces in aces_probes.sets_in(t.limit_to_xyz, aces_probes.TRAINING_SEED, VIEW_FIT_COUNT).items():
        ap1 = np.clip(aces @ t.ap0_to_ap1.T, 0.0, lat.upper)
        colours[name] = (lat.coordinate(ap1) * (lat.size - 1), _encoded(lat.view, ap1, lat.curve))
    kept = np.zeros((lat.size,) * 3, dtype=bool)
    # Black keeps its sampled values, none below 0: fitted ones of either sign near 0 cancel in
    # float32, which a pure-power display's encoding magnifies (4e-4 in gamma 2.6).
    kept[:, :, 0] = True
    system = system_at(lat.cube, colours, kept.ravel())
    return reweighted_nodes(lat.cube, system, _error(lat), ACES_FIT_RTOL, decimals=None)


def _error(lat: AcesLattice):
    """Per-colour error of encoded table values: ten-bit codes (SDR), ΔE ITP of the light (HDR)."""
    if not lat.view.is_hdr:
        return lambda actual, expected: channel_max(np.abs(actual - expected)) * 1023.0
    t = views.tables(lat.view)
    to_2020 = gamuts()["Rec.2020"].xyz_to_rgb @ t.limit_to_xyz * (lat.view.render_peak * t.display_scale)

    def itp(actual, expected):
        light = [np.clip(mon_decode(v, lat.curve), 0.0, None) @ to_2020.T for v in (actual, expected)]
        with np.errstate(all="ignore"):
            return np.nan_to_num(delta_e_itp_of_light(*light))

    return itp


def file_output(lat: AcesLattice, ap1) -> np.ndarray:
    """The file alone, in float64: AP1 (m, 3; clamped to [0, upper] as the config does before
    it) to limiting RGB over the peak, unclamped."""
    return output_at(lat, lat.coordinate(ap1))


def output_at(lat: AcesLattice, u) -> np.ndarray:
    """The file's output (limiting RGB over the peak) at lattice coordinates ``u`` (m, 3) in [0, 1]."""
    nodes, weights = tetrahedra(np.ascontiguousarray(np.asarray(u).T * (lat.size - 1)), lat.size)
    return mon_decode(interpolate(nodes, weights, lat.planes).T, lat.curve)


def evaluate(lat: AcesLattice, aces) -> np.ndarray:
    """ACES2065-1 (..., 3) through the baked view as OCIO runs it, in float64: CIE XYZ,
    1.0 = 100 cd/m² (the display then encodes)."""
    t = views.tables(lat.view)
    aces = np.asarray(aces, dtype=np.float64)
    flat = np.nan_to_num(aces.reshape(-1, 3), nan=0.0)
    rgb = np.clip(file_output(lat, flat @ t.ap0_to_ap1.T), 0.0, 1.0)
    return (rgb @ to_xyz(lat.view).T).reshape(aces.shape)


def to_xyz(view: ACESView) -> np.ndarray:
    """Normalised limiting RGB (1 = the peak) to CIE XYZ, 1.0 = 100 cd/m² (with the white
    scaling of a white simulation)."""
    t = views.tables(view)
    return t.limit_to_xyz * (view.render_peak / 100.0) * t.display_scale


def ocio_file(lat: AcesLattice) -> bytes:
    """The CTF of the lattice, written by PyOpenColorIO: the matrix to (R, L, B), XYZ_TO_xyY,
    the matrix to (p, q, L), the Log operator, the 1D table, LUT3D (16-bit codes), Exponent
    (monCurveMirrorFwd)."""
    import PyOpenColorIO as ocio

    from generator.luts import transforms  # with PyOpenColorIO, when a file is written

    axes = lat.axes
    # OCIO writes every operator, the 3D table a 2³ stand-in that :func:`_with_table` fills with
    # 16-bit integer codes (six digits of a float32 value would be 1.5e-6 of the range): two
    # thirds of the text
    cube = transforms.lut3d(np.zeros((2, 2, 2, 3)))
    cube.setFileOutputBitDepth(ocio.BIT_DEPTH_UINT16)
    to_pq = np.eye(3)
    to_pq[:2, :2] = axes.matrix
    log = transforms.log_shaper(
        (CHROMA_LOG_SPAN, CHROMA_LOG_SPAN, axes.log.span), (CHROMA_LOG_OFFSET, CHROMA_LOG_OFFSET, axes.log.toe)
    )
    group = ocio.GroupTransform(
        [
            transforms.matrix_transform(axes.ryb, offset=(BLACK_OFFSET,) * 3),
            ocio.FixedFunctionTransform(ocio.FIXED_FUNCTION_XYZ_TO_xyY),
            transforms.matrix_transform(to_pq, offset=(*axes.offset, -BLACK_OFFSET)),
            log,
            transforms.lut1d(np.stack([axes.chroma, axes.chroma, axes.bend], axis=1)),
            cube,
            transforms.mon_curve(*lat.curve),
        ]
    )
    group.getFormatMetadata().setID(f"ocioforge:{file_name(lat.view)[:-4]}")
    group.getFormatMetadata().addChildElement(
        "Description",
        f"ocioforge ACES view LUT: {lat.view.name}; AP1 clamped to [0, {lat.upper:g}] to limiting "
        f"RGB over the peak, {lat.size}^3 over AP1's chromaticity and luminance (log2(L + {axes.log.toe:.6g})), "
        f"encoded by a monCurve of gamma {lat.curve[0]:g} and offset {lat.curve[1]:g}, which the last operator "
        "undoes.",
    )
    return _with_table(group.write("Color Transform Format", ocio.Config.CreateRaw()), lat.cube).encode("utf-8")


def table_rows(cube: np.ndarray) -> str:
    """A 3D table's rows as OCIO writes them at 16-bit integer output depth (the float32 value
    times 65535, blue fastest), one space apart where OCIO pads each to six characters."""
    codes = np.rint(np.asarray(cube, dtype=np.float32).astype(np.float64).reshape(-1, 3) * CODE_STEPS)
    return numbers.integer_table(codes).decode("ascii")


def _with_table(text: str, cube: np.ndarray) -> str:
    """OCIO's text of the CTF with its stand-in 3D table replaced by ``cube``'s :func:`table_rows`:
    a fifth shorter than OCIO's padded rows, the same to any reader, and written in a sixth of
    OCIO's time (2.7 s for a 117³ table)."""
    head, _, rest = text.partition("<LUT3D")
    opening, _, rest = rest.partition(">\n")
    array, _, tail = rest.partition("</Array>")
    first = array.partition(">\n")[0].replace('dim="2 2 2 3"', 'dim="{0} {0} {0} 3"'.format(cube.shape[0]))
    return f"{head}<LUT3D{opening}>\n{first}>\n{table_rows(cube)}        </Array>{tail}"


def file_name(view: ACESView) -> str:
    """The view's file in a config's LUT folder, named after the view."""
    from generator.luts.names import slug

    return f"{slug(view.name)}_{lattice_size(view)}.ctf"


def baked_file(view: ACESView) -> bytes:
    """The CLF of ``view``'s lattice (what a build's workers bake)."""
    return ocio_file(bake(view))


def upper(view: ACESView) -> float:
    """The view's AP1 clamp, where its lattice's axis ends: the tone scale's forward limit."""
    return float(views.tables(view).tone.forward_limit)
