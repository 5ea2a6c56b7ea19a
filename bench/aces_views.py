"""ACES 2.0 views baked for OCIO 2.1-2.3: accuracy against the float64 output transform.

For each ACES 2.0 studio view a 2.1 config bakes (on a display that shows it), prints the
error of ocioforge's lattice (the file's float64 evaluation, which OCIO runs within 2e-6 of
the peak with its lossless flags) and of the plain recipe public generators use (AP0 to AP1, an ACEScct
shaper, a 65³ table of display codes sampled from the same reference), measured in one run
on the same probe sets: ten-bit codes on SDR displays, ΔE ITP (BT.2124) on HDR ones; p99 and
max per set; then each file's size and the bake time.

Last, why a table with AP1's channels as its axes cannot meet 1 code p99: the reference's own
bend. For each probe, the largest gap between the view's codes at a colour and the mean of its
codes a step either side along six random directions of log2(AP1 + toe), for steps of 1/4, 1/16
and 1/64 stop. That gap is the error of a straight line between two points twice the step
apart, at its middle: what a lattice with nodes that far apart pays between them, before
any fitting.
"""

from __future__ import annotations

import time

import generator  # noqa: F401  (numpy's settings first)

# isort: split
import numpy as np

from generator import reference
from generator.luts import aces_axes, aces_lattice, aces_probes, probes
from generator.luts.plain import plain_recipe
from generator.rendering import views
from generator.spec.load import load

#: The display each view is measured on.
DISPLAYS = {
    "ACES 2.0 - SDR 100 nits (Rec.709)": "sRGB - Display",
    "ACES 2.0 - SDR 100 nits (P3 D65)": "Display P3 - Display",
    "ACES 2.0 - HDR 1000 nits (P3 D65)": "Rec.2100-PQ - Display",
    "ACES 2.0 - HDR 1000 nits (Rec.2020)": "Rec.2100-PQ - Display",
    "ACES 2.0 - HDR 500 nits (Rec.2020)": "Rec.2100-PQ - Display",
    "ACES 2.0 - HDR 108 nits (P3 D65)": "ST2084-P3-D65 - Display",
}


def probe_sets(display, seed: int = 11, n: int = 20000) -> dict[str, np.ndarray]:
    """ACES2065-1 probes: the issue's six sets (:func:`generator.luts.aces_probes.sets`), by label."""
    return {aces_probes.LABELS[k]: v for k, v in aces_probes.sets(display, seed, n).items()}


def main() -> None:
    spec = load(None)
    shown = {d.name: d for d in spec.displays}
    print(f"{'view':<36} {'set':<9} {'ocioforge p99':>13} {'max':>7} {'plain p99':>10} {'max':>7}  unit")
    for name, display_name in DISPLAYS.items():
        view, display = views.catalogue()[name], shown[display_name]
        started = time.perf_counter()
        lat = aces_lattice.baked(view)
        seconds = time.perf_counter() - started
        plain = plain_recipe(spec, display, view)
        unit = "ΔE ITP" if display.is_hdr else "10-bit codes"
        for set_name, aces in probe_sets(display).items():
            truth = reference.display_xyz_encode(spec, display, views.evaluate(view, aces))
            ours = probes.errors(
                display, reference.display_xyz_encode(spec, display, aces_lattice.evaluate(lat, aces)), truth
            )[0]
            theirs = probes.errors(display, plain(aces), truth)[0]
            print(
                f"{name:<36} {set_name:<9} {np.percentile(ours, 99):13.2f} {ours.max():7.1f} "
                f"{np.percentile(theirs, 99):10.2f} {theirs.max():7.1f}  {unit}"
            )
        size_mb = len(aces_lattice.ocio_file(lat)) / 1e6
        print(
            f"{name:<36} bake {seconds:.2f} s, file {size_mb:.1f} MB ({lat.size}³ table, half of it reached: "
            f"{lat.size**2 * (lat.size + 1) // 2} nodes, the plain recipe's 65³ {65**3})"
        )


#: Steps (stops of AP1) of the bend measurement, and its probes per set.
BEND_STEPS, BEND_COUNT = (1 / 4, 1 / 16, 1 / 64), 4000


def bend(name: str = "ACES 2.0 - SDR 100 nits (Rec.709)") -> None:
    """Print the reference's midpoint gap per set and step (see the module's docstring)."""
    spec = load(None)
    view, display = views.catalogue()[name], {d.name: d for d in spec.displays}[DISPLAYS[name]]
    t, lat = views.tables(view), aces_lattice.bake(view)
    toe = lat.axes.log.toe
    node = float(lat.coordinate(np.ones((1, 3)))[0, 2]) + np.array([0.0, 1.0 / (lat.size - 1)])
    per_stop = 1.0 / float(np.diff(np.log2(lat.value(node) + toe))[0])

    def codes(log):
        ap1 = np.clip(np.exp2(log) - toe, 0.0, lat.upper)
        return reference.display_xyz_encode(spec, display, views.evaluate(view, ap1 @ t.ap1_to_ap0.T))

    rng = np.random.default_rng(1)
    print(f"\n{name} on {display.name}: the reference's midpoint gap, 10-bit codes p99 / max")
    light = aces_axes.thinning(view)[0]
    print(
        f"(the {lat.size}³ table's luminance nodes are 1/{per_stop:.1f} stop apart below {light:g}: "
        f"a step of 1/{2 * per_stop:.1f})"
    )
    print(f"{'set':<9} " + " ".join(f"{f'step 1/{round(1 / d)} stop':>20}" for d in BEND_STEPS))
    for set_name, aces in probe_sets(display, n=BEND_COUNT).items():
        log = np.log2(np.clip(aces @ t.ap0_to_ap1.T, 0.0, lat.upper) + toe)
        cells = []
        for step in BEND_STEPS:
            gap = np.zeros(len(log))
            for _ in range(6):
                way = rng.standard_normal(log.shape)
                way *= step / np.linalg.norm(way, axis=1, keepdims=True)
                middle = codes(log) - 0.5 * (codes(log + way) + codes(log - way))
                gap = np.maximum(gap, np.abs(middle).max(axis=1) * 1023.0)
            cells.append(f"{np.percentile(gap, 99):10.2f} / {gap.max():6.1f}")
        print(f"{set_name:<9} " + " ".join(f"{c:>20}" for c in cells))


if __name__ == "__main__":
    main()
    bend()
