"""LUT accuracy: ocioforge's bakes against ociobakelut's, on the same probes.

For each transform (source colour space to display, gamut mapping clip, the
only one a config's display colour space expresses for ociobakelut) this bakes
ocioforge's CLF and Resolve .cube, and ociobakelut's Resolve .cube, then reads
all of them back through PyOpenColorIO, tetrahedral and trilinear, and
measures them against the reference evaluation on the probe sets of
generator.luts.probes (ten-bit codes for SDR, ΔE ITP for HDR).

ociobakelut refuses a shaper space whose conversion from the input space has
channel crosstalk, which any space is when both go through a matrix to the
scene reference (the product of a matrix and its computed inverse is not
exactly diagonal). So its config is built with the source's own linear space
as the scene reference (the same transform, the matrices rounded differently),
and every per-channel space with the source's primaries is tried as a shaper,
as well as none.

Per probe set it prints max/p99 for every bake, then two ratios of p99,
theirs over ours (above 1: ours is better): against ociobakelut's best bake
(the one whose p99 over all four sets pooled is lowest) and against the best
of all its bakes for that set alone; "overall" is the pooled p99. The other
gamut mappings are measured for ocioforge alone (CLF), then every display's
config views as the config runs them, and the Desaturate views' lattices with
trilinear weights rounded as a GPU's texture filtering rounds them (simulated).

Every file is read with OCIO's default optimisation flags, as most hosts run it,
and ocioforge's CLFs also losslessly (each operator as written): the default flags'
fast pow, log and exp move a CLF's decoding curve and Log operator, which the
lossless rows leave out. ocioforge's .cube is also read with its node values
clamped to [0, 1] first, as a reader that clamps a table's entries (a camera's or
monitor's LUT slot, a LUT box) does: fitted nodes lie outside that range.

Run: .venv/bin/python bench/lut_accuracy.py [--size 33]
"""

from __future__ import annotations

import argparse
import dataclasses
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import generator  # noqa: F401  (before numpy: the numbers ocioforge itself gets, see generator/backends.py)

# isort: split
import numpy as np

from generator import reference

PAIRS = (
    ("ACEScg", "sRGB - Display"),
    ("ACEScct", "sRGB - Display"),
    ("ARRI LogC4", "Rec.1886 Rec.709 - Display"),
    ("Linear Rec.2020", "Gamma 2.6 P3-D65 - Display"),
    ("ACEScg", "Rec.2100-PQ - Display"),
)
METHODS = ("clip", "scale", "desaturate", "rgc", "perceptual")
#: Displays whose CLF is also measured for every method (HLG has no ociobakelut comparison here).
EXTRA_DISPLAYS = ("Rec.2100-HLG - Display",)
OVERALL = "overall"


def _figures(errors: dict) -> dict:
    """Set name (and "overall", all sets pooled) to (max, p99)."""
    out = {name: (float(e.max()), float(np.percentile(e, 99))) for name, e in errors.items()}
    pooled = np.concatenate(list(errors.values()))
    out[OVERALL] = (float(pooled.max()), float(np.percentile(pooled, 99)))
    return out


def _fmt(figures: dict) -> str:
    return "  ".join(f"{name} {mx:8.3f}/{p99:7.3f}" for name, (mx, p99) in figures.items())


def linear_twin(spec, source):
    """The linear colour space with ``source``'s primaries (``source`` itself when linear)."""
    from generator.colorimetry.transfer import Linear

    for space in spec.colour_spaces:
        if space.gamut is not None and space.gamut.name == source.gamut.name and isinstance(space.curve, Linear):
            return space
    return None


def shaper_spaces(spec, source) -> list[str]:
    """Per-channel encodings of ``source``'s primaries other than itself."""
    from generator.colorimetry.transfer import Linear

    return [
        s.name
        for s in spec.colour_spaces
        if s.gamut is not None
        and s.gamut.name == source.gamut.name
        and not isinstance(s.curve, Linear)
        and s.name != source.name
        and not s.special
    ]


