"""The capability table against OpenColorIO's own refusal of newer styles in older profiles."""

import PyOpenColorIO as ocio
import pytest

from generator.ocio import capabilities
from generator.ocio.capabilities import BUILTIN_MIN_VERSION, CURVE_BUILTINS, SPACE_BUILTINS, curve_chain
from tests.conftest import VERSIONS


def accepts(style: str, version) -> bool:
    cfg = ocio.Config()
    cfg.setMajorVersion(version[0])
    cfg.setMinorVersion(version[1])
    space = ocio.ColorSpace(name="probe")
    space.setTransform(ocio.BuiltinTransform(style), ocio.COLORSPACE_DIR_TO_REFERENCE)
    cfg.addColorSpace(space)
    try:
        cfg.serialize()
    except ocio.Exception:
        return False
    return True


@pytest.mark.parametrize("style", sorted(BUILTIN_MIN_VERSION))
def test_min_versions_match_what_ocio_accepts(style):
    for version in VERSIONS:
        assert accepts(style, version) == (version >= BUILTIN_MIN_VERSION[style]), (style, version)


def test_every_style_used_is_in_the_table():
    used = {s for chain in CURVE_BUILTINS.values() for s, _ in chain} | set(SPACE_BUILTINS.values())
    assert used <= set(BUILTIN_MIN_VERSION)


def test_curves_without_builtins_at_a_version_are_baked():
    assert curve_chain("Canon Log 3", (2, 1)) is None
    assert curve_chain("Canon Log 3", (2, 2)) is not None
    assert curve_chain("Apple Log", (2, 3)) is None
    assert curve_chain("Apple Log", (2, 4)) is not None


@pytest.mark.parametrize("style", sorted(capabilities.BUILTIN_CODE_DOMAIN))
def test_builtin_code_domains_are_where_ocio_clamps(style):
    """A code below (or above) a clamping builtin's domain decodes as its end does; inside,
    the curve goes on."""
    import numpy as np
    import PyOpenColorIO as ocio

    processor = ocio.Config.CreateRaw().getProcessor(ocio.BuiltinTransform(style)).getDefaultCPUProcessor()

    def decode(code):
        pixel = np.full((1, 3), code, dtype=np.float32)
        processor.applyRGB(pixel)
        return float(pixel[0, 0])

    lo, hi = capabilities.BUILTIN_CODE_DOMAIN[style]
    assert decode(lo - 0.2) == decode(lo) != decode(lo + 0.05)
    if np.isfinite(hi):
        assert decode(hi + 0.2) == decode(hi) != decode(hi - 0.05)
    else:
        assert decode(1.2) > decode(1.0)


def test_the_pq_tables_are_those_of_every_library_reading_a_version():
    """Before 2.4 OCIO tabulates PQ over 4096 codes, from 2.4 over every half-float code; a
    config of 2.1 to 2.3 meets both, a newer one only the second, which this library has."""
    assert capabilities.pq_builtin_tables((2, 1)) == (4096, capabilities.HALF_DOMAIN)
    assert capabilities.pq_builtin_tables((2, 3)) == (4096, capabilities.HALF_DOMAIN)
    assert capabilities.pq_builtin_tables((2, 4)) == (capabilities.HALF_DOMAIN,)
    if tuple(int(v) for v in ocio.__version__.split(".")[:2]) >= (2, 4):
        transform = ocio.BuiltinTransform(capabilities.PQ_BUILTIN)
        (table,) = ocio.Config.CreateRaw().getProcessor(transform).createGroupTransform()
        assert isinstance(table, ocio.Lut1DTransform) and table.getInputHalfDomain() and table.getLength() == 65536


@pytest.mark.parametrize("style", sorted(capabilities.BUILTIN_CLAMPED_DOMAIN))
def test_builtins_a_config_clamps_do_not_clamp_by_themselves(style):
    """Outside its domain the builtin goes on (or mirrors), so a scene space clamps first."""
    import numpy as np

    processor = ocio.Config.CreateRaw().getProcessor(ocio.BuiltinTransform(style)).getDefaultCPUProcessor()
    lo, hi = capabilities.BUILTIN_CLAMPED_DOMAIN[style]
    pixel = np.repeat(np.array([[lo - 0.2], [lo], [hi], [hi + 0.2]], dtype=np.float32), 3, axis=1)
    processor.applyRGB(pixel)
    below, low, high, above = pixel[:, 0]
    assert below != low and above != high
