"""OCIO's GPU path: the GLSL shader and textures a host's viewer draws with.

Nuke's, Blender's and Maya's viewers do not run OCIO's CPU processor: they ask
it for a GPU processor, compile the shader text it writes and upload the LUTs
it holds as textures (1D tables as 2D textures, 3D tables as 3D textures,
filtered by the device where OCIO asks for linear interpolation). This engine
does the same, with OCIO's default flags as hosts do, on an OpenGL 4.0 device
reached headless through EGL (on a machine without a GPU, Mesa's llvmpipe, a
software rasteriser), and reads the drawn pixels back as float32: every probe
is a texel of an RGBA32F input texture, drawn once into an RGBA32F target.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import PyOpenColorIO as ocio

from generator.verify.check import KINDS, Check
from generator.verify.engines import apply, cpu_with, isolate, load_config, processor, uncached_config
from generator.verify.judge import Output

#: GLSL version the shaders are written in (OCIO's GPU_LANGUAGE_GLSL_4_0), and the OpenGL
#: version asked of the device.
GLSL_VERSION = 400

#: Probes per row of the input and output textures.
ROW = 1024

#: What to install when no device can be opened (Debian's packages of Mesa's EGL and drivers).
REMEDY = "install Mesa's EGL and drivers (Debian: libegl1 libegl-mesa0 libgl1-mesa-dri libgl1) or a GPU's driver"

_VERTEX = f"""#version {GLSL_VERSION} core
in vec2 position;
void main() {{ gl_Position = vec4(position, 0.0, 1.0); }}
"""

_MAIN = """
uniform sampler2D ocioforge_input;
out vec4 ocioforge_output;
void main() { ocioforge_output = ocioforge_view(texelFetch(ocioforge_input, ivec2(gl_FragCoord.xy), 0)); }
"""


def open_device():
    """A headless OpenGL context (moderngl over EGL); raises when none can be opened."""
    import moderngl  # optional: without it the GPU engine reports itself missing

    return moderngl.create_standalone_context(backend="egl", require=GLSL_VERSION)


def _texture(texture, interpolation, resources: list, unit: int, program, sampler: str):
    """Bind a LUT's ``texture`` (kept in ``resources``, to be released) to ``unit`` as ``sampler``."""
    import moderngl

    resources.append(texture)
    filtering = moderngl.NEAREST if interpolation == ocio.INTERP_NEAREST else moderngl.LINEAR
    texture.filter = (filtering, filtering)
    texture.repeat_x = texture.repeat_y = False
    if hasattr(texture, "repeat_z"):
        texture.repeat_z = False
    texture.use(unit)
    program[sampler].value = unit


