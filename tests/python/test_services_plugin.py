"""The out-of-tree service module example (examples/service-module), built from outside the source tree
against the installed sbsim (its CMake package in this environment), then loaded with --plugin."""

from __future__ import annotations

import re
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

import pytest
from sbsim.runner import RunResult, run
from sbsim_helpers import REPO, STORIES, assert_no_crash, message_counts, sdk_prefix

EXAMPLE = REPO / "examples" / "service-module"
#: The accident scenario: the queue behind the wreck brakes hard, so brake lights go on.
ACCIDENT = STORIES / "accident"


@dataclass
class Module:
    source: Path  # the example's copy (CMakeLists.txt, sources, services.xml)
    library: Path  # the built plugin


def cmake(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["cmake", *args], capture_output=True, text=True, timeout=600, check=False)


@pytest.fixture(scope="module")
def module(tmp_path_factory: pytest.TempPathFactory) -> Module:
    if shutil.which("cmake") is None:
        pytest.skip("cmake is not installed")
    root = tmp_path_factory.mktemp("plugin")
    source = root / "service-module"
    shutil.copytree(EXAMPLE, source, ignore=shutil.ignore_patterns("build", "CMakeCache.txt", "CMakeFiles"))
    build = root / "build"
    # The SDK of the sbsim under test (its build folder's, installed; else the one pip installed):
    # a module built against other headers may not match its classes' layout.
    # pytest.fail, not assert: a failed build is a broken environment, not a failed check.
    configure = cmake("-S", str(source), "-B", str(build), f"-DCMAKE_PREFIX_PATH={sdk_prefix(root)}")
    if configure.returncode != 0:
        pytest.fail(f"configuring the example failed:\n{configure.stdout}\n{configure.stderr}")
    built = cmake("--build", str(build), "-j2")
    if built.returncode != 0:
        pytest.fail(f"building the example failed:\n{built.stdout}\n{built.stderr}")
    library = build / "libbrake_light.so"
    assert library.is_file(), sorted(p.name for p in build.iterdir())
    return Module(source, library)


def run_accident(*extra: str) -> RunResult:
    result = run(ACCIDENT / "accident.sumocfg", story=ACCIDENT / "story.py", extra=list(extra), timeout=120)
    assert_no_crash(result)
    assert result.returncode == 0, f"sbsim failed ({result.returncode}):\n{result.stderr}"
    return result


def services_with_threshold(module: Module, directory: Path, threshold: str) -> Path:
    text = (module.source / "services.xml").read_text(encoding="utf-8")
    text, n = re.subn(r'threshold="[^"]*"', f'threshold="{threshold}"', text)
    assert n == 1, text
    path = directory / "services.xml"
    path.write_text(text, encoding="utf-8")
    return path


def test_plugin_sends_and_delivers_brake_lights(module: Module) -> None:
    result = run_accident("--plugin", str(module.library), "--services", str(module.source / "services.xml"))
    summary = result.summary()
    # The example's services.xml has no filters: every vehicle gets one BrakeLightService.
    assert summary["services created"] == summary["vehicles seen"] != "0"
    counts = message_counts(result.stdout)
    assert "BrakeLight" in counts, result.stdout
    sent, delivered = counts["BrakeLight"]
    assert sent > 0 and delivered > 0, (sent, delivered)
    line = f"messages BrakeLight: sent {sent}, delivered {delivered}"
    assert line in result.stdout.splitlines()


def test_plugin_reads_its_parameters_and_changes_traffic(module: Module, tmp_path: Path) -> None:
    plugin = ["--plugin", str(module.library)]
    warning = "activations collision-warning"
    plain = run_accident().summary()
    # Nobody brakes at 100 m/s²: no messages, and services that do nothing leave traffic as it was.
    quiet = run_accident(*plugin, "--services", str(services_with_threshold(module, tmp_path, "100")))
    assert "BrakeLight" not in message_counts(quiet.stdout), quiet.stdout
    assert quiet.summary()["services created"] == plain["vehicles seen"]
    assert quiet.summary()[warning] == plain[warning]
    # The default threshold (3 m/s²): warned vehicles cap their speed, so the traffic differs.
    (tmp_path / "default").mkdir()
    active = run_accident(*plugin, "--services", str(services_with_threshold(module, tmp_path / "default", "3.0")))
    assert message_counts(active.stdout)["BrakeLight"][0] > 0
    assert active.summary()[warning] != plain[warning], (active.summary()[warning], plain[warning])


def test_two_plugins_registering_the_same_type(module: Module, tmp_path: Path) -> None:
    twin = tmp_path / "libbrake_light_twin.so"
    shutil.copy(module.library, twin)
    result = run(
        ACCIDENT / "accident.sumocfg",
        extra=["--plugin", str(module.library), "--plugin", str(twin), "--end", "1"],
        timeout=120,
    )
    assert_no_crash(result)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert "BrakeLightService" in lines[0] and str(twin) in lines[0], lines[0]
