"""Writing a built config folder atomically: config.ocio, luts/, the resolved spec.

Everything is written into a temporary sibling folder, then renamed into place,
so a failed build never leaves a half-written folder behind.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from pathlib import Path

from generator import tolerances
from generator.files import staged_folder
from generator.luts.curve1d import MAX_SIZE, curve_file
from generator.luts.names import slug
from generator.ocio.curves import curve_label
from generator.ocio.emit import LUT_FOLDER, emit
from generator.ocio.environment import set_aside
from generator.spec import resolved
from generator.spec.looks import LOOK_FOLDER
from generator.spec.schema import Spec, SpecError

CONFIG_FILENAME = "config.ocio"


@dataclass(frozen=True)
class BuildResult:
    """What a build wrote: the config's path and how many colour spaces, displays and views it holds."""

    path: Path
    colour_spaces: int
    displays: int
    views: int
    files: int
    worst_lut_error: float


def _check_baked(spec: Spec, luts: dict) -> None:
    """A curve no 1D LUT holds within BAKED_CURVE_RELATIVE (a table stepping between unevenly
    spaced rows) is refused, naming its file, rather than written off its bound."""
    owners = [(s.name, s.curve_name, "custom_space") for s in spec.colour_spaces if not (s.is_data or s.special)]
    owners += [(d.name, d.eotf_name, "display") for d in spec.displays]
    for name, lut in luts.items():
        if lut.max_relative_error > tolerances.BAKED_CURVE_RELATIVE:
            files = {f"{slug(curve_label(spec, o, c))}_to_linear.spi1d": (o, t) for o, c, t in owners}
            owner, table = files.get(name, ("", "custom_space"))
            field = f"{table}[name = {owner!r}].{'eotf' if table == 'display' else 'transfer'}" if owner else "transfer"
            raise SpecError(
                spec.source,
                field,
                f"the curve baked as {LUT_FOLDER}/{name} departs "
                f"{lut.max_relative_error:.2g} relative from its table at the most entries a 1D LUT "
                f"takes here ({MAX_SIZE + 1}): a step or kink between rows; allowed: a table whose rows "
                "are evenly spaced in code (baked on its rows, exactly) or a smoother one",
            )


def for_folder(spec: Spec, out_dir: Path, version: tuple[int, int] | None = None) -> Spec:
    """The spec as built into ``out_dir``: the config's name is the folder's name, which must
    therefore be text (OCIO writes a config in UTF-8: a name of other bytes failed in OCIO)."""
    try:
        out_dir.name.encode("utf-8")
    except UnicodeEncodeError:
        shown = os.fsencode(out_dir).decode("utf-8", "backslashreplace")
        raise SpecError(
            shown,
            "-o",
            "the folder's name, which names the config, is not UTF-8 text; allowed: a folder named in UTF-8",
        ) from None
    return replace(spec, name=out_dir.name, ocio_version=version or spec.ocio_version)


def write_files(spec: Spec, folder: Path) -> BuildResult:
    """Write the config of ``spec`` and its LUT files into ``folder``; what was written."""
    emitted = emit(spec)
    _check_baked(spec, emitted.luts)
    (folder / CONFIG_FILENAME).write_text(emitted.config.serialize(), encoding="utf-8")
    if emitted.luts or emitted.view_luts:
        (folder / LUT_FOLDER).mkdir()
    for name, lut in emitted.luts.items():
        (folder / LUT_FOLDER / name).write_bytes(curve_file(lut))
    for name, data in emitted.view_luts.items():
        (folder / LUT_FOLDER / name).write_bytes(data)
    copied = copy_look_files(spec, folder)
    (folder / resolved.FILENAME).write_text(resolved.dumps(spec), encoding="utf-8")
    cfg = emitted.config
    views = sum(len(cfg.getViews(d)) for d in cfg.getDisplays())
    worst = max((lut.max_relative_error for lut in emitted.luts.values()), default=0.0)
    files = len(emitted.luts) + len(emitted.view_luts) + copied + 2
    import PyOpenColorIO as ocio

    spaces = cfg.getColorSpaceNames(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL)  # inactive ones too
    return BuildResult(folder, len(spaces), len(cfg.getDisplays()), views, files, worst)


