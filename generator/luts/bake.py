"""Baking one transform, source colour space to display, into LUT files.

The transform is the reference evaluation
(:func:`~generator.reference.mapped_view`): decode the source,
matrix with chromatic adaptation, gamut map, display encoding. Which lattice
layout each format gets is in :mod:`generator.luts.lattice`; bad requests raise
:class:`~generator.spec.schema.SpecError` before anything is computed, and
:func:`write` replaces the output only once every byte is ready.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from generator import reference
from generator.colorimetry import library
from generator.colorimetry.transfer import Linear
from generator.files import check_file_output, write_files
from generator.gamut import METHODS
from generator.luts import aces_bake, fit, formats, lattice, source_axes
from generator.luts.axes import LogAxis
from generator.luts.names import slug
from generator.rendering import views
from generator.spec.fields import suggest
from generator.spec.schema import ColourSpace, Display, Spec, SpecError

WHERE = "ocioforge bake"

#: The gamut mapping of ``ocioforge bake`` and of the standalone pack: clip's result
#: inside the gamut and for negative components, the chromaticity of over-range colours
#: kept; its CLF is exact but for float32 (0.011 ten-bit codes at 33³, see luts/README.md).
DEFAULT_METHOD = "scale"

DEFAULT_SIZE = 33

#: Nodes a side of an ACES view's lattice by default: the plain recipe's (bench/aces_views.py).
ACES_SIZE = 65


@dataclass(frozen=True)
class Format:
    """A LUT format: its file suffix, lattice sizes OCIO reads, and what it can hold."""

    suffix: str
    max_size: int
    shaper: bool
    matrix: bool


#: OpenColorIO reads 3D LUTs of at most 129 nodes a side (Resolve's own limit is 256).
FORMATS = {
    "resolve_cube": Format(".cube", 129, True, False),
    "iridas_cube": Format(".cube", 129, False, False),
    "spi3d": Format(".spi3d", 129, True, False),
    "clf": Format(".clf", 129, True, True),
}

_BY_SUFFIX = {".cube": "resolve_cube", ".spi3d": "spi3d", ".clf": "clf"}

#: The suffix of the shaper file written beside a .spi3d.
SHAPER_SUFFIX = ".spi1d"


@dataclass(frozen=True)
class Request:
    """A validated bake: everything :func:`bake` needs."""

    spec: Spec
    source: ColourSpace
    display: Display
    method: str
    fmt: str
    size: int
    shaper: str | ColourSpace
    #: An ACES view (:class:`~generator.rendering.views.ACESView`) baked instead of a gamut mapping.
    view: views.ACESView | None = None


def find_display(spec: Spec, name: str, field: str) -> Display:
    """The display called ``name`` or one of its aliases; SpecError naming the kind otherwise."""
    for display in spec.displays:
        if name.lower() in (n.lower() for n in (display.name, *display.aliases)):
            return display
    try:
        space = spec.space(name)
    except KeyError:
        names = [n for d in spec.displays for n in (d.name, *d.aliases)]
        raise SpecError(
            WHERE,
            field,
            f"unknown display {name!r}{suggest(name, names)}; allowed: {', '.join(d.name for d in spec.displays)}",
        ) from None
    raise SpecError(WHERE, field, f"{space.name!r} is a scene colour space; {field} takes a display")


def find_source(spec: Spec, name: str, field: str, role: str = "source") -> ColourSpace:
    """An encoded scene colour space (not data, not a display, a per-channel curve and primaries)."""
    try:
        space = spec.space(name)
    except KeyError:
        if any(name.lower() in (n.lower() for n in (d.name, *d.aliases)) for d in spec.displays):
            raise SpecError(WHERE, field, f"{name!r} is a display; {field} takes a scene colour space") from None

        if name.lower() in (n.lower() for d in library.SPACES for n in (d.name, *d.aliases)):
            raise SpecError(
                WHERE,
                field,
                f"{name!r} is in the library but not in this spec ({spec.source}); allowed: "
                f"add it to the spec's colour_spaces{suggest(name, spec.space_names)}",
            ) from None
        raise SpecError(
            WHERE,
            field,
            f"unknown colour space {name!r}{suggest(name, spec.space_names)}; 'ocioforge list' lists the library's",
        ) from None
    if space.is_data:
        raise SpecError(WHERE, field, f"{space.name!r} is data (never colour managed); it cannot be a {role}")
    if space.special or space.gamut is None:
        raise SpecError(
            WHERE,
            field,
            f"{space.name!r} is not a per-channel curve of RGB primaries (it decodes to "
            "the scene reference by its own transform); allowed: a space with a curve and primaries",
        )
    return space


def format_for(fmt: str | None, output: str) -> str:
    """The format named, or the one the output's suffix implies."""
    if fmt is None:
        suffix = Path(output).suffix.lower()
        if suffix not in _BY_SUFFIX:
            raise SpecError(
                WHERE,
                "--format",
                f"cannot tell the format from {suffix or 'no suffix'!r}; give --format ({', '.join(FORMATS)})",
            )
        return _BY_SUFFIX[suffix]
    fmt = fmt.lower()
    if fmt not in FORMATS:
        raise SpecError(WHERE, "--format", f"unknown format {fmt!r}; allowed: {', '.join(FORMATS)}")
    suffix = Path(output).suffix.lower()
    if suffix != FORMATS[fmt].suffix:
        ends = f"ends in {suffix}" if suffix else "has no suffix"
        raise SpecError(
            WHERE,
            "-o",
            f"{Path(output).name!r} {ends}, not {fmt}'s; allowed: a name "
            f"ending in {FORMATS[fmt].suffix} (hosts tell formats by suffix)",
        )
    return fmt


