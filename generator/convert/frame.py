"""One frame through a config: read, convert the colour channels with OCIO, write under a
temporary name, rename into place, and (asked) read back and judge against the reference.

The colour channels go through PyOpenColorIO's CPU processor with lossless flags, the config
as written (measured faster on a frame than ImageBufAlgo.colorconvert, which runs OCIO's
default flags and its fast approximations; bench/convert.py); every other channel (alpha,
depth, a layer's channels) is written as read. Everything a frame writes goes first into a
hidden folder beside its output, under the output's own name (a DPX records its file name),
and is renamed into place once complete: a frame stopped at any point, a worker killed
included, leaves nothing under an output's name.
"""

from __future__ import annotations

import filecmp
import os
import shutil
import tempfile
import time
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from generator.avx_state import clear_upper
from generator.convert import formats, pixels
from generator.convert.frames import Source
from generator.convert.judge import Route, Verdict, judge
from generator.convert.pixels import FrameError
from generator.ocio.environment import set_aside
from generator.spec import resolved
from generator.verify.paths import LazyEndpoints

WRITTEN, SKIPPED, FAILED = "written", "skipped", "failed"

#: Prefix of the hidden folder a frame is written in before its rename.
PARTIAL = ".ocioforge-partial-"

#: ``Plan.verify`` for every pixel (otherwise a number of pixels per part, 0 for none).
EVERY_PIXEL = -1


@dataclass(frozen=True)
class Plan:
    """What every frame of a run does. ``src`` is the colour space read (None: each file's own
    metadata, else the config's file rules); ``dst``, or ``display`` and ``view``, the result."""

    config: str
    src: str | None
    dst: str = ""
    display: str = ""
    view: str = ""
    format: str = "exr"
    depth: str | None = None
    compression: str | None = None
    verify: int = 0
    memory: int = pixels.MEMORY_BUDGET
    force: bool = False
    skip_existing: bool = False


@dataclass(frozen=True)
class FrameResult:
    """What became of one frame: written (with its verdict when verified), skipped, or failed
    and why; the colour space it was read as; the seconds it took."""

    source: str
    output: str
    status: str
    reason: str = ""
    src: str = ""
    verdict: Verdict | None = None
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        """Whether the frame was converted and, when verified, passed."""
        return self.status != FAILED and (self.verdict is None or self.verdict.passed)


@lru_cache(maxsize=4)
def _config(path: str):
    import PyOpenColorIO as ocio

    return ocio.Config.CreateFromFile(path)


@lru_cache(maxsize=32)
def _processor(config: str, src: str, dst: str, display: str, view: str):
    import PyOpenColorIO as ocio

    cfg = _config(config)
    proc = cfg.getProcessor(src, display, view, ocio.TRANSFORM_DIR_FORWARD) if display else cfg.getProcessor(src, dst)
    return proc.getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS)


@lru_cache(maxsize=4)
def _spec(config: str):
    """The spec stored beside ``config`` and its endpoints (costly: built once per process)."""
    spec = resolved.read_beside(config)
    return spec, LazyEndpoints(spec)


def source_space(config: str, path: str, part_spec, asked: str | None) -> str:
    """The colour space a frame is read as: ``asked``, else the colour space its metadata
    names where the config knows it, else the config's file rules for its path."""
    cfg = _config(config)
    if asked:
        return cfg.getCanonicalName(asked) or asked
    for tag in (pixels.COLOUR_SPACE, "oiio:ColorSpace"):
        tagged = part_spec.get_string_attribute(tag)
        if tagged and cfg.getColorSpace(tagged) is not None:
            return cfg.getColorSpace(tagged).getName()
    ruled = cfg.getColorSpaceFromFilepath(path)[0]  # (colour space or role, index of the rule)
    return cfg.getCanonicalName(ruled) or ruled


def written_space(plan: Plan) -> str:
    """The colour space an output is in, as recorded in its metadata: ``dst``, or the config's
    ``<view> - <display>`` space where it has one (else the view's display space)."""
    cfg = _config(plan.config)
    if not plan.display:
        return cfg.getCanonicalName(plan.dst) or plan.dst
    named = f"{plan.view} - {plan.display}"
    return named if cfg.getColorSpace(named) is not None else cfg.getDisplayViewColorSpaceName(plan.display, plan.view)