#: What a build writes into its folder: only a folder holding these alone, the resolved spec
#: among them, is a previous build that ``--force`` may replace.
BUILD_ENTRIES = (CONFIG_FILENAME, LUT_FOLDER, resolved.FILENAME, LOOK_FOLDER)

#: What a build writes into its LUT folder: files of these suffixes alone.
LUT_SUFFIXES = (".clf", ".ctf", ".spi1d")


def _replace_problem(out_dir: Path) -> str:
    """Why ``--force`` may not replace the existing ``out_dir`` ("" when it may: a previous build)."""
    if not out_dir.is_dir():
        return "is a file; -o takes a folder"
    names = sorted(entry.name for entry in out_dir.iterdir())
    foreign = [name for name in names if name not in BUILD_ENTRIES]
    if foreign:
        return (
            f"holds {foreign[0]!r}, which no build writes; --force replaces only a previous build "
            f"(a folder of {', '.join(BUILD_ENTRIES)})"
        )
    for written in (resolved.FILENAME, CONFIG_FILENAME):
        if written not in names:
            return f"has no {written}, so it is not a previous build; --force replaces only those"
    stray_look = _foreign_look_file(out_dir)
    if stray_look:
        return (
            f"holds {stray_look}, which no look of its {resolved.FILENAME} reads; --force replaces only a previous "
            "build (move the file out first)"
        )
    luts = out_dir / LUT_FOLDER
    if luts.exists():
        if not luts.is_dir():
            return f"holds a file {LUT_FOLDER!r} where a build writes a folder; --force replaces only a previous build"
        entries = sorted(luts.iterdir())
        stray = next((e for e in entries if not e.is_file() or e.suffix not in LUT_SUFFIXES), None)
        if stray is not None:
            return (
                f"holds {LUT_FOLDER}/{stray.name}, which no build writes; --force replaces only a previous build "
                f"(its {LUT_FOLDER} holds {', '.join(LUT_SUFFIXES)} files alone)"
            )
        read = files_read(out_dir / CONFIG_FILENAME) if entries else set()
        if read is None:
            return (
                f"has a {CONFIG_FILENAME} OpenColorIO cannot load, so which files of {LUT_FOLDER} the build wrote "
                "cannot be told; --force replaces only a previous build"
            )
        own = next((e for e in entries if e.name not in read), None)
        if own is not None:
            return (
                f"holds {LUT_FOLDER}/{own.name}, which its {CONFIG_FILENAME} does not read, so no build wrote it; "
                "--force replaces only a previous build (move the file out first)"
            )
    return ""


def files_read(config: Path) -> set[str] | None:
    """The files of the LUT folder the config at ``config`` reads as a build writes it: the
    FileTransforms of its colour spaces (inactive ones too, both directions) and view
    transforms whose source is a bare file name, found on a search path that is the LUT folder
    alone. A build writes no look or named transform, so a file only they read (a TD's grade)
    is not the build's, nor is one named by a path. Empty when the search path is another
    (every file there is then someone's own); None when OpenColorIO cannot load the config."""
    import PyOpenColorIO as ocio

    try:
        cfg = ocio.Config.CreateFromFile(str(config))
    except Exception:  # ocio.Exception, and ExceptionMissingFile, which does not derive from it
        return None
    if cfg.getSearchPath().split(":")[0] != LUT_FOLDER:
        return set()
    return {
        t.getSrc()
        for _, t in leaf_transforms(cfg)
        if isinstance(t, ocio.FileTransform) and Path(t.getSrc()).name == t.getSrc()
    }


def copy_look_files(spec: Spec, folder: Path) -> int:
    """Copy the files ``spec``'s looks read (each shot's, for a path naming context variables) from
    the spec's folder into ``folder``'s looks folder, keeping their paths; how many were copied."""
    names = sorted({name for look in spec.looks for name, _ in look.files})
    for name in names:
        target_file = folder / LOOK_FOLDER / name
        target_file.parent.mkdir(parents=True, exist_ok=True)
        target_file.write_bytes((Path(spec.look_folder) / name).read_bytes())
    return len(names)


