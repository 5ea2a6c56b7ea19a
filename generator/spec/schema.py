"""The validated, typed, frozen description a spec resolves to.

Nothing here builds OCIO objects or evaluates colour; these records are what
the colorimetry, the emitter, the baker and the verifier all read.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from generator.colorimetry.cdl import Correction
from generator.colorimetry.matrices import Gamut
from generator.colorimetry.transfer import TransferFunction
from generator.gamut.rgc import RGCParams


class SpecError(ValueError):
    """Bad input in a spec: names the file and the field (``-``: the file as a whole, left out of
    the message), says what is allowed."""

    def __init__(self, source: str, field: str, message: str):
        super().__init__(f"{source}: {message}" if field == "-" else f"{source}:{field}: {message}")
        self.source, self.field, self.message = source, field, message


@dataclass(frozen=True)
class ColourSpace:
    """A scene-referred colour space: decode with ``curve``, then ``gamut`` linear RGB.

    ``special`` names an encoding that is not a per-channel curve and a gamut
    (ADX10 / ADX16, whose decoding goes straight to ACES2065-1).
    """

    name: str
    gamut: Gamut | None
    curve: TransferFunction
    curve_name: str
    aliases: tuple[str, ...] = ()
    family: str = ""
    encoding: str = "scene-linear"
    description: str = ""
    is_data: bool = False
    special: str = ""

    @property
    def all_names(self) -> tuple[str, ...]:
        """The name, then the aliases."""
        return (self.name, *self.aliases)


@dataclass(frozen=True)
class Display:
    """A display: gamut, EOTF, peak luminance (cd/m²) and the views it offers."""

    name: str
    gamut: Gamut
    eotf: TransferFunction
    eotf_name: str
    views: tuple[str, ...]
    aliases: tuple[str, ...] = ()
    peak: float = 100.0
    encoding: str = "sdr-video"
    description: str = ""
    #: An SDR display driven in absolute luminance: its code 1 emits ``peak`` (an LED wall at
    #: 1500 cd/m² with a 2.4 power), rather than the 100 cd/m² of display-referred 1.0.
    absolute: bool = False
    #: (view, looks) for each view that applies looks (OCIO's view ``looks``: "+Show Look, +Grade").
    looks: tuple[tuple[str, str], ...] = ()

    def view_looks(self, view: str) -> tuple[str, ...]:
        """The names of the looks ``view`` applies, in order (none for most views)."""
        given = dict(self.looks).get(view, "")
        return tuple(n.strip().lstrip("+").strip() for n in given.split(",") if n.strip())

    @property
    def is_hdr(self) -> bool:
        """Whether the display's encoding is an HDR one (anything but sdr-video)."""
        return self.encoding != "sdr-video"

    @property
    def clip_high(self) -> float:
        """Largest display-linear value shown (1.0 = 100 cd/m²)."""
        return self.peak / 100.0

    @property
    def code_one(self) -> float:
        """Display-linear light (1.0 = 100 cd/m²) the EOTF's code 1 stands for: the peak for
        an :attr:`absolute` display, else 1 (PQ and HLG carry their own luminance; an
        extended-range display's codes pass 1)."""
        return self.clip_high if self.absolute else 1.0


@dataclass(frozen=True)
class FileRule:
    """A file rule: a glob ``pattern`` and ``extension``, or, when ``regex`` is given, that
    regular expression (OCIO's, ECMAScript) alone, on the whole path."""

    name: str
    colour_space: str
    pattern: str = "*"
    extension: str = "*"
    regex: str = ""


#: A context variable as OpenColorIO reads one in a file name or CCC id: $NAME, ${NAME}, %NAME%.
CONTEXT_VARIABLE = re.compile(r"\$\{([A-Za-z_][A-Za-z0-9_]*)\}|\$([A-Za-z_][A-Za-z0-9_]*)|%([A-Za-z_][A-Za-z0-9_]*)%")


def context_variables(text: str) -> tuple[str, ...]:
    """The context variables ``text`` names, each once, in order."""
    return tuple(dict.fromkeys(next(g for g in m.groups() if g) for m in CONTEXT_VARIABLE.finditer(text)))


def with_context(text: str, context: dict[str, str]) -> str:
    """``text`` with each context variable it names replaced by its value in ``context``."""
    return CONTEXT_VARIABLE.sub(lambda m: context[next(g for g in m.groups() if g)], text)


