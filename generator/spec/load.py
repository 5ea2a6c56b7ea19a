"""Reading a TOML spec (or the embedded default) into a frozen :class:`Spec`.

Strict: an unknown key is an error listing the allowed ones; an unknown
colour-space name suggests close matches. Nothing in a spec is executed.
"""

from __future__ import annotations

import re
import tomllib
from dataclasses import replace
from functools import lru_cache
from importlib import resources
from pathlib import Path

import numpy as np

from generator import tolerances
from generator.colorimetry import library
from generator.colorimetry.matrices import CATS, Gamut
from generator.colorimetry.transfer import Linear
from generator.rendering import views as aces_views
from generator.spec import fields, labels, looks, lut_pack, namespace, resolved
from generator.spec.allowed import (
    COLORIMETRIC_ALIASES,
    HLG_DISPLAY_PEAK,
    OCIO_MIN_VERSION,
    VIEW_METHODS,  # noqa: F401  (verify.paths reads load.VIEW_METHODS)
    VIEWS,
    newest_ocio_version,
)
from generator.spec.schema import ColourSpace, Display, FileRule, Spec, SpecError

TOP_KEYS = (
    "name",
    "description",
    "ocio_version",
    "scene_reference",
    "chromatic_adaptation",
    "rgc",
    "colour_spaces",
    "inactive",
    "display_view_spaces",
    "custom_space",
    "display",
    "roles",
    "file_rule",
    "lut_pack",
    "look",
    "environment",
)
CUSTOM_SPACE_KEYS = (
    "name",
    "aliases",
    "family",
    "encoding",
    "description",
    "gamut",
    "primaries",
    "primaries_spectra",
    "white",
    "transfer",
)
DISPLAY_KEYS = (
    "name",
    "aliases",
    "views",
    "gamut",
    "primaries",
    "primaries_spectra",
    "white",
    "eotf",
    "peak_luminance",
    "absolute_luminance",
    "description",
)

#: Peak luminance (cd/m²) an SDR display driven in absolute luminance may have.
ABSOLUTE_PEAK_RANGE = (1.0, 10000.0)
FILE_RULE_KEYS = ("name", "colour_space", "pattern", "extension", "regex")

#: Keys a library display takes: its gamut, EOTF, luminance, aliases and description are the library's.
LIBRARY_DISPLAY_KEYS = ("name", "views")
ENCODINGS = ("scene-linear", "display-linear", "log", "sdr-video", "edr-video", "hdr-video", "data")

#: Views a display offers when the spec does not say. Colorimetric (clip) and RGC are
#: analytic; Scale is a CLF lattice on which the mapping is linear inside every tetrahedron,
#: and Desaturate a lattice in OCIO's HSV on which it is trilinear (generator.luts.hsv):
#: both within 0.02 ten-bit codes of the reference on the probe sets, 0.003 ΔE ITP on HDR
#: displays, whose view files end in display light. Perceptual is its 33³ lattice
#: (generator.luts.view.LATTICE_DEFINED): no lattice holds the soft compression, and
#: bench/lut_accuracy.py measures the file's departure from it. SDR displays offer
#: Desaturate and Perceptual by default; an HDR display's Desaturate file (1 MB) and
#: Perceptual file are built when its spec asks.
DEFAULT_VIEWS = ("Colorimetric", "Desaturate", "Perceptual", "Scale", "RGC", "Raw")
DEFAULT_HDR_VIEWS = ("Colorimetric", "Scale", "RGC", "Raw")


def default_views(encoding: str, name: str = "") -> tuple[str, ...]:
    """The views a display of ``encoding`` offers when its spec names none: a library display
    (``name``) first the ACES views the ACES studio configs give it, its ACES 2.0 view the
    default, and Un-tone-mapped, as there."""
    studio = (*aces_views.STUDIO_VIEWS[name], *COLORIMETRIC_ALIASES) if name in aces_views.STUDIO_VIEWS else ()
    return studio + (DEFAULT_VIEWS if encoding == "sdr-video" else DEFAULT_HDR_VIEWS)


#: Roles a config must set so hosts load it without warnings, with their default targets.
DEFAULT_ROLES = {
    "scene_linear": "ACEScg",
    "rendering": "ACEScg",
    "compositing_linear": "ACEScg",
    "compositing_log": "ACEScct",
    "color_timing": "ACEScct",
    "color_picking": "sRGB Encoded Rec.709 (sRGB)",
    "texture_paint": "sRGB Encoded Rec.709 (sRGB)",
    "matte_paint": "sRGB Encoded Rec.709 (sRGB)",
    "data": "Raw",
    "default": "sRGB Encoded Rec.709 (sRGB)",
    "aces_interchange": "ACES2065-1",
    "cie_xyz_d65_interchange": "CIE XYZ-D65 - Display-referred",
    "default_byte": "sRGB Encoded Rec.709 (sRGB)",
    "default_float": "ACEScg",
    "default_sequencer": "sRGB Encoded Rec.709 (sRGB)",
    "reference": "ACES2065-1",  # the spec's scene_reference unless [roles] says otherwise
    # scene_linear's target unless [roles] says otherwise: OpenImageIO 2.4 (Debian's oiiotool, OCIO
    # 2.1) reads an EXR as colour space "Linear", and without this role its --ociodisplay failed.
    "linear": "ACEScg",
}

#: The chromatic adaptation of a spec that names none.
DEFAULT_ADAPTATION = "Bradford"