def convert_frame(plan: Plan, source: Source) -> FrameResult:
    """Convert one frame as ``plan`` says; any failure is the frame's, with its reason."""
    started = time.perf_counter()
    if plan.skip_existing and os.path.lexists(source.output):
        return FrameResult(source.path, source.output, SKIPPED)
    try:
        with set_aside():
            src, verdict = _convert(plan, source)
    except FrameError as error:
        return FrameResult(source.path, source.output, FAILED, str(error), seconds=time.perf_counter() - started)
    except Exception as error:  # OIIO and OCIO raise their own types; each names the problem
        reason = f"{type(error).__name__}: {str(error).strip().splitlines()[0] if str(error).strip() else ''}"
        return FrameResult(source.path, source.output, FAILED, reason, seconds=time.perf_counter() - started)
    return FrameResult(
        source.path, source.output, WRITTEN, src=src, verdict=verdict, seconds=time.perf_counter() - started
    )


def _convert(plan: Plan, source: Source) -> tuple[str, Verdict | None]:
    fmt = formats.FORMATS[plan.format]
    inp = pixels.open_input(source.path)
    try:
        frame_parts = pixels.parts(inp, fmt.name == "exr")
        first = frame_parts[0].spec
        src = source_space(plan.config, source.path, first, plan.src)
        depth = formats.choose_depth(fmt, plan.depth, str(first.format), first.get_int_attribute("oiio:BitsPerSample"))
        compression = formats.choose_compression(
            fmt, plan.compression, formats.format_of(source.path) or "", first.get_string_attribute("compression")
        )
        if plan.verify and formats.is_lossy(fmt, compression, depth):
            raise FrameError(
                f"would be written {compression or fmt.name}-compressed, which is lossy, and cannot be "
                "verified; allowed: --verify with a lossless --compression (zip, piz, ...) or format"
            )
        route = Route(src, plan.dst, plan.display, plan.view)
        _write(plan, source, inp, frame_parts, fmt, depth, compression, route)
    finally:
        inp.close()
    if not plan.verify:
        return src, None
    return src, _verify(plan, source, frame_parts, fmt, depth, route)


def _write(plan, source, inp, frame_parts, fmt, depth, compression, route) -> None:
    """Write every part to a hidden sibling folder, then rename the file into place."""
    import OpenImageIO as oiio

    cpu = _processor(plan.config, route.src, route.dst, route.display, route.view)
    stamp = pixels.stamp_of(source.path)
    colour_space = written_space(plan)
    kept = [pixels.kept_channels(p, fmt) for p in frame_parts]
    specs = [pixels.output_spec(p, fmt, depth, compression, colour_space, k, stamp) for p, k in zip(frame_parts, kept)]
    if len({(s.tile_width, s.tile_height) for s in specs}) > 1:  # OpenEXR's parts, as OIIO writes them, are all
        for spec in specs:  # tiled or all scanlines
            spec.tile_width = spec.tile_height = spec.tile_depth = 0
    folder = tempfile.mkdtemp(prefix=PARTIAL, dir=os.path.dirname(source.output) or ".")
    staged = os.path.join(folder, os.path.basename(source.output))
    try:
        out = oiio.ImageOutput.create(staged)
        if out is None or not out.open(staged, specs if len(specs) > 1 else specs[0]):
            raise FrameError(f"cannot write {fmt.name}: {oiio.geterror() or (out.geterror() if out else '')}".strip())
        for index, (part, spec, channels) in enumerate(zip(frame_parts, specs, kept)):
            if index and not out.open(staged, spec, "AppendSubimage"):
                raise FrameError(f"cannot write part {index}: {out.geterror()}")
            for y0, y1 in pixels.bands(part, plan.memory):
                band = pixels.read_rows(inp, part, y0, y1)
                if part.rgb:
                    band = _converted(cpu, band, part.rgb)
                if channels != tuple(range(band.shape[-1])):
                    band = band[..., list(channels)]
                pixels.write_rows(out, spec, y0, y1, np.ascontiguousarray(formats.quantised(band, depth)))
        if not out.close():
            raise FrameError(f"cannot write: {out.geterror()}")
        _place(staged, source.output, plan.force)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _converted(cpu, band: np.ndarray, rgb: tuple[int, ...]) -> np.ndarray:
    """``band`` with its colour channels through the CPU processor (float32, as OCIO runs); in
    place where the band is R, G, B alone."""
    band = np.ascontiguousarray(band, dtype=np.float32)
    clear_upper()  # the EXR reader's AVX state slowed OCIO's SSE code tenfold
    if rgb == (0, 1, 2) and band.shape[-1] == 3:
        cpu.applyRGB(band.reshape(-1, 3))
        return band
    colours = np.ascontiguousarray(band[..., list(rgb)]).reshape(-1, 3)
    cpu.applyRGB(colours)
    band[..., list(rgb)] = colours.reshape((*band.shape[:-1], 3))
    return band