def ocio_bakes(spec, source, display: str, size: int, folder: Path):
    """ociobakelut's Resolve cubes of source -> display, one per accepted shaper."""
    from generator.ocio.write import build, for_folder

    twin = linear_twin(spec, source)
    config = folder / ("config_" + "".join(c if c.isalnum() else "_" for c in twin.name))
    if not config.exists():
        build(for_folder(dataclasses.replace(spec, scene_reference=twin.name), config, (2, 1)), config)
    for number, shaper in enumerate([None, *shaper_spaces(spec, source)]):
        out = folder / f"ociobakelut_{number}.cube"
        args = [
            "ociobakelut",
            "--iconfig",
            str(config / "config.ocio"),
            "--inputspace",
            source.name,
            "--outputspace",
            display,
            "--format",
            "resolve_cube",
            "--cubesize",
            str(size),
            str(out),
        ]
        if shaper:
            args[-1:-1] = ["--shaperspace", shaper]
        if subprocess.run(args, capture_output=True, text=True).returncode == 0:
            yield shaper or "none", out


def _measure(spec, req, path: Path, method: str, interpolation, optimization: str = "OPTIMIZATION_DEFAULT") -> dict:
    import PyOpenColorIO as ocio

    from generator.luts import probes

    apply = probes.ocio_apply(ocio.FileTransform(str(path), interpolation=interpolation), optimization=optimization)
    sets = probes.reference_sets(spec, req.source, req.display, method)
    return _figures(probes.errors_on(req.display, probes.targets(req.display, sets), apply)[0])


def clamped_cube(path: Path, out: Path) -> Path:
    """A copy of a Resolve .cube with its 3D table's values clamped to [0, 1] (its shaper kept)."""
    lines = path.read_text(encoding="ascii").splitlines(keepends=True)
    shaper = next((int(line.split()[1]) for line in lines if line.startswith("LUT_1D_SIZE")), 0)
    first = next(i for i, line in enumerate(lines) if line[:1] in "-0123456789.")
    table = np.loadtxt(lines[first + shaper :], ndmin=2)
    body = "".join(f"{r:.5f} {g:.5f} {b:.5f}\n" for r, g, b in np.clip(table, 0.0, 1.0))
    out.write_text("".join(lines[: first + shaper]) + body, encoding="ascii")
    return out


def _ratios(ours: dict, theirs: dict[str, dict]) -> tuple[str, str]:
    """Lines of p99 ratios (theirs / ours) against the best bake and the per-set best."""
    best = min(theirs, key=lambda shaper: theirs[shaper][OVERALL][1])
    against_best = "  ".join(
        f"{name} {theirs[best][name][1] / max(p99, 1e-12):6.2f}x" for name, (_, p99) in ours.items()
    )
    per_set = "  ".join(
        f"{name} {min(t[name][1] for t in theirs.values()) / max(p99, 1e-12):6.2f}x" for name, (_, p99) in ours.items()
    )
    return f"vs best bake (shaper {best}): {against_best}", f"vs per-set best: {per_set}"


