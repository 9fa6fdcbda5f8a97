"""Geo-referenced networks: sbsim points PROJ at the proj.db SUMO's wheel ships (no "Cannot find proj.db")."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest
from sbsim.runner import executable

UTM = "+proj=utm +zone=32 +ellps=WGS84 +datum=WGS84 +units=m +no_defs"


@pytest.fixture(scope="module")
def geo_cfg(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The trips scenario with a UTM projection in its <location>, as an OSM import has."""
    out = tmp_path_factory.mktemp("geo")
    for f in trips_cfg.parent.iterdir():
        shutil.copy(f, out / f.name)
    net = out / "net.net.xml"
    text = net.read_text(encoding="utf-8")
    assert 'projParameter="!"' in text
    net.write_text(text.replace('projParameter="!"', f'projParameter="{UTM}"'), encoding="utf-8")
    return out / trips_cfg.name


def run_with(cfg: Path, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    args = [str(executable()), "--sumocfg", str(cfg), "--end", "10"]
    return subprocess.run(args, capture_output=True, text=True, env=env, timeout=120, check=False)


def test_proj_finds_its_database_without_help(geo_cfg: Path) -> None:
    env = {k: v for k, v in os.environ.items() if k not in ("PROJ_DATA", "PROJ_LIB")}
    result = run_with(geo_cfg, env)
    assert result.returncode == 0, result.stderr
    assert "proj.db" not in result.stderr, result.stderr


def test_a_proj_data_the_user_set_is_kept(geo_cfg: Path, tmp_path: Path) -> None:
    # Pointing PROJ at an empty folder brings the error back: sbsim did not override the user.
    env = {k: v for k, v in os.environ.items() if k != "PROJ_LIB"} | {"PROJ_DATA": str(tmp_path)}
    result = run_with(geo_cfg, env)
    assert result.returncode == 0, result.stderr
    assert "Cannot find proj.db" in result.stderr, result.stderr
