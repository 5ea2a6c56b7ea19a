"""The script Blender runs for verify: each job's probe image loaded in its colour space and saved
through the scene's display and view as a 16-bit RGB PNG, that transform alone (no dither, look,
exposure or curve), and each job's status written, a job Blender refuses failing alone."""

from __future__ import annotations

import json
import os
import subprocess

import numpy as np
import OpenImageIO as oiio
import PyOpenColorIO as ocio

from generator import tolerances
from generator.verify import images
from generator.verify.blender import SCRIPT
from tests.conftest import require_program


def _request(workdir) -> tuple[list[dict], dict]:
    request = json.loads((workdir / "blender-jobs.json").read_text(encoding="utf-8"))
    return request["jobs"], json.loads((workdir / "blender-status.json").read_text(encoding="utf-8"))


def test_every_job_has_a_status_and_one_blender_refuses_fails_alone(blender_run):
    """The job asking for a view the display lacks carries Blender's words; the job after it ran."""
    _, _, workdir = blender_run
    jobs, status = _request(workdir)
    assert list(status) == [job["output"] for job in jobs]
    assert [status[job["output"]] == "ok" for job in jobs] == [True, True, True, False, True]
    assert status[jobs[3]["output"]].startswith('TypeError: bpy_struct: item.attr = val: enum "No Such View" not found')


def test_each_render_is_a_16_bit_rgb_png(blender_run):
    _, _, workdir = blender_run
    jobs, status = _request(workdir)
    for job in jobs:
        if status[job["output"]] == "ok":
            spec = oiio.ImageInput.open(job["output"]).spec()
            assert (spec.format.basetype, spec.nchannels) == (oiio.UINT16, 3), job["output"]


def test_a_render_is_the_view_transform_alone(build_config, blender_run):
    """Each render is what PyOpenColorIO's processor of the job's space, display and view makes of
    the probe image, clipped to [0, 1]: most pixels to the 16-bit file's rounding, none further
    than a few steps (Blender holds the image in scene_linear, in float32, which a steep display
    curve near black shows). Raw is left out: Blender shows scene_linear there."""
    _, _, workdir = blender_run
    jobs, status = _request(workdir)
    cfg = ocio.Config.CreateFromFile(str(build_config((2, 1))))
    for job in jobs:
        if status[job["output"]] != "ok" or job["view"] == "Raw":
            continue
        values = np.asarray(oiio.ImageBuf(job["input"]).get_pixels(oiio.FLOAT), dtype=np.float64).reshape(-1, 3)
        finite = np.all(np.isfinite(values), axis=1)
        pixels = np.ascontiguousarray(values[finite], dtype=np.float32)
        processor = cfg.getProcessor(job["src"], job["display"], job["view"], ocio.TRANSFORM_DIR_FORWARD)
        processor.getDefaultCPUProcessor().applyRGB(pixels)
        rendered, step = images.read(job["output"], len(values))
        assert step == tolerances.UINT16_STEP
        departure = np.abs(rendered[finite] - np.clip(pixels, 0.0, 1.0))
        assert np.median(departure) <= 0.5 * step and departure.max() <= 8 * step, (job, departure.max() / step)


def test_a_file_loaded_again_in_another_space_is_an_image_of_its_own(build_config, blender_run, tmp_path):
    """Two jobs on one probe file: the second, in a space the config lacks, fails on its own
    account, not passing on the image the first one loaded."""
    first = _request(blender_run[2])[0][0]
    outputs = [tmp_path / "first.png", tmp_path / "second.png"]
    jobs = [dict(first, output=str(outputs[0])), dict(first, src="No Such Space", output=str(outputs[1]))]
    request, status = tmp_path / "jobs.json", tmp_path / "status.json"
    request.write_text(json.dumps({"jobs": jobs, "status": str(status)}), encoding="utf-8")
    command = [require_program("blender"), "-b", "--factory-startup", "--python", str(SCRIPT), "--", str(request)]
    env = {**os.environ, "OCIO": str(build_config((2, 1)))}
    subprocess.run(command, env=env, capture_output=True, check=False, timeout=300)
    result = json.loads(status.read_text(encoding="utf-8"))
    assert result[str(outputs[0])] == "ok"
    assert 'enum "No Such Space" not found' in result[str(outputs[1])]
