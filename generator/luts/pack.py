"""A show's LUT pack: the files its spec's ``[[lut_pack]]`` tables declare, baked and measured.

Each table is expanded (:func:`plan`) into files, each a request ``ocioforge bake`` would take:
for every source, display, gamut mapping (or ACES view the display can show) and format. Every
file is read back through OpenColorIO and measured on :mod:`generator.luts.probes` (ACES views:
:mod:`generator.luts.aces_probes`), and README.md lists the figures, labelled as what they are:
maxima over those random probe sets, not bounds over the gamut. Files are baked in forked
workers (:mod:`generator.luts.pool`); the same spec gives the same bytes. The default spec's
tables are the repository's luts/ folder. Writing the folder is :mod:`generator.luts.pack_folder`'s.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import PyOpenColorIO as ocio

from generator.colorimetry.transfer import Linear
from generator.luts import aces_bake, aces_probes, bake, pack_folder, pack_readme, probes
from generator.luts.aces_bake import ACES_SHAPER_SIZES
from generator.luts.lattice import CUBE_DECIMALS
from generator.luts.names import slug
from generator.luts.pool import Pool
from generator.luts.source_axes import SOURCE_SHAPER_SIZES
from generator.rendering.views import ACESView
from generator.spec import load
from generator.spec.schema import LutPack, Spec, SpecError

#: The spec option each of bake's options is declared by in a ``[[lut_pack]]`` table.
KEY_OF_OPTION = {
    "--from": "sources",
    "--to": "displays",
    "--gamut-map": "gamut_maps",
    "--view": "views",
    "--size": "size",
    "--format": "formats",
    "--shaper": "shaper",
}

GAMUT_NAME, VIEW_NAME = "{source}_to_{display}", "{source}_{view}_{display}"


@dataclass(frozen=True)
class Item:
    """One file of the pack (with its .spi1d, a .spi3d that needs one)."""

    name: str
    req: bake.Request
    table: int
    decimals: int | None = None
    shaper_entries: int | None = None

    @property
    def names(self) -> tuple[str, ...]:
        """Every file it may write: a .spi3d's shaper too."""
        extra = (Path(self.name).with_suffix(bake.SHAPER_SUFFIX).name,) if self.req.fmt == "spi3d" else ()
        return (self.name, *extra)


def _request(spec: Spec, where: str, index: int, *args) -> bake.Request:
    """:func:`bake.request`, its errors naming the table's key instead of bake's option."""
    try:
        return bake.request(spec, *args)
    except SpecError as error:
        key = KEY_OF_OPTION.get(error.field, error.field)
        raise SpecError(where, f"lut_pack[{index}].{key}", error.message) from None


def _pairs(spec: Spec, where: str, index: int, table: LutPack) -> list[tuple[str, str]]:
    """(display, view) of a views table: each view on each display, by its full name ("ACES 2.0"
    is each display's own); a view a display cannot show is refused."""
    field = f"lut_pack[{index}]"
    pairs = []
    for i, name in enumerate(table.displays):
        display = bake.find_display(spec, name, f"{field}.displays[{i}]")
        for k, view in enumerate(table.views):
            try:
                pairs.append((name, bake.find_view(display, view).name))
            except SpecError as error:
                raise SpecError(where, f"{field}.views[{k}]", error.message) from None
    return pairs


def _formats(spec: Spec, table: LutPack, source: str) -> list[tuple[str, int | None]]:
    """(format, size) the table bakes ``source`` in: a linear source's from ``linear_source_formats``."""
    allowed = table.linear_source_formats
    linear = allowed is not None and isinstance(spec.space(source).curve, Linear)
    return [(f, s) for f, s in zip(table.formats, table.sizes) if not linear or f in (allowed or ())]


