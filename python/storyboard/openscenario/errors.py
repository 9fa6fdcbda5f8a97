"""Errors of the OpenSCENARIO importer: each names the file, the line and the element."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any


class ScenarioError(Exception):
    """An .xosc sbsim cannot run: one line (several unsupported elements: one line, all listed)."""


def read_xml(path: Path, what: str) -> Any:
    """The root element of the XML file at `path` (lxml), or a ScenarioError: "{path}: cannot read {what}: ..."."""
    from lxml import etree

    try:
        return etree.parse(str(path)).getroot()
    except (OSError, etree.XMLSyntaxError) as e:
        raise ScenarioError(f"{path}: cannot read {what}: {e}") from None


def where(path: Path, element: Any) -> str:
    """`file:line: <Tag>` for an lxml element (its line, as lxml records it)."""
    tag = element.tag if isinstance(element.tag, str) else "comment"
    source = element.getroottree().docinfo.URL  # a catalog's element names the catalog's file
    return f"{source or path}:{element.sourceline}: <{tag}>"


@dataclass
class Problems:
    """What the importer met and cannot run, collected so that one error lists every one."""

    path: Path
    unsupported: list[str] = field(default_factory=list)

    def add(self, element: Any, why: str = "") -> None:
        tag = element.tag if isinstance(element.tag, str) else "comment"
        source = element.getroottree().docinfo.URL
        line = (
            f"line {element.sourceline}"
            if not source or Path(source) == self.path
            else f"{source}:{element.sourceline}"
        )
        text = f"<{tag}> ({line})"
        if why:
            text += f": {why}"
        self.unsupported.append(text)

    def raise_if_any(self) -> None:
        if self.unsupported:
            raise ScenarioError(
                f"{self.path}: {len(self.unsupported)} unsupported OpenSCENARIO element"
                f"{'s' if len(self.unsupported) != 1 else ''}: " + "; ".join(self.unsupported)
            )
