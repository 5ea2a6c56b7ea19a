"""The LUT pack: [[lut_pack]] tables planned, baked, measured and written beside other files."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from generator import tolerances
from generator.luts import aces_probes, pack, pack_folder, probes
from generator.spec import load
from generator.spec.schema import SpecError

COMMITTED = Path(__file__).resolve().parents[2] / "luts"

SMALL = """
colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]
[[display]]
name = "sRGB - Display"
[[lut_pack]]
sources = ["ACEScct"]
displays = ["sRGB - Display"]
formats = ["resolve_cube", "clf"]
size = { resolve_cube = 9, clf = 5 }
[[lut_pack]]
sources = ["ACEScct"]
displays = ["sRGB - Display"]
views = ["ACES 2.0"]
formats = ["clf", "resolve_cube"]
size = 7
decimals = 4
shaper_entries = 256
"""


def small_spec(text: str = SMALL):
    return load.parse(text, "small.toml", Path("."))


@pytest.fixture
def few_probes(monkeypatch):
    monkeypatch.setattr(probes, "COUNT", 256)
    monkeypatch.setattr(aces_probes, "PROBE_COUNT", 256)


def test_default_plan_is_the_committed_pack(default_spec):
    """The default spec's tables name every LUT of luts/, and nothing else."""
    names = [name for item in pack.plan(default_spec) for name in item.names]
    committed = {p.name for p in COMMITTED.iterdir()} - {pack_folder.README, pack_folder.MANIFEST}
    assert len(names) == len(set(names)) == len(committed) and set(names) == committed


def test_committed_pack_is_what_the_build_gives_and_fits(default_spec, tmp_path):
    """luts/ is rebuilt bit-identically from the default spec (its manifest too), and stays
    under the size limit: the proof that baking through [[lut_pack]] changed nothing."""
    built = pack.build_pack(tmp_path / "luts", default_spec)
    files = {p.name: p.read_bytes() for p in sorted(built.iterdir())}
    assert files == {p.name: p.read_bytes() for p in sorted(COMMITTED.iterdir())}, "luts/ is stale: run make run"
    assert sum(len(data) for data in files.values()) <= tolerances.LUT_PACK_BYTES
    rows = [line.split("|") for line in files["README.md"].decode().splitlines() if "_to_" in line and ".clf |" in line]
    sdr = [cells for cells in rows if "codes" in cells[10]]
    assert len(sdr) == 18
    # read as written, every CLF meets the in-gamut target on every probe set; with
    # OCIO's default flags (fast pow, log and exp), its every-set target
    assert max(float(cells[8]) for cells in sdr) <= tolerances.LUT_CLF_IN_GAMUT_CODES
    assert max(float(cells[9]) for cells in sdr) <= tolerances.LUT_CLF_SCALE_CODES


def test_pack_is_reproducible_and_measured(tmp_path, few_probes):
    spec = small_spec()
    first = pack.build_pack(tmp_path / "a", spec, workers=2)
    second = pack.build_pack(tmp_path / "b", spec, workers=1)
    names = sorted(p.name for p in first.iterdir())
    view = "acescct_aces_2_0_sdr_100_nits_rec_709_srgb_display"
    assert names == [
        pack_folder.MANIFEST,
        "README.md",
        f"{view}.clf",
        f"{view}.cube",
        "acescct_to_srgb_display.clf",
        "acescct_to_srgb_display.cube",
    ]
    for name in names:
        assert (first / name).read_bytes() == (second / name).read_bytes()
    readme = (first / "README.md").read_text()
    views = [line.split("|") for line in readme.splitlines() if line.startswith(f"| {view}")]
    assert len(views) == 2 and "| in gamut p99 / max | AP0 0..1 p99 / max |" in readme
    assert np.isfinite([float(part) for row in views for cell in row[6:12] for part in cell.split("/")]).all()
    rows = [line for line in readme.splitlines() if line.startswith("| acescct_to")]
    assert len(rows) == 2 and all("| scale | " in row for row in rows)
    assert "| In-gamut probes max | Worst set p99 | All probes max |" in readme and "not bounds" in readme
    cube, clf = (row.split("|") for row in sorted(rows, key=lambda row: ".clf" in row))
    assert clf[11].strip() == "(named in the file)" and float(cube[11]) != float(cube[7])
    assert "9³ lattice" in readme and "5³ lattice" in readme and "256-entry 1D shaper" in readme