def _table_items(spec: Spec, where: str, index: int, table: LutPack) -> list[Item]:
    aces = bool(table.views)
    pattern = table.file_name or (VIEW_NAME if aces else GAMUT_NAME)
    absent = "gamut_map" if aces else "view"
    if "{" + absent + "}" in pattern:
        raise SpecError(
            where,
            f"lut_pack[{index}].file_name",
            f"{{{absent}}} in a table of {'views' if aces else 'gamut_maps'}; allowed: the fields it has",
        )
    choices = (
        _pairs(spec, where, index, table)
        if aces
        else [(d, m) for d in table.displays for m in table.gamut_maps or (bake.DEFAULT_METHOD,)]
    )
    items = []
    for source in table.sources:
        try:
            bake.find_source(spec, source, "--from")  # a source bake refuses: named before its displays
        except SpecError as error:
            raise SpecError(where, f"lut_pack[{index}].sources", error.message) from None
        for display, choice in choices:
            for fmt, size in _formats(spec, table, source):
                default = bake.ACES_SIZE if aces else bake.DEFAULT_SIZE
                view, method = (choice, "") if aces else (None, choice)
                req = _request(spec, where, index, source, display, method, fmt, size or default, table.shaper, view)
                fields = {
                    "source": req.source.name,
                    "display": req.display.name,
                    "gamut_map": method,
                    "view": choice if aces else "",
                    "format": fmt,
                    "size": str(req.size),
                }
                stem = pattern.format(**{k: slug(v) for k, v in fields.items()})
                if not stem:
                    raise SpecError(
                        where,
                        f"lut_pack[{index}].file_name",
                        f"{pattern!r} names {fmt} files by nothing; allowed: a pattern with {{source}} or text",
                    )
                items.append(Item(stem + bake.FORMATS[fmt].suffix, req, index, table.decimals, table.shaper_entries))
    return items


def plan(spec: Spec, where: str | None = None) -> list[Item]:
    """Every file of ``spec``'s pack, in its tables' order; SpecError naming ``lut_pack[i].key``
    (of ``where``, the spec's path as given: default its recorded name) for a file bake would
    refuse or a name two files would share."""
    where = where or spec.source
    if not spec.lut_packs:
        raise SpecError(where, "lut_pack", "the spec declares no LUT pack; allowed: one [[lut_pack]] table or more")
    items = [item for i, table in enumerate(spec.lut_packs) for item in _table_items(spec, where, i, table)]
    seen: dict[str, Item] = {}
    for item in items:
        for name in item.names:
            other = seen.setdefault(name.lower(), item)
            if other is not item:
                raise SpecError(
                    where,
                    f"lut_pack[{item.table}].file_name",
                    f"{name!r} would be written twice (also by lut_pack[{other.table}]); allowed: a pattern "
                    "whose fields tell the files apart ({source}, {display}, {gamut_map}, {view}, {size})",
                )
    return items


def _decimals(item: Item) -> int:
    return CUBE_DECIMALS if item.decimals is None else item.decimals


def shared_key(item: Item) -> tuple | None:
    """What an ACES view's display-layout CLF shares with the pack's others from other sources:
    its lattice values (:func:`aces_bake.display_values`) are the same for every source.
    None for a file whose lattice is its own."""
    req = item.req
    if req.view is None or req.fmt != "clf" or req.shaper != "auto":
        return None
    return (req.display.name, req.view.name, req.size, _decimals(item))


def view_key(item: Item) -> tuple | None:
    """The ACES view an item bakes, on its display: every source's file of it shares the view's
    evaluations (:func:`view_shared`). None for a gamut mapping."""
    req = item.req
    return None if req.view is None else (req.display.name, req.view.name)


def view_shared(items: list[Item]) -> dict:
    """What the files of one ACES view (``items``, of one :func:`view_key`) share: the measuring
    probes and their targets (``probes``, :func:`_aces_targets`), the view's display codes on
    the fit's colours where a file's fit needs them (``training``), and each display layout's
    lattice values (``values``, by :func:`shared_key`)."""
    req = items[0].req
    view = _aces_view(req)
    keys = {key: item for item in items if (key := shared_key(item)) is not None}
    # a source layout fits to the training; so does a display layout holding the view's own codes
    own_codes = bool(keys) and aces_bake.light_before_clamp(req.spec, req.display, view) is None
    training = aces_bake.training_sets(req.spec, req.display, view) if own_codes or len(keys) < len(items) else None
    probes_ = _aces_targets(req, view)
    values = {
        key: aces_bake.display_values(req.spec, req.display, view, item.req.size, _decimals(item), training)
        for key, item in keys.items()
    }
    return {"probes": probes_, "training": training, "values": values}


