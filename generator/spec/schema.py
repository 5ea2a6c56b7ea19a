"""The validated, typed, frozen description a spec resolves to.

Nothing here builds OCIO objects or evaluates colour; these records are what
the colorimetry, the emitter, the baker and the verifier all read.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from generator.colorimetry.matrices import Gamut
from generator.colorimetry.transfer import TransferFunction
from generator.gamut.rgc import RGCParams


class SpecError(ValueError):
    """Bad input in a spec: names the file and the field, says what is allowed."""

    def __init__(self, source: str, field: str, message: str):
        super().__init__(f"{source}:{field}: {message}")
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

    @property
    def is_hdr(self) -> bool:
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
        return self.space(self.scene_reference)
