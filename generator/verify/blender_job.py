"""Run inside Blender (``blender -b --factory-startup --python THIS -- jobs.json``), never imported.

For each job: load the EXR probe image in its colour space, set the scene's
display and view (look none, exposure 0, gamma 1, no curves, no dither) and save
it as a render, a 16-bit PNG. Writes ``{output: "ok" | error}`` to the status
file named in the jobs file. Blender reads the config from $OCIO.
"""

import json
import sys

import bpy


def configure(scene):
    """Scene settings under which a render is the view transform alone: no dither, look, exposure or curve."""
    scene.render.dither_intensity = 0.0
    view = scene.view_settings
    view.look = "None"
    view.exposure = 0.0
    view.gamma = 1.0
    view.use_curve_mapping = False
    settings = scene.render.image_settings
    settings.file_format = "PNG"
    settings.color_depth = "16"
    settings.color_mode = "RGB"


def main():
    """Render the request's jobs (input, space, display, view, output) and write each one's status."""
    with open(sys.argv[sys.argv.index("--") + 1], encoding="utf-8") as handle:
        request = json.load(handle)
    scene = bpy.context.scene
    configure(scene)
    loaded, status = {}, {}
    for job in request["jobs"]:
        try:
            key = (job["input"], job["src"])  # one image per file and colour space: a second space is its own
            if key not in loaded:
                image = bpy.data.images.load(job["input"], check_existing=False)
                image.colorspace_settings.name = job["src"]
                loaded[key] = image
            scene.display_settings.display_device = job["display"]
            scene.view_settings.view_transform = job["view"]
            loaded[key].save_render(job["output"], scene=scene)
            status[job["output"]] = "ok"
        except Exception as error:  # Blender raises TypeError / RuntimeError with a message
            status[job["output"]] = f"{type(error).__name__}: {error}"
    with open(request["status"], "w", encoding="utf-8") as handle:
        json.dump(status, handle)


main()
