"""ocioforge init: the embedded default spec written to a file, which builds; only a regular
file replaced, and only with --force."""

import pytest

from tests.cli.conftest import refuses_a_special_file, run, writes_through_a_link_only_with_force


def test_init_writes_the_default_spec_that_builds(tmp_path, capsys):
    path = tmp_path / "my-show.toml"
    assert run(capsys, "init", str(path))[0] == 0
    assert path.read_text().startswith("# ocioforge spec")
    assert run(capsys, "init", str(path))[0] == 2
    assert run(capsys, "build", str(path), "-o", str(tmp_path / "cfg"))[0] == 0


def test_init_replaces_only_a_regular_file(tmp_path, capsys):
    """A pipe, a link (dangling or not) or a name too long is refused in one line, --force or
    not (run as root, --force had turned /dev/null into a text file)."""
    import os

    os.mkfifo(tmp_path / "pipe")
    (tmp_path / "link").symlink_to(tmp_path / "nowhere")
    for name, words in (("pipe", "is not a regular file"), ("link", "is a link to nothing")):
        code, _, err = run(capsys, "init", str(tmp_path / name), "--force")
        assert code == 2 and words in err and err.count("\n") == 1
    assert (tmp_path / "link").is_symlink() and not (tmp_path / "nowhere").exists()
    code, _, err = run(capsys, "init", str(tmp_path / ("x" * 300 + ".toml")))
    assert code == 2 and "cannot write" in err and err.count("\n") == 1


@pytest.mark.parametrize("kind", ("fifo", "socket", "device"))
def test_a_device_or_pipe_is_never_replaced(tmp_path, capsys, kind):
    refuses_a_special_file(capsys, tmp_path, kind, ["init", "{out}"], ".toml")


def test_a_link_is_written_through_only_with_force(tmp_path, capsys):
    """A dangling link is refused, --force or not; a link to a regular file needs --force, and
    then the file it points to is written, the link kept."""
    writes_through_a_link_only_with_force(capsys, tmp_path, ["init", "{out}"], ".toml")


def test_an_unwritable_output_is_one_line_and_exit_2(tmp_path, capsys):
    """A file under a regular file cannot be written, for any user: the path and the OS's reason
    on one line, exit status 2, nothing left behind."""
    blocked = tmp_path / "blocked"
    blocked.write_bytes(b"")
    code, _, err = run(capsys, "init", f"{blocked}/show.toml")
    assert code == 2 and err.count("\n") == 1, err
    assert err == f"error: {blocked / 'show.toml'}: cannot write: Not a directory\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["blocked"]


@pytest.mark.parametrize(
    "name, words",
    [
        ("nd/sub/show.toml", "its folder"),  # made nd/sub, and left it when the write failed
        ("show.toml/", "ends in a slash"),  # wrote show.toml
    ],
)
def test_a_file_output_in_no_folder_or_naming_one_is_refused_and_makes_nothing(
    capsys, tmp_path, monkeypatch, name, words
):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "gamuts").mkdir()
    code, _, err = run(capsys, "init", name)
    assert code == 2 and err.count("\n") == 1 and words in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["gamuts"] and not any((tmp_path / "gamuts").iterdir())


def test_force_replaces_a_spec_with_the_default_one_and_says_what_next(tmp_path, capsys):
    from generator.spec.load import default_text

    path = tmp_path / "show.toml"
    path.write_text('name = "old"\n')
    code, out, err = run(capsys, "init", path, "--force")
    assert code == 0 and err == "", err
    assert out == f"{path}: default spec written; edit it, then: ocioforge build {path} -o configs/NAME\n"
    assert path.read_text(encoding="utf-8") == default_text()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["show.toml"]
