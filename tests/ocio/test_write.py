"""Writing a built config folder: config.ocio, its LUT files and the resolved spec
(generator/ocio/write.py)."""

from __future__ import annotations

import re

import PyOpenColorIO as ocio
import pytest

from generator.ocio import write
from generator.spec.schema import SpecError


def test_same_spec_builds_byte_identical_files(tmp_path, default_spec):
    from generator.ocio.write import build, for_folder

    outputs = []
    for run in ("a", "b"):
        folder = tmp_path / run / "same"
        build(for_folder(default_spec, folder), folder)
        outputs.append({p.relative_to(folder): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()})
    assert outputs[0] == outputs[1]


def test_committed_default_config_is_what_the_build_gives(tmp_path, default_spec):
    from pathlib import Path

    from generator.ocio.write import build, for_folder

    committed = Path(__file__).resolve().parents[2] / "configs" / "ocioforge-studio"
    folder = tmp_path / committed.name
    build(for_folder(default_spec, folder), folder)
    built = {p.relative_to(folder): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}
    on_disk = {p.relative_to(committed): p.read_bytes() for p in sorted(committed.rglob("*")) if p.is_file()}
    assert built == on_disk, "configs/ is stale: run make run"


def test_a_table_no_lut_holds_is_refused(tmp_path):
    """Rows 1e-7 apart with a step between them: no 1D LUT holds it within the bound, and the
    build says so in one line instead of writing a config 0.12 off."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    (tmp_path / "step.csv").write_text("code,linear\n0,0\n0.5,0.5\n0.5000001,0.6\n1,1\n")
    spec = load.parse(
        '[[custom_space]]\nname = "Step"\ngamut = "Rec.709"\ntransfer = { family = "tabulated", file = "step.csv" }\n',
        "show.toml",
        tmp_path,
    )
    with pytest.raises(SpecError, match="step_to_linear.spi1d departs 0.12 relative"):
        build(for_folder(spec, tmp_path / "out"), tmp_path / "out")
    assert not (tmp_path / "out").exists()


def test_the_config_reads_every_lut_file_the_build_wrote_and_no_other(build_config):
    config = build_config((2, 1))
    written = {p.name for p in (config.parent / "luts").iterdir()}
    assert written and write.files_read(config) == written


def test_every_leaf_transform_is_found_inside_groups(build_config):
    """The files the leaves name are those the config's text names; no group is left closed."""
    config = build_config((2, 1))
    leaves = write.leaf_transforms(ocio.Config.CreateFromFile(str(config)))
    assert not [t for _, t in leaves if isinstance(t, ocio.GroupTransform)]
    named = {t.getSrc() for _, t in leaves if isinstance(t, ocio.FileTransform)}
    assert named == set(re.findall(r"!<FileTransform> \{src: ([^,}]+)", config.read_text()))
    owners = {owner for owner, _ in leaves}
    assert "colour space 'ACEScct'" in owners and any(o.startswith("view transform ") for o in owners)


def test_a_config_searching_elsewhere_reads_no_build_file_and_one_that_does_not_load_none(build_config, tmp_path):
    config = build_config((2, 1))
    moved = tmp_path / "config.ocio"
    moved.write_text(re.sub(r"search_path: .*", "search_path: grades", config.read_text(), count=1))
    assert ocio.Config.CreateFromFile(str(moved)).getSearchPath() == "grades"
    assert write.files_read(moved) == set()
    (tmp_path / "broken.ocio").write_text("ocio_profile_version: 2.1\ncolorspaces: [\n")
    assert write.files_read(tmp_path / "broken.ocio") is None
