"""OpenSCENARIO 1.2 expressions (`${...}`) and parameter references, evaluated without eval()."""

from __future__ import annotations

import re

import pytest
from storyboard.openscenario.errors import ScenarioError
from storyboard.openscenario.expressions import ExpressionError, evaluate
from storyboard.openscenario.parameters import Scope, convert


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("1 + 2 * 3", 7),
        ("(1 + 2) * 3", 9),
        ("-$a / 4", -2.5),
        ("$a % 4", 2.0),
        ("round(2.5) + round(-2.5)", 1.0),  # half up: 3 + (-2)
        ("floor(1.7) + ceil(1.2)", 3.0),
        ("sqrt(16) + pow(2, 3)", 12.0),
        ("$a > 5 and not $b", False),
        ("$a < 5 or $b", True),
        ("1 < $a <= 10", True),
        ("$a == 10", True),
        ("$a != 10", False),
    ],
)
def test_the_standards_grammar(text: str, expected: object) -> None:
    assert evaluate(text, {"a": 10, "b": True}) == expected


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("__import__('os')", "is not allowed"),
        ("$a.real", "is not allowed"),
        ("[1, 2]", "is not allowed"),
        ("abs(-1)", "is not allowed"),
        ("$nope + 1", "no parameter 'nope' is declared"),
        ("a + 1", "write $a"),
        ("1 / 0", "division by zero"),
        ("1 +", "is not an expression"),
        ("sqrt(-1)", "sqrt"),
        ("$s * 2", "'text' is not a number"),
    ],
)
def test_anything_else_is_an_error(text: str, message: str) -> None:
    with pytest.raises(ExpressionError, match=re.escape(message)):
        evaluate(text, {"a": 1, "s": "text"})


def test_references_and_declared_types() -> None:
    scope = Scope({"speed": 20.0, "name": "ego"})
    assert scope.resolve("$speed", "here") == 20.0
    assert scope.resolve("${$speed * 1.5}", "here") == 30.0
    assert scope.resolve("plain", "here") == "plain"
    with pytest.raises(ScenarioError, match="here: no parameter 'nope' is declared"):
        scope.resolve("$nope", "here")
    assert convert("3", "integer", "x") == 3
    assert convert("true", "boolean", "x") is True
    with pytest.raises(ScenarioError, match="x: '2.5' is not a integer"):
        convert("2.5", "integer", "x")
    with pytest.raises(ScenarioError, match="x: '-1' is not a unsignedInt"):
        convert("-1", "unsignedInt", "x")