def compare(spec, source: str, display: str, size: int, folder: Path) -> None:
    import PyOpenColorIO as ocio

    from generator.luts import bake

    interpolations = (("tetrahedral", ocio.INTERP_TETRAHEDRAL), ("trilinear", ocio.INTERP_LINEAR))
    print(f"\n== {source} -> {display}, clip, {size}^3, max/p99 per probe set")
    ours = {}
    for fmt in ("clf", "resolve_cube"):
        req = bake.request(spec, source, display, "clip", fmt, size)
        path = folder / f"ours{bake.FORMATS[fmt].suffix}"
        path.write_bytes(bake.bake(req)[""])
        for label, interpolation in interpolations:
            ours[(fmt, label)] = _measure(spec, req, path, "clip", interpolation)
            print(f"  ocioforge {fmt:12s} {label:11s} {_fmt(ours[(fmt, label)])}")
        if fmt == "clf":
            lossless = _measure(spec, req, path, "clip", ocio.INTERP_TETRAHEDRAL, "OPTIMIZATION_LOSSLESS")
            print(f"  ocioforge clf lossless   tetrahedral {_fmt(lossless)}")
        else:
            clamped = _measure(spec, req, clamped_cube(path, folder / "clamped.cube"), "clip", ocio.INTERP_TETRAHEDRAL)
            print(f"  ocioforge .cube clamped  tetrahedral {_fmt(clamped)}")
            ours[("clamped", "tetrahedral")] = clamped
    theirs = {label: {} for label, _ in interpolations}
    for shaper, path in ocio_bakes(spec, req.source, display, size, folder):
        for label, interpolation in interpolations:
            theirs[label][shaper] = _measure(spec, req, path, "clip", interpolation)
            print(f"  ociobakelut {shaper[:22]:22s} {label:11s} {_fmt(theirs[label][shaper])}")
    for label, _ in interpolations:
        for fmt in ("resolve_cube", "clf", "clamped"):
            if (fmt, label) in ours:
                for line in _ratios(ours[(fmt, label)], theirs[label]):
                    print(f"  ratio {fmt:12s} {label:11s} {line}")


def methods(spec, source: str, display: str, size: int, folder: Path) -> None:
    import PyOpenColorIO as ocio

    from generator.luts import bake

    for method in METHODS:
        req = bake.request(spec, source, display, method, "clf", size)
        path = folder / "method.clf"
        path.write_bytes(bake.bake(req)[""])
        figures = _measure(spec, req, path, method, ocio.INTERP_TETRAHEDRAL)
        print(f"  ocioforge clf {method:11s} {_fmt(figures)}")
        lossless = _measure(spec, req, path, method, ocio.INTERP_TETRAHEDRAL, "OPTIMIZATION_LOSSLESS")
        print(f"      lossless  {method:11s} {_fmt(lossless)}")


def config_views(spec) -> None:
    """The config's baked views of every display (HDR displays' files end in display light,
    which the config's display space encodes; Desaturate is a lattice in OCIO's HSV),
    measured through OCIO on ACEScg colours against the mapping. Perceptual's view is its
    lattice (verify holds OCIO to that): its row is the lattice's departure from the mapping."""
    from generator.luts.view import bake_view_lut
    from generator.ocio.view_luts import view_figures

    print(
        "\n== config views (as the config runs them) against the mapping, ten-bit codes (SDR) or ΔE ITP (HDR), "
        "max/p99; perceptual: how far its lattice departs from the mapping"
    )
    for display in spec.displays:
        for method in ("scale", "desaturate", "perceptual"):
            lut = bake_view_lut(spec, display, method)
            figures = {name: (f.maximum, f.p99) for name, f in view_figures(lut).items()}
            print(f"  {display.name[:24]:24s} {method:11s} {_fmt(figures)}")


#: Bits of the interpolation weights a GPU's texture filtering commonly keeps (OCIO's GPU
#: renderer lets the hardware interpolate trilinear 3D LUTs).
GPU_WEIGHT_BITS = 8


def gpu_desaturate(spec) -> None:
    """The Desaturate views' lattices interpolated with GPU_WEIGHT_BITS-bit weights, as a GPU's
    texture filtering does, against the reference (the 1D tables' exact functions, float64)."""
    from generator import reference
    from generator.luts import hsv, hsv_axes, probes

    print(
        f"\n== Desaturate views, trilinear weights rounded to {GPU_WEIGHT_BITS} bits (a GPU's texture "
        "filtering, simulated), ten-bit codes max/p99"
    )
    for display in (d for d in spec.displays if "Desaturate" in d.views):
        lat, to_display = hsv.hsv_lattice(display), reference.scene_to_display_matrix(spec, display)
        figures = {}
        for name, ref in probes.probes(spec, spec.space("ACEScg"), display).items():
            values = hsv_axes.ocio_rgb_to_hsv(reference.apply_matrix(to_display, ref) / display.clip_high)
            out = hsv.apply(lat, values, GPU_WEIGHT_BITS)
            light = np.clip(hsv_axes.ocio_hsv_to_rgb(out), 0.0, 1.0) * display.clip_high
            error = probes.errors(
                display,
                reference.display_encode(display, light),
                reference.mapped_view(spec, display, "desaturate", ref),
            )[0]
            figures[name] = (float(error.max()), float(np.percentile(error, 99)))
        print(f"  {display.name[:24]:24s} {_fmt(figures)}")