def item_share(item: Item, shared: dict | None) -> dict | None:
    """The part of :func:`view_shared` ``item`` reads (None: none given)."""
    if shared is None:
        return None
    key = shared_key(item)
    own = {"values": shared["values"][key]} if key is not None else {"training": shared["training"]}
    return {"probes": shared["probes"], **own}


def _lattice(item: Item, shared: dict | None = None):
    """The lattice ``item`` holds: the bake's, an ACES view's with the table's decimals and
    entries (with :func:`item_share` ``shared`` if given: the display layout's values, the
    source layout's training)."""
    req = item.req
    if req.view is None:
        return bake.build_lattice(req)
    decimals = _decimals(item)
    shared = shared or {}
    if shared_key(item) is not None:
        values = shared.get("values")  # None: fitted here
        return aces_bake.display_lattice(req.spec, req.source, req.display, req.view, req.size, decimals, values)
    shaper = "none" if not bake.FORMATS[req.fmt].shaper else req.shaper
    return aces_bake.source_lattice(
        req.spec,
        req.source,
        req.display,
        req.view,
        req.size,
        shaper,
        decimals,
        item.shaper_entries,
        shared.get("training"),
    )


def _transform(paths: list[Path], interpolation: str):
    """The OCIO transform reading the written files (a .spi1d shaper first, then the lattice)."""
    mode = {"tetrahedral": ocio.INTERP_TETRAHEDRAL, "trilinear": ocio.INTERP_LINEAR}[interpolation]
    main = ocio.FileTransform(str(paths[0]), interpolation=mode)
    if len(paths) == 1:
        return main
    shaper = ocio.FileTransform(str(paths[1]), interpolation=ocio.INTERP_LINEAR)
    return ocio.GroupTransform([shaper, main])


def _apply(transform, optimization: str):
    """:func:`probes.ocio_apply`, OCIO's file cache kept: a pack reads each file it wrote (each
    at a path of its own, in a new staging folder) up to three times, and parsing a .cube took
    a quarter of a second each time."""
    config = ocio.Config.CreateRaw()
    processor = config.getProcessor(transform).getOptimizedCPUProcessor(getattr(ocio, optimization))

    def apply(code):
        pixels = np.ascontiguousarray(np.asarray(code, dtype=np.float32))
        processor.applyRGB(pixels)
        return pixels.astype(np.float64)

    return apply


def _measure(
    req: bake.Request,
    paths: list[Path],
    wanted: dict,
    interpolation="tetrahedral",
    optimization="OPTIMIZATION_LOSSLESS",
):
    """The file's figures on :func:`probes.targets` ``wanted`` of the probes, read as OCIO reads it."""
    apply = _apply(_transform(paths, interpolation), optimization)
    return probes.figures(*probes.errors_on(req.display, wanted, apply))


def _row(name: str, req: bake.Request, figures: dict, default: dict, trilinear: dict | None) -> str:
    """A README row: ``figures`` read as written (lossless), ``default`` with OCIO's default
    flags, ``trilinear`` with trilinear interpolation for a file that cannot name its
    interpolation (None: one that does)."""
    inside = max(figures["in_gamut"].maximum, figures["dark"].maximum)
    p99 = max(f.p99 for f in figures.values())
    worst = max(f.maximum for f in figures.values())
    fast = max(f.maximum for f in default.values())
    unit = figures["in_gamut"].unit
    other = f"{max(f.p99 for f in trilinear.values()):.2f}" if trilinear else "(named in the file)"
    return (
        f"| {name} | {req.source.name} | {req.display.name} | {req.method} | {req.size}³ | "
        f"{inside:.3f} | {p99:.3f} | {worst:.3f} | {fast:.3f} | {unit} | {other} |\n"
    )


