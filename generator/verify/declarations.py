"""What a config declares beside its transforms, against its stored spec.

Roles, file rules, inactive spaces, each display's views in order (the first is its
default), the active displays, the spec's aliases, the search path (relative, so the
config's files travel with it) and what menus sort and filter spaces by (family,
encoding, data flag, categories) decide which transform a host picks or finds; none of
them moves a number the checks compare, so an edit to one (a role pointed elsewhere, a
file rule sending EXR to a log space, an alias moved onto another space, a search path
made absolute) is found here, by name; so is what a build never writes and a host would
act on (:func:`_additions`).
"""

from __future__ import annotations

import PyOpenColorIO as ocio

from generator.ocio.emit import LUT_FOLDER, generated_spaces, space_categories
from generator.ocio.write import leaf_transforms
from generator.spec.schema import ColourSpace, Display, Spec
from generator.verify.looks import look_differences


def _canonical(cfg, name: str) -> str:
    """The colour space (or display) ``name`` names in ``cfg``, as its own name."""
    space = cfg.getColorSpace(name)
    return space.getName() if space is not None else name


def _names(listed) -> list[str]:
    """A config's list of names: a comma-separated string or, in later PyOpenColorIO, an iterable."""
    items = listed.split(",") if isinstance(listed, str) else list(listed)
    return [n.strip() for n in items if n.strip()]


def _menu(space) -> tuple:
    """What hosts sort and filter a colour space's menus by, as the build writes it: family,
    encoding, the data flag and categories."""
    if isinstance(space, Display):
        return ("Display", space.encoding, False, ["file-io"])
    return (space.family, space.encoding, space.is_data, space_categories(space))


def differences(cfg, spec: Spec) -> list[str]:
    """Each declaration of ``cfg`` that is not what ``spec`` builds, described in a phrase."""
    out = []
    roles = dict(cfg.getRoles())
    for role, target in spec.roles:
        held = roles.get(role)
        if held is None or _canonical(cfg, held) != _canonical(cfg, target):
            out.append(f"role {role} is {held!r}, the spec's {target!r}")
    out += [f"role {role} is not the spec's" for role in sorted(set(roles) - {r for r, _ in spec.roles})]
    rules = cfg.getFileRules()
    held_rules = [
        (
            rules.getName(i),
            rules.getPattern(i),
            rules.getExtension(i),
            rules.getRegex(i),
            _canonical(cfg, rules.getColorSpace(i)),
        )
        for i in range(rules.getNumEntries())
    ]
    built = [(r.name, r.pattern, r.extension, r.regex, _canonical(cfg, r.colour_space)) for r in spec.file_rules]
    if held_rules[:-1] != built[:-1] or held_rules[-1][-1] != built[-1][-1]:
        index = next((i for i, (a, b) in enumerate(zip(held_rules, built)) if a != b), min(len(held_rules), len(built)))
        out.append(
            f"file rule {index + 1} is {held_rules[index] if index < len(held_rules) else None}, "
            f"the spec's {built[index] if index < len(built) else None}"
        )
    inactive = set(_names(cfg.getInactiveColorSpaces()))
    if inactive != set(spec.inactive):
        out.append(f"inactive spaces are {sorted(inactive)}, the spec's {sorted(spec.inactive)}")
    active = _names(cfg.getActiveDisplays())
    if active != [d.name for d in spec.displays]:
        out.append(f"active displays are {active}, the spec's {[d.name for d in spec.displays]}")
    if _names(cfg.getActiveViews()):
        out.append(f"active views are {_names(cfg.getActiveViews())}, where the spec lets each display order its own")
    for display in spec.displays:
        views = list(cfg.getViews(ocio.VIEW_DISPLAY_DEFINED, display.name))
        if views != list(display.views):
            out.append(f"{display.name}'s views are {views}, the spec's {list(display.views)} (the first the default)")
        shared = list(cfg.getViews(ocio.VIEW_SHARED, display.name))
        if shared:
            out.append(f"{display.name} also lists the shared views {shared}, which the build does not write")
    out += _additions(cfg, spec)
    out += look_differences(cfg, spec, LUT_FOLDER)  # looks, environment, search path
    spaces: tuple[ColourSpace | Display, ...] = (*spec.colour_spaces, *spec.displays)
    for space in spaces:
        held = cfg.getColorSpace(space.name)
        menu = _menu(space)
        shown = (
            None if held is None else (held.getFamily(), held.getEncoding(), held.isData(), list(held.getCategories()))
        )
        if held is not None and shown != menu:
            out.append(f"{space.name}'s family, encoding, data flag and categories are {shown}, the spec's {menu}")
        for alias in space.aliases:
            if _canonical(cfg, alias) != space.name:
                out.append(f"alias {alias!r} names {_canonical(cfg, alias)!r}, the spec's {space.name!r}")
        extra = [] if held is None else sorted(set(held.getAliases()) - set(space.aliases))
        if extra:
            out.append(f"{space.name} has the aliases {extra}, which the spec does not give it")
    for built in generated_spaces(spec):
        held = cfg.getColorSpace(built.getName())
        if held is None:
            out.append(f"{built.getName()!r}, which the build writes, is missing")
        elif _declared(held) != _declared(built):
            out.append(
                f"{built.getName()}'s family, encoding, data flag, categories and aliases are {_declared(held)}, "
                f"the build's {_declared(built)}"
            )
    return out


def _additions(cfg, spec: Spec) -> list[str]:
    """What a build never writes and a host would act on: another profile version than the
    spec's (a 2.1 config made 2.3 loads in no OCIO 2.1 host), viewing rules (they change which
    views, and so which default, a host offers an image), named transforms (listed in hosts'
    colour-space menus), context variables (a file name then depends on the shell), and a file
    read by any name but a bare one on the search path (a path leaves the build's folder)."""
    out = []
    version = (cfg.getMajorVersion(), cfg.getMinorVersion())
    if version != tuple(spec.ocio_version):
        out.append(
            f"the config is OCIO {version[0]}.{version[1]}, the spec's {spec.ocio_version[0]}.{spec.ocio_version[1]}"
        )
    rules = cfg.getViewingRules()
    if rules.getNumEntries():
        out.append(
            f"viewing rules {[rules.getName(i) for i in range(rules.getNumEntries())]} choose views per "
            "image, which the build does not write"
        )
    named = [t.getName() for t in cfg.getNamedTransforms(ocio.NAMEDTRANSFORM_ALL)]
    if named:
        out.append(f"named transforms {named}, which the build does not write, appear in hosts' menus")
    names = list(cfg.getEnvironmentVarNames())
    if names and not spec.environment:  # a spec's own are compared by look_differences
        out.append(
            f"environment variables {names}, which the build does not write, make what a view reads depend on the shell"
        )
    for owner, source in _file_sources(cfg):
        if source != source.strip() or "/" in source or "\\" in source or "$" in source or "%" in source:
            out.append(f"{owner} reads {source!r}, where the build reads a file of its LUT folder by its bare name")
    return out


def _file_sources(cfg) -> list[tuple[str, str]]:
    """Every FileTransform's file in ``cfg``'s colour spaces and view transforms, with its owner."""
    return [(owner, t.getSrc()) for owner, t in leaf_transforms(cfg) if isinstance(t, ocio.FileTransform)]


def _declared(space) -> tuple:
    """A config's colour space as menus see it: family, encoding, data flag, categories, aliases."""
    return space.getFamily(), space.getEncoding(), space.isData(), list(space.getCategories()), list(space.getAliases())