#: ACES views baked by ``ocioforge bake --view``, each on a display that shows it, from these sources.
ACES_VIEWS = (
    ("ACES 2.0 - SDR 100 nits (Rec.709)", "sRGB - Display"),
    ("ACES 2.0 - HDR 1000 nits (P3 D65)", "Rec.2100-PQ - Display"),
)
ACES_SOURCES = ("ACEScct", "ACEScg")
ACES_FORMATS = ("clf", "resolve_cube", "iridas_cube", "spi3d")
#: The ACES studio config whose views ociobakelut bakes, and the shaper spaces it takes there
#: (per channel from ACEScct and ACEScg: ACEScc's conversion has crosstalk), at two shaper sizes.
STUDIO_CONFIG = "ocio://studio-config-v5.0.0_aces-v2.1_ocio-v2.6"
STUDIO_SHAPERS = (None, "ACEScct", "sRGB Encoded AP1", "Gamma 2.2 Encoded AP1", "ACEScg")
STUDIO_SHAPER_SIZES = (4096, 65536)
ACES_CUBE_SIZE = 65


def studio_bakes(source: str, view: str, display: str, folder: Path):
    """ociobakelut's Resolve cubes of the studio config's view, one per accepted shaper and size:
    (label, path)."""
    tool = Path(sys.executable).with_name("ociobakelut")  # OCIO 2.6's, which has the studio config built in
    for number, (shaper, count) in enumerate((s, n) for s in STUDIO_SHAPERS for n in STUDIO_SHAPER_SIZES):
        if shaper is None and count != STUDIO_SHAPER_SIZES[0]:
            continue
        out = folder / f"studio_{number}.cube"
        args = [
            str(tool if tool.exists() else "ociobakelut"),
            "--iconfig",
            STUDIO_CONFIG,
            "--inputspace",
            source,
            "--displayview",
            display,
            view,
            "--format",
            "resolve_cube",
            "--cubesize",
            str(ACES_CUBE_SIZE),
            str(out),
        ]
        if shaper:
            args[-1:-1] = ["--shaperspace", shaper, "--shapersize", str(count)]
        if subprocess.run(args, capture_output=True, text=True).returncode == 0:
            yield (f"{shaper}, {count}" if shaper else "none"), out


def _aces_figures(spec, source, display, view: str, apply) -> dict:
    """Set name to (p99, max) of ``apply`` (source codes to display codes) on bench/aces_views.py's
    probe sets, against the reference."""
    from aces_views import probe_sets

    from generator.luts import aces_probes, probes

    out = {}
    for name, aces in probe_sets(display).items():
        code, expected = aces_probes.in_source(spec, source, display, view, aces)
        e = probes.errors(display, apply(code), expected)[0]
        out[name] = (float(np.percentile(e, 99)), float(e.max()))
    return out


def _pooled_p99(spec, source, display, view: str, apply) -> float:
    from aces_views import probe_sets

    from generator.luts import aces_probes, probes

    errors = []
    for aces in probe_sets(display).values():
        code, expected = aces_probes.in_source(spec, source, display, view, aces)
        errors.append(probes.errors(display, apply(code), expected)[0])
    return float(np.percentile(np.concatenate(errors), 99))