def test_aces_clfs_of_several_sources_share_one_fit(tmp_path, few_probes):
    """An ACES view's display-layout CLFs from several sources share their lattice values, fitted
    once, and every file of the view its evaluations: each file is what baking its item alone
    writes. A kind of colour a source cannot hold is named so in its row."""
    spec = small_spec(SMALL.replace('sources = ["ACEScct"]', 'sources = ["ACEScct", "sRGB Encoded Rec.709 (sRGB)"]'))
    items = [item for item in pack.plan(spec) if item.req.view is not None]
    keys = [pack.shared_key(item) for item in items]
    shared = [key for key in keys if key is not None]
    assert len(shared) == 2 and len(set(shared)) == 1 and keys.count(None) == 2  # the .cube files
    assert len({pack.view_key(item) for item in items}) == 1 and None not in {pack.view_key(i) for i in items}
    rows = [row for _, row in pack.bake_all(items, tmp_path, workers=2)]
    # sRGB's codes hold no bright colour: the row says so (measuring the empty set failed)
    assert ["none held" in row for row in rows] == [item.req.source.name != "ACEScct" for item in items]
    alone = tmp_path / "alone"
    alone.mkdir()
    for item in items:
        names, _ = pack.bake_item(item, alone)
        for name in names:
            assert (tmp_path / name).read_bytes() == (alone / name).read_bytes(), name
    clfs = [item.req for item, key in zip(items, keys) if key is not None]
    cubes = [pack.aces_bake.display_lattice(spec, r.source, r.display, r.view, 7, 4) for r in clfs]
    assert np.array_equal(cubes[0].cube, cubes[1].cube) and not np.array_equal(cubes[0].matrix, cubes[1].matrix)


def test_a_views_shared_evaluations_are_those_its_files_read(monkeypatch):
    """A view's files share the probes' codes always, the fit's colours only where a file fits to
    them: a .cube does; the SDR Rec.709 CLF on sRGB fits the codes before the display's clamp,
    evaluated apart, so a view with CLFs alone leaves the fit's colours unevaluated."""
    monkeypatch.setattr(pack.aces_bake, "ACES_FIT_COUNT", 64)
    monkeypatch.setattr(aces_probes, "PROBE_COUNT", 64)
    items = [item for item in pack.plan(small_spec()) if item.req.view is not None]
    both = pack.view_shared(items)
    clf = next(item for item in items if item.req.fmt == "clf")
    alone = pack.view_shared([clf])
    assert both["training"] is not None and alone["training"] is None
    assert list(both["values"]) == list(alone["values"]) == [pack.shared_key(clf)]
    assert np.array_equal(both["values"][pack.shared_key(clf)], alone["values"][pack.shared_key(clf)])
    assert set(both["probes"]) == set(aces_probes.SETS)
    cube = next(item for item in items if item.req.fmt == "resolve_cube")
    assert set(pack.item_share(cube, both)) == {"probes", "training"}
    assert set(pack.item_share(clf, both)) == {"probes", "values"}
    # a second table of the view at another size: each display layout's values at its own size
    second = SMALL[SMALL.rindex("[[lut_pack]]") :].replace("size = 7", 'size = 5\nfile_name = "{source}_{size}"')
    spec = small_spec(SMALL + second)
    sized = [item for item in pack.plan(spec) if item.req.view is not None and item.req.fmt == "clf"]
    values = pack.view_shared(sized)["values"]
    assert sorted(v.shape[0] for v in values.values()) == [5, 7]
    assert all(values[pack.shared_key(item)].shape[0] == item.req.size for item in sized)


def bad(text: str) -> SpecError:
    with pytest.raises(SpecError) as caught:
        pack.plan(small_spec(SMALL + text))
    return caught.value


@pytest.mark.parametrize(
    "table, field, words",
    [
        # bake refuses it: the key that declared it is named
        (
            'sources = ["ACEScg"]\ndisplays = ["sRGB - Display"]\nformats = ["iridas_cube"]',
            "lut_pack[2].formats",
            "linear",
        ),
        (
            'sources = ["ACEScct"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]\nsize = 2',
            "lut_pack[2].size",
            "2 is outside",
        ),
        ('sources = ["Raw"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]', "lut_pack[2].sources", "data"),
        (
            'sources = ["ACEScct"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]\nviews = ["ACES 2.0 - HDR 1000 nits (P3 D65)"]',
            "lut_pack[2].views[0]",
            "cannot show",
        ),
        # a name the first table writes already
        (
            'sources = ["ACEScct"]\ndisplays = ["sRGB - Display"]\nformats = ["clf"]\ngamut_maps = ["clip"]',
            "lut_pack[2].file_name",
            "twice",
        ),
    ],
)
def test_what_bake_refuses_is_named_when_planned(table, field, words):
    error = bad(f"[[lut_pack]]\n{table}\n")
    assert error.field == field and words in error.message and error.source == "small.toml"


def test_a_spec_without_a_pack_is_refused(default_spec):
    spec = small_spec(SMALL.split("[[lut_pack]]")[0])
    with pytest.raises(SpecError, match="no LUT pack"):
        pack.plan(spec)
