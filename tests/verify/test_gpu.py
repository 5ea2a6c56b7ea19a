"""verify's gpu engine: OCIO's GLSL shaders and textures drawn on an OpenGL device, as a host's
viewer draws a view (CI installs Mesa's EGL, whose llvmpipe is the device without a GPU)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from generator.verify.checks import LUT, VIEW
from generator.verify.gpu import GpuEngine, gpu_apply, open_device
from generator.verify.judge import FAIL, PASS
from generator.verify.run import verify
from tests.conftest import host_missing
from tests.verify.conftest import dim_output_table


@pytest.fixture(scope="module")
def device():
    reason = GpuEngine().missing(Path("."))
    if reason:
        host_missing(reason, "CI installs Mesa's EGL: see .ci/run")
    ctx = open_device()
    yield ctx
    ctx.release()


def test_a_shader_with_every_kind_of_texture_draws_what_the_cpu_computes(device):
    """A matrix, a 1D table (a 2D texture, filtered) and a 3D table (a 3D texture, tetrahedral
    in the shader): drawn, every probe comes back where OCIO's CPU puts it."""
    import PyOpenColorIO as ocio

    size = 5
    lut3d = ocio.Lut3DTransform(gridSize=size, interpolation=ocio.INTERP_TETRAHEDRAL)
    nodes = np.linspace(0.0, 1.0, size)
    for r, red in enumerate(nodes):
        for g, green in enumerate(nodes):
            for b, blue in enumerate(nodes):
                lut3d.setValue(r, g, b, red**2, (green + blue) / 2, blue**0.5)
    lut1d = ocio.Lut1DTransform(length=1024)
    for i, x in enumerate(np.linspace(0.0, 1.0, 1024)):
        lut1d.setValue(i, x**0.45, x**0.5, x**0.55)
    group = ocio.GroupTransform(
        [ocio.MatrixTransform([0.9, 0.1, 0, 0, 0, 0.8, 0.2, 0, 0.1, 0, 0.9, 0, 0, 0, 0, 1]), lut1d, lut3d]
    )
    proc = ocio.Config.CreateRaw().getProcessor(group)
    values = np.random.default_rng(5).uniform(0.0, 1.0, (3000, 3))
    cpu = np.ascontiguousarray(values, dtype=np.float32)
    proc.getDefaultCPUProcessor().applyRGB(cpu)
    drawn = gpu_apply(device, proc, values)
    assert drawn.shape == values.shape
    np.testing.assert_allclose(drawn, cpu, rtol=0, atol=1e-4)
    assert np.abs(drawn - values).max() > 0.1  # the transform moved them: the shader ran


def test_the_gpu_draws_the_default_configs_scale_views_within_their_targets(build_config, device):
    config = build_config((2, 1))
    result = verify(config, ("gpu",), density="quick", kinds=(VIEW,), only="Scale from ACEScg", strict=True)
    outcomes = [o for o in result.outcomes if o.engine.startswith("gpu")]
    assert len(outcomes) >= 10 and all(o.verdict == PASS for o in outcomes), [
        (o.check.title, o.verdict, o.worst) for o in outcomes if o.verdict != PASS
    ]


def test_the_gpu_names_a_scale_file_dimmed_by_half_a_code(config_copy, device):
    """What the CPU engines catch, the shader path catches: the sRGB Scale file's output table
    scaled by 0.9995."""
    dim_output_table(config_copy.parent / "luts" / "view_srgb_display_scale_17.clf", 0.9995)
    result = verify(config_copy, ("gpu",), density="quick", kinds=(VIEW, LUT), only="srgb_display_scale", strict=True)
    failed = [o for o in result.outcomes if o.engine.startswith("gpu")]
    assert [o.verdict for o in failed] == [FAIL]
    # the config's numbers, not OCIO's GPU path (which README lists as a known departure)
    assert failed[0].note.startswith("not OCIO's GPU path: its CPU processor, lossless, departs"), failed[0].note


def test_a_failure_of_the_gpu_path_names_its_operator(build_config, device):
    """OCIO's shader inverts a 1D LUT by a table of its inverse whatever the flags, 3% off on
    N-Log's inverse near black: the failure stays a failure, and names that operator."""
    from generator.verify.checks import FROM_REFERENCE

    config = build_config((2, 1))
    result = verify(config, ("gpu",), kinds=(FROM_REFERENCE,), only="-> N-Log N-Gamut", strict=True)
    failing = [o for o in result.outcomes if o.engine.startswith("gpu") and o.verdict == FAIL]
    assert failing, "N-Log's inverse passed on the GPU: update README's list of the GPU path's departures"
    assert all("OCIO's GPU path: Lut1DTransform inverse drawn alone" in o.note for o in failing), [
        o.note for o in failing
    ]


def test_no_probes_draw_nothing(device):
    """A check with no probes had made the device refuse its empty target, failing on the GPU alone."""
    import PyOpenColorIO as ocio

    proc = ocio.Config.CreateRaw().getProcessor(ocio.MatrixTransform([2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]))
    assert gpu_apply(device, proc, np.zeros((0, 3))).shape == (0, 3)


def test_the_gpu_keeps_desaturate_near_black(build_config, device):
    """OCIO's shader forms a 3D table's coordinate as ``(x (N - 1) + 0.5) / N`` in float32, which
    resolves about 3e-8 of a cell: the desaturate lattice's value axis has a first cell of 2**-16
    so that colours a billionth of the peak keep their value (a first cell of 1/64 drew them black,
    0.26 ten-bit codes off on Gamma 2.6). From an encoded display space every channel is
    positive, so OCIO HSV's value is too (negative values are README's known departure)."""
    config = build_config((2, 1))
    result = verify(config, ("gpu",), kinds=(VIEW,), only="Desaturate from sRGB - Display", strict=True)
    outcomes = [o for o in result.outcomes if o.engine.startswith("gpu")]
    assert len(outcomes) >= 6 and all(o.verdict == PASS for o in outcomes), [
        (o.check.title, o.verdict, o.worst) for o in outcomes if o.verdict != PASS
    ]
