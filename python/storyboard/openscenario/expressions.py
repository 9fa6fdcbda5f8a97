"""OpenSCENARIO 1.2 expressions (`${...}`), evaluated over Python's ast with only what the
standard allows: numbers, parameter references (`$name`), + - * / % (and unary -), comparisons,
`and`/`or`/`not`, and round, floor, ceil, sqrt, pow. Anything else is an error, never eval()."""

from __future__ import annotations

import ast
import math
import re
from collections.abc import Callable, Mapping

Value = bool | int | float | str

_FUNCTIONS: dict[str, Callable[..., float]] = {
    "round": lambda x: float(math.floor(x + 0.5)),  # the standard rounds half up
    "floor": lambda x: float(math.floor(x)),
    "ceil": lambda x: float(math.ceil(x)),
    "sqrt": math.sqrt,
    "pow": math.pow,
}

_BINARY: dict[type[ast.operator], Callable[[float, float], float]] = {
    ast.Add: lambda a, b: a + b,
    ast.Sub: lambda a, b: a - b,
    ast.Mult: lambda a, b: a * b,
    ast.Div: lambda a, b: a / b,
    ast.Mod: lambda a, b: math.fmod(a, b),
}

_COMPARE: dict[type[ast.cmpop], Callable[[float, float], bool]] = {
    ast.Eq: lambda a, b: a == b,
    ast.NotEq: lambda a, b: a != b,
    ast.Lt: lambda a, b: a < b,
    ast.LtE: lambda a, b: a <= b,
    ast.Gt: lambda a, b: a > b,
    ast.GtE: lambda a, b: a >= b,
}


class ExpressionError(ValueError):
    """An expression outside the standard's grammar, or one naming an undeclared parameter."""


def evaluate(text: str, parameters: Mapping[str, Value]) -> Value:
    """The value of the expression inside `${...}` (without the braces)."""
    # `$name` becomes a plain name; the standard's `not`, `and`, `or` are Python's own words.
    source = re.sub(r"\$([A-Za-z_][A-Za-z0-9_]*)", r"__p_\1", text)
    try:
        tree = ast.parse(source.strip(), mode="eval")
    except SyntaxError as e:
        raise ExpressionError(f"'{text}' is not an expression: {e.msg}") from None
    return _eval(tree.body, parameters, text)


def _number(value: Value, text: str) -> float:
    if isinstance(value, bool):
        return 1.0 if value else 0.0
    if isinstance(value, int | float):
        return float(value)
    try:
        return float(value)
    except ValueError:
        raise ExpressionError(f"'{text}': '{value}' is not a number") from None


def _eval(node: ast.expr, parameters: Mapping[str, Value], text: str) -> Value:
    if isinstance(node, ast.Constant) and isinstance(node.value, int | float) and not isinstance(node.value, bool):
        return node.value
    if isinstance(node, ast.Name):
        if node.id.startswith("__p_"):
            name = node.id[4:]
            if name not in parameters:
                raise ExpressionError(f"'{text}': no parameter '{name}' is declared")
            return parameters[name]
        if node.id in ("true", "false"):
            return node.id == "true"
        raise ExpressionError(f"'{text}': '{node.id}' is no parameter reference (write ${node.id})")
    if isinstance(node, ast.UnaryOp):
        operand = _eval(node.operand, parameters, text)
        if isinstance(node.op, ast.USub):
            return -_number(operand, text)
        if isinstance(node.op, ast.UAdd):
            return _number(operand, text)
        if isinstance(node.op, ast.Not):
            return not bool(_number(operand, text))
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        a = _number(_eval(node.left, parameters, text), text)
        b = _number(_eval(node.right, parameters, text), text)
        try:
            return _BINARY[type(node.op)](a, b)
        except ZeroDivisionError:
            raise ExpressionError(f"'{text}': division by zero") from None
    if isinstance(node, ast.BoolOp):
        values = [bool(_number(_eval(v, parameters, text), text)) for v in node.values]
        return all(values) if isinstance(node.op, ast.And) else any(values)
    if isinstance(node, ast.Compare) and all(type(op) in _COMPARE for op in node.ops):
        left = _number(_eval(node.left, parameters, text), text)
        for op, right_node in zip(node.ops, node.comparators, strict=True):
            right = _number(_eval(right_node, parameters, text), text)
            if not _COMPARE[type(op)](left, right):
                return False
            left = right
        return True
    if (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id in _FUNCTIONS
        and not node.keywords
    ):
        args = [_number(_eval(a, parameters, text), text) for a in node.args]
        try:
            return _FUNCTIONS[node.func.id](*args)
        except (TypeError, ValueError) as e:
            raise ExpressionError(f"'{text}': {node.func.id}: {e}") from None
    raise ExpressionError(f"'{text}': {ast.unparse(node).replace('__p_', '$')} is not allowed in an expression")