def default_text() -> str:
    """The embedded default spec, with its comments."""
    return resources.files("generator.spec").joinpath("default.toml").read_text(encoding="utf-8")


def embedded_default(key: str):
    """The embedded default spec's value of the top-level ``key``: what a spec that leaves
    ``key`` out gets, so that leaving a key out and copying the default spec agree."""
    return _parsed(default_text())[key]


@lru_cache(maxsize=2)
def _parsed(text: str) -> dict:
    """A spec's TOML, parsed once per text (read-only by convention)."""
    return tomllib.loads(text)


def load(path: str | Path | None = None, keep: tuple[str, ...] | None = None) -> Spec:
    """Read and validate the spec at ``path`` (a TOML spec; or a build's folder, its config.ocio
    or the resolved spec it stored, ocioforge-spec.json), or the embedded default when None.

    With ``keep``, library colour spaces other than those named there, the scene
    reference and the roles' targets are left out: commands that use one space
    (bake) load faster, and never derive gamuts they do not use. The spec is
    checked whole all the same: what a build accepts, they accept.
    """
    if path is None:
        return parse(default_text(), "<default>", Path.cwd(), keep)
    path = Path(path)
    if path.is_dir() or path.suffix.lower() in (".ocio", ".json"):  # a build: the resolved spec it stored
        folder = path if path.is_dir() else path.parent
        return resolved.read(path if path.suffix.lower() == ".json" else folder / resolved.FILENAME)
    from generator.files import not_readable

    why = not_readable(path)
    if why is not None:
        raise SpecError(
            str(path),
            "-",
            f"cannot read the spec: it {why}; allowed: a spec's TOML file, a build's "
            "folder, its config.ocio or the ocioforge-spec.json beside it",
        )
    try:
        text = path.read_text(encoding="utf-8-sig")  # a BOM some editors write is not TOML
    except OSError as error:
        raise SpecError(str(path), "-", f"cannot read the spec: {error.strerror}") from None
    except UnicodeDecodeError:
        raise SpecError(str(path), "-", "not UTF-8 text; allowed: a TOML file in UTF-8") from None
    return parse(text, str(path), path.parent, keep)


def parse(text: str, source: str, base: Path | None, keep: tuple[str, ...] | None = None) -> Spec:
    """The spec of TOML ``text`` (read from ``source``, relative paths from ``base``), validated."""
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise SpecError(source, "-", f"not valid TOML: {error}") from None
    labels.check_keys(raw, TOP_KEYS, source, "")
    version = parse_version(raw.get("ocio_version", "2.1"), source)
    cat = raw.get("chromatic_adaptation", DEFAULT_ADAPTATION)
    if not isinstance(cat, str) or cat not in CATS:
        raise SpecError(source, "chromatic_adaptation", f"unknown {cat!r}; allowed: {', '.join(CATS)}")
    reference = labels.string(raw.get("scene_reference", "ACES2065-1"), source, "scene_reference")
    roles = raw.get("roles", {})
    if not isinstance(roles, dict):
        raise SpecError(source, "roles", "expected a table of role = colour space")
    for role in roles:
        labels.label(role, source, f"roles.{labels.toml_key(role)}")
        _check_role_name(role, source)
    listed = _listed(raw, source)
    customs = tuple(
        _custom_space(t, source, f"custom_space[{i}]", base or Path.cwd())
        for i, t in enumerate(_tables(raw, "custom_space", source))
    )
    owners = list(labels.owners(listed, customs, "colour_spaces" in raw and raw["colour_spaces"] != ["*"]))
    labels.distinct(owners, source)
    all_names = [name for name, _, _ in owners]
    displays, view_looks = _displays(raw, source, base or Path.cwd())
    if not displays:
        raise SpecError(
            source, "display", "no displays; allowed: one [[display]] or more, or none given for the library's"
        )
    twice = labels.repeated([d.name for d in displays])
    if twice:
        i, earlier = twice
        raise SpecError(
            source,
            f"display[{i}].name",
            f"{displays[i].name!r} is listed twice (display[{earlier}]); allowed: each display once",
        )
    view_spaces = labels.boolean(
        raw["display_view_spaces"] if "display_view_spaces" in raw else embedded_default("display_view_spaces"),
        source,
        "display_view_spaces",
    )
    defaults = _default_roles(all_names, displays, roles)
    taken = namespace.generated(displays, view_spaces, tuple(defaults), source, tuple(roles))
    namespace.check_free(listed, customs, taken, source)
    every = {n.lower() for n in all_names}
    if reference.lower() not in every:
        raise SpecError(source, "scene_reference", f"{reference!r} is not among the colour spaces")
    both: tuple[library.SpaceDef | ColourSpace, ...] = (*listed, *customs)
    chosen = next(s for s in both if reference.lower() in (n.lower() for n in (s.name, *s.aliases)))
    linear = chosen.curve == "linear" if isinstance(chosen.curve, str) else isinstance(chosen.curve, Linear)
    if chosen.encoding != "scene-linear" or not linear:
        what = (
            chosen.encoding if chosen.encoding != "scene-linear" else "labelled scene-linear but has a transfer curve"
        )
        raise SpecError(
            source,
            "scene_reference",
            f"{reference!r} is {what}; allowed: a scene-linear colour space "
            "with a linear transfer (ACES2065-1, ACEScg, Linear Rec.709 (sRGB), ...)",
        )
    if keep is not None:
        keep = (*keep, reference, *DEFAULT_ROLES.values(), *roles.values())
    spaces = (*_kept(listed, keep), *customs)
    present = {n.lower() for s in spaces for n in s.all_names}
    left_out = tuple(n for d in listed for n in (d.name, *d.aliases) if n.lower() not in present)
    chosen_roles = _roles(roles, defaults, reference, source, every | {namespace.DISPLAY_REFERENCE.lower()})
    _check_data(spaces, displays, chosen_roles, source)
    rules = _file_rules(raw, source, every | set(taken))
    names = namespace.colour_spaces((*listed, *customs), taken)
    environment = looks.environment(raw.get("environment"), source)
    by_name = {n.lower(): s for s in both for n in (s.name, *s.aliases)}
    spec_looks = looks.tables(raw.get("look"), source, base or Path.cwd(), by_name, environment)
    looks.check_view_looks(displays, spec_looks, source, view_looks)
    return Spec(
        name=labels.string(raw.get("name", "ocioforge"), source, "name"),
        description=labels.string(raw.get("description", ""), source, "description", text=True),
        ocio_version=version,
        scene_reference=reference,
        chromatic_adaptation=cat,
        colour_spaces=spaces,
        displays=displays,
        roles=chosen_roles,
        file_rules=rules,
        inactive=_inactive(
            raw.get("inactive", []), source, names, left_out, _picked_by_hosts(chosen_roles, rules, names, displays)
        ),
        display_view_spaces=view_spaces,
        source=recorded(source),
        rgc=fields.rgc_params(raw.get("rgc"), source),
        left_out=left_out,
        lut_packs=lut_pack.tables(
            raw.get("lut_pack"), source, every, {n.lower() for d in displays for n in (d.name, *d.aliases)}
        ),
        looks=spec_looks,
        environment=environment,
        look_folder=str((base or Path.cwd()).absolute()),
    )


