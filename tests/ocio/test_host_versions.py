"""The hosts a config of a newer profile does not load: data, said by build in one line."""

from __future__ import annotations

import re
import shutil

from generator.ocio.host_versions import HOSTS, Host, not_loading
from tests.cli.test_cli import run
from tests.conftest import host_missing

TINY = (
    'colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]\n'
    '[[display]]\nname = "sRGB - Display"\nviews = ["Colorimetric", "Raw"]\n'
)


def test_every_host_loads_21_and_the_platform_years_run_in_order():
    assert not_loading((2, 1)) == ""
    years = [h for h in HOSTS if h.platform]
    assert [h.platform for h in years] == sorted(h.platform for h in years)
    assert [h.ocio for h in years] == sorted(h.ocio for h in years)
    assert all(h.name == f"CY{h.platform}" for h in years)


def test_the_hosts_that_refuse_a_version_are_one_phrase():
    said = not_loading((2, 4))
    assert "Debian 12's Blender 3.4, ocioconvert and oiiotool (OCIO 2.1)" in said
    assert "hosts of VFX Reference Platform CY2022–CY2024 (OCIO 2.1–2.3)" in said
    assert not_loading((2, 2), (Host("A", (2, 1)), Host("CY2022", (2, 1), 2022), Host("CY2023", (2, 2), 2023))) == (
        "A (OCIO 2.1), hosts of VFX Reference Platform CY2022 (OCIO 2.1)"
    )


def test_debians_entry_is_the_ocio_its_tools_load():
    from generator.verify.hosts import linked_ocio

    program = shutil.which("ocioconvert", path="/usr/bin")
    if program is None:
        host_missing("Debian's ocioconvert is not installed")
    debian = next(h for h in HOSTS if h.name.startswith("Debian 12"))
    assert linked_ocio(program).startswith(".".join(map(str, debian.ocio)) + ".")


def test_a_build_newer_than_21_names_the_hosts_that_will_not_load_it(tmp_path, capsys):
    (tmp_path / "tiny.toml").write_text(TINY, encoding="utf-8")
    code, out, err = run(
        capsys, "build", str(tmp_path / "tiny.toml"), "-o", str(tmp_path / "v24"), "--ocio-version", "2.4"
    )
    assert code == 0 and "OCIO 2.4" in out, err
    assert err.count("\n") == 1 and err.startswith("note: an OCIO 2.4 config does not load in Debian 12's"), err
    assert re.search(r"CY2022–CY2024 \(OCIO 2\.1–2\.3\); --ocio-version 2\.1 writes one they load\n$", err), err
    code, _, err = run(capsys, "build", str(tmp_path / "tiny.toml"), "-o", str(tmp_path / "v21"))
    assert code == 0 and err == "", err  # the spec's 2.1: every known host loads it
