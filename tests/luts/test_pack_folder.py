"""Writing a LUT pack into a folder that may hold other things (generator/luts/pack_folder.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from generator.luts import pack_folder


def fake(folder: Path, names: list[str], force: bool = False, text: str = "new") -> None:
    """A pack of ``names`` written through the pack's staging, without baking."""
    with pack_folder.staged(folder, names, force) as staging:
        for name in [*names, pack_folder.README]:
            (staging / name).write_text(f"{text} {name}")


def test_foreign_files_are_left_alone_and_a_clash_refused(tmp_path):
    folder = tmp_path / "pack"
    folder.mkdir()
    (folder / "plate.exr").write_text("a plate")
    fake(folder, ["a.cube", "b.clf"])
    assert (folder / "plate.exr").read_text() == "a plate" and (folder / "a.cube").read_text() == "new a.cube"
    (folder / "c.clf").write_text("theirs")
    with pytest.raises(pack_folder.Refused, match="c.clf: exists and is not a file ocioforge pack wrote"):
        fake(folder, ["a.cube", "c.clf"], text="second")
    assert (folder / "a.cube").read_text() == "new a.cube" and (folder / "c.clf").read_text() == "theirs"
    assert sorted(p.name for p in folder.iterdir()) == [
        pack_folder.MANIFEST,
        "README.md",
        "a.cube",
        "b.clf",
        "c.clf",
        "plate.exr",
    ]
    fake(folder, ["a.cube", "c.clf"], force=True, text="second")
    assert (folder / "c.clf").read_text() == "second c.clf" and (folder / "plate.exr").read_text() == "a plate"


def test_rerun_replaces_its_own_files_and_deletes_only_what_it_wrote(tmp_path):
    folder = tmp_path / "deep" / "pack"
    fake(folder, ["a.cube", "b.clf", "c.clf"])
    (folder / "c.clf").write_text("edited by hand")  # no longer what the pack wrote: kept
    fake(folder, ["a.cube", "d.clf"], text="second")
    assert sorted(p.name for p in folder.iterdir()) == [pack_folder.MANIFEST, "README.md", "a.cube", "c.clf", "d.clf"]
    assert (folder / "a.cube").read_text() == "second a.cube" and (folder / "c.clf").read_text() == "edited by hand"
    with pytest.raises(pack_folder.Refused):  # and now foreign to it
        fake(folder, ["c.clf"])


def test_a_failed_pack_changes_nothing(tmp_path):
    folder = tmp_path / "pack"
    fake(folder, ["a.cube"])
    before = {p.name: p.read_bytes() for p in folder.iterdir()}
    with pytest.raises(RuntimeError), pack_folder.staged(folder, ["a.cube"], False) as staging:
        (staging / "a.cube").write_text("half")
        raise RuntimeError("a bake failed")
    assert {p.name: p.read_bytes() for p in folder.iterdir()} == before
    with pytest.raises(RuntimeError), pack_folder.staged(tmp_path / "new" / "pack", ["a.cube"], False):
        raise RuntimeError("a bake failed")
    assert not (tmp_path / "new").exists()


def test_the_manifest_names_each_file_with_its_sha256(tmp_path):
    import hashlib
    import json

    folder = tmp_path / "pack"
    fake(folder, ["b.clf", "a.cube"])
    record = json.loads((folder / pack_folder.MANIFEST).read_text(encoding="utf-8"))
    expected = {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in folder.iterdir() if p.name[0] != "."}
    assert record["files"] == expected and list(record["files"]) == sorted(expected)
    files = {name: (folder / name).read_bytes() for name in expected}
    assert pack_folder.manifest(dict(reversed(list(files.items())))) == (folder / pack_folder.MANIFEST).read_bytes()
    assert [p.name for p in folder.iterdir() if p.name.startswith(".") and p.is_dir()] == []  # staging removed


def test_a_file_is_the_packs_own_only_while_it_holds_what_was_written(tmp_path):
    folder = tmp_path / "pack"
    fake(folder, ["a.cube", "b.clf", "c.clf"])
    (folder / "b.clf").write_text("edited")
    (folder / "c.clf").unlink()
    (folder / "c.clf").symlink_to(folder / "a.cube")  # a link, even to the same bytes, is not a file it wrote
    assert pack_folder.own_files(folder) == {"a.cube", "README.md", pack_folder.MANIFEST}


@pytest.mark.parametrize(
    "manifest",
    ["not json", '["a.cube"]', '{"files": {"../a.cube": "0"}}', '{"files": {"a.cube": 1}}'],
    ids=["text", "a list", "a path", "no digest"],
)
def test_a_manifest_no_pack_wrote_owns_nothing(tmp_path, manifest):
    folder = tmp_path / "pack"
    fake(folder, ["a.cube"])
    (folder / pack_folder.MANIFEST).write_text(manifest)
    assert pack_folder.own_files(folder) == set()
    with pytest.raises(pack_folder.Refused, match="a.cube"):
        pack_folder.check(folder, ["a.cube"], False)


def test_a_file_where_the_folder_goes_is_refused_even_with_force(tmp_path):
    (tmp_path / "pack").write_text("a file")
    for force in (False, True):
        with pytest.raises(pack_folder.Refused, match="not a folder"):
            pack_folder.check(tmp_path / "pack", ["a.cube"], force)
    pack_folder.check(tmp_path / "missing", ["a.cube"], False)  # a folder to make: nothing to refuse
