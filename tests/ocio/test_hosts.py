"""Real hosts load the built config: Debian's OCIO 2.1 ociocheck, and Blender 3.x."""

import os
import subprocess

from tests.conftest import require_program


def test_ocio21_config_passes_debian_ociocheck(build_config):
    ociocheck = require_program("ociocheck")
    result = subprocess.run(
        [ociocheck, "--iconfig", str(build_config((2, 1)))], capture_output=True, text=True, timeout=120
    )
    output = result.stdout + result.stderr
    assert result.returncode == 0, output
    assert "ERROR" not in output, output
    assert "passed" in output.split("** Validation **")[1]


def test_blender_loads_the_config_through_ocio(build_config, default_spec):
    blender = require_program("blender")
    script = (
        "import bpy\n"
        "s = bpy.context.scene\n"
        "items = bpy.types.ColorManagedInputColorspaceSettings.bl_rna.properties['name'].enum_items\n"
        "print('OCIOFORGE', s.display_settings.display_device, '|', s.view_settings.view_transform, '|', len(items))\n"
    )
    env = {**os.environ, "OCIO": str(build_config((2, 1)))}
    result = subprocess.run(
        [blender, "-b", "--factory-startup", "--python-expr", script],
        capture_output=True,
        text=True,
        env=env,
        timeout=300,
    )
    output = result.stdout + result.stderr
    line = next(line for line in output.splitlines() if line.startswith("OCIOFORGE"))
    display, view, spaces = (part.strip() for part in line.removeprefix("OCIOFORGE").split("|"))
    assert display == default_spec.displays[0].name
    assert view == default_spec.displays[0].views[0]
    assert int(spaces) >= len(default_spec.colour_spaces)
    # The factory scene names Blender's own display/view ("sRGB", "Filmic"); falling back from those
    # to the config's defaults is expected. Anything else Blender says about colour management is not.
    complaints = [
        line
        for line in output.splitlines()
        if "Color management" in line
        and "Using" not in line
        and "used by scene not found" not in line
        and "scene view" not in line
    ]
    assert not complaints, complaints


def test_debian_oiiotool_shows_a_float_exr_through_a_view(build_config, default_spec, tmp_path):
    """OpenImageIO 2.4 (Debian's openimageio-tools, OCIO 2.1) reads an EXR as colour space "Linear":
    the config's linear role, scene_linear's target, lets its --ociodisplay run (it had failed with
    "Cannot find source color space named 'Linear'")."""
    import numpy as np
    import OpenImageIO as oiio

    from generator import reference, tolerances

    oiiotool = require_program("/usr/bin/oiiotool")
    colour = (0.18, 0.3, 0.05)
    pattern = ["--pattern", f"fill:color={','.join(map(str, colour))}", "4x4", "3", "-d", "float"]
    subprocess.run([oiiotool, *pattern, "-o", str(tmp_path / "in.exr")], check=True, capture_output=True)
    result = subprocess.run(
        [
            oiiotool,
            str(tmp_path / "in.exr"),
            "--colorconfig",
            str(build_config((2, 1))),
            "--ociodisplay",
            "sRGB - Display",
            "Colorimetric",
            "-d",
            "float",
            "-o",
            str(tmp_path / "out.exr"),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    shown = oiio.ImageBuf(str(tmp_path / "out.exr")).get_pixels(oiio.FLOAT)[0, 0]
    display = next(d for d in default_spec.displays if d.name == "sRGB - Display")
    scene_linear = default_spec.space(dict(default_spec.roles)["scene_linear"])
    expected = reference.colorimetric_view(
        default_spec, display, reference.to_reference(default_spec, scene_linear, np.array([colour]))
    )[0]
    assert np.abs(shown - expected).max() <= tolerances.ANALYTIC_RELATIVE * tolerances.RELATIVE_FLOOR, (shown, expected)