def request(
    spec: Spec,
    source: str,
    display: str,
    method: str,
    fmt: str,
    size: int,
    shaper: str = "auto",
    view: str | None = None,
) -> Request:
    """Validate a bake's parameters (SpecError naming the option otherwise). With ``view`` (an
    ACES view's name) the bake is that view and ``method`` is not used."""
    if fmt not in FORMATS:
        raise SpecError(WHERE, "--format", f"unknown format {fmt!r}; allowed: {', '.join(FORMATS)}")
    if view is None and method not in METHODS:
        raise SpecError(WHERE, "--gamut-map", f"unknown method {method!r}; allowed: {', '.join(METHODS)}")
    src, dst = find_source(spec, source, "--from"), find_display(spec, display, "--to")
    aces = None if view is None else find_view(dst, view)
    chosen: str | ColourSpace = shaper.lower() if shaper.lower() in SHAPER_KEYWORDS else shaper
    if chosen not in SHAPER_KEYWORDS:
        if not FORMATS[fmt].shaper:
            raise SpecError(WHERE, "--shaper", f"{fmt} holds no shaper; allowed: auto, none")
        chosen = _shaper_space(spec, shaper)
    _refuse_linear_without_shaper(src, fmt, chosen)
    top = FORMATS[fmt].max_size
    smallest = ACES_SMALLEST if aces is not None else _smallest_size(spec, dst, src, method, fmt, chosen)
    if not smallest <= size <= top:
        raise SpecError(WHERE, "--size", f"{size} is outside what {fmt} allows here: {smallest} to {top}")
    return Request(spec, src, dst, aces.name if aces is not None else method, fmt, size, chosen, aces)


#: Fewest nodes a side of an ACES view's lattice (its source layout puts 0 on a node with two
#: intervals above it at least).
ACES_SMALLEST = 4


def find_view(display: Display, name: str):
    """The ACES view called ``name`` that ``display`` can show (SpecError naming ``--view``
    otherwise), in any case: a studio view, or the display's own ACES 2.0 view; "ACES 2.0" is the
    display's first ACES 2.0 studio view, or its own."""
    shown = [v for v in (*views.catalogue(), _own_name(display)) if v and _shows(display, v)]
    if name.lower() == views.OWN_ACES2.lower():
        studio = [v for v in views.STUDIO_VIEWS.get(display.name, ()) if v.startswith(views.OWN_ACES2 + " - ")]
        name = studio[0] if studio else _own_name(display) or name
    name = next((v for v in (*views.catalogue(), _own_name(display)) if v and v.lower() == name.lower()), name)
    found = reference.aces_view_of(display, name)
    if found is None:
        raise SpecError(
            WHERE,
            "--view",
            f"unknown ACES view {name!r} for {display.name!r}; allowed: "
            f"{views.OWN_ACES2!r} or one it can show: {', '.join(shown)}",
        )
    why = views.cannot_show(found, display.gamut.primaries, display.peak, display.is_hdr or display.absolute)
    if why:
        raise SpecError(WHERE, "--view", f"{display.name!r} cannot show {name!r}: {why}; allowed: {', '.join(shown)}")
    return found


def _own_name(display: Display) -> str:
    """The display's own ACES 2.0 view's name ("" where the algorithm cannot take the display)."""
    try:
        return views.own_view(display.name, display.peak, display.gamut.primaries, display.gamut.whitepoint).name
    except ValueError:
        return ""


