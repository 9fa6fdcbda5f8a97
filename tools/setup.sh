#!/usr/bin/env bash
# One-time and incremental set-up shared by ./sbsim and ./run-tests: Debian packages, the .venv,
# the Python dependencies, and an incremental `pip install` of sbsim whenever a source changed.
# Source it; it defines SBSIM_ROOT and VENV. Set SBSIM_BUILD_TESTS=ON to build the C++ tests too.
set -euo pipefail

SBSIM_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="$SBSIM_ROOT/.venv"
# Build: compilers (and ccache), Eigen, GoogleTest and the C++ libraries sbsim uses (XML, command line, JSON,
# formatting, regular expressions, allocator, gzip, the radio's R-tree (Boost.Geometry) and its TOML
# file); tests: clang-format and a virtual X server for sumo-gui.
DEBIAN_PACKAGES=(cmake g++ ccache python3-dev libeigen3-dev libgtest-dev libtinyxml2-dev libcli11-dev nlohmann-json3-dev
  libfmt-dev libre2-dev libjemalloc-dev libboost-dev libtomlplusplus-dev zlib1g-dev clang-format xvfb xauth)
# Studies (python -m sbsim.study): Dask runs the sweep, pandas and pyarrow write the tables; reports
# (python -m sbsim.report): sumolib reads the net and the FCD, at SUMO's own version.
STUDY_DEPENDENCIES=("dask>=2024" "distributed>=2024" "pandas>=2" "pyarrow>=14" "tqdm>=4" "matplotlib>=3.7" "sumolib==1.28.*")
PYTHON_DEPENDENCIES=(pip "scikit-build-core>=0.10" "pybind11>=2.12" "numpy>=1.24" "eclipse-sumo==1.28.*" "lxml>=5")
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}"
# A rebuild after a branch switch or in a fresh clone compiles only what changed: ccache, with paths
# taken relative to the checkout so clones share the cache (CMake reads the launcher from the
# environment when it configures a build folder).
if command -v ccache >/dev/null && [ -z "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ]; then
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR="${CCACHE_BASEDIR:-$SBSIM_ROOT}"
fi

say() { printf 'sbsim setup: %s\n' "$*" >&2; }

ensure_debian_packages() {
  local missing=() p
  command -v dpkg-query >/dev/null || return 0  # not Debian: trust the system
  for p in "${DEBIAN_PACKAGES[@]}"; do
    # python3-dev is only needed when the interpreter has no headers of its own (pyenv builds do).
    if [ "$p" = python3-dev ] && python3 -c 'import sysconfig,os,sys; sys.exit(not os.path.exists(sysconfig.get_paths()["include"]+"/Python.h"))' 2>/dev/null; then continue; fi
    if [ "$p" = cmake ] || [ "$p" = g++ ] || [ "$p" = clang-format ]; then command -v "$p" >/dev/null && continue; fi
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -eq 0 ]; then
    say "installing Debian packages: ${missing[*]}"
    DEBIAN_FRONTEND=noninteractive apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
  else
    say "missing Debian packages; install them with:"
    printf '  sudo apt-get install -y %s\n' "${missing[*]}" >&2
    exit 1
  fi
}

find_python() {
  local candidate
  for candidate in "${PYTHON:-}" python3.11 python3; do
    [ -n "$candidate" ] && command -v "$candidate" >/dev/null || continue
    if "$candidate" -c 'import sys; sys.exit(sys.version_info[:2] < (3, 11))' 2>/dev/null; then
      echo "$candidate"
      return
    fi
  done
  say "Python 3.11 or newer is needed (set PYTHON=/path/to/python3.11)"
  exit 1
}

# Whether every requirement given is installed in the venv, at a version it allows (pip's own
# `packaging` judges, as pip would); quiet, exit status only.
requirements_satisfied() {
  "$VENV/bin/python" - "$@" <<'PY' 2>/dev/null
import sys
from importlib.metadata import PackageNotFoundError, version
from pip._vendor.packaging.requirements import Requirement

for text in sys.argv[1:]:
    requirement = Requirement(text)
    try:
        if not requirement.specifier.contains(version(requirement.name), prereleases=True):
            sys.exit(1)
    except PackageNotFoundError:
        sys.exit(1)
PY
}

