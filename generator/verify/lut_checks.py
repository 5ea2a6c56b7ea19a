"""The checks of a config's LUT files on their own: every baked curve against the curve it
stands for, every baked view LUT against its view's mapping (the two files of an HSV view
each; a view defined by its lattice against that lattice, its nodes against the mapping), so
that a broken file is named, not only the conversions that read it."""

from __future__ import annotations

from functools import partial

import numpy as np

from generator import reference, tolerances
from generator.colorimetry.matrices import apply_matrix
from generator.luts import aces_lattice, hsv, hsv_axes
from generator.luts.axes import LogAxis
from generator.luts.evaluate import cell_inputs, shaper_inputs
from generator.luts.hsv_axes import ocio_hsv_to_rgb
from generator.luts.lattice import as_pre_shaper, grid, node_values, preimages
from generator.luts.view import HSV_METHOD, LATTICE_DEFINED, ends_in_light, view_filename, view_lattice
from generator.ocio.curves import curve_label
from generator.ocio.emit import LUT_FOLDER, baked_aces_views
from generator.spec.schema import Display, Spec
from generator.verify import paths, probes
from generator.verify.allowance import hsv_file_allowance, lattice_file_allowance
from generator.verify.check import LUT, Check, baked_lut, discontinuity_band, evaluate, judging
from generator.verify.probes import Family, Probes, Sizes


def lut_checks(spec: Spec, sizes: Sizes) -> list[Check]:
    """Every baked LUT file (a colour space's curve, a display's EOTF) against the curve it
    stands for, on its nodes, between them (a quarter, a half, three quarters of the way)
    and on a ramp."""
    curves = {
        curve_label(spec, s.name, s.curve_name): s.curve for s in spec.colour_spaces if paths.space_is_baked(spec, s)
    }
    curves.update(
        {curve_label(spec, d.name, d.eotf_name): d.eotf for d in spec.displays if paths.eotf_is_baked(spec, d)}
    )
    out = []
    for name, curve in curves.items():
        baked = baked_lut(name, curve)
        nodes = len(baked.values)
        u = np.concatenate([np.arange(4 * (nodes - 1) + 1) / (4.0 * (nodes - 1)), np.linspace(0.0, 1.0, sizes.ramp)])
        lo, hi = baked.domain
        codes = lo + (hi - lo) * u**baked.shaper
        inputs = Probes((Family("LUT nodes and between", np.repeat(u[:, None], 3, axis=1)),))
        keep = discontinuity_band(None, np.repeat(codes[:, None], 3, axis=1), curve)
        out.append(
            Check(
                LUT,
                f"{LUT_FOLDER}/{baked.filename}",
                src=name,
                lut=f"{LUT_FOLDER}/{baked.filename}",
                probes=inputs,
                expected=np.repeat(curve.decode(codes)[:, None], 3, axis=1),
                output=paths.LINEAR,
                tolerance=tolerances.BAKED_CURVE_RELATIVE,
                keep=keep,
            )
        )
    return out