def _aces_view(req: bake.Request) -> ACESView:
    """The ACES view ``req`` bakes; ValueError for a gamut-mapping request."""
    if req.view is None:
        raise ValueError("the request bakes a gamut mapping, not an ACES view")
    return req.view


def _aces_figures(req: bake.Request, paths: list[Path], sets: dict | None = None) -> dict:
    """Set name to (p99, max) of the file read through OCIO (default flags, tetrahedral) on
    :mod:`generator.luts.aces_probes`' sets (their :func:`_aces_targets`, evaluated here unless
    given), against the reference; a set the source's codes hold no colour of is left out."""
    view = _aces_view(req)
    apply = _apply(_transform(paths, "tetrahedral"), "OPTIMIZATION_DEFAULT")
    sets = sets or _aces_targets(req, view)
    out = {}
    for name, pair in sets.items():
        code, wanted = aces_probes.held_in(req.spec, req.source, req.display, pair)
        if not len(code):  # a bounded source (sRGB's codes) holds no bright colour
            continue
        error = probes.errors_against(req.display, apply(code), wanted)[0]
        out[name] = (float(np.percentile(error, 99)), float(error.max()))
    return out


def _aces_targets(req: bake.Request, view: ACESView) -> dict:
    """:func:`aces_probes.view_sets` of the pack's probes, each with its :func:`probes.target`
    for the display's codes: the same for every source's file of the view."""
    sets = aces_probes.view_sets(req.spec, req.display, view.name, aces_probes.PROBE_SEED, aces_probes.PROBE_COUNT)
    return {name: (aces, probes.target(req.display, expected)) for name, (aces, expected) in sets.items()}


def _aces_row(name: str, req: bake.Request, figures: dict) -> str:
    unit = "ΔE ITP" if req.display.is_hdr else "10-bit codes"
    cells = " | ".join(
        f"{figures[kind][0]:.2f} / {figures[kind][1]:.1f}" if kind in figures else "none held"
        for kind in aces_probes.SETS
    )
    view = _aces_view(req).name
    return f"| {name} | {req.source.name} | {view} | {req.display.name} | {req.size}³ | {cells} | {unit} |\n"


def bake_item(item: Item, folder: Path, shared: dict | None = None) -> tuple[tuple[str, ...], str]:
    """Bake ``item`` into ``folder`` (an ACES view's with its :func:`item_share` ``shared``, else
    evaluating the view itself) and measure the file written; returns the names written and its
    README row."""
    req = item.req
    files = bake.lattice_files(req, _lattice(item, shared))
    paths = [folder / (item.name if not suffix else Path(item.name).with_suffix(suffix).name) for suffix in files]
    for path, data in zip(paths, files.values()):
        path.write_bytes(data)
    if req.view is not None:
        figures = _aces_figures(req, paths, (shared or {}).get("probes"))
        return tuple(p.name for p in paths), _aces_row(item.name, req, figures)
    sets = probes.reference_sets(req.spec, req.source, req.display, req.method)
    wanted = probes.targets(req.display, sets)  # one reference, three readings
    trilinear = _measure(req, paths, wanted, "trilinear") if req.fmt != "clf" else None
    default = _measure(req, paths, wanted, optimization="OPTIMIZATION_DEFAULT")
    return tuple(p.name for p in paths), _row(item.name, req, _measure(req, paths, wanted), default, trilinear)


#: The items a pack's forked workers bake (a spec holds functions, which do not pickle: the
#: workers find them here, as they were when forked).
_PACKING: list[list[Item]] = []


def _worker(index: int, folder: str, shared: dict | None = None) -> tuple[tuple[str, ...], str]:
    return bake_item(_PACKING[-1][index], Path(folder), shared)


def _view_worker(indices: list[int]) -> dict:
    return view_shared([_PACKING[-1][i] for i in indices])