# The venv and the Python dependencies: PYTHON_DEPENDENCIES, the study extras (every documented
# feature: studies, --statistics, reports) and any given. The stamp lists what was installed, one
# requirement a line: a command wanting a subset of it (./sbsim after ./run-tests) installs nothing.
# Without a stamp (a venv made by hand, or by an older set-up) the venv itself is asked first, so a
# ready checkout starts at once.
ensure_venv() {
  if [ ! -x "$VENV/bin/python" ]; then
    if [ -L "$VENV" ] || [ -e "$VENV" ]; then
      say "$VENV exists but holds no Python (a dangling link or a broken copy); remove it and run again"
      exit 1
    fi
    say "creating $VENV"
    "$(find_python)" -m venv "$VENV"
  fi
  local stamp="$VENV/.sbsim-deps" wanted=() missing=() r
  wanted=("${PYTHON_DEPENDENCIES[@]}" "${STUDY_DEPENDENCIES[@]}" "$@")
  for r in "${wanted[@]}"; do
    [ -f "$stamp" ] && grep -qxF -- "$r" "$stamp" && continue
    missing+=("$r")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if ! requirements_satisfied "${missing[@]}"; then
    say "installing Python dependencies: ${missing[*]}"
    "$VENV/bin/python" -m pip install -q --disable-pip-version-check --upgrade "${missing[@]}"
  fi
  { [ -f "$stamp" ] && cat "$stamp"; printf '%s\n' "${missing[@]}"; } | sort -u > "$stamp.new"
  mv "$stamp.new" "$stamp"
}

# Reinstalls sbsim when a source is newer than the last install; the build folder is kept, so
# only what changed is recompiled. An install with the C++ tests (./run-tests) serves ./sbsim too.
ensure_sbsim_installed() {
  local wanted="${SBSIM_BUILD_TESTS:-OFF}" stamp
  for stamp in "$SBSIM_ROOT/build/.installed-tests-$wanted" "$SBSIM_ROOT/build/.installed-tests-ON"; do
    if [ -f "$stamp" ] && [ -x "$VENV/bin/sbsim" ] && [ -z "$(cd "$SBSIM_ROOT" && find CMakeLists.txt cmake cpp python pyproject.toml stories tests/cpp -newer "$stamp" -print -quit 2>/dev/null)" ]; then
      return 0
    fi
  done
  stamp="$SBSIM_ROOT/build/.installed-tests-$wanted"
  say "building and installing sbsim (log: build/pip-install.log)"
  mkdir -p "$SBSIM_ROOT/build"
  if ! (cd "$SBSIM_ROOT" && SBSIM_BUILD_TESTS="$wanted" "$VENV/bin/python" -m pip install \
        --disable-pip-version-check --no-build-isolation --no-deps . >build/pip-install.log 2>&1); then
    tail -n 40 "$SBSIM_ROOT/build/pip-install.log" >&2
    say "build failed; full log: build/pip-install.log"
    exit 1
  fi
  rm -f "$SBSIM_ROOT"/build/.installed-tests-*
  touch "$stamp"
}

# The style checks the test command runs: clang-format over the C++ tree, ruff over the Python.
# Prints what is off and returns non-zero when anything is.
check_style() {
  local status=0 cxx
  cd "$SBSIM_ROOT"
  mapfile -t cxx < <(find cpp tests/cpp examples -name '*.h' -o -name '*.cpp' | sort)
  clang-format --dry-run -Werror "${cxx[@]}" || { say "C++ not formatted: run clang-format -i on the files above"; status=1; }
  "$VENV/bin/ruff" check . || status=1
  "$VENV/bin/ruff" format --check . || { say "Python not formatted: run .venv/bin/ruff format ."; status=1; }
  # What set-up and builds make must never be committed (a committed .venv link broke a clean clone).
  if [ -e .git ] && [ -n "$(git ls-files .venv build results bench/out)" ]; then
    say "generated files are tracked by git: $(git ls-files .venv build results bench/out | head -3 | tr '\n' ' ')"
    status=1
  fi
  return $status
}
