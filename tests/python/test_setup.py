"""The newcomer's path (issue 29): ./sbsim's set-up (tools/setup.sh) installs what every documented feature
needs and, on a ready checkout, installs nothing; a tool missing one of the study extras says so in one
line with the command to run.

The set-up runs for real (bash sourcing tools/setup.sh) on a scratch root and venv whose Python is the
test venv's behind a wrapper that refuses `pip install` (exit 97): the shared venv is never changed, and
any install the set-up tries shows as that exit."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
from sbsim.extras import STUDY_EXTRAS
from sbsim_helpers import REPO

PIP_REFUSED = 97


def scratch_root(tmp_path: Path) -> tuple[Path, Path]:
    """A checkout holding only tools/setup.sh (and what its freshness check looks at) and a venv whose
    python is the real one, pip install refused."""
    root = tmp_path / "checkout"
    (root / "tools").mkdir(parents=True)
    shutil.copy(REPO / "tools" / "setup.sh", root / "tools" / "setup.sh")
    for name in ("cpp", "cmake", "python", "stories", "tests/cpp"):
        (root / name).mkdir(parents=True)
    for name in ("CMakeLists.txt", "pyproject.toml"):
        (root / name).write_text("", encoding="utf-8")
    venv = root / ".venv"
    (venv / "bin").mkdir(parents=True)
    python = venv / "bin" / "python"
    python.write_text(
        "#!/bin/sh\n"
        'if [ "$1" = "-m" ] && [ "$2" = "pip" ]; then echo "pip was run: $*" >&2; exit 97; fi\n'
        f'exec {sys.executable} "$@"\n',
        encoding="utf-8",
    )
    sbsim = venv / "bin" / "sbsim"
    sbsim.write_text("#!/bin/sh\n", encoding="utf-8")
    for f in (python, sbsim):
        f.chmod(0o755)
    return root, venv


def set_up(root: Path, *steps: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    script = f"source {root / 'tools' / 'setup.sh'}; " + "; ".join(steps)
    return subprocess.run(
        ["bash", "-c", script], capture_output=True, text=True, timeout=120, env={**os.environ, **(env or {})}
    )


def test_the_first_command_installs_the_study_extras(tmp_path: Path) -> None:
    # An empty venv (its python knows nothing): ./sbsim's set-up installs the extras with the rest.
    root, venv = scratch_root(tmp_path)
    empty = venv / "bin" / "python"
    empty.write_text(
        '#!/bin/sh\nif [ "$1" = "-m" ] && [ "$2" = "pip" ]; then echo "pip was run: $*" >&2; exit 97; fi\n'
        f'exec {sys.executable} -S "$@"\n',
        encoding="utf-8",
    )
    done = set_up(root, "ensure_venv")
    assert done.returncode == PIP_REFUSED, done.stderr
    asked = done.stderr.split("pip was run: ", 1)[1]
    for requirement in STUDY_EXTRAS.values():
        assert requirement in asked.split(), (requirement, asked)
    assert "eclipse-sumo==1.28.*" in asked.split()


def test_a_ready_venv_without_a_stamp_installs_nothing(tmp_path: Path) -> None:
    # The venv has everything (this test's own), but no stamp (made by hand, or by an older set-up).
    root, venv = scratch_root(tmp_path)
    done = set_up(root, "ensure_venv")
    assert done.returncode == 0, done.stderr
    assert "installing" not in done.stderr
    stamp = (venv / ".sbsim-deps").read_text(encoding="utf-8").splitlines()
    assert set(STUDY_EXTRAS.values()) <= set(stamp)


def test_sbsim_after_run_tests_installs_nothing(tmp_path: Path) -> None:
    # ./run-tests wrote a stamp with more requirements than ./sbsim wants, and installed sbsim with its
    # C++ tests: ./sbsim reinstalls neither (it used to compare the stamp as one string, and want the
    # tests-OFF build stamp).
    root, venv = scratch_root(tmp_path)
    assert set_up(root, 'ensure_venv "pytest>=7"').returncode == 0
    (root / "build").mkdir()
    (root / "build" / ".installed-tests-ON").touch()
    done = set_up(root, "ensure_venv", "ensure_sbsim_installed", "echo ready")
    assert done.returncode == 0, done.stderr
    assert done.stdout == "ready\n"
    assert "installing" not in done.stderr and "building" not in done.stderr


def test_a_changed_source_still_rebuilds(tmp_path: Path) -> None:
    root, _ = scratch_root(tmp_path)
    (root / "build").mkdir()
    stamp = root / "build" / ".installed-tests-OFF"
    stamp.touch()
    os.utime(stamp, (1_000_000_000, 1_000_000_000))
    (root / "cpp" / "new.cpp").write_text("", encoding="utf-8")
    done = set_up(root, "ensure_sbsim_installed")
    assert done.returncode == 1 and "building and installing sbsim" in done.stderr, done.stderr


def test_setup_and_pyproject_list_the_same_study_extras() -> None:
    pyproject = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))
    study = pyproject["project"]["optional-dependencies"]["study"]
    assert sorted(study) == sorted(STUDY_EXTRAS.values())
    setup = (REPO / "tools" / "setup.sh").read_text(encoding="utf-8")
    line = next(x for x in setup.splitlines() if x.startswith("STUDY_DEPENDENCIES=("))
    assert sorted(w.strip('"') for w in line.split("(", 1)[1].rstrip(")").split()) == sorted(study)


@pytest.mark.parametrize(
    ("tool", "needs"),
    [("sbsim.study", ["study.toml"]), ("sbsim.report", ["ev.jsonl", "--sumocfg", "x.sumocfg", "-o", "r.html"])],
)
def test_a_tool_without_the_extras_says_what_to_run(tool: str, needs: list[str], tmp_path: Path) -> None:
    # -S: this Python without its site-packages, as a venv without the study extras.
    done = subprocess.run(
        [sys.executable, "-S", "-m", tool, *needs],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=60,
        env={**os.environ, "PYTHONPATH": str(REPO / "python")},
    )
    assert done.returncode == 2, done.stderr
    assert "Traceback" not in done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr
    assert f"install with: {sys.executable} -m pip install " in lines[0] and "'pandas>=2'" in lines[0]