def bake_all(
    items: list[Item], folder: Path, progress: Callable[[int, int], None] | None = None, workers: int | None = None
) -> list[tuple[tuple[str, ...], str]]:
    """Bake every item into ``folder`` in forked workers, returning each one's names and row in
    ``items``' order and calling ``progress(done, total)`` as they are. What an ACES view's
    files share (:func:`view_shared`) is evaluated first, once a view; then the gamut
    mappings, and last the files waiting on their view's."""
    _PACKING.append(items)
    try:
        with Pool(workers) as pool:
            keys = [view_key(item) for item in items]
            groups: dict[tuple, list[int]] = {}
            for index, key in enumerate(keys):
                if key is not None:
                    groups.setdefault(key, []).append(index)
            for key, indices in groups.items():
                pool.submit(key, _view_worker, indices)
            for index, key in enumerate(keys):
                if key is None:
                    pool.submit(index, _worker, index, str(folder))
            if progress is not None:
                progress(0, len(items))
            arguments: list[tuple] = [(i, str(folder)) for i in range(len(items))]
            for key, indices in groups.items():
                shared = pool.result(key, _view_worker, indices)
                for index in indices:
                    arguments[index] = (index, str(folder), item_share(items[index], shared))
                    pool.submit(index, _worker, *arguments[index])
            out = []
            for index in range(len(items)):
                out.append(pool.result(index, _worker, *arguments[index]))
                if progress is not None:
                    progress(index + 1, len(items))
            return out
    finally:
        _PACKING.remove(items)


def readme(items: list[Item], rows: list[str]) -> str:
    """README.md of a pack of ``items`` whose measured rows are ``rows``."""
    gamut = [(i, r) for i, r in zip(items, rows) if i.req.view is None]
    aces = [(i, r) for i, r in zip(items, rows) if i.req.view is not None]
    sizes = {f: [i.req.size for i, _ in gamut if i.req.fmt == f] for f in bake.FORMATS}
    head = pack_readme.gamut_head(
        list(dict.fromkeys(i.req.method for i, _ in gamut)),
        list(dict.fromkeys(i.req.fmt for i, _ in gamut)),
        sizes["resolve_cube"],
        sizes["clf"],
        ocio=ocio.__version__,
        count=probes.COUNT,
        shaper_steps=SOURCE_SHAPER_SIZES[1] - 1,
    )
    aces_head = pack_readme.ACES_HEAD.format(
        size=pack_readme.joined_sizes(i.req.size for i, _ in aces),
        decimals=" or ".join(
            str(d) for d in sorted({CUBE_DECIMALS if i.decimals is None else i.decimals for i, _ in aces})
        ),
        entries=" or ".join(str(e) for e in sorted({i.shaper_entries or ACES_SHAPER_SIZES[0] for i, _ in aces})),
        count=aces_probes.PROBE_COUNT,
        ocio=ocio.__version__,
        labels=" | ".join(f"{aces_probes.LABELS[k]} p99 / max" for k in aces_probes.SETS),
        rule=" --- |" * len(aces_probes.SETS),
    )
    return pack_readme.readme(head, [r for _, r in gamut], aces_head, [r for _, r in aces])


def build_pack(
    folder: str | Path,
    spec: Spec | None = None,
    force: bool = False,
    progress: Callable[[int, int], None] | None = None,
    workers: int | None = None,
    where: str | None = None,
) -> Path:
    """Bake ``spec``'s pack (default: the embedded spec's, the repository's luts/) into ``folder``,
    bit-identically: its earlier files replaced all or none, nothing else there touched, a
    file of another's name refused without ``force`` (:mod:`generator.luts.pack_folder`)."""
    spec = spec or load.load()
    items = plan(spec, where)
    names = [name for item in items for name in item.names]
    with pack_folder.staged(Path(folder), names, force) as staging:
        baked = bake_all(items, staging, progress, workers)
        text = readme(items, [row for _, row in baked])
        (staging / pack_folder.README).write_text(text, encoding="utf-8")
    return Path(folder)