def _place(staged: str, output: str, force: bool) -> None:
    """Rename the complete file onto ``output`` (keeping the permissions of a file it replaces).
    Without ``force`` an output was absent when the run began: one there now is this frame's own,
    written by a worker that died before saying so (the same bytes), or another's, refused."""
    if os.path.lexists(output):
        if not force and not (os.path.isfile(output) and filecmp.cmp(staged, output, shallow=False)):
            raise FrameError(f"{output} appeared during the run; allowed: --force to replace it, or --skip-existing")
        os.chmod(staged, os.stat(output).st_mode & 0o7777)
    os.replace(staged, output)


def _verify(plan, source, frame_parts, fmt, depth, route) -> Verdict:
    """Read the written file back and judge its converted parts, on every pixel or on evenly
    spaced rows holding about ``plan.verify`` pixels per part; the worst verdict."""
    spec, ends = _spec(plan.config)
    verdicts = []
    written, inp = pixels.open_input(source.output), pixels.open_input(source.path)
    try:
        for part in (p for p in frame_parts if p.rgb):
            inputs, outputs, where = _sampled(plan, inp, written, part, fmt, depth)
            clear_upper()  # as before OCIO: numpy's SSE code ran 2.5 times slower after the reader
            verdicts.append(judge(spec, ends, route, inputs, outputs, where, depth))
    finally:
        written.close()
        inp.close()
    failed = [v for v in verdicts if not v.passed]
    return max(failed or verdicts, key=lambda v: (v.worst / v.tolerance) if v.compared else np.inf)


def sampled_rows(part, pixels_wanted: int) -> list[int]:
    """The rows of ``part`` verified: every row, or evenly spaced rows holding about
    ``pixels_wanted`` pixels (first and last included)."""
    rows = part.rows
    if pixels_wanted == EVERY_PIXEL:
        return list(rows)
    count = min(len(rows), max(2, -(-pixels_wanted // max(1, part.spec.width))))
    return sorted(set(np.linspace(rows.start, rows.stop - 1, count).round().astype(int).tolist()))


def _sampled(plan, inp, written, part, fmt, depth):
    """The sampled rows' source colours, written colours (float64) and pixel positions."""
    out_part = pixels.Part(part.index, _part_spec(written, part.index), ())
    channels = pixels.kept_channels(part, fmt)
    where = [channels.index(c) for c in part.rgb]
    ins, outs, places = [], [], []
    for y0, y1 in _runs(sampled_rows(part, plan.verify), plan.memory // max(1, part.spec.width * 4 * 16)):
        ins.append(pixels.read_rows(inp, part, y0, y1)[..., list(part.rgb)].astype(np.float64).reshape(-1, 3))
        stored = pixels.read_rows(written, out_part, y0, y1, formats.read_type(depth))[..., where]
        outs.append(formats.dequantised(stored, depth).reshape(-1, 3))
        ys, xs = np.mgrid[y0:y1, part.spec.x : part.spec.x + part.spec.width]
        places.append(np.stack([xs.ravel(), ys.ravel()], axis=-1))
    return np.concatenate(ins), np.concatenate(outs), np.concatenate(places)


def _part_spec(inp, index: int):
    if not inp.seek_subimage(index, 0):
        raise FrameError(f"the written file lacks part {index}")
    return inp.spec()


def _runs(rows: list[int], longest: int) -> list[tuple[int, int]]:
    """``rows`` grouped into runs ``(y0, y1)`` of consecutive rows, each at most ``longest`` long."""
    runs: list[list[int]] = []
    for y in rows:
        if runs and y == runs[-1][1] and y - runs[-1][0] < max(1, longest):
            runs[-1][1] = y + 1
        else:
            runs.append([y, y + 1])
    return [(a, b) for a, b in runs]
