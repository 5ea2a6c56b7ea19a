"""What a spec may ask for that depends on no spec: its views, the config versions the
installed OpenColorIO writes, the HLG display's peak.

Loading (:mod:`generator.spec.load`) checks a spec against these and reading a build's
resolved spec (:mod:`generator.spec.resolved`) checks it again; the config emitter
(:mod:`generator.ocio`) reads them above.
"""

from __future__ import annotations

import PyOpenColorIO as ocio

#: Views a display may offer: each scene-referred view names its gamut-mapping method
#: (generator.gamut.METHODS); Raw shows data unchanged.
VIEW_METHODS = {
    "Colorimetric": "clip",
    "Desaturate": "desaturate",
    "Scale": "scale",
    "Perceptual": "perceptual",
    "RGC": "rgc",
}
VIEWS = (*VIEW_METHODS, "Raw")

#: The ACES studio configs' name for a view without tone mapping: our Colorimetric.
COLORIMETRIC_ALIASES = ("Un-tone-mapped",)

#: The oldest config version a spec may ask for.
OCIO_MIN_VERSION = (2, 1)


def newest_ocio_version() -> tuple[int, int]:
    """The newest config version the installed PyOpenColorIO writes."""
    major, minor = ocio.__version__.split(".")[:2]
    return int(major), int(minor)


#: The peak luminance (cd/m²) of an HLG display: OCIO's one HLG display builtin,
#: DISPLAY - CIE-XYZ-D65_to_REC.2100-HLG-1000nit, holds BT.2100's OOTF for 1000 cd/m².
HLG_DISPLAY_PEAK = 1000.0

#: LUT formats a bake writes (generator.luts.bake.FORMATS), which a ``[[lut_pack]]`` may name.
LUT_FORMATS = ("resolve_cube", "iridas_cube", "spi3d", "clf")
