"""A convert run's arguments checked, all before any frame is read or any file made: the
frames and their outputs, the config and its names, the format. Bad input is a SpecError
naming the option (the command prints it as one line and exits 2)."""

from __future__ import annotations

import os

from generator.convert import config as configs
from generator.convert import formats
from generator.convert.frame import EVERY_PIXEL, Plan
from generator.convert.frames import FramesError, Source, sources
from generator.files import target
from generator.spec.schema import SpecError


def _format(
    fmt: str | None, depth: str | None, compression: str | None, inputs: tuple[str, ...], verify: bool
) -> formats.Format:
    """The output format, with the sample type and compression asked checked against it."""
    first = next((formats.format_of(p) for p in inputs if formats.format_of(p)), None)
    chosen = formats.FORMATS[(fmt or first or "exr").lower()]
    if depth and depth.lower() not in chosen.depths:
        raise SpecError("--depth", depth, f"is not written as {chosen.name}; allowed: {', '.join(chosen.depths)}")
    if compression is not None:
        method = compression.split(":")[0].lower()
        if method not in chosen.compressions:
            allowed = ", ".join(chosen.compressions) or f"none: {chosen.name} takes no --compression"
            raise SpecError("--compression", compression, f"is not a {chosen.name} compression; allowed: {allowed}")
    if verify and formats.is_lossy(chosen, compression or "", (depth or chosen.depths[0]).lower()):
        raise SpecError(
            "--verify",
            chosen.name if chosen.lossy else compression or "",
            "is lossy: what it writes cannot be compared with the reference; allowed: exr (half or float, "
            "a lossless compression), tiff, png or dpx",
        )
    return chosen


def _sample(text: str) -> int:
    if text.lower() == "all":
        return EVERY_PIXEL
    if not text.isdigit() or int(text) < 1:
        raise SpecError("--sample", text, "is not a number of pixels; allowed: a whole number from 1, or 'all'")
    return int(text)


def _outputs(found: list[Source], force: bool, skip_existing: bool) -> list[Source]:
    """Each output checked as every command checks a file it writes (:func:`generator.files.target`):
    an existing one needs --force (or --skip-existing, which leaves it); through a link, the file
    it points to is written."""
    if force and skip_existing:
        raise SpecError("--force", "--skip-existing", "ask for opposite things; allowed: one of them")
    if skip_existing:
        return found
    return [Source(s.path, str(target(s.output, force))) for s in found]


def _route(cfg, src, dst, display, view) -> tuple[str | None, str, str, str]:
    if bool(dst) == bool(display):
        raise SpecError("--to", dst or "-", "give --to SPACE or --display DISPLAY (with --view), one of them")
    if view and not display:
        raise SpecError("--view", view, "needs --display")
    source = configs.colour_space(cfg, src, "--from") if src else None
    if dst:
        return source, configs.colour_space(cfg, dst, "--to"), "", ""
    return (source, "", *configs.display_view(cfg, display, view))


def plan_run(
    inputs,
    output,
    config,
    src,
    dst,
    display,
    view,
    frames,
    fmt,
    depth,
    compression,
    verify: bool,
    sample: str,
    skip_existing: bool,
    force: bool,
    memory: int,
    announce=lambda text: None,
):
    """The run's Plan and its frames; SpecError on any bad argument."""
    if os.path.exists(output) and not os.path.isdir(output):
        raise SpecError("-o", output, "exists and is not a folder; allowed: a folder, or a path to make one at")
    chosen = _format(fmt, depth, compression, inputs, verify)
    samples = _sample(sample) if verify else 0
    try:
        found = sources(tuple(inputs), frames, output, chosen.suffix)
    except FramesError as error:
        raise SpecError("convert", "INPUTS" if frames is None else "--frames", str(error)) from None
    found = _outputs(found, force, skip_existing)
    path = configs.choose(config, announce)
    cfg = configs.load(path, verify)
    source, dst, display, view = _route(cfg, src, dst, display, view)
    return Plan(
        os.path.abspath(path) if not path.startswith("ocio://") else path,
        source,
        dst,
        display,
        view,
        chosen.name,
        depth.lower() if depth else None,
        compression,
        samples,
        memory,
        force,
        skip_existing,
    ), found