def _foreign_look_file(out_dir: Path) -> str:
    """A file (or anything else) in a previous build's looks folder that no look of its stored
    spec reads, as a path inside the build; "" when there is none."""
    looks = out_dir / LOOK_FOLDER
    if not looks.exists():
        return ""
    if not looks.is_dir():
        return LOOK_FOLDER
    try:
        spec = resolved.read(out_dir / resolved.FILENAME)
    except SpecError:
        return LOOK_FOLDER
    own = {name for look in spec.looks for name, _ in look.files}
    for entry in sorted(looks.rglob("*")):
        name = entry.relative_to(looks).as_posix()
        if (entry.is_file() and name not in own) or not (entry.is_file() or entry.is_dir()):
            return f"{LOOK_FOLDER}/{name}"
        if entry.is_dir() and not any(n.startswith(name + "/") for n in own):
            return f"{LOOK_FOLDER}/{name}"
    return ""


def leaf_transforms(cfg) -> list[tuple[str, object]]:
    """Every transform of ``cfg``'s colour spaces (inactive ones too) and view transforms, both
    directions, groups opened, with its owner described."""
    import PyOpenColorIO as ocio

    owners = [
        (
            f"colour space {s.getName()!r}",
            [s.getTransform(d) for d in (ocio.COLORSPACE_DIR_TO_REFERENCE, ocio.COLORSPACE_DIR_FROM_REFERENCE)],
        )
        for s in cfg.getColorSpaces(ocio.SEARCH_REFERENCE_SPACE_ALL, ocio.COLORSPACE_ALL)
    ]
    owners += [
        (
            f"view transform {v.getName()!r}",
            [v.getTransform(d) for d in (ocio.VIEWTRANSFORM_DIR_TO_REFERENCE, ocio.VIEWTRANSFORM_DIR_FROM_REFERENCE)],
        )
        for v in cfg.getViewTransforms()
    ]
    found = []
    for owner, transforms in owners:
        stack = [t for t in transforms if t is not None]
        while stack:
            t = stack.pop()
            if isinstance(t, ocio.GroupTransform):
                stack.extend(t)
            else:
                found.append((owner, t))
    return found


def target(out_dir: str | Path) -> Path:
    """The folder a build into ``out_dir`` writes, absolute: a link to a folder (a show's
    ``current``) stays a link, and the folder it points to is replaced (and names the config)."""
    out_dir = Path(out_dir).absolute()
    real = Path(os.path.realpath(out_dir))  # a loop of links stays a loop (Path.resolve raises)
    return real if out_dir.is_symlink() and real.is_dir() else out_dir


def _check_replaceable(out_dir: Path, force: bool, contents: Path | None = None) -> None:
    """SpecError naming ``out_dir`` unless what it holds (at ``contents`` when moved aside to be
    replaced) may be replaced: nothing or an empty folder, or with ``force`` a previous build."""
    contents = out_dir if contents is None else contents
    if not contents.exists() or (contents.is_dir() and not any(contents.iterdir())):
        return
    problem = _replace_problem(contents) or ("" if force else "holds a previous build; pass --force to replace it")
    if problem:
        raise SpecError(str(out_dir), "-o", problem)


def build(spec: Spec, out_dir: str | Path, force: bool = False) -> BuildResult:
    """Build ``spec`` into ``out_dir``: a new or empty folder, or with ``force`` a previous
    build (never a folder holding anything a build does not write), at :func:`target`; checked
    before the build and again as the folder is replaced (another process may write there)."""
    if Path(out_dir).is_symlink() and not Path(out_dir).exists():
        raise SpecError(
            str(out_dir),
            "-o",
            f"is a link to {str(Path(out_dir).readlink())!r}, which does not exist "
            "(or is a loop of links); allowed: a folder, or a link to one",
        )
    out_dir = target(out_dir)
    _check_replaceable(out_dir, force)
    with set_aside(), staged_folder(out_dir, lambda contents: _check_replaceable(out_dir, force, contents)) as staging:
        result = write_files(spec, staging)
    return replace(result, path=out_dir)