def _displays(raw: dict, source: str, base: Path) -> tuple[tuple[Display, ...], dict]:
    """The displays, each view that applies looks recorded on its display (views may be given as
    tables, :func:`generator.spec.looks.split_views`); and display index -> entry -> looks as given."""
    out, given = [], {}
    for i, table in enumerate(_tables(raw, "display", source)):
        field = f"display[{i}]"
        entries: dict[int, str] = {}
        if isinstance(table, dict) and "views" in table:
            names, entries = looks.split_views(table["views"], source, f"{field}.views")
            table = {**table, "views": names}
        display = _display(table, source, field, base)
        if entries:
            given[i] = entries
            display = replace(display, looks=tuple((display.views[j], text) for j, text in entries.items()))
        out.append(display)
    return tuple(out), given


def recorded(source: str) -> str:
    """How a built config records the spec it came from: the file's name alone, so that the same
    spec gives the same bytes however its path was typed, and no machine's paths are written."""
    return Path(source).name


def _tables(raw: dict, key: str, source: str) -> list:
    """The array of tables ``[[key]]`` (the library's displays when ``display`` is absent)."""
    if key not in raw:
        return _default_displays() if key == "display" else []
    value = raw[key]
    if not isinstance(value, list):
        raise SpecError(source, key, f"expected an array of tables ([[{key}]]), got {value!r}")
    return value


def parse_version(value, source: str) -> tuple[int, int]:
    """The spec's config version; the oldest supported one is accepted without asking the
    installed PyOpenColorIO (every supported release writes it), which spares its import."""
    if not isinstance(value, str):
        raise SpecError(
            source,
            "ocio_version",
            f'expected a quoted version like "2.1", got {value!r} (a TOML '
            f"number loses its digits: 2.10 reads as 2.1); allowed: {_allowed()}",
        )
    written = re.fullmatch(r"([0-9])\.(0|[1-9][0-9]?)", value)
    if written is None:
        raise SpecError(source, "ocio_version", f'expected a version like "2.1", got {value!r}; allowed: {_allowed()}')
    major, minor = int(written[1]), int(written[2])
    if (major, minor) != OCIO_MIN_VERSION and not OCIO_MIN_VERSION <= (major, minor) <= newest_ocio_version():
        raise SpecError(source, "ocio_version", f"{value} is not supported; allowed: {_allowed()}")
    return (major, minor)


def _allowed() -> str:
    newest = newest_ocio_version()
    return f"2.{OCIO_MIN_VERSION[1]} to {newest[0]}.{newest[1]}"


def library_def(name: str, source: str, field: str) -> library.SpaceDef:
    """The library's record of the colour space called ``name`` or one of its aliases."""
    for space in library.SPACES:
        if name.lower() in (n.lower() for n in (space.name, *space.aliases)):
            return space
    display = next(
        (d.name for d in library.DISPLAYS if name.lower() in (n.lower() for n in (d.name, *d.aliases))), None
    )
    if display is not None:
        raise SpecError(
            source,
            field,
            f"{display!r} is a display, not a scene colour space; allowed: a colour space "
            "of ocioforge list (displays are in ocioforge list --displays)",
        )
    choices = [n for s in library.SPACES for n in (s.name, *s.aliases)]
    raise SpecError(source, field, f"unknown colour space {name!r}{fields.suggest(name, choices)}; see ocioforge list")


def library_space(name: str, source: str, field: str) -> ColourSpace:
    """The library colour space ``name`` (or an alias); SpecError naming ``field`` otherwise."""
    return from_library(library_def(name, source, field))