def aces_views(spec, folder: Path) -> None:
    """Every format of ``ocioforge bake --view`` at 65³ against the float64 reference, beside
    ociobakelut's best bake of the studio config's view (the lowest p99 over the six sets pooled)
    and the plain recipe (:mod:`generator.luts.plain`), all read through OCIO (default flags,
    tetrahedral), on bench/aces_views.py's probe sets. Prints a Markdown table."""
    import time

    import PyOpenColorIO as ocio

    from generator.luts import bake, probes
    from generator.luts.plain import plain_recipe
    from generator.rendering import views

    def read(paths):
        steps = [ocio.FileTransform(str(p), interpolation=ocio.INTERP_TETRAHEDRAL) for p in reversed(paths)]
        return probes.ocio_apply(steps[0] if len(steps) == 1 else ocio.GroupTransform(steps))

    print(f"\n== ACES views, {ACES_CUBE_SIZE}^3, p99 / max per probe set (ten-bit codes; HDR: ΔE ITP)")
    print(
        "| view (display) | source | set | CLF | Resolve .cube | Iridas .cube | .spi3d | ociobakelut's best "
        "| plain recipe |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
    )
    for view, display_name in ACES_VIEWS:
        for source_name in ACES_SOURCES:
            ours, seconds = {}, {}
            for fmt in ACES_FORMATS:
                try:
                    started = time.perf_counter()
                    req = bake.request(spec, source_name, display_name, None, fmt, ACES_CUBE_SIZE, "auto", view)
                    files = bake.paths(bake.bake(req), folder / f"aces{bake.FORMATS[fmt].suffix}")
                    seconds[fmt] = time.perf_counter() - started
                except ValueError:  # refused (a linear source's Iridas .cube)
                    continue
                bake.write(files, force=True)
                ours[fmt] = _aces_figures(spec, req.source, req.display, view, read(list(files)))
            source, display = spec.space(source_name), req.display
            best, label = None, ""
            for shaper, path in studio_bakes(source_name, view, display_name, folder):
                p99 = _pooled_p99(spec, source, display, view, read([path]))
                if best is None or p99 < best[0]:
                    best = (p99, _aces_figures(spec, source, display, view, read([path])), shaper)
            plain = plain_recipe(spec, display, views.catalogue()[view])
            to_aces = reference.to_aces_matrix(spec) @ reference.space_matrix(spec, source)
            plain_figures = _aces_figures(
                spec,
                source,
                display,
                view,
                lambda code: plain(reference.apply_matrix(to_aces, source.curve.decode(code))),  # noqa: B023 (called at once)
            )
            for name in plain_figures:
                cells = [
                    f"{ours[f][name][0]:.2f} / {ours[f][name][1]:.1f}" if f in ours else "refused" for f in ACES_FORMATS
                ]
                theirs = f"{best[1][name][0]:.2f} / {best[1][name][1]:.1f}" if best else "none"
                print(
                    f"| {view} ({display_name}) | {source_name} | {name} | {' | '.join(cells)} | {theirs} | "
                    f"{plain_figures[name][0]:.2f} / {plain_figures[name][1]:.1f} |"
                )
            label = best[2] if best else "none"
            print(
                f"  (ociobakelut's best: shaper {label}; bake seconds: "
                + ", ".join(f"{f} {t:.2f}" for f, t in seconds.items())
                + ")"
            )


def main(argv=None) -> None:
    from generator.spec import load

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=33)
    parser.add_argument("--aces-only", action="store_true", help="only the ACES views (ocioforge bake --view)")
    args = parser.parse_args(argv)
    if shutil.which("ociobakelut") is None:
        sys.exit("ociobakelut is not installed")
    spec = load.load()
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        aces_views(spec, folder)
        if args.aces_only:
            return
        for source, display in PAIRS:
            compare(spec, source, display, args.size, folder)
            methods(spec, source, display, args.size, folder)
        for display in EXTRA_DISPLAYS:
            print(f"\n== ACEScg -> {display}, {args.size}^3, ocioforge CLF only")
            methods(spec, "ACEScg", display, args.size, folder)
    config_views(spec)
    gpu_desaturate(spec)


if __name__ == "__main__":
    main()
