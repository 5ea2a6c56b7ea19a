"""Figures for the verify report and ``ocioforge plot``: matplotlib, colour-science's diagram.

* the CIE 1931 xy chromaticity diagram with the spectral locus, the gamut
  triangle of every display and of the colour spaces asked for;
* per gamut-mapping method of :data:`generator.gamut.METHODS` (and ACES view)
  of one display, each probe colour's move from where it was to where the
  method put it (the lecture's picture: desaturation moves a colour toward
  white, scaling keeps its chromaticity and lowers its luminance);
* ramps from grey to spectral colours before and after each mapping;
* exposure ramps up to 16 times scene white through each view of one display (what a view does
  to a highlight);
* heatmaps of each engine's worst error over each probe family, per check kind.
"""

from __future__ import annotations

import io
import warnings
from collections.abc import Callable
from functools import partial

import numpy as np

from generator import reference
from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import apply_matrix
from generator.gamut import METHODS
from generator.rendering import views
from generator.spec.schema import Display, Spec
from generator.verify import paths, probes

#: Wavelengths (nm) of the spectral colours the mapping ramps run toward.
RAMP_WAVELENGTHS = (450.0, 480.0, 500.0, 520.0, 560.0, 590.0, 620.0)


def _pyplot():
    """pyplot on the Agg backend (matplotlib is imported only when figures are asked for: it is slow to load)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def png(figure, fmt: str = "png") -> bytes:
    """The figure as PNG (or ``fmt``: svg, pdf) bytes; the figure is closed."""
    buffer = io.BytesIO()
    # No dates, and SVG element ids from a fixed salt: the same figure gives the same bytes.
    metadata = {"png": {}, "svg": {"Date": None}, "pdf": {"CreationDate": None}}.get(fmt, {})
    # A name in a script the font lacks (日本) is drawn as boxes; matplotlib's warning per glyph
    # would reach a command's standard error, which carries one line for an error.
    with _pyplot().rc_context({"svg.hashsalt": "ocioforge"}), warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Glyph .* missing from font", category=UserWarning)
        figure.savefig(buffer, format=fmt, dpi=110, bbox_inches="tight", metadata=metadata)
    _pyplot().close(figure)
    return buffer.getvalue()


def _xy(xyz: np.ndarray) -> np.ndarray:
    """Chromaticities of the colours (n, 3) that have one: black (X + Y + Z = 0, where
    desaturate sends a colour of negative luminance) is left out, not drawn at (0, 0)."""
    total = np.sum(xyz, axis=-1, keepdims=True)
    return (xyz[..., :2] / np.where(total == 0.0, 1.0, total))[total[..., 0] != 0.0]


def _triangle(axes, primaries, label: str, colour=None, style="-") -> None:
    points = np.asarray(primaries, dtype=np.float64)
    closed = np.vstack([points, points[:1]])
    axes.plot(closed[:, 0], closed[:, 1], style, color=colour, linewidth=1.2, label=label)


def _display_linear(spec: Spec, display: Display, scene: np.ndarray) -> np.ndarray:
    """Display-linear RGB of ``scene`` colours before any mapping, in units of peak."""
    matrix = reference.display_matrix(spec, display) @ reference.scene_to_display_reference(spec)
    return apply_matrix(matrix, scene) / display.clip_high


def _mapped(spec: Spec, display: Display, scene: np.ndarray) -> dict[str, np.ndarray]:
    """Display-linear RGB of ``scene`` colours after each mapping method and each ACES view
    the display offers, in [0, 1] of peak."""
    gamut = reference.display_gamut(display)
    linear = _display_linear(spec, display, scene)
    out = {name: method(linear, gamut) for name, method in METHODS.items()}
    aces = apply_matrix(reference.to_aces_matrix(spec), scene)
    for name in display.views:
        view = reference.aces_view_of(display, name)
        if view is not None:
            shown = apply_matrix(reference.display_matrix(spec, display), views.evaluate(view, aces))
            out[name] = np.clip(shown / display.clip_high, 0.0, 1.0)
    return out


def _probe_scene(spec: Spec) -> np.ndarray:
    """The colours the mapping figures move: spectral colours, camera primaries, a ColorChecker."""
    sizes = probes.SIZES["quick"]
    return np.concatenate(
        [
            probes.monochromatic(spec, sizes.wavelength_step).values,
            probes.camera_gamut(spec).values,
            probes.colorchecker(spec, "D65").values,
        ]
    )


def _label(space) -> str:
    """A colour space's name, with its gamut's where they differ (ACEScg (AP1))."""
    return space.name if space.gamut.name == space.name else f"{space.name} ({space.gamut.name})"


def _diagram(axes, title: str, colours: bool = True) -> None:
    """colour-science's CIE 1931 diagram (the locus, filled with colour or not) on ``axes``."""
    from generator.colour_science import plotting  # colour-science's plotting: slow to import, figures only

    plotting().plot_chromaticity_diagram_CIE1931(axes=axes, show=False, show_diagram_colours=colours, title=title)
    axes.set_xlim(-0.1, 0.9)
    axes.set_ylim(-0.1, 0.95)