def _shows(display: Display, name: str) -> bool:
    found = reference.aces_view_of(display, name)
    return found is not None and not views.cannot_show(
        found, display.gamut.primaries, display.peak, display.is_hdr or display.absolute
    )


#: ``--shaper`` words that name no colour space (matched in any case, before space names).
SHAPER_KEYWORDS = ("auto", "none")


def _shaper_space(spec: Spec, name: str) -> ColourSpace:
    """The colour space whose curve spaces a lattice's nodes: encoded, not linear (a lattice
    uniform in linear light leaves black hundreds of codes off)."""
    space = find_source(spec, name, "--shaper", "shaper")
    if isinstance(space.curve, Linear):
        raise SpecError(
            WHERE,
            "--shaper",
            f"{space.name!r} is linear, which would space the nodes uniformly in light "
            "(black off by hundreds of ten-bit codes); allowed: auto, or a space with a log or video curve",
        )
    with np.errstate(all="ignore"):
        ends = space.curve.decode(np.array([0.0, 1.0]))
    if not (np.all(np.isfinite(ends)) and ends[0] < ends[1]):
        raise SpecError(
            WHERE,
            "--shaper",
            f"{space.name!r}'s codes 0 to 1 hold no range of light to space nodes "
            "over; allowed: auto, or a space whose curve rises over codes 0 to 1",
        )
    return space


def _refuse_linear_without_shaper(source: ColourSpace, fmt: str, shaper) -> None:
    """A lattice with no shaper over a linear source is uniform in linear light, up to 16 times
    white: two of a 33³ lattice's nodes lie below display white, and ACEScg black comes out at
    sRGB code 0.25. No request for such a file is taken (a log source's codes are its shaper)."""
    if not isinstance(source.curve, Linear) or (FORMATS[fmt].shaper and shaper != "none"):
        return
    option, what = ("--format", f"{fmt} holds no shaper") if not FORMATS[fmt].shaper else ("--shaper", "no shaper")
    raise SpecError(
        WHERE,
        option,
        f"{what}, and {source.name!r} is linear: a lattice uniform in linear light up to "
        "16 times white cannot follow the display's encoding (black off by hundreds of ten-bit codes); "
        "allowed: a format with a shaper (resolve_cube, spi3d, clf) with --shaper auto or a log space, "
        "or a log source of the same primaries",
    )


def _smallest_size(spec: Spec, display: Display, source: ColourSpace, method: str, fmt: str, shaper) -> int:
    """Fewest nodes a side the layout needs (2 without a shaper)."""
    if shaper == "none" or not FORMATS[fmt].shaper:
        return 2
    for size in range(2, 16):
        try:
            if fmt == "clf" and shaper == "auto":
                lattice.display_axis(display, size, method)
            else:
                source_axes.source_axis(spec, source, display, size)
            return size
        except ValueError:
            continue
    return 16


def build_lattice(req: Request) -> lattice.Lattice:
    """The lattice ``req`` asks for: an ACES view's or a gamut mapping's, in the layout its format takes."""
    if req.view is not None:
        if req.fmt == "clf" and req.shaper == "auto":
            return aces_bake.display_lattice(req.spec, req.source, req.display, req.view, req.size)
        shaper = "none" if not FORMATS[req.fmt].shaper else req.shaper
        return aces_bake.source_lattice(req.spec, req.source, req.display, req.view, req.size, shaper)
    if req.fmt == "clf" and req.shaper == "auto":
        return lattice.display_lattice(req.spec, req.display, req.method, req.size, source=req.source)
    shaper = "none" if not FORMATS[req.fmt].shaper else req.shaper
    return fit.source_lattice(req.spec, req.source, req.display, req.method, req.size, shaper)


def describe(req: Request) -> str:
    """``req`` in one line: source, display, view or mapping, lattice size."""
    if req.view is not None:
        return f"{req.source.name} to {req.display.name}, view {req.view.name}, {req.size}^3 lattice"
    return f"{req.source.name} to {req.display.name}, gamut mapping {req.method}, {req.size}^3 lattice"