def named_space(spec: Spec | None, name: str, source: str, field: str) -> ColourSpace:
    """The colour space ``name`` (or an alias) of ``spec``, or of the library without one;
    a SpecError of ``source``'s ``field`` otherwise."""
    from generator.spec.fields import suggest

    if spec is None:
        return library_space(name, source, field)
    try:
        return spec.space(name)
    except KeyError:
        displays = [n for d in spec.displays for n in (d.name, *d.aliases)]
        raise SpecError(
            source,
            field,
            f"no colour space {name!r} in {spec.source}, nor a display"
            f"{suggest(name, [*spec.space_names, *displays])}; allowed: one of its colour spaces or "
            "displays (ocioforge list --spec lists them)",
        ) from None


def named_display(spec: Spec, name: str) -> Display | None:
    """The display of ``spec`` called ``name`` or one of its aliases (in any case); None when
    it has none of that name."""
    key = name.lower()
    return next((d for d in spec.displays if key in (n.lower() for n in (d.name, *d.aliases))), None)


def from_library(space: library.SpaceDef) -> ColourSpace:
    """The resolved record of a library colour space."""
    from generator.colorimetry.curves import CURVES
    from generator.colorimetry.gamuts import gamuts

    special = space.curve.lower() if space.curve.startswith("ADX") else ""
    return ColourSpace(
        name=space.name,
        gamut=gamuts()[space.gamut] if space.gamut else None,
        curve=Linear() if special else CURVES[space.curve],
        curve_name=space.curve,
        aliases=space.aliases,
        family=space.family,
        encoding=space.encoding,
        description=space.description,
        is_data=space.is_data,
        special=special,
    )


def _listed(raw: dict, source: str) -> tuple[library.SpaceDef, ...]:
    """The library colour spaces the spec names (["*"]: all of them)."""
    value = raw.get("colour_spaces", ["*"])
    if value == ["*"]:
        return library.SPACES
    return tuple(
        library_def(n, source, f"colour_spaces[{i}]")
        for i, n in enumerate(labels.strings(value, source, "colour_spaces"))
    )


def _kept(listed, keep: tuple[str, ...] | None) -> tuple[ColourSpace, ...]:
    """The listed library spaces resolved: all, or with ``keep`` those it names."""
    wanted = None if keep is None else {str(k).lower() for k in keep}
    return tuple(
        from_library(d) for d in listed if wanted is None or {n.lower() for n in (d.name, *d.aliases)} & wanted
    )


def _gamut(table: dict, source: str, field: str, base: Path, name: str) -> Gamut:
    from generator.colorimetry.gamuts import gamuts

    given = [k for k in ("gamut", "primaries", "primaries_spectra") if k in table]
    if len(given) != 1:
        raise SpecError(
            source, field, "give exactly one of 'gamut' (a library gamut), 'primaries' or 'primaries_spectra'"
        )
    if "gamut" in table:
        key = labels.string(table["gamut"], source, f"{field}.gamut")
        if key not in gamuts():
            raise SpecError(source, f"{field}.gamut", f"unknown gamut {key!r}{fields.suggest(key, gamuts())}")
        if "white" in table:
            raise SpecError(source, f"{field}.white", "a library gamut brings its own white point")
        return gamuts()[key]
    if "white" not in table:
        raise SpecError(source, f"{field}.white", "required with 'primaries' or 'primaries_spectra'")
    white = fields.whitepoint(table["white"], base, source, f"{field}.white")
    if "primaries" in table:
        prims = fields.primaries(table["primaries"], source, f"{field}.primaries")
    else:
        prims = fields.spectral_primaries(table["primaries_spectra"], base, source, f"{field}.primaries_spectra")
    fields.check_triangle(prims, white, source, f"{field}.{given[0]}", f"{field}.white")
    return Gamut(name, prims, white, citation=f"custom, {recorded(source)}")


def _default_encoding(curve) -> str:
    """A custom space's OCIO encoding when its spec names none: scene-linear for the identity,
    log for a log curve, sdr-video for any other curve (code values, as OCIO's own configs
    label a gamma-encoded scene space)."""
    from generator.colorimetry.transfer import LogCamera

    if isinstance(curve, Linear):
        return "scene-linear"
    return "log" if isinstance(curve, LogCamera) else "sdr-video"


def _custom_space(table: dict, source: str, field: str, base: Path) -> ColourSpace:
    labels.check_keys(table, CUSTOM_SPACE_KEYS, source, f"{field}.")
    name = labels.table_name(table, source, field)
    curve_name, curve = fields.transfer_function(table.get("transfer", "linear"), base, source, f"{field}.transfer")
    encoding = table.get("encoding", _default_encoding(curve))
    if encoding not in ENCODINGS:
        raise SpecError(source, f"{field}.encoding", f"unknown {encoding!r}; allowed: {', '.join(ENCODINGS)}")
    return ColourSpace(
        name=name,
        gamut=_gamut(table, source, field, base, name),
        curve=curve,
        curve_name=curve_name,
        aliases=labels.aliases(table.get("aliases", []), source, f"{field}.aliases"),
        family=labels.string(table.get("family", "Custom"), source, f"{field}.family"),
        encoding=encoding,
        description=labels.string(table.get("description", ""), source, f"{field}.description", text=True),
    )


def _default_displays() -> list[dict]:
    return [{"name": d.name} for d in library.DISPLAYS]