@dataclass(frozen=True)
class Look:
    """A look (``[[look]]``) applied in ``process_space``: an ASC CDL given inline (``cdl``),
    or a file the show provides (``file``: a CDL file, read by ``cccid`` where it holds several,
    or a LUT file), by its path inside the build's looks folder, which may name context
    variables ($SHOT) the config's environment gives defaults for."""

    name: str
    process_space: str
    description: str = ""
    cdl: Correction | None = None
    #: The CDL's style: "asc" (OCIO's CDL_ASC) or "no_clamp" (CDL_NO_CLAMP).
    style: str = "asc"
    file: str = ""
    cccid: str = ""
    #: A LUT file's interpolation as OCIO runs it: "linear" (trilinear) or "tetrahedral".
    interpolation: str = "linear"
    #: (path, SHA-256) of each file the build copies for the look (every shot's): verify reads a
    #: build's copy only while it is the file the build copied.
    files: tuple[tuple[str, str], ...] = ()

    @property
    def variables(self) -> tuple[str, ...]:
        """The context variables the look's file or CCC id names, in order."""
        return context_variables(self.file + " " + self.cccid)


@dataclass(frozen=True)
class LutPack:
    """A ``[[lut_pack]]`` table: each source to each display, through each gamut mapping (or
    each ACES view), in each format, as ``ocioforge bake`` bakes one file."""

    sources: tuple[str, ...]
    displays: tuple[str, ...]
    formats: tuple[str, ...]
    gamut_maps: tuple[str, ...] = ()
    views: tuple[str, ...] = ()
    #: Lattice nodes a side per format (None: the bake's default).
    sizes: tuple[int | None, ...] = ()
    shaper: str = "auto"
    #: File name pattern without suffix; "" takes the default.
    file_name: str = ""
    #: The formats baked from a linear source (None: all of ``formats``).
    linear_source_formats: tuple[str, ...] | None = None
    #: An ACES view's lattice values' decimals and .cube shaper entries (None: the bake's).
    decimals: int | None = None
    shaper_entries: int | None = None


@dataclass(frozen=True)
class Spec:
    """A whole config description."""

    name: str
    description: str
    ocio_version: tuple[int, int]
    scene_reference: str
    chromatic_adaptation: str
    colour_spaces: tuple[ColourSpace, ...]
    displays: tuple[Display, ...]
    roles: tuple[tuple[str, str], ...]
    file_rules: tuple[FileRule, ...]
    display_view_spaces: bool  # no default here: a spec that leaves it out takes the embedded default spec's
    inactive: tuple[str, ...] = ()
    source: str = "<default>"
    #: The ACES Reference Gamut Compression's parameters, for every RGC view and bake.
    rgc: RGCParams = RGCParams()  # noqa: RUF009 (frozen, shared safely)
    #: Names of the spec's colour spaces a load for one command left out (see
    #: :func:`generator.spec.load.load`'s ``keep``): offered when a name is mistyped, never built.
    left_out: tuple[str, ...] = field(default=(), compare=False, metadata={"resolved": False})
    #: The show's standalone LUTs (``[[lut_pack]]``), baked by ``ocioforge pack``; not part of a build.
    lut_packs: tuple[LutPack, ...] = field(default=(), compare=False, metadata={"resolved": False})
    #: The looks (``[[look]]``) and the context variables' defaults (``[environment]``), in
    #: order; the resolved spec records them only when there are any (:mod:`generator.spec.looks`).
    looks: tuple[Look, ...] = field(default=(), metadata={"resolved": False})
    environment: tuple[tuple[str, str], ...] = field(default=(), metadata={"resolved": False})
    #: The folder the looks' files are read from: the spec's, or a build's looks folder.
    look_folder: str = field(default="", compare=False, metadata={"resolved": False})

    @property
    def space_names(self) -> list[str]:
        """Every name and alias of the spec's colour spaces, those a load left out included."""
        return [n for s in self.colour_spaces for n in s.all_names] + list(self.left_out)

    def space(self, name: str) -> ColourSpace:
        """The colour space called ``name`` or one of its aliases (case-insensitive)."""
        key = name.lower()
        for space in self.colour_spaces:
            if key in (n.lower() for n in space.all_names):
                return space
        raise KeyError(name)

    @property
    def reference(self) -> ColourSpace:
        """The scene-reference colour space."""
        return self.space(self.scene_reference)
