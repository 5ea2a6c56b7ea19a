"""The config's view LUTs and the standalone pack."""

from __future__ import annotations

import numpy as np

from generator import tolerances
from generator.luts import pack, probes
from generator.luts.view import bake_view_lut, view_transform


def test_view_lut_reads_back_and_is_measured(default_spec, tmp_path):
    display = default_spec.displays[0]
    view = bake_view_lut(default_spec, display, "clip")
    assert view.bound <= tolerances.LUT_CLF_IN_GAMUT_CODES and view.unit == "10-bit codes"
    path = tmp_path / view.filename
    path.write_bytes(view.data)
    apply = probes.ocio_apply(view_transform(view.matrix, str(path)))
    figures = probes.measure(default_spec, None, display, "clip", apply, count=512)
    assert max(f.maximum for f in figures.values()) <= tolerances.LUT_CLF_IN_GAMUT_CODES
    assert bake_view_lut(default_spec, display, "clip").data == view.data


def test_pack_is_reproducible(default_spec, tmp_path, monkeypatch):
    monkeypatch.setattr(pack, "SOURCES", ("ACEScct",))
    monkeypatch.setattr(pack, "DISPLAYS", ("sRGB - Display",))
    monkeypatch.setattr(probes, "COUNT", 256)
    first = pack.build_pack(tmp_path / "a", default_spec)
    second = pack.build_pack(tmp_path / "b", default_spec)
    names = sorted(p.name for p in first.iterdir())
    assert names == ["README.md", "acescct_to_srgb_display.clf", "acescct_to_srgb_display.cube"]
    for name in names:
        assert (first / name).read_bytes() == (second / name).read_bytes()
    rows = [line for line in (first / "README.md").read_text().splitlines() if line.startswith("| acescct")]
    assert len(rows) == 2 and all("scale" in row for row in rows)
    assert np.isfinite([float(cell) for row in rows for cell in row.split("|")[6:9]]).all()


def test_committed_pack_is_what_the_build_gives_and_fits(default_spec, tmp_path):
    """luts/ is rebuilt bit-identically from the default spec, and stays under the size limit."""
    from pathlib import Path

    committed = Path(__file__).resolve().parents[2] / "luts"
    built = pack.build_pack(tmp_path / "luts", default_spec)
    files = {p.name: p.read_bytes() for p in sorted(built.iterdir())}
    assert files == {p.name: p.read_bytes() for p in sorted(committed.iterdir())}, "luts/ is stale: run make run"
    assert len(files) == 1 + len(pack.SOURCES) * len(pack.DISPLAYS) * len(pack.FORMATS)
    assert sum(len(data) for data in files.values()) <= tolerances.LUT_PACK_BYTES
    rows = [line for line in files["README.md"].decode().splitlines() if line.startswith("| ") and ".clf" in line]
    sdr = [float(line.split("|")[8]) for line in rows if "codes" in line.split("|")[9]]
    assert len(sdr) == 3 * len(pack.SOURCES) and max(sdr) <= tolerances.LUT_CLF_SCALE_CODES