def _display(table: dict, source: str, field: str, base: Path) -> Display:
    from generator.colorimetry.curves import CURVES
    from generator.colorimetry.gamuts import gamuts

    labels.check_keys(table, DISPLAY_KEYS, source, f"{field}.")
    name = labels.table_name(table, source, field)
    views = labels.strings(table["views"], source, f"{field}.views") if "views" in table else None
    if views == ():
        raise SpecError(
            source,
            f"{field}.views",
            f"empty; allowed: one or more of {', '.join(VIEWS)}, or the key left out for the defaults",
        )
    listed_views = views or ()
    for i, view in enumerate(listed_views):
        if view not in VIEWS and view not in COLORIMETRIC_ALIASES and not aces_views.is_aces_name(view):
            raise SpecError(
                source,
                f"{field}.views[{i}]",
                f"unknown view {view!r}{fields.suggest(view, _view_names())}; "
                f"allowed: {', '.join(VIEWS)}, {', '.join(COLORIMETRIC_ALIASES)}, {aces_views.OWN_ACES2} "
                "(the display's own) or an ACES studio view ('ocioforge list --views' shows them)",
            )
        if view in listed_views[:i]:
            raise SpecError(source, f"{field}.views[{i}]", f"{view!r} is listed twice; allowed: each view once")
    known = {n.lower(): d for d in library.DISPLAYS for n in (d.name, *d.aliases)}
    custom = any(k in table for k in ("gamut", "primaries", "primaries_spectra", "eotf"))
    if custom:
        aliases = labels.aliases(table.get("aliases", []), source, f"{field}.aliases")
        taken = next(
            ((key, n) for key, names in (("name", (name,)), ("aliases", aliases)) for n in names if n.lower() in known),
            None,
        )
        if taken:
            key, n = taken
            raise SpecError(
                source,
                f"{field}.{key}",
                f"{n!r} names the library display {known[n.lower()].name!r}, "
                "whose gamut and eotf are fixed; allowed: another name for a custom display",
            )
    if name.lower() in known and not custom:
        fixed = next((k for k in table if k not in LIBRARY_DISPLAY_KEYS), None)
        if fixed:
            raise SpecError(
                source,
                f"{field}.{fixed}",
                f"{known[name.lower()].name!r} is a library display, whose "
                f"{fixed} is fixed; allowed: {', '.join(LIBRARY_DISPLAY_KEYS)} here, or a display of "
                "another name with gamut (or primaries) and eotf",
            )
        d = known[name.lower()]
        gamut = gamuts()[d.gamut]
        views = _aces(
            views or default_views(d.encoding, d.name), d.name, gamut, d.peak, d.encoding != "sdr-video", source, field
        )
        return Display(d.name, gamut, CURVES[d.eotf], d.eotf, views, d.aliases, d.peak, d.encoding, d.description)
    if not custom:
        raise SpecError(
            source,
            f"{field}.name",
            f"unknown display {name!r}{fields.suggest(name, [d.name for d in library.DISPLAYS])}; "
            "a custom display needs 'gamut' or 'primaries' and 'eotf'",
        )
    if "eotf" not in table:
        raise SpecError(
            source,
            f"{field}.eotf",
            "required for a custom display: a library curve (sRGB, gamma 2.4, ST 2084, HLG, ...) or a transfer family",
        )
    eotf_name, eotf = fields.transfer_function(table["eotf"], base, source, f"{field}.eotf")
    hdr = eotf_name in ("ST 2084", "HLG")
    absolute = labels.boolean(table.get("absolute_luminance", False), source, f"{field}.absolute_luminance")
    if absolute and hdr:
        raise SpecError(
            source,
            f"{field}.absolute_luminance",
            f"an {eotf_name} signal carries its own luminance; allowed: absolute_luminance with an SDR eotf",
        )
    peak = fields.number(table.get("peak_luminance", 1000.0 if hdr else 100.0), source, f"{field}.peak_luminance")
    if eotf_name == "HLG" and peak != HLG_DISPLAY_PEAK:
        raise SpecError(
            source,
            f"{field}.peak_luminance",
            f"{peak:g} cd/m²: HLG displays are built for "
            f"{HLG_DISPLAY_PEAK:g} cd/m² (BT.2100's reference); allowed: {HLG_DISPLAY_PEAK:g}",
        )
    low, high = (100.0, 10000.0) if hdr else ABSOLUTE_PEAK_RANGE if absolute else (100.0, 100.0)
    if not low <= peak <= high:
        raise SpecError(
            source,
            f"{field}.peak_luminance",
            f"{peak:g} cd/m² is outside what a {eotf_name} display "
            f"{'driven in absolute luminance ' if absolute else ''}takes; "
            "allowed: 100 to 10000 cd/m² for ST 2084 displays; 100 for "
            "SDR (code 1 shows display-referred 1.0, 100 cd/m²), or with absolute_luminance = true "
            f"{ABSOLUTE_PEAK_RANGE[0]:g} to {ABSOLUTE_PEAK_RANGE[1]:g} (code 1 emits the peak)",
        )
    views = views or default_views("hdr-video" if hdr else "sdr-video")
    gamut = _gamut(table, source, field, base, name)
    given = next((k for k in ("primaries", "primaries_spectra") if k in table), "gamut")
    views = _aces(views, name, gamut, peak, hdr or absolute, source, field)
    _check_views_can_hold(views, eotf, gamut, source, field, given)
    if eotf_name == "HLG":
        _check_bt2020(gamut, source, f"{field}.{given}", f"{field}.{'white' if 'white' in table else given}")
    return Display(
        name,
        gamut,
        eotf,
        eotf_name,
        views,
        labels.aliases(table.get("aliases", []), source, f"{field}.aliases"),
        peak,
        "hdr-video" if hdr else "sdr-video",
        labels.string(table.get("description", ""), source, f"{field}.description", text=True),
        absolute,
    )


