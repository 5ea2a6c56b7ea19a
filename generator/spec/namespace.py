"""The config's names: those a build generates beside the spec's colour spaces, and the check
that a spec's colour space takes none of them.

Beside the spec's colour spaces a build adds the display-referred reference space, a colour
space per display (named and aliased as the display), a "<view> - <display>" space per view
when the spec asks for them, and the roles. OCIO compares names without case, replaces a
colour space added under a taken name without a word, and refuses a role named as a colour
space: so every name may be used once.
"""

from __future__ import annotations

from dataclasses import dataclass

from generator.spec.schema import Display, SpecError

#: The display-referred reference space every config has, and its aliases (OCIO's ACES configs').
DISPLAY_REFERENCE = "CIE XYZ-D65 - Display-referred"
DISPLAY_REFERENCE_ALIASES = ("cie_xyz_d65_display", "lin_ciexyzd65_display")
#: The view that shows data unchanged: it has no display-view space.
RAW_VIEW = "Raw"
_GENERATED = (
    "the build names the display reference, each display, each role and, with display_view_spaces, "
    "each '<view> - <display>'"
)


def display_view_space(view: str, display: str) -> str:
    """The name of the colour space that applies ``view`` of ``display`` (display_view_spaces)."""
    return f"{view} - {display}"


@dataclass(frozen=True)
class Owner:
    """What a generated name belongs to: the spec field that brings it ("" for one every config
    has), its description in errors, and the colour space it names (``space``, its own name;
    "" for a role)."""

    field: str
    what: str
    space: str = ""


def generated(
    displays: tuple[Display, ...], display_view_spaces: bool, roles, source: str, spec_roles=()
) -> dict[str, Owner]:
    """Every name the build gives beside the spec's colour spaces (lower case) and its owner.

    A name taken twice is an error naming the field that came second: the display reference
    and the default ``roles`` come first, then the displays, their display-view spaces and
    the roles the spec names itself (``spec_roles``), so a display named like a default role
    is the display's error and a role the spec names like a display is the role's.
    """
    taken: dict[str, Owner] = {}

    def add(name: str, owner: Owner) -> None:
        if name.lower() in taken:
            raise _taken(source, owner.field, name, taken)
        taken[name.lower()] = owner

    for name in (DISPLAY_REFERENCE, *DISPLAY_REFERENCE_ALIASES):
        add(name, Owner("", f"the generated display-referred reference space {DISPLAY_REFERENCE!r}", DISPLAY_REFERENCE))
    chosen = {r.lower() for r in spec_roles}
    for role in dict.fromkeys(r for r in roles if r.lower() not in chosen):
        add(role, Owner(f"roles.{role}", f"the role {role!r}"))
    for i, display in enumerate(displays):
        what = f"the generated display colour space of display[{i}] {display.name!r}"
        add(display.name, Owner(f"display[{i}].name", what, display.name))
        for j, alias in enumerate(display.aliases):
            add(alias, Owner(f"display[{i}].aliases[{j}]", f"an alias of {what}", display.name))
    for i, display in enumerate(displays if display_view_spaces else ()):
        for j, view in enumerate(display.views):
            if view != RAW_VIEW:
                space = display_view_space(view, display.name)
                add(
                    space,
                    Owner(
                        f"display[{i}].views[{j}]",
                        f"the generated display-view colour space of view "
                        f"{view!r} on display[{i}] (display_view_spaces = true)",
                        space,
                    ),
                )
    for role in dict.fromkeys(spec_roles):
        add(role, Owner(f"roles.{role}", f"the role {role!r}"))
    return taken


def colour_spaces(spaces, taken: dict[str, Owner]) -> dict[str, str]:
    """Every name and alias of a config's colour spaces (lower case) to the space's own name: the
    spec's ``spaces`` and the generated ones among the names :func:`generated` has ``taken``."""
    names = {n.lower(): space.name for space in spaces for n in (space.name, *space.aliases)}
    names.update((name, owner.space) for name, owner in taken.items() if owner.space)
    return names


def check_free(library_spaces, custom_spaces, taken: dict[str, Owner], source: str) -> None:
    """No colour space of the spec may have a name or alias in ``taken``: for a custom space the
    error names its field, for a library space the field of the display that took its name."""
    for i, space in enumerate(custom_spaces):
        for key, name in (("name", space.name), *((f"aliases[{j}]", a) for j, a in enumerate(space.aliases))):
            if name.lower() in taken:
                raise _taken(source, f"custom_space[{i}].{key}", name, taken)
    for space in library_spaces:
        for name in (space.name, *space.aliases):
            if name.lower() in taken:
                owner = taken[name.lower()]
                raise SpecError(
                    source,
                    owner.field or "colour_spaces",
                    f"{name!r} names the library colour space "
                    f"{space.name!r} as well as {owner.what}; allowed: a name no colour space uses",
                )


def _taken(source: str, field: str, name: str, taken: dict[str, Owner]) -> SpecError:
    return SpecError(
        source, field, f"{name!r} is taken by {taken[name.lower()].what}; allowed: a name of its own ({_GENERATED})"
    )
