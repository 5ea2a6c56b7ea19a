"""Small frames for the convert tests, written with OpenImageIO, and the command run in-process."""

from __future__ import annotations

from pathlib import Path

import numpy as np

WIDTH, HEIGHT = 64, 48


def pixels(seed: int, channels: int = 4, low: float = -0.05, high: float = 1.5) -> np.ndarray:
    """Random float32 pixels (HEIGHT, WIDTH, channels), alpha in [0, 1]."""
    rng = np.random.default_rng(seed)
    values = rng.uniform(low, high, (HEIGHT, WIDTH, channels)).astype(np.float32)
    if channels >= 4:
        values[..., 3] = rng.uniform(0.0, 1.0, (HEIGHT, WIDTH)).astype(np.float32)
    return values


def write(path: Path, values: np.ndarray, kind: str = "half", **attributes) -> Path:
    """``values`` as an image file of sample type ``kind``; ``tile`` (a size) writes it tiled."""
    import OpenImageIO as oiio

    height, width, channels = values.shape
    spec = oiio.ImageSpec(width, height, channels, oiio.TypeDesc(kind))
    tile = attributes.pop("tile", 0)
    if tile:
        spec.tile_width = spec.tile_height = tile
    for name, value in attributes.items():
        spec.attribute(name.replace("__", ":"), value)
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), spec), out.geterror()
    assert out.write_image(values), out.geterror()
    assert out.close()
    return path


def sequence(folder: Path, name: str, frames, kind: str = "half", **attributes) -> list[Path]:
    """Frames ``name.NNNN.exr`` of random pixels in ``folder`` (seeded by frame)."""
    folder.mkdir(parents=True, exist_ok=True)
    return [write(folder / f"{name}.{f:04d}.exr", pixels(f), kind, **attributes) for f in frames]


def read(path: Path, kind: str = "float", subimage: int = 0):
    """The pixels of ``path`` in ``kind`` (alpha as stored) and its spec."""
    import OpenImageIO as oiio

    hints = oiio.ImageSpec()
    hints.attribute("oiio:UnassociatedAlpha", 1)
    inp = oiio.ImageInput.open(str(path), hints)
    assert inp is not None, oiio.geterror()
    assert inp.seek_subimage(subimage, 0)
    spec = inp.spec()
    data = inp.read_image(subimage, 0, 0, spec.nchannels, kind)
    inp.close()
    return np.asarray(data).reshape(spec.height, spec.width, spec.nchannels), spec


def ocio_applied(config: Path, values: np.ndarray, src: str, dst: str = "", display: str = "", view: str = ""):
    """``values``' first three channels through PyOpenColorIO's lossless CPU processor."""
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(config))
    proc = cfg.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD) if display else cfg.getProcessor(src, dst)
    rgb = np.ascontiguousarray(values[..., :3], dtype=np.float32).reshape(-1, 3)
    proc.getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS).applyRGB(rgb)
    return rgb.reshape((*values.shape[:-1], 3))


def convert(capsys, *argv):
    """``ocioforge convert`` with ``argv``, in this process: its exit code, standard output and error."""
    from generator.cli import main

    try:
        main(["convert", *map(str, argv)])
        code = 0
    except SystemExit as exit_:
        code = exit_.code
    out, err = capsys.readouterr()
    return code, out, err


def cg_to_cct(source, config, out, jobs) -> tuple:
    """``convert``'s arguments for ``source`` from ACEScg to ACEScct through ``config``, into
    ``out``, with ``jobs`` workers: what most conversion tests run."""
    return (source, "--config", config, "--from", "ACEScg", "--to", "ACEScct", "-o", out, "--jobs", jobs)