def _view_names() -> list[str]:
    return [*VIEWS, *COLORIMETRIC_ALIASES, aces_views.OWN_ACES2, *aces_views.catalogue()]


def _aces(views, name: str, gamut: Gamut, peak: float, bright: bool, source: str, field: str) -> tuple[str, ...]:
    """``views`` with ``ACES 2.0`` replaced by the display's own ACES 2.0 view (a library display's
    first studio ACES 2.0 view), each ACES view checked against what the display can show
    (``bright``: an HDR display, or an SDR one driven in absolute luminance)."""
    out = []
    for i, view in enumerate(views):
        key = f"{field}.views[{i}]"
        if view == aces_views.OWN_ACES2:
            studio = [v for v in aces_views.STUDIO_VIEWS.get(name, ()) if v.startswith(aces_views.OWN_ACES2 + " - ")]
            if studio:
                view = studio[0]
            else:
                try:
                    view = aces_views.own_view(name, peak, gamut.primaries, gamut.whitepoint).name
                except ValueError as error:
                    raise SpecError(
                        source,
                        key,
                        f"the display's own ACES 2.0 view cannot be made: {error}; allowed: "
                        "a peak luminance, primaries and white the ACES 2.0 Output Transform takes",
                    ) from None
        if aces_views.is_aces_name(view):
            found = aces_views.resolve(view, name, peak, gamut.primaries, gamut.whitepoint)
            if found is None:
                raise SpecError(
                    source,
                    key,
                    f"unknown ACES view {view!r}; allowed: {aces_views.OWN_ACES2} or an ACES "
                    "studio view ('ocioforge list --views' shows them)",
                )
            why = aces_views.cannot_show(found, gamut.primaries, peak, bright)
            if why:
                raise SpecError(
                    source,
                    key,
                    f"{name!r} cannot show {view!r}: {why}; allowed: a view whose peak and "
                    "limiting primaries the display holds",
                )
        if view in out:
            raise SpecError(source, key, f"{view!r} is listed twice; allowed: each view once")
        out.append(view)
    return tuple(out)


def _check_views_can_hold(views, eotf, gamut: Gamut, source: str, field: str, given: str) -> None:
    """What two views need of a display (a display's views default to both on SDR): Perceptual an
    EOTF exponent of at least 1 (below, its encoding raises light above the peak to ever larger
    codes, past what its shaper table holds: gamma 0.3 asked for petabytes); Desaturate primaries
    each giving at least :data:`~generator.tolerances.DISPLAY_MIN_LUMINANCE_SHARE` of white's
    luminance. The other views take any."""
    from generator.colorimetry.matrices import normalised_primary_matrix
    from generator.colorimetry.transfer import Power
    from generator.tolerances import DISPLAY_MIN_LUMINANCE_SHARE

    if "Perceptual" in views and isinstance(eotf, Power) and eotf.exponent < 1.0:
        raise SpecError(
            source,
            f"{field}.eotf",
            f"the Perceptual view needs an exponent of at least 1, got "
            f"{eotf.exponent:g}; allowed: such an exponent, or views without Perceptual",
        )
    if "Desaturate" not in views:
        return
    shares = normalised_primary_matrix(gamut.primaries, gamut.whitepoint)[1]
    for label, (x, y), share in zip(("red", "green", "blue"), gamut.primaries, shares):
        if not share >= DISPLAY_MIN_LUMINANCE_SHARE:
            raise SpecError(
                source,
                f"{field}.{given}",
                f"the {label} primary (x {x:g}, y {y:g}) gives {share:.3g} of "
                f"white's luminance, and the Desaturate view, which keeps luminance, needs at least "
                f"{DISPLAY_MIN_LUMINANCE_SHARE:g}; allowed: such primaries, or views without Desaturate",
            )


def _check_bt2020(gamut, source: str, field: str, white: str) -> None:
    """HLG is defined on BT.2020's primaries and white (ITU-R BT.2100): its OOTF weighs the
    channels by BT.2020 luminance, and OCIO's HLG display builtin encodes BT.2020 RGB."""
    from generator.colorimetry.gamuts import gamuts

    bt2020 = gamuts()["Rec.2020"]
    for ours, theirs, key in ((gamut.primaries, bt2020.primaries, field), (gamut.whitepoint, bt2020.whitepoint, white)):
        if not np.allclose(ours, theirs, rtol=0, atol=tolerances.GAMUT_SAME_XY_ABSOLUTE):
            raise SpecError(
                source,
                key,
                "an HLG display is BT.2100's, on BT.2020 primaries and D65 (x 0.3127, "
                'y 0.3290); allowed: gamut = "Rec.2020" (or its primaries and white)',
            )


#: Roles whose colour space hosts take without asking (Blender's images, renders, sequencer
#: and non-colour data): an inactive one is refused, as is a file rule's.
HOST_ROLES = ("scene_linear", "default_byte", "default_float", "default_sequencer", "data")