def view_lut_checks(spec: Spec, scene: tuple[Family, ...], sizes: Sizes) -> list[Check]:
    """Every baked view LUT file (a CLF from normalised display-linear RGB, 1 = peak, to
    the display's codes, or to display light that the verifier then encodes in float64,
    applied tetrahedrally) against its view's mapping (:func:`_lattice_probes` for a view
    defined by its lattice)."""
    out: list[Check] = []
    for display in spec.displays:
        to_display = reference.normalised_display_matrix(spec, display)
        families = probes.code_families(0.0, 1.0, sizes) + [
            f if f.name == probes.NON_FINITE else Family(f.name, apply_matrix(to_display, f.values), f.notes)
            for f in scene
        ]
        Probes(tuple(families))
        for view in display.views:
            method = paths.view_method(view)
            if method is None or method in paths.ANALYTIC_METHODS:
                continue
            if method == HSV_METHOD:
                checks = hsv_lut_checks(spec, display, view, families)
                out += [c for c in checks if c.lut not in {o.lut for o in out}]  # one check of the shared file
                continue
            name = f"{LUT_FOLDER}/{view_filename(spec, display, method)}"
            encode = partial(_encode_light, display) if ends_in_light(display) else None
            allowance = None
            if method in LATTICE_DEFINED:
                checked, expected = _lattice_probes(spec, display, method, families)
                allowance = lattice_file_allowance(spec, display, method, checked.values * display.clip_high)
            else:
                fn = paths.view_function(spec, display, view)
                assert fn is not None  # a gamut-mapped view has an evaluation
                checked = Probes((*families, *_output_table_greys(spec, display, method)))
                expected = evaluate(lambda v: fn(apply_matrix(np.linalg.inv(to_display), v)), checked.values)  # noqa: B023
            out.append(
                Check(
                    LUT,
                    name,
                    src=view,
                    lut=name,
                    interpolation="tetrahedral",
                    probes=checked,
                    expected=expected,
                    output=paths.DISPLAY,
                    encode=encode,
                    allowance=allowance,
                    **judging(None, display, None, view),
                )
            )
    return out


def aces_lut_checks(spec: Spec, sizes: Sizes) -> list[Check]:
    """Every baked ACES 2.0 file (AP1, clamped, to limiting RGB over the peak) against its
    float64 evaluation: on the axis's nodes and between them on greys and on each channel
    alone, and on random AP1 colours along the axis."""
    out = []
    for view in baked_aces_views(spec):
        lat = aces_lattice.bake(view)
        halves = np.arange(2 * (lat.size - 1) + 1) / (2.0 * (lat.size - 1))
        axis = lat.value(halves)
        single = np.zeros((3, axis.size, 3))
        for channel in range(3):
            single[channel, :, channel] = axis
        rng = np.random.default_rng(21)
        random = lat.value(rng.random((sizes.random, 3)))
        inputs = Probes(
            (
                Family("AP1 greys on and between nodes", np.repeat(axis[:, None], 3, axis=1)),
                Family("AP1 single channels", single.reshape(-1, 3)),
                Family("AP1 random", random),
            )
        )
        name = f"{LUT_FOLDER}/{aces_lattice.file_name(view)}"
        out.append(
            Check(
                LUT,
                name,
                src=view.name,
                lut=name,
                interpolation="tetrahedral",
                probes=inputs,
                expected=aces_lattice.file_output(lat, inputs.values),
                output=paths.LINEAR,
                tolerance=tolerances.ACES_LATTICE_FILE_RELATIVE,
            )
        )
    return out


def _output_table_greys(spec: Spec, display: Display, method: str) -> tuple[Family, ...]:
    """Greys reading every entry of a view file's output table (a :class:`~generator.luts.axes.
    LogAxis` lattice's 1D table from the mapped grey's coordinate to its code) and the middle
    between neighbours, up to the peak's coordinate, beyond which the mapping sends nothing:
    random colours read the table only where they land. None for a file without one (it ends
    in light)."""
    lat = view_lattice(spec, display, method)
    if lat.post is None or not isinstance(lat.pre, LogAxis):
        return ()
    halves = np.arange(2 * (len(lat.post) - 1) + 1) / (2 * (len(lat.post) - 1))
    grey = lat.pre.position(halves[halves <= float(lat.pre.coordinate(1.0)) + 1e-12])
    return (Family("a grey on every entry of the output table and between", np.repeat(grey[:, None], 3, axis=1)),)


