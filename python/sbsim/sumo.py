"""The SUMO installation the host tools use: the ``eclipse-sumo`` package of the running interpreter
(the same SUMO the program is built against)."""

from __future__ import annotations

import importlib
import os
from pathlib import Path

__all__ = ["sumo_binary", "sumo_environment", "sumo_home"]


def sumo_home() -> Path:
    """SUMO_HOME of the ``eclipse-sumo`` package of the running interpreter."""
    try:
        sumo = importlib.import_module("sumo")
    except ImportError as exc:  # pragma: no cover - environment problem
        raise RuntimeError("the 'sumo' package is missing; pip install eclipse-sumo") from exc
    return Path(str(sumo.SUMO_HOME))


def sumo_binary(name: str) -> Path:
    """Path of a SUMO binary such as ``sumo`` or ``netgenerate``."""
    exe = name + (".exe" if os.name == "nt" else "")
    path = sumo_home() / "bin" / exe
    if not path.exists():
        raise FileNotFoundError(path)
    return path


def sumo_environment() -> dict[str, str]:
    """This process's environment with ``SUMO_HOME`` set, for running SUMO's binaries and tools."""
    env = dict(os.environ)
    env["SUMO_HOME"] = str(sumo_home())
    return env
