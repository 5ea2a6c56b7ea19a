"""The reference evaluation of a spec's looks against OpenColorIO: an inline CDL as its
CDLTransform, a CDL or LUT file as its FileTransform reads it, each in its process space as the
ACES studio config converts to it, in the context a shot gives."""

from __future__ import annotations

import dataclasses

import colour
import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator import looks, tolerances
from generator.metrics import colour_relative_error
from generator.spec.load import load
from generator.spec.schema import SpecError
from tests.looks_cases import SPEC, correction, write_show

#: A show LUT beside the looks of tests/looks_cases.py.
FILM = '\n[[look]]\nname = "Film"\nprocess_space = "ACEScct"\nfile = "film.cube"\ninterpolation = "tetrahedral"\n'
#: OCIO's float32 CDL and LUT against the float64 evaluation.
OCIO_ABSOLUTE = 2e-6


@pytest.fixture(scope="module")
def show(tmp_path_factory):
    folder = tmp_path_factory.mktemp("show")
    lut = colour.LUT3D(size=9)
    lut.table = lut.table**1.2 * np.array([1.0, 0.95, 0.9]) + np.array([0.0, 0.02, 0.04])
    colour.write_LUT(lut, str(folder / "film.cube"))
    text = SPEC.replace("[[display]]", FILM + "\n[[display]]")
    return load(write_show(folder, text))


def look(spec, name: str):
    return next(k for k in spec.looks if k.name == name)


def through_ocio(transform, rgb, config=None) -> np.ndarray:
    config = config or ocio.Config.CreateRaw()
    pixels = np.ascontiguousarray(rgb, dtype=np.float32).copy()
    config.getProcessor(transform).getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS).applyRGB(pixels)
    return pixels.astype(np.float64)


def codes() -> np.ndarray:
    """Values of the process space, some beyond [0, 1] (where CDL styles differ), float32 exact."""
    return np.random.default_rng(8).uniform(-0.2, 1.3, (2000, 3)).astype(np.float32).astype(np.float64)


def test_the_context_is_the_specs_defaults_then_the_given_values(show):
    assert looks.context_of(show) == {"SHOT": "sh010"}
    assert looks.context_of(show, {"SHOT": "sh020", "SEQ": "a"}) == {"SHOT": "sh020", "SEQ": "a"}
    assert looks.context_of(show) == {"SHOT": "sh010"}  # the defaults are not changed
    grade = look(show, "Shot Grade")
    assert looks.look_file(show, grade, {"SHOT": "sh020"}).read_text() == correction("sh020")


def test_an_inline_cdl_is_ocios_cdl_transform_in_its_style(show):
    cdl = look(show, "Show Look")
    assert cdl.style == "asc"
    c = cdl.cdl
    transform = ocio.CDLTransform(slope=list(c.slope), offset=list(c.offset), power=list(c.power), sat=c.saturation)
    transform.setStyle(ocio.CDL_ASC)
    ours = looks.look_function(show, cdl, looks.context_of(show))(codes())
    np.testing.assert_allclose(ours, through_ocio(transform, codes()), rtol=0, atol=OCIO_ABSOLUTE)


@pytest.mark.parametrize("shot", ["sh010", "sh020"])
def test_a_cdl_file_is_read_as_ocios_file_transform_reads_it_without_clamping(show, shot):
    grade = look(show, "Shot Grade")
    ours = looks.look_function(show, grade, {"SHOT": shot})(codes())
    path = str(looks.look_file(show, grade, {"SHOT": shot}))
    np.testing.assert_allclose(ours, through_ocio(ocio.FileTransform(path), codes()), rtol=0, atol=OCIO_ABSOLUTE)
    assert looks.FILE_CDL_STYLE == "no_clamp" and (ours.min() < 0.0 or ours.max() > 1.0)


def test_a_lut_file_is_applied_with_its_interpolation_as_ocio_applies_it(show):
    film = look(show, "Film")
    ours = looks.look_function(show, film, {})(codes())
    transform = ocio.FileTransform(str(looks.look_file(show, film, {})), interpolation=ocio.INTERP_TETRAHEDRAL)
    np.testing.assert_allclose(ours, through_ocio(transform, codes()), rtol=0, atol=OCIO_ABSOLUTE)


def test_a_ccc_id_the_file_lacks_names_the_look(show, tmp_path):
    grade = look(show, "Shot Grade")
    (tmp_path / "grades.ccc").write_text(
        '<?xml version="1.0" encoding="UTF-8"?>\n<ColorCorrectionCollection xmlns="urn:ASC:CDL:v1.01">\n'
        f"{correction('sh010').split(chr(10), 1)[1]}</ColorCorrectionCollection>\n"
    )
    moved = dataclasses.replace(show, look_folder=str(tmp_path))
    by_id = dataclasses.replace(grade, file="grades.ccc", cccid="$SHOT")
    np.testing.assert_allclose(
        looks.look_function(moved, by_id, {"SHOT": "sh010"})(codes()),
        looks.look_function(show, grade, {"SHOT": "sh010"})(codes()),
        rtol=0,
        atol=1e-15,
    )
    with pytest.raises(SpecError) as error:
        looks.look_function(moved, by_id, {"SHOT": "sh020"})
    assert error.value.field == "cccid" and "look 'Shot Grade'" in error.value.message


def studio_in_acescct(transform) -> ocio.GroupTransform:
    """``transform`` applied in ACEScct, from and back to ACES2065-1, as the studio config converts."""
    return ocio.GroupTransform(
        [
            ocio.ColorSpaceTransform("ACES2065-1", "ACEScct"),
            transform,
            ocio.ColorSpaceTransform("ACEScct", "ACES2065-1"),
        ]
    )


def test_looks_apply_in_their_process_space_in_order(show):
    """ACES2065-1 into ACEScct, the look, back: the studio config's conversions around OCIO's own
    look; two looks in the order a view names them, which is not the other order."""
    studio = ocio.Config.CreateFromFile("ocio://studio-config-latest")
    aces = np.random.default_rng(6).uniform(0.005, 4.0, (2000, 3)).astype(np.float32).astype(np.float64)
    context = looks.context_of(show)
    c = look(show, "Show Look").cdl
    cdl = ocio.CDLTransform(slope=list(c.slope), offset=list(c.offset), power=list(c.power), sat=c.saturation)
    cdl.setStyle(ocio.CDL_ASC)
    grade = ocio.FileTransform(str(looks.look_file(show, look(show, "Shot Grade"), context)))
    ours = looks.in_reference(show, look(show, "Show Look"), context)(aces)
    theirs = through_ocio(studio_in_acescct(cdl), aces, studio)
    assert colour_relative_error(ours, theirs).max() <= tolerances.ANALYTIC_RELATIVE
    both = looks.looks_in_reference(show, ("Show Look", "Shot Grade"), context)(aces)
    theirs = through_ocio(studio_in_acescct(ocio.GroupTransform([cdl, grade])), aces, studio)
    assert colour_relative_error(both, theirs).max() <= tolerances.ANALYTIC_RELATIVE
    swapped = looks.looks_in_reference(show, ("Shot Grade", "Show Look"), context)(aces)
    assert colour_relative_error(swapped, both).max() > 100 * tolerances.ANALYTIC_RELATIVE
    assert np.array_equal(looks.looks_in_reference(show, (), context)(aces), aces)
