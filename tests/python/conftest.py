"""Small generated scenarios shared by the whole test session (generated once: the machine is busy)."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest
from sbsim.scenarios.grid import make_grid
from sbsim_helpers import OFFSET_BOUNDARY, SERVICES_SOURCE, sdk_prefix


@pytest.fixture(scope="session")
def trips_cfg(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """4 x 4 grid, 300 s, one random trip every 2 s (150 vehicles, ids veh0..veh149); vehicles arrive and leave."""
    return make_grid(tmp_path_factory.mktemp("trips"), grid=4, end=300.0, seed=1, period=2.0)


@pytest.fixture(scope="session")
def loops_cfg(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """3 x 3 grid, 300 s, 30 vehicles (veh00..veh29) inserted during the first 30 s, driving loops until the end."""
    return make_grid(
        tmp_path_factory.mktemp("loops"), grid=3, end=300.0, seed=3, traffic="loops", vehicles=30, ramp=30.0
    )


@pytest.fixture(scope="session")
def offset_cfg(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The trips scenario with a net boundary not starting at (0, 0), so the canvas frame is not trivial.

    Only ``<location convBoundary>`` changes (the geometry stays), so Coord(x, y) means SUMO
    (x - 100, 650 - y) here.
    """
    out = tmp_path_factory.mktemp("offset")
    for f in trips_cfg.parent.iterdir():
        shutil.copy(f, out / f.name)
    net = out / "net.net.xml"
    text = net.read_text(encoding="utf-8")
    boundary = ",".join(f"{v:.2f}" for v in OFFSET_BOUNDARY)
    text, n = re.subn(r'convBoundary="[^"]*"', f'convBoundary="{boundary}"', text, count=1)
    assert n == 1
    net.write_text(text, encoding="utf-8")
    return out / trips_cfg.name


@pytest.fixture(scope="session")
def services_module(tmp_path_factory: pytest.TempPathFactory) -> Path:
    if shutil.which("cmake") is None:
        pytest.skip("cmake is not installed")
    root = tmp_path_factory.mktemp("test-services")
    build = root / "build"
    for args in (
        ["-S", str(SERVICES_SOURCE), "-B", str(build), f"-DCMAKE_PREFIX_PATH={sdk_prefix(root)}"],
        ["--build", str(build), "-j2"],
    ):
        done = subprocess.run(["cmake", *args], capture_output=True, text=True, timeout=600, check=False)
        if done.returncode != 0:
            pytest.fail(f"cmake {args[0]} failed:\n{done.stdout}\n{done.stderr}")
    library = build / "libtest_services.so"
    assert library.is_file()
    return library
