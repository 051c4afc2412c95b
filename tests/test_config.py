"""TOML settings: the shipped defaults file loads; unknown keys and wrong types are errors."""
from __future__ import annotations

from pathlib import Path

import pytest

from cityshade.config import BuildSettings, Settings, load_settings, settings_from_mapping
from cityshade.errors import ConfigError

CONFIGS = Path(__file__).resolve().parents[1] / "src" / "cityshade" / "configs"


def test_default_toml_equals_defaults():
    assert load_settings(CONFIGS / "default.toml") == Settings()


def test_unknown_table_and_key():
    with pytest.raises(ConfigError, match="unknown key.*render"):
        settings_from_mapping({"render": {}})
    with pytest.raises(ConfigError, match=r"unknown key\(s\) in config.build: lodd"):
        settings_from_mapping({"build": {"lodd": 2}})
    with pytest.raises(ConfigError, match="kdtree.*bins"):
        settings_from_mapping({"kdtree": {"bins": 1}})


def test_types_and_ranges():
    with pytest.raises(ConfigError, match="must be of type int"):
        settings_from_mapping({"build": {"lod": "2"}})
    with pytest.raises(ConfigError, match="lod must be between 0 and 4"):
        BuildSettings(lod=5)
    with pytest.raises(ConfigError, match="time_source"):
        BuildSettings(time_source="sometimes")
    assert settings_from_mapping({"build": {"merge_distance_m": 0}}).build.merge_distance_m == 0.0


def test_bad_toml(tmp_path):
    p = tmp_path / "x.toml"
    p.write_text("[build\n")
    with pytest.raises(ConfigError, match="invalid TOML"):
        load_settings(p)
    with pytest.raises(ConfigError, match="cannot read config"):
        load_settings(tmp_path / "missing.toml")


def test_shadow_tables_name_the_key_and_the_file():
    from cityshade.config import ShadowSettings

    with pytest.raises(ConfigError, match=r"unknown key\(s\) in x\.toml\.shadows: mapp "):
        settings_from_mapping({"shadows": {"mapp": {}}}, "x.toml")
    with pytest.raises(ConfigError, match=r"x\.toml\.shadows\.vsm: blur_px \(vsm_blur\)"):
        settings_from_mapping({"shadows": {"vsm": {"blur_px": 99}}}, "x.toml")
    with pytest.raises(ConfigError, match="must be of type int"):
        settings_from_mapping({"shadows": {"map": {"px": "big"}}}, "x.toml")
    loaded = settings_from_mapping({"shadows": {"technique": "lispsm/pcf", "map": {"px": 512},
                                                "pcf": {"kernel": 5}}})
    assert loaded.shadows == ShadowSettings(technique="lispsm/pcf").override(map_px=512,
                                                                             pcf_kernel=5)
    with pytest.raises(ConfigError, match="unknown shadow option.*vsm_blurr"):
        ShadowSettings().override(vsm_blurr=4)   # a typo is an error, not a silent no-op