def _picked_by_hosts(roles, rules, names: dict[str, str], displays) -> dict[str, str]:
    """The colour spaces (own names) hosts pick by themselves: each display's, which its views
    show through, and the targets of :data:`HOST_ROLES` and of every file rule (through a role
    it names), each to what picks it."""
    targets = {role.lower(): target for role, target in roles}
    picked = {d.name: "a display's colour space (its views show through it)" for d in displays}
    for role in HOST_ROLES:
        if role in targets:
            picked.setdefault(names.get(targets[role].lower()), f"the {role} role's colour space")
    for rule in rules:
        target = targets.get(rule.colour_space.lower(), rule.colour_space)
        picked.setdefault(names.get(target.lower()), f"the colour space of file rule {rule.name!r}")
    picked.pop(None, None)
    return picked


def _inactive(
    value, source: str, names: dict[str, str], left_out: tuple[str, ...], picked: dict[str, str]
) -> tuple[str, ...]:
    """The colour spaces kept out of menus (``names``: every name and alias of the config's,
    generated ones too, to the space's own name), each by its own name: OCIO takes no alias
    there, and a space named by its alias stayed in every menu. None may be one hosts pick
    themselves (``picked``): Blender lists no inactive space; it read an EXR whose file rule
    led to one with no colour space, then crashed, and showed the views of a display whose
    space was inactive wrong. Those a load ``left_out`` are dropped."""
    chosen: dict[str, int] = {}
    for i, name in enumerate(labels.strings(value, source, "inactive")):
        if name.lower() not in names:
            raise SpecError(
                source,
                f"inactive[{i}]",
                f"{name!r} is not among the colour spaces; allowed: a colour "
                "space of the spec, the display reference or a '<view> - <display>' space, by name or alias",
            )
        own = names[name.lower()]
        if own in picked:
            raise SpecError(
                source,
                f"inactive[{i}]",
                f"{name!r} is {picked[own]}, which hosts take without asking "
                "(Blender lists no inactive space: it crashed reading a file that led to one, and showed "
                "a display whose space was inactive wrong); allowed: a space of the spec no file rule "
                f"and none of the roles {', '.join(HOST_ROLES)} name, or a '<view> - <display>' space",
            )
        if own in chosen:
            raise SpecError(
                source,
                f"inactive[{i}]",
                f"{name!r} names {own!r}, as inactive[{chosen[own]}] does; allowed: each colour space once",
            )
        chosen[own] = i
    return tuple(own for own in chosen if own not in left_out)


def _check_data(spaces, displays, roles, source: str) -> None:
    """A Raw view shows a data colour space, and the data role names one."""
    data = {n.lower() for s in spaces if s.is_data for n in (s.name, *s.aliases)}
    allowed = "allowed: list 'Raw' (the library's data space) in colour_spaces"
    for i, display in enumerate(displays):
        if "Raw" in display.views and not data:
            raise SpecError(
                source,
                f"display[{i}].views",
                f"{display.name!r} offers the Raw view, which shows a data "
                f"colour space, and the spec has none; {allowed}, or leave Raw out of its views",
            )
    target = dict(roles).get("data")
    if target is not None and target.lower() not in data:
        raise SpecError(
            source,
            "roles.data",
            f"{target!r} is not a data colour space (hosts read files of the data "
            f"role unconverted, and this space converts); {allowed}, and name it or its alias",
        )


#: Edits (insertions, deletions, substitutions) within which a role the spec names is taken for a
#: misspelling of a known one (scene_lienar, colour_picking), not for a custom role (plate_linear).
ROLE_TYPO_EDITS = 2


def _edits(a: str, b: str) -> int:
    """Levenshtein distance between ``a`` and ``b``."""
    row = list(range(len(b) + 1))
    for i, x in enumerate(a, 1):
        previous, row[0] = row[0], i
        for j, y in enumerate(b, 1):
            previous, row[j] = row[j], min(row[j] + 1, row[j - 1] + 1, previous + (x != y))
    return row[-1]


def _check_role_name(role: str, source: str) -> None:
    """A role the spec names is one OCIO or a host reads (:data:`DEFAULT_ROLES`) or a custom one;
    a custom one within :data:`ROLE_TYPO_EDITS` of a known one is taken for its misspelling,
    which would leave the known role at its default without a word."""
    key = role.lower()
    if key in DEFAULT_ROLES:
        return
    near = sorted(known for known in DEFAULT_ROLES if _edits(key, known) <= ROLE_TYPO_EDITS)
    if near:
        raise SpecError(
            source,
            f"roles.{labels.toml_key(role)}",
            f"unknown role (did you mean "
            f"{', '.join(map(repr, near))}?); allowed: {', '.join(DEFAULT_ROLES)}, or a custom role "
            "not spelt within two letters of one of them",
        )


def _default_roles(names, displays, spec_roles) -> dict[str, str]:
    """The default roles a spec gets: all of :data:`DEFAULT_ROLES` but the linear role where a
    colour space or display is called "linear" and the spec sets no such role (OpenImageIO finds
    that space by its name; the role would take the name from it)."""
    called = {n.lower() for n in names} | {n.lower() for d in displays for n in (d.name, *d.aliases)}
    if "linear" in called and "linear" not in {r.lower() for r in spec_roles}:
        return {role: target for role, target in DEFAULT_ROLES.items() if role != "linear"}
    return DEFAULT_ROLES