def _lattice_probes(spec: Spec, display: Display, method: str, families: list[Family]) -> tuple[Probes, np.ndarray]:
    """The probes of a view file defined by its lattice (:data:`generator.luts.view.LATTICE_DEFINED`)
    and their expected codes: ``families``, a colour in every cell and colours on every entry of
    the shaper table against the lattice rebuilt from the spec (so no part of the file goes
    unread), and every node against the *mapping itself* at the node's input, rounded as the
    file holds it (a lattice assembled wrongly fails here, whatever the rebuilt lattice says)."""
    lat, peak = view_lattice(spec, display, method), display.clip_high
    through = paths.lattice_codes(spec, display, method)
    lattice_families = (
        *families,
        Family("a colour in every lattice cell", cell_inputs(lat)),
        Family("a channel on every shaper entry and between", shaper_inputs(lat)),
    )
    axis = as_pre_shaper(lat.pre).inverse(preimages(lat.size, lat.shaper, lat.domain))
    nodes = Family("lattice nodes (the mapping itself)", grid(axis).reshape(-1, 3))
    with np.errstate(all="ignore"):
        light = None if lat.light is None else as_pre_shaper(lat.light)
        held = node_values(display, method, axis * peak, None, None, light, lat.decimals).reshape(-1, 3)
        at_nodes = held if light is None else reference.display_encode(display, light.inverse(held) * peak)
        expected = np.concatenate([through(f.values * peak) for f in lattice_families] + [at_nodes])
    return Probes((*lattice_families, nodes)), expected


def hsv_lut_checks(spec: Spec, display: Display, view: str, families: list[Family]) -> list[Check]:
    """The two files of an HSV view (generator.luts.hsv) on their own: the shared file
    from OCIO HSV values of the families' colours to lattice coordinates, and the
    display's file from those coordinates (in float32) to the HSV of the mapped colour,
    judged as the view is, in display codes (the verifier turns the output back into RGB
    with OCIO's HSV_TO_RGB, in float64, and encodes it)."""
    to_display = reference.normalised_display_matrix(spec, display)
    finite = [f for f in families if f.name != probes.NON_FINITE]
    values = [Family(f.name, _float32(hsv_axes.ocio_rgb_to_hsv(f.values)), f.notes) for f in finite]
    shared = Probes((*values, Family("every entry of the table", _float32(hsv_axes.table_inputs()))))
    coordinates = Probes(
        tuple(Family(f.name, _float32(hsv_axes.shared_coordinates(f.values)), f.notes) for f in values)
    )
    shared_name = f"{LUT_FOLDER}/{hsv.SHARED_FILE}"
    fn = paths.view_function(spec, display, view)
    assert fn is not None  # an HSV view has an evaluation

    light = hsv_axes.ocio_hsv_to_rgb(hsv_axes.hsv_of_coordinates(coordinates.values), max_saturation=2.0)
    expected = evaluate(lambda v: fn(apply_matrix(np.linalg.inv(to_display), v)), light)
    name = f"{LUT_FOLDER}/{view_filename(spec, display, HSV_METHOD)}"
    return [
        Check(
            LUT,
            shared_name,
            src=view,
            lut=shared_name,
            probes=shared,
            expected=hsv_axes.shared_coordinates(shared.values),
            output=paths.CODE,
        ),
        Check(
            LUT,
            name,
            src=view,
            lut=name,
            probes=coordinates,
            expected=expected,
            output=paths.DISPLAY,
            encode=partial(_encode_hsv, display),
            allowance=hsv_file_allowance(display, view, light * display.clip_high, expected),
            **judging(None, display, None, view),
        ),
    ]


def _float32(values: np.ndarray) -> np.ndarray:
    return np.asarray(values, dtype=np.float32).astype(np.float64)


def _encode_hsv(display: Display, values: np.ndarray) -> np.ndarray:
    """An HSV view file's output (OCIO HSV of normalised display light) to the display's codes."""
    return _encode_light(display, ocio_hsv_to_rgb(values))


def _encode_light(display: Display, light: np.ndarray) -> np.ndarray:
    """Normalised display light (a view file's output) to the display's codes."""
    with np.errstate(all="ignore"):
        return reference.display_encode(display, np.asarray(light, dtype=np.float64) * display.clip_high)