def gpu_apply(ctx, proc, values: np.ndarray) -> np.ndarray:
    """``values`` (n, 3) through ``proc``'s GPU processor (OCIO's default flags), drawn on ``ctx``."""
    import moderngl

    if not len(values):
        return np.zeros((0, 3))
    desc = ocio.GpuShaderDesc.CreateShaderDesc(language=ocio.GPU_LANGUAGE_GLSL_4_0)
    desc.setAllowTexture1D(False)  # 1D tables as 2D textures, as every GLSL host can bind them
    desc.setFunctionName("ocioforge_view")
    proc.getDefaultGPUProcessor().extractGpuShaderInfo(desc)
    if len(list(desc.getUniforms())):
        raise RuntimeError("the shader has uniforms (dynamic properties), which no config of ocioforge writes")
    resources: list = []
    try:
        resources.append(
            program := ctx.program(
                vertex_shader=_VERTEX, fragment_shader=f"#version {GLSL_VERSION} core\n{desc.getShaderText()}{_MAIN}"
            )
        )
        unit = 1
        for table in desc.getTextures():
            data = np.ascontiguousarray(table.getValues(), dtype=np.float32).tobytes()
            components = 1 if table.channel == ocio.GpuShaderDesc.TEXTURE_RED_CHANNEL else 3
            _texture(
                ctx.texture((table.width, table.height), components, data, dtype="f4"),
                table.interpolation,
                resources,
                unit,
                program,
                table.samplerName,
            )
            unit += 1
        for table in desc.get3DTextures():
            data = np.ascontiguousarray(table.getValues(), dtype=np.float32).tobytes()
            edge = table.edgeLen
            _texture(
                ctx.texture3d((edge, edge, edge), 3, data, dtype="f4"),
                table.interpolation,
                resources,
                unit,
                program,
                table.samplerName,
            )
            unit += 1
        count = len(values)
        width, height = min(count, ROW), -(-count // ROW)
        pixels = np.zeros((width * height, 4), dtype=np.float32)
        pixels[:count, :3] = values
        pixels[:, 3] = 1.0
        resources.append(source := ctx.texture((width, height), 4, pixels.tobytes(), dtype="f4"))
        source.filter = (moderngl.NEAREST, moderngl.NEAREST)
        source.use(0)
        program["ocioforge_input"].value = 0
        resources.append(target := ctx.texture((width, height), 4, dtype="f4"))
        resources.append(frame := ctx.framebuffer(color_attachments=[target]))
        resources.append(corners := ctx.buffer(np.array([-1, -1, 3, -1, -1, 3], dtype=np.float32).tobytes()))
        resources.append(array := ctx.vertex_array(program, [(corners, "2f", "position")]))
        frame.use()
        ctx.viewport = (0, 0, width, height)
        array.render(moderngl.TRIANGLES)
        drawn = np.frombuffer(frame.read(components=4, dtype="f4"), dtype=np.float32).reshape(-1, 4)
        return drawn[:count, :3].astype(np.float64)
    finally:
        for resource in reversed(resources):
            resource.release()


@dataclass(frozen=True)
class GpuEngine:
    """OCIO's GLSL shaders and textures on an OpenGL device, as a host's viewer runs them."""

    name: str = "gpu"
    kinds: tuple = KINDS

    def missing(self, config: Path) -> str:
        """Why the GPU engine cannot run here (no moderngl, no OpenGL device), or ""."""
        try:
            import moderngl  # noqa: F401
        except ImportError as error:
            return f"moderngl is not installed ({error}); install the project's dependencies (pip install -e .)"
        try:
            open_device().release()
        except Exception as error:  # ImportError, or moderngl/glcontext's own errors naming the device
            return f"no OpenGL {GLSL_VERSION // 100}.{GLSL_VERSION % 100 // 10} device ({error}); {REMEDY}"
        return ""

    def version(self) -> str:
        """PyOpenColorIO, GLSL and the OpenGL renderer the shaders run on."""
        ctx = open_device()
        try:
            return (
                f"PyOpenColorIO {ocio.__version__} GLSL {GLSL_VERSION // 100}.{GLSL_VERSION % 100 // 10}, default "
                f"flags, on {ctx.info['GL_RENDERER']} (OpenGL {ctx.info['GL_VERSION']})"
            )
        finally:
            ctx.release()

    def run(self, config_path: Path, checks: list[Check], workdir: Path) -> list[list[Output]]:
        """Each check's probes through OCIO's GPU shader for its processor, read back as float32."""
        cfg = load_config(config_path)
        ctx = open_device()
        out = []
        try:
            for check in checks:
                try:
                    proc = processor(cfg, check, config_path.parent)
                    out.append([Output(gpu_apply(ctx, proc, check.probes.values), "GLSL float32")])
                except Exception as error:  # OCIO's and the device's errors, each naming the problem
                    out.append([Output(None, "GLSL float32", error=f"{type(error).__name__}: {error}")])
        finally:
            ctx.release()
        return out

    def explain(self, config_path: Path, check: Check, error_of) -> str:
        """Why ``check`` fails here: :func:`culprit`."""
        return culprit(config_path, check, error_of)


def culprit(config_path: Path, check: Check, error_of) -> str:
    """Why a check fails on the GPU: the config's numbers, where OCIO's CPU processor (lossless)
    departs too; else the operator of its chain that, drawn
    alone on the GPU while every other runs on the CPU losslessly, gives the largest error
    (``error_of(values)``, the check's worst error for an output; :func:`~generator.verify.
    engines.isolate`), or, when no operator alone does, that OCIO's GPU processor of the whole
    chain departs (its optimiser merges or drops operators there)."""
    cfg = uncached_config(config_path)
    proc = processor(cfg, check, config_path.parent)
    cpu = error_of(apply(proc.getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS), check.probes.values))
    if cpu > check.tolerance:  # a broken config is not the GPU's to answer for
        return f"not OCIO's GPU path: its CPU processor, lossless, departs {cpu:.2g} too (the config's numbers)"
    transforms = list(proc.createGroupTransform())
    ctx = open_device()
    try:
        alone, name, split = isolate(
            cfg,
            transforms,
            check.probes.values,
            cpu_with(ocio.OPTIMIZATION_LOSSLESS),
            lambda proc, values: gpu_apply(ctx, proc, values),
            error_of,
        )
    finally:
        ctx.release()
    if split > check.tolerance:
        return (
            f"OCIO's GPU path (its operator not isolated: the chain run operator by operator on the CPU departs "
            f"{split:.2g} by itself)"
        )
    if alone > check.tolerance:
        return f"OCIO's GPU path: {name} drawn alone, the rest on the CPU, gives {alone:.2g}"
    return (
        f"OCIO's GPU path: its shader of the whole chain (no operator drawn alone departs beyond {alone:.2g}: "
        "OCIO optimises the chain as a whole for the GPU)"
    )