def _roles(table, defaults: dict, reference: str, source: str, names: set[str]) -> tuple[tuple[str, str], ...]:
    """Roles by name in lower case, as OCIO keeps them (the namespace check has refused a role
    given twice in two cases): ``defaults`` (:func:`_default_roles`), the reference role following
    ``reference`` and the linear role the scene_linear role unless set."""
    given = {"reference": reference, **{role.lower(): target for role, target in table.items()}}
    roles = {**defaults, **given}
    if "linear" in defaults and "linear" not in given:
        roles["linear"] = roles["scene_linear"]
    for role, target in roles.items():
        if not isinstance(target, str):
            raise SpecError(
                source, f"roles.{labels.toml_key(role)}", f"expected a string naming a colour space, got {target!r}"
            )
        if target.lower() not in names:
            if role in given:
                raise SpecError(
                    source,
                    f"roles.{role}",
                    f"{target!r} is not among the spec's scene colour spaces; "
                    "allowed: a colour space of colour_spaces or custom_space, by name or alias, or "
                    f"{namespace.DISPLAY_REFERENCE!r}",
                )
            raise SpecError(
                source,
                f"roles.{role}",
                f"the default target {target!r} is not among the colour spaces; "
                f"allowed: list it in colour_spaces, or set {role} under [roles]",
            )
    return tuple(sorted(roles.items()))


def _check_glob(rule: FileRule, source: str, field: str) -> None:
    """A rule's pattern and extension as OCIO reads them (globs: a '[' opens a set), checked by
    OCIO itself when they hold one."""
    if "[" not in rule.pattern + rule.extension and "]" not in rule.pattern + rule.extension:
        return
    import PyOpenColorIO as ocio

    try:
        ocio.FileRules().insertRule(0, "check", "check", rule.pattern, rule.extension)
    except Exception as error:  # PyOpenColorIO.Exception
        key = "pattern" if "[" in rule.pattern or "]" in rule.pattern else "extension"
        raise SpecError(
            source,
            f"{field}.{key}",
            f"OpenColorIO cannot read it ({str(error).splitlines()[0]}); "
            "allowed: a glob of *, ? and complete [...] sets",
        ) from None


def _check_regex(rule: FileRule, source: str, field: str) -> None:
    """A rule's regular expression as OCIO reads it (ECMAScript, matched against the whole
    path), checked by OCIO itself: Python's dialect differs."""
    import PyOpenColorIO as ocio

    try:
        ocio.FileRules().insertRule(0, "check", "check", rule.regex)
    except Exception as error:  # PyOpenColorIO.Exception
        raise SpecError(
            source,
            f"{field}.regex",
            f"OpenColorIO cannot read it ({str(error).splitlines()[0]}); "
            "allowed: a non-empty ECMAScript regular expression",
        ) from None


def _file_rules(raw: dict, source: str, names: set[str]) -> tuple[FileRule, ...]:
    """The file rules; each names a colour space, display or role of the config (``names``)."""
    if "file_rule" not in raw:  # the embedded default's, as for every key left out
        raw = {"file_rule": embedded_default("file_rule")}
    rules: list[FileRule] = []
    for i, table in enumerate(_tables(raw, "file_rule", source)):
        field = f"file_rule[{i}]"
        labels.check_keys(table, FILE_RULE_KEYS, source, f"{field}.")
        for key in ("name", "colour_space"):
            if key not in table:
                raise SpecError(source, f"{field}.{key}", "required: a file rule has a name and a colour_space")
        values = {k: labels.string(v, source, f"{field}.{k}") for k, v in table.items()}
        if "regex" in values:
            glob = next((k for k in ("pattern", "extension") if k in values), None)
            if glob:
                raise SpecError(
                    source,
                    f"{field}.{glob}",
                    "a rule matches by its regex or by pattern and extension, "
                    "not both; allowed: regex alone, or pattern and extension",
                )
            values.update(pattern="", extension="")
        rule = FileRule(**values)
        labels.label(rule.name, source, f"{field}.name", context=False)
        empty = next((k for k in ("pattern", "extension") if k in table and getattr(rule, k) == ""), None)
        if empty:
            raise SpecError(
                source,
                f"{field}.{empty}",
                "empty, which OCIO refuses; allowed: a glob ('*' matches every file), or the key left out",
            )
        if rule.extension.startswith("."):
            raise SpecError(
                source,
                f"{field}.extension",
                f"{rule.extension!r} starts with a dot, and OCIO puts one "
                f"before the extension, so the rule would match only names ending in "
                f"'.{rule.extension}'; allowed: the extension without its dot, {rule.extension[1:]!r}",
            )
        if "regex" in table:
            _check_regex(rule, source, field)
        else:
            _check_glob(rule, source, field)
        if rule.name.lower() == "colorspacenamepathsearch":
            raise SpecError(
                source,
                f"{field}.name",
                "OCIO reserves 'ColorSpaceNamePathSearch' for its rule that "
                "finds a colour space's name in the file path, which takes no colour_space; allowed: "
                "another name",
            )
        if rule.name.lower() in (r.name.lower() for r in rules):
            raise SpecError(
                source, f"{field}.name", f"{rule.name!r} names an earlier rule too; allowed: one rule a name"
            )
        matching = next((k for k in ("pattern", "extension", "regex") if k in table), None)
        if rule.name == "Default" and matching:
            raise SpecError(
                source,
                f"{field}.{matching}",
                "the Default rule matches every file; allowed: name and colour_space alone",
            )
        if rule.colour_space.lower() not in names:
            raise SpecError(
                source,
                f"{field}.colour_space",
                f"{rule.colour_space!r} is not among the colour spaces; "
                "allowed: a colour space, display or role of the config",
            )
        rules.append(rule)
    if not rules or rules[-1].name != "Default":
        raise SpecError(source, "file_rule", "the last file rule must be named 'Default'")
    return tuple(rules)
