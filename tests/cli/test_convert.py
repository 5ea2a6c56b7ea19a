"""ocioforge convert: bad arguments are one line, exit 2, and nothing written; a verified run's
frames and summary."""

from __future__ import annotations

import subprocess
import sys

import pytest

from tests.cli.conftest import run
from tests.convert import images


@pytest.fixture(scope="module")
def plates(tmp_path_factory):
    folder = tmp_path_factory.mktemp("plates")
    images.sequence(folder, "s", [1, 2])
    return folder


@pytest.mark.parametrize(
    "args, message",
    [
        ((), "give --to SPACE or --display"),
        (("--to", "ACEScct", "--display", "sRGB - Display"), "one of them"),
        (("--to", "ACEScgg"), "did you mean 'ACEScg'"),
        (("--display", "sRGB - Display", "--view", "Nope"), "is no view"),
        (("--view", "Scale", "--to", "ACEScg"), "needs --display"),
        (("--to", "ACEScg", "--depth", "uint8"), "is not written as exr"),
        (("--to", "ACEScg", "--compression", "lzw"), "is not a exr compression"),
        (("--to", "ACEScg", "--format", "jpeg", "--verify"), "is lossy"),
        (("--to", "ACEScg", "--compression", "dwaa", "--verify"), "is lossy"),
        (("--to", "ACEScg", "--frames", "9-1"), "runs backwards"),
        (("--to", "ACEScg", "--verify", "--sample", "many"), "--sample"),
        (("--to", "ACEScg", "--force", "--skip-existing"), "opposite"),
        (("--to", "ACEScg", "--jobs", "0"), "--jobs"),
        (("--to", "ACEScg", "--from", "ACEScg", "--from", "ACEScct"), "more than once"),
    ],
)
def test_bad_arguments_are_one_line_and_write_nothing(tmp_path, capsys, build_config, plates, args, message):
    out = tmp_path / "out"
    code, stdout, err = run(
        capsys, "convert", str(plates / "s.####.exr"), "--config", str(build_config((2, 1))), "-o", str(out), *args
    )
    assert code == 2 and err.count("\n") == 1 and err.startswith("error: ") and message in err, err
    assert not out.exists() and stdout == ""


def test_inputs_naming_nothing_are_refused(tmp_path, capsys, build_config):
    code, _, err = run(
        capsys,
        "convert",
        str(tmp_path / "s.####.exr"),
        "--to",
        "ACEScg",
        "--config",
        str(build_config((2, 1))),
        "-o",
        str(tmp_path / "out"),
    )
    assert code == 2 and err.count("\n") == 1 and "matches no file" in err


def test_verify_needs_a_config_beside_its_spec(tmp_path, capsys, plates):
    code, _, err = run(
        capsys,
        "convert",
        str(plates / "s.0001.exr"),
        "--to",
        "ACEScg",
        "--config",
        "ocio://studio-config-latest",
        "-o",
        str(tmp_path / "out"),
        "--verify",
    )
    assert code == 2 and err.count("\n") == 1 and "builtin" in err


def test_an_unreachable_scheduler_is_refused(tmp_path, capsys, build_config, plates):
    code, _, err = run(
        capsys,
        "convert",
        str(plates / "s.####.exr"),
        "--to",
        "ACEScct",
        "--from",
        "ACEScg",
        "--config",
        str(build_config((2, 1))),
        "-o",
        str(tmp_path / "out"),
        "--scheduler",
        "tcp://127.0.0.1:9",
    )
    assert code == 2 and err.count("\n") == 1 and "--scheduler" in err and "cannot reach" in err
    assert err.count("--scheduler") == 1 and "cannot reach it (" in err, err  # the option named once
    assert not (tmp_path / "out").exists()


def test_start_up_imports_no_dask_and_no_image_library():
    probe = (
        "import sys\nfrom generator.cli import main\n"
        "try:\n    main(['convert', '--help'])\nexcept SystemExit:\n    pass\n"
        "print(sorted(m for m in ('dask', 'distributed', 'OpenImageIO', 'PyOpenColorIO', 'colour') "
        "if m in sys.modules))"
    )
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=60)
    assert "--scheduler" in result.stdout and result.stdout.strip().splitlines()[-1] == "[]"


def test_a_verified_run_writes_acescct_as_colour_science_encodes_it(tmp_path, capsys, build_config, plates):
    import colour
    import numpy as np

    code, out, err = run(
        capsys,
        "convert",
        str(plates / "s.####.exr"),
        "--config",
        str(build_config((2, 1))),
        "--from",
        "ACEScg",
        "--to",
        "ACEScct",
        "--depth",
        "float",
        "--verify",
        "--jobs",
        "1",
        "-o",
        str(tmp_path / "out"),
    )
    assert code == 0 and out.count("\n") == 1, err
    assert out.startswith("2 written, 0 skipped, 0 failed of 2 frames (") and "; verified 2: 0 depart, worst " in out
    for frame in (1, 2):
        written, spec = images.read(tmp_path / "out" / f"s.{frame:04d}.exr")
        source, _ = images.read(plates / f"s.{frame:04d}.exr")
        expected = colour.models.log_encoding_ACEScct(source[..., :3].astype(np.float64))
        assert spec.format == "float" and np.allclose(written[..., :3], expected, rtol=0, atol=1e-6)
        assert np.array_equal(written[..., 3], source[..., 3])


def test_a_refused_scheduler_removes_only_the_folder_the_run_made(tmp_path, capsys, build_config, plates):
    """An address Dask cannot use is refused at once: the output folder the run made is removed,
    an empty one that was there is kept."""
    kept = tmp_path / "kept"
    kept.mkdir()
    for out in (tmp_path / "made", kept):
        code, stdout, err = run(
            capsys,
            "convert",
            str(plates / "s.####.exr"),
            "--from",
            "ACEScg",
            "--to",
            "ACEScct",
            "--config",
            str(build_config((2, 1))),
            "-o",
            str(out),
            "--scheduler",
            "notascheme://x",
        )
        assert code == 2 and err.count("\n") == 1 and "--scheduler" in err and "cannot reach" in err, err
        assert stdout == ""
    assert sorted(p.name for p in tmp_path.iterdir()) == ["kept"] and not any(kept.iterdir())
