"""Which config a convert run uses and the names it is given, checked against it
(generator/convert/config.py)."""

from __future__ import annotations

import shutil

import pytest

from generator.convert import config as configs
from generator.spec.schema import SpecError


def test_the_cache_is_xdgs_or_the_home_folders(monkeypatch, tmp_path):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    assert configs.cache_folder() == tmp_path / "cache" / "ocioforge"
    monkeypatch.setenv("XDG_CACHE_HOME", "")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert configs.cache_folder() == tmp_path / "home" / ".cache" / "ocioforge"


def test_the_config_given_wins_then_ocio_then_the_cached_default(monkeypatch, tmp_path, config):
    """A default already built for these sources is used as it is: nothing is built or announced."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    digest = configs._sources_digest()
    assert len(digest) == 12 and int(digest, 16) >= 0 and digest == configs._sources_digest()
    cached = tmp_path / "ocioforge" / f"default-{digest}" / configs.DEFAULT_NAME
    shutil.copytree(config.parent, cached)
    said = []
    monkeypatch.setenv("OCIO", "  ")
    assert configs.choose(None, said.append) == str(cached / "config.ocio") and said == []
    monkeypatch.setenv("OCIO", " ocio://studio-config-latest ")
    assert configs.choose(None) == "ocio://studio-config-latest"
    assert configs.choose("show/config.ocio") == "show/config.ocio"


def test_a_builtin_loads_and_a_missing_or_broken_config_is_one_line(tmp_path):
    assert configs.load("ocio://studio-config-latest", verify=False).getColorSpace("ACEScg") is not None
    with pytest.raises(SpecError, match="no such config file"):
        configs.load(str(tmp_path / "missing.ocio"), verify=False)
    (tmp_path / "broken.ocio").write_text("ocio_profile_version: 2.1\ncolorspaces: [\n")
    with pytest.raises(SpecError, match="OpenColorIO cannot load it") as caught:
        configs.load(str(tmp_path / "broken.ocio"), verify=False)
    assert "\n" not in caught.value.message


def test_verify_needs_the_spec_the_config_was_built_from(tmp_path, config):
    configs.load(str(config), verify=True)
    shutil.copy(config, tmp_path / "config.ocio")
    with pytest.raises(SpecError):
        configs.load(str(tmp_path / "config.ocio"), verify=True)
    assert configs.load(str(tmp_path / "config.ocio"), verify=False).getColorSpace("ACEScct") is not None


@pytest.mark.parametrize(
    "name, space", [("ACEScg", "ACEScg"), ("lin_ap1", "ACEScg"), ("color_timing", "ACEScct"), ("data", "Raw")]
)
def test_a_space_alias_or_role_is_the_configs_space(config, name, space):
    cfg = configs.load(str(config), verify=False)
    assert configs.colour_space(cfg, name, "--from") == space


def test_a_display_without_a_view_is_its_default_and_a_misspelt_one_is_answered(config):
    cfg = configs.load(str(config), verify=False)
    assert configs.display_view(cfg, "Rec.2100-PQ - Display", None)[1] == cfg.getDefaultView("Rec.2100-PQ - Display")
    assert configs.display_view(cfg, "sRGB - Display", "Raw") == ("sRGB - Display", "Raw")
    with pytest.raises(SpecError, match="did you mean 'sRGB - Display'"):
        configs.display_view(cfg, "sRGB Display", None)
