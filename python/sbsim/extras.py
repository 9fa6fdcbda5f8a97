"""The study extras (``pip install 'sbsim[study]'``, which ``./sbsim`` installs): what the study and the report
need beyond sbsim itself, and the one line a tool prints when one is missing, naming the command that
installs it (never a traceback)."""

from __future__ import annotations

import importlib.util
import shlex
import sys
from collections.abc import Iterable

#: Module imported -> the requirement that installs it; the same list as pyproject.toml's ``study`` extras.
STUDY_EXTRAS: dict[str, str] = {
    "dask": "dask>=2024",
    "distributed": "distributed>=2024",
    "pandas": "pandas>=2",
    "pyarrow": "pyarrow>=14",
    "tqdm": "tqdm>=4",
    "matplotlib": "matplotlib>=3.7",
    "sumolib": "sumolib==1.28.*",
}


def missing(modules: Iterable[str]) -> list[str]:
    """The modules among ``modules`` that this Python cannot import (looked up, not imported)."""
    return [m for m in modules if importlib.util.find_spec(m) is None]


def missing_message(prog: str, modules: Iterable[str]) -> str | None:
    """One line for ``prog`` if any of ``modules`` is missing: which, and the exact command that installs
    them into this Python; None when all are there."""
    gone = missing(modules)
    if not gone:
        return None
    requirements = " ".join(shlex.quote(STUDY_EXTRAS[m]) for m in gone)
    return (
        f"{prog}: needs the Python package{'s' if len(gone) > 1 else ''} {', '.join(gone)} (sbsim's study extras, "
        f"which ./sbsim installs); install with: {shlex.quote(sys.executable)} -m pip install {requirements}"
    )


def require(prog: str, modules: Iterable[str]) -> None:
    """Exits with code 2 and one line on stderr if any of ``modules`` is missing."""
    message = missing_message(prog, modules)
    if message is not None:
        print(message, file=sys.stderr)
        sys.exit(2)
