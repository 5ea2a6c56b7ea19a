"""What each OCIO config version can express: data, checked by the test suite
against OpenColorIO's own refusal to write newer styles into older profiles.
"""

from __future__ import annotations

#: BuiltinTransform styles the generator uses, with the first config version that accepts them.
BUILTIN_MIN_VERSION = {
    "ADX10_to_ACES2065-1": (2, 0),
    "ADX16_to_ACES2065-1": (2, 0),
    "CURVE - ST-2084_to_LINEAR": (2, 0),
    "DISPLAY - CIE-XYZ-D65_to_REC.2100-HLG-1000nit": (2, 0),
    "CURVE - CANON_CLOG2_to_LINEAR": (2, 2),
    "CURVE - CANON_CLOG3_to_LINEAR": (2, 2),
    "CURVE - APPLE_LOG_to_LINEAR": (2, 4),
}

#: Curves with no LogCamera form, and the builtin chain (decode direction:
#: code -> linear) that expresses each exactly. A chain is a tuple of
#: (style, inverse?) pairs. Curves absent here, or whose chain the target
#: version lacks, are baked into a 1D LUT. (ACEScc is baked: OCIO's
#: ACEScc_to_ACES2065-1 clamps negative ACES2065-1 values, so it is not the
#: curve and a matrix. The HLG scene curve is baked too: OCIO's
#: CURVE - HLG-OETF-INVERSE returns three times BT.2100's scene light E.)
CURVE_BUILTINS = {
    "ST 2084": (("CURVE - ST-2084_to_LINEAR", False),),
    "Canon Log 2": (("CURVE - CANON_CLOG2_to_LINEAR", False),),
    "Canon Log 3": (("CURVE - CANON_CLOG3_to_LINEAR", False),),
    "Apple Log": (("CURVE - APPLE_LOG_to_LINEAR", False),),
}

#: Code values the camera-curve builtins decode; they clamp codes outside (and their inverse
#: clamps the codes it returns): OCIO tabulates Canon Log 2 and 3 over codes 0 to 1, and Apple
#: Log's toe stops at code 0 (measured through PyOpenColorIO). A config expressing such a
#: curve by its builtin defines it there only, as a baked curve is on its LUT's domain.
BUILTIN_CODE_DOMAIN = {
    "CURVE - CANON_CLOG2_to_LINEAR": (0.0, 1.0),
    "CURVE - CANON_CLOG3_to_LINEAR": (0.0, 1.0),
    "CURVE - APPLE_LOG_to_LINEAR": (0.0, float("inf")),
}

#: OCIO's library evaluates its ST-2084 builtin (PQ code to light, 1 = 100 cd/m²) as a LUT1D,
#: not the formula: libraries before 2.4 over 4096 codes from 0 to 1, 2.4 and later over every
#: half-float code (OpenColorIO's Displays.cpp). A display encodes through its inverse, which
#: OCIO's default optimisation replaces with a table over every half-float light. First library
#: version -> table size (HALF_DOMAIN: every half-float code).
PQ_BUILTIN = "CURVE - ST-2084_to_LINEAR"
HALF_DOMAIN = 0
PQ_BUILTIN_TABLES = {(2, 0): 4096, (2, 4): HALF_DOMAIN}

#: Curve builtins that do not clamp where their curve ends, and the codes a scene space's
#: decoding clamps first (a RangeTransform), so that the config defines the curve there only,
#: as a clamping builtin or a baked curve does: OCIO's CURVE - ST-2084_to_LINEAR mirrors
#: negative codes, goes on past code 1 (10000 cd/m², where ST 2084 ends) to 2.7e9 at code 1.9
#: and decodes codes from 2 up to 0, and its inverse mirrors negative light (measured through
#: PyOpenColorIO). A display's PQ codes are clamped after encoding, where its light, clipped
#: to the display's peak (at most 10000 cd/m²), never leaves the range: read back, codes
#: beyond it come to the peak or black as the scene spaces' do, in every library.
BUILTIN_CLAMPED_DOMAIN = {
    "CURVE - ST-2084_to_LINEAR": (0.0, 1.0),
}

#: Whole-space builtins: encodings that are not a per-channel curve and a gamut.
SPACE_BUILTINS = {
    "adx10": "ADX10_to_ACES2065-1",
    "adx16": "ADX16_to_ACES2065-1",
}

#: HLG display encoding, including BT.2100's OOTF for a 1000 cd/m² display (the peak a
#: spec's HLG display must have: :data:`generator.spec.allowed.HLG_DISPLAY_PEAK`).
HLG_DISPLAY_BUILTIN = "DISPLAY - CIE-XYZ-D65_to_REC.2100-HLG-1000nit"


def has_builtin(style: str, version: tuple[int, int]) -> bool:
    """Whether OCIO ``version`` has the builtin transform ``style``."""
    return version >= BUILTIN_MIN_VERSION[style]


def curve_chain(curve_name: str, version: tuple[int, int]):
    """The builtin chain expressing ``curve_name`` at ``version``, or None (bake it)."""
    chain = CURVE_BUILTINS.get(curve_name)
    if chain and all(has_builtin(style, version) for style, _ in chain):
        return chain
    return None


def clamped_code_domain(curve_name: str, version: tuple[int, int]) -> tuple[float, float] | None:
    """The codes a scene space of ``version`` clamps ``curve_name``'s codes to before the builtin
    expressing it (:data:`BUILTIN_CLAMPED_DOMAIN`), or None."""
    chain = curve_chain(curve_name, version)
    return next((BUILTIN_CLAMPED_DOMAIN[style] for style, _ in chain or () if style in BUILTIN_CLAMPED_DOMAIN), None)


def builtin_code_domain(curve_name: str, version: tuple[int, int]) -> tuple[float, float] | None:
    """The codes a scene space of ``version`` decodes ``curve_name`` on when a builtin expresses
    it that clamps (:data:`BUILTIN_CODE_DOMAIN`) or is clamped (:data:`BUILTIN_CLAMPED_DOMAIN`), or None."""
    chain = curve_chain(curve_name, version)
    clamps = {**BUILTIN_CODE_DOMAIN, **BUILTIN_CLAMPED_DOMAIN}
    domains = [clamps[style] for style, _ in chain or () if style in clamps]
    if not domains:
        return None
    return max(lo for lo, _ in domains), min(hi for _, hi in domains)


def pq_builtin_tables(version: tuple[int, int]) -> tuple[int, ...]:
    """The ST-2084 tables (:data:`PQ_BUILTIN_TABLES`) of the libraries that read a config of
    ``version``: the oldest such library's (the last entry at or before ``version``) and every later one."""
    first = max(v for v in PQ_BUILTIN_TABLES if v <= version)
    return tuple(size for v, size in sorted(PQ_BUILTIN_TABLES.items()) if v >= first)


#: First config version that runs the ACES output transforms analytically: ACES 1.x's
#: builtins exist from 2.0; ACES 2.0's builtins and FixedFunction ACES_OUTPUT_TRANSFORM_20
#: from 2.4 (an older config is refused by OCIO when it holds them).
ACES_ANALYTIC_MIN_VERSION = {"1.3": (2, 0), "2.0": (2, 4)}


def aces_analytic(version_of_aces: str, version: tuple[int, int]) -> bool:
    """Whether a config of ``version`` runs an ACES ``version_of_aces`` view analytically."""
    return version >= ACES_ANALYTIC_MIN_VERSION[version_of_aces]
