"""ParameterDeclarations, `$name` references and `${...}` expressions, with `--param` overrides."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from .errors import ScenarioError, where
from .expressions import ExpressionError, Value, evaluate

_TYPES = {"double", "integer", "unsignedInt", "unsignedShort", "string", "boolean", "dateTime"}


def convert(text: str, kind: str, what: str) -> Value:
    """`text` as a value of OpenSCENARIO parameter type `kind`."""
    try:
        if kind == "double":
            return float(text)
        if kind in ("integer", "unsignedInt", "unsignedShort"):
            value = float(text)
            if value != int(value) or (kind != "integer" and value < 0):
                raise ValueError(text)
            return int(value)
        if kind == "boolean":
            if text.lower() not in ("true", "false", "1", "0"):
                raise ValueError(text)
            return text.lower() in ("true", "1")
    except ValueError:
        raise ScenarioError(f"{what}: '{text}' is not a {kind}") from None
    return text


class Scope:
    """The parameters visible at one element: its own declarations over its parents'."""

    def __init__(self, values: Mapping[str, Value] | None = None, parent: Scope | None = None) -> None:
        self.values: dict[str, Value] = dict(values or {})
        self.parent = parent

    def all(self) -> dict[str, Value]:
        merged = self.parent.all() if self.parent else {}
        merged.update(self.values)
        return merged

    def declare(
        self,
        declarations: Any,
        path: Path,
        overrides: Mapping[str, Any] | None = None,
        used: set[str] | None = None,
    ) -> Scope:
        """A child scope with `declarations` (a <ParameterDeclarations> element, or None).
        `overrides` (--param) replace declared values, converted to the declared type."""
        scope = Scope(parent=self)
        if declarations is None:
            return scope
        for d in declarations.iterfind("ParameterDeclaration"):
            name = d.get("name", "")
            kind = d.get("parameterType", "string")
            what = f"{where(path, d)} '{name}'"
            if kind not in _TYPES:
                raise ScenarioError(f"{what}: unknown parameterType '{kind}'")
            if overrides is not None and name in overrides:
                raw = overrides[name]
                if used is not None:
                    used.add(name)
                scope.values[name] = convert(
                    str(raw).lower() if isinstance(raw, bool) else str(raw), kind, f"--param {name}"
                )
                continue
            text = d.get("value", "")
            scope.values[name] = convert(str(scope.resolve(text, what)), kind, what)
        return scope

    def resolve(self, text: str, what: str) -> Value:
        """An attribute's value: a `$name` reference, a `${...}` expression, or the text itself."""
        text = text.strip()
        try:
            if text.startswith("${") and text.endswith("}"):
                return evaluate(text[2:-1], self.all())
            if text.startswith("$"):
                name = text[1:]
                values = self.all()
                if name not in values:
                    raise ExpressionError(f"no parameter '{name}' is declared")
                return values[name]
        except ExpressionError as e:
            raise ScenarioError(f"{what}: {e}") from None
        return text


def as_stored(declared: Any, value: Any, what: str) -> Any:
    """`value` as ScenarioParameters keeps a parameter declared as `declared`: text, or a number."""
    if isinstance(declared, str):
        return str(value)
    if isinstance(declared, bool):
        return 1.0 if str(value).lower() in ("true", "1") else 0.0
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ScenarioError(f"{what}: '{value}' is not a number") from None