def chromaticity(spec: Spec, spaces=()):
    """The xy diagram: the spectral locus, every display's triangle (solid) and those of the
    colour spaces ``spaces`` (:class:`ColourSpace` records with a gamut; dotted)."""
    plt = _pyplot()
    figure, axes = plt.subplots(figsize=(9, 9))
    _diagram(axes, f"{spec.name}: CIE 1931 chromaticity")
    for space in spaces:
        _triangle(axes, space.gamut.primaries, _label(space), style=":")
    for d in spec.displays:
        _triangle(axes, d.gamut.primaries, d.name)
    axes.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8)
    return figure


def _pairs(before: np.ndarray, after: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The chromaticities (n, 2) of colours (XYZ) before and after a mapping, where both have one."""
    keep = (np.sum(before, axis=-1) != 0.0) & (np.sum(after, axis=-1) != 0.0)
    return _xy(before[keep]), _xy(after[keep])


#: What each method's panel shows, under its name.
MOVES = {
    "clip": "each channel clamped to [0, 1]",
    "desaturate": "toward white at equal luminance",
    "scale": "negatives clamped, then toward black (xy kept)",
    "rgc": "ACES reference gamut compression",
    "perceptual": "chroma compressed softly in Oklab",
}


def _moved(before: np.ndarray, after: np.ndarray) -> str:
    """How many of the colours (XYZ) a mapping moved."""
    moved = np.any(np.abs(after - before) > 1e-9, axis=-1)
    return f"{int(moved.sum())} of {len(moved)} probes moved"


def mapping(spec: Spec, display: Display, spaces=()):
    """One panel per gamut-mapping method and ACES view of ``display``: each probe colour's move
    in xy, a line from where it was to where the method put it, the display's triangle and
    white point (desaturate moves toward white; scale keeps the chromaticity of a colour inside
    the triangle and lowers its luminance, a move xy cannot show), and the gamuts of
    ``spaces`` dotted."""
    from matplotlib.collections import LineCollection

    plt = _pyplot()
    scene = _probe_scene(spec)
    to_xyz = display.gamut.rgb_to_xyz
    before = apply_matrix(to_xyz, _display_linear(spec, display, scene))
    mapped = _mapped(spec, display, scene)
    columns = min(3, len(mapped))
    rows = -(-len(mapped) // columns)
    figure, panels = plt.subplots(rows, columns, figsize=(4.2 * columns, 4.4 * rows), squeeze=False)
    white = display.gamut.whitepoint
    for index, (axes, (name, rgb)) in enumerate(zip(panels.flat, mapped.items())):
        after = apply_matrix(to_xyz, rgb)
        what = MOVES.get(name, "ACES output transform")
        _diagram(axes, f"{name}: {what}\n{_moved(before, after)}", colours=False)
        axes.title.set_fontsize(9)
        for space in spaces:
            _triangle(axes, space.gamut.primaries, _label(space), colour="0.55", style=":")
        _triangle(axes, display.gamut.primaries, display.name, colour="black")
        source, target = _pairs(before, after)
        axes.add_collection(
            LineCollection(list(np.stack([source, target], axis=1)), colors="0.45", linewidths=0.6, label="moves")
        )
        axes.scatter(source[:, 0], source[:, 1], s=9, facecolors="none", edgecolors="black", linewidths=0.6)
        axes.scatter(target[:, 0], target[:, 1], s=9, color=f"C{index % 10}", zorder=3)
        axes.plot(*white, "+", color="black", markersize=9)
        axes.set_xlabel("")
        axes.set_ylabel("")
    for axes in panels.flat[len(mapped) :]:
        axes.set_axis_off()
    figure.suptitle(
        f"{spec.name}: where each method moves the probe colours on {display.name} "
        "(hollow: before, filled: after, +: white)",
        fontsize=10,
    )
    figure.tight_layout()
    return figure


def mapping_ramps(spec: Spec, display: Display):
    """Ramps from grey (Y = 0.3) to spectral colours of the same luminance, each method's result
    shown with the display's own encoding (one row per wavelength, one panel per method)."""
    import colour  # slow to import: figures only

    plt = _pyplot()
    steps = np.linspace(0.0, 1.0, 96)
    cmfs = colour.MSDS_CMFS[probes.OBSERVER]
    spectral = np.array([cmfs[w] / cmfs[w][1] * 0.3 for w in RAMP_WAVELENGTHS])
    grey = np.asarray(colour.xy_to_XYZ(display.gamut.whitepoint)) * 0.3
    xyz = grey + steps[None, :, None] * (spectral[:, None, :] - grey)
    scene = apply_matrix(np.linalg.inv(reference.scene_to_display_reference(spec)), xyz)
    mapped = _mapped(spec, display, scene)
    figure, panels = plt.subplots(len(mapped), 1, figsize=(8, 1.2 * len(mapped)), squeeze=False)
    for axes, (name, rgb) in zip(panels[:, 0], mapped.items()):
        codes = np.clip(reference.display_encode(display, rgb * display.clip_high), 0.0, 1.0)
        axes.imshow(codes, aspect="auto", extent=(0, 1, len(RAMP_WAVELENGTHS), 0), interpolation="nearest")
        axes.set_yticks(np.arange(len(RAMP_WAVELENGTHS)) + 0.5, [f"{w:g} nm" for w in RAMP_WAVELENGTHS], fontsize=6)
        axes.set_ylabel(name, rotation=0, ha="right", fontsize=8)
        axes.set_xticks([])
    panels[-1, 0].set_xlabel(f"grey -> spectral colour at equal luminance, mapped onto {display.name}")
    return figure


#: The highlight ramps' colours, in ACEScg: a grey and six hues, each channel over the largest.
HIGHLIGHT_COLOURS = {
    "grey": (1.0, 1.0, 1.0),
    "red": (1.0, 0.08, 0.05),
    "orange": (1.0, 0.45, 0.12),
    "green": (0.12, 1.0, 0.08),
    "cyan": (0.06, 0.7, 1.0),
    "blue": (0.08, 0.1, 1.0),
    "magenta": (0.9, 0.1, 0.8),
}

#: The ramps' largest channel runs over these stops of scene light (1.0: scene white), in columns.
HIGHLIGHT_STOPS, HIGHLIGHT_COLUMNS = (-6.0, 4.0), 321


def highlight_codes(spec: Spec, display: Display) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """The ramps' exposures (the largest ACEScg channel, 2^-6 to 16, one per column) and, for each
    view of ``display`` but Raw, the display codes (colours, columns, 3) of :data:`HIGHLIGHT_COLOURS`
    (ACES views by the float64 output transform, the others as verify's reference evaluates them)."""
    exposures = 2.0 ** np.linspace(*HIGHLIGHT_STOPS, HIGHLIGHT_COLUMNS)
    ap1 = np.array(list(HIGHLIGHT_COLOURS.values()))[:, None, :] * exposures[None, :, None]
    ref = apply_matrix(reference.gamut_matrix(spec, gamuts()["AP1"]), ap1)
    return exposures, {view: function(ref) for view, function in _highlight_views(spec, display).items()}


def _highlight_views(spec: Spec, display: Display) -> dict[str, Callable[[np.ndarray], np.ndarray]]:
    """Each view of ``display`` with an evaluation, Raw left out: scene reference to its codes."""
    out: dict[str, Callable[[np.ndarray], np.ndarray]] = {}
    for view in display.views:
        if reference.aces_view_of(display, view) is not None:
            out[view] = partial(reference.aces_view, spec, display, view)
            continue
        function = paths.view_function(spec, display, view)
        if function is not None:
            out[view] = function
    return out


def highlight_views(spec: Spec, display: Display) -> list[str]:
    """The views :func:`highlights` draws a panel for."""
    return list(_highlight_views(spec, display))


def highlights(spec: Spec, display: Display):
    """One panel per view of ``display``: each of :data:`HIGHLIGHT_COLOURS` ramped from 2^-6 to
    16 times scene white, shown by its display codes (an HDR display's signal, drawn as is)."""
    plt = _pyplot()
    exposures, shown = highlight_codes(spec, display)
    names = list(HIGHLIGHT_COLOURS)
    figure, panels = plt.subplots(len(shown), 1, figsize=(8, 0.95 * len(shown) + 0.6), squeeze=False)
    stops = np.log2(exposures)
    ticks = (1 / 64, 1 / 16, 0.18, 1.0, 2.0, 4.0, 8.0, 16.0)
    for axes, (name, codes) in zip(panels[:, 0], shown.items()):
        axes.imshow(
            np.clip(codes, 0.0, 1.0),
            aspect="auto",
            extent=(stops[0], stops[-1], len(names), 0),
            interpolation="nearest",
        )
        axes.set_yticks(np.arange(len(names)) + 0.5, names, fontsize=6)
        axes.set_ylabel(name, rotation=0, ha="right", va="center", fontsize=8)
        axes.set_xticks(np.log2(ticks), [])
        for x in (0.0, 3.0, 4.0):  # scene white, 8 and 16: the Colorimetric view shows all three alike
            axes.axvline(x, color="white", linewidth=0.5, alpha=0.6)
    panels[-1, 0].set_xticks(np.log2(ticks), [f"{v:g}" if v >= 0.18 else f"1/{round(1 / v)}" for v in ticks])
    panels[-1, 0].set_xlabel("scene light of the largest ACEScg channel (1.0: scene white)")
    signal = f" ({display.eotf_name} signal drawn as is)" if display.is_hdr else ""
    figure.suptitle(f"{spec.name}: highlights through each view of {display.name}{signal}", fontsize=10)
    figure.tight_layout()
    return figure


def family_errors(outcome) -> dict[str, float]:
    """The worst error over tolerance of each probe family in an outcome."""
    out: dict[str, float] = {}
    if outcome.errors is None:
        return out
    index = outcome.check.probes.family_index
    for number, family in enumerate(outcome.check.probes.families):
        values = outcome.errors[index == number]
        values = values[~np.isnan(values)]
        if values.size:
            out[family.name] = max(out.get(family.name, 0.0), float(values.max()) / outcome.check.tolerance)
    return out


def error_heatmaps(verification):
    """Per check kind: engines x probe families, log10 of the worst error over tolerance."""
    plt = _pyplot()
    from matplotlib.colors import TwoSlopeNorm

    kinds = list(dict.fromkeys(o.check.kind for o in verification.outcomes))
    figure, panels = plt.subplots(len(kinds), 1, figsize=(10, 2.2 * len(kinds) + 1), squeeze=False)
    for axes, kind in zip(panels[:, 0], kinds):
        cells: dict[tuple[str, str], float] = {}
        for o in (o for o in verification.outcomes if o.check.kind == kind):
            for family, value in family_errors(o).items():
                cells[(o.engine, family)] = max(cells.get((o.engine, family), 0.0), value)
        engines = list(dict.fromkeys(e for e, _ in cells))
        families = list(dict.fromkeys(f for _, f in cells))
        grid = np.full((len(engines), len(families)), np.nan)
        for (engine, family), value in cells.items():
            grid[engines.index(engine), families.index(family)] = np.log10(max(value, 1e-6))
        norm = TwoSlopeNorm(vmin=-4.0, vcenter=0.0, vmax=2.0)
        image = axes.imshow(grid, cmap="RdYlGn_r", norm=norm, aspect="auto")
        axes.set_xticks(range(len(families)), families, rotation=30, ha="right", fontsize=7)
        axes.set_yticks(range(len(engines)), engines, fontsize=7)
        axes.set_title(f"{kind}: log10(worst error / tolerance); above 0 exceeds it", fontsize=9)
        figure.colorbar(image, ax=axes)
    figure.tight_layout()
    return figure


def report_figures(verification) -> dict[str, bytes]:
    """The report's figures as PNG bytes, by title."""
    spec = verification.spec
    display = next((d for d in spec.displays if not d.is_hdr), spec.displays[0] if spec.displays else None)
    out = {"Chromaticity diagram: every display's gamut": png(chromaticity(spec))}
    if display is not None:
        out[f"Where each gamut mapping moves the probe colours ({display.name})"] = png(mapping(spec, display))
        out[f"Ramps before and after gamut mapping ({display.name})"] = png(mapping_ramps(spec, display))
    out["Error heatmaps"] = png(error_heatmaps(verification))
    return out