def notes(req: Request, lat: lattice.Lattice) -> list[str]:
    """Comment lines: what the file does and what its input is."""
    if req.view is not None:
        return [f"ocioforge: {describe(req)}.", *aces_bake.notes(lat, req.view, req.shaper)]
    lo, hi = lat.domain
    top = float(reference.display_encode(req.display, np.full(3, req.display.clip_high))[0])
    output = f"Output: {req.display.name} code values (full range, 0 to {top:.6g})."
    if lat.pre is not None:
        low, high = (0.0, lat.pre.high) if isinstance(lat.pre, LogAxis) else lat.pre.inverse(np.array(lat.domain))
        return [
            f"ocioforge: {describe(req)}.",
            f"Input: {req.source.name} values, decoded and converted to {req.display.name} light exactly; the "
            f"lattice covers {low:.9g} to {high:.9g} times the display's peak per channel (clamped beyond).",
            output,
        ]
    low, high = float(lat.cube.min()), float(lat.cube.max())
    output = output[:-1] + f" for black to the peak; the fitted node values range from {low:.6g} to {high:.6g}."
    lines = [
        f"ocioforge: {describe(req)}.",
        f"Input: {req.source.name} values, sampled over [{lo:.9g}, {hi:.9g}] (clamped outside).",
        output,
    ]
    if lat.shaper is not None and req.shaper == "auto":
        lines.append(
            "A 1D shaper spaces the nodes by the display's code values of the decoded input "
            "(by a root of it above the peak), linear in code values between nodes."
        )
    lines.append(
        "Node values are fitted by least squares to colours of the source gamut; greys and colours "
        "with a zero channel keep the sampled values. Interpolate tetrahedrally."
    )
    return lines


def bake(req: Request) -> dict[str, bytes]:
    """The files of a bake: suffix ("" for the main file) to bytes."""
    return lattice_files(req, build_lattice(req))


def lattice_files(req: Request, lat: lattice.Lattice) -> dict[str, bytes]:
    """The files of ``req``'s format holding ``lat`` (built for ``req``): suffix to bytes."""
    title = describe(req)
    if req.fmt == "resolve_cube":
        return {"": formats.resolve_cube(lat, title, notes(req, lat))}
    if req.fmt == "iridas_cube":
        return {"": formats.iridas_cube(lat, title, notes(req, lat))}
    if req.fmt == "spi3d":
        if not formats.needs_spi1d(lat):
            return {"": formats.spi3d(lat, [f"ocioforge: {title}.", *notes(req, lat)[1:]])}
        chain = (
            f"Apply the {SHAPER_SUFFIX} of the same name first (its 1D shaper, linear), then the .spi3d "
            "(tetrahedral): in OCIO a GroupTransform of the two FileTransforms, in Nuke two OCIOFileTransform "
            "nodes in that order."
        )
        return {
            "": formats.spi3d(lat, [f"ocioforge: {title}.", *notes(req, lat)[1:], chain]),
            SHAPER_SUFFIX: formats.spi1d_shaper(lat, [f"ocioforge: the shaper of {title}.", chain]),
        }
    return {
        "": formats.clf(
            lat, identifier(req), " ".join(notes(req, lat)), descriptors=(req.source.name, req.display.name)
        )
    }


def identifier(req: Request) -> str:
    """The identifier written in ``req``'s file (its source, display, method and size)."""
    return f"ocioforge:{slug(req.source.name)}_to_{slug(req.display.name)}_{slug(req.method)}_{req.size}"


def _beside(output: str | Path) -> Path:
    """The file a shaper goes beside: ``output``, or the file it links to (where the main file
    is written), so a .spi3d and its .spi1d stay a pair."""
    output = Path(output)
    return Path(os.path.realpath(output)) if output.is_symlink() else output


def paths(files: dict[str, bytes], output: str | Path) -> dict[Path, bytes]:
    """Where each file goes: the main file at ``output``, a shaper beside it (beside the file
    ``output`` links to, if it is a link) with its own suffix."""
    output = Path(output)
    return {(output if not suffix else _beside(output).with_suffix(suffix)): data for suffix, data in files.items()}


def stale(files: dict[Path, bytes], output: str | Path, fmt: str) -> list[Path]:
    """Files an earlier bake to ``output`` left that this one does not write: the shaper
    beside a .spi3d (paired with the new file, it would put colours tens of codes off)."""
    shaper = _beside(output).with_suffix(SHAPER_SUFFIX)
    return [shaper] if fmt == "spi3d" and shaper not in files and shaper.is_file() else []


def write(files: dict[Path, bytes], force: bool = False, remove: list[Path] | None = None) -> None:
    """Write every file or none (:func:`generator.files.write_files`, which refuses what is there
    without ``force``), after checking each path's folder exists; then, with ``force``,
    delete ``remove`` (:func:`stale`: refused without it, as the files it replaces are)."""
    for path in remove or ():
        if not force:
            raise SpecError(
                WHERE,
                "-o",
                f"{str(path)!r} exists, an earlier bake's shaper this one does not write; "
                "pass --force to replace the bake and delete it",
            )
    for path in files:
        check_file_output(path)
    write_files(files, force)
    for path in remove or ():
        path.unlink(missing_ok=True)
