"""Errors of the OpenSCENARIO importer: each names the file, the line and the element."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any


class ScenarioError(Exception):
    """An .xosc sbsim cannot run: one line (several unsupported elements: one line, all listed)."""


def where(path: Path, element: Any) -> str:
    """`file:line: <Tag>` for an lxml element (its line, as lxml records it)."""
    tag = element.tag if isinstance(element.tag, str) else "comment"
    return f"{path}:{element.sourceline}: <{tag}>"


@dataclass
class Problems:
    """What the importer met and cannot run, collected so that one error lists every one."""

    path: Path
    unsupported: list[str] = field(default_factory=list)

    def add(self, element: Any, why: str = "") -> None:
        tag = element.tag if isinstance(element.tag, str) else "comment"
        text = f"<{tag}> (line {element.sourceline})"
        if why:
            text += f": {why}"
        self.unsupported.append(text)

    def raise_if_any(self) -> None:
        if self.unsupported:
            raise ScenarioError(
                f"{self.path}: {len(self.unsupported)} unsupported OpenSCENARIO element"
                f"{'s' if len(self.unsupported) != 1 else ''}: " + "; ".join(self.unsupported)
            )
