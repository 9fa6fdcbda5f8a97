"""The type stubs (python/storyboard/__init__.pyi) against the compiled module: every public name of
``_sbsim`` and every public member of its classes is typed in the stub, and the stub types nothing the
module lacks. A binding added without a stub (or a stub left behind by a removed binding) fails here."""

from __future__ import annotations

import ast
import json
from pathlib import Path

from sbsim.runner import run
from sbsim_helpers import REPO, write_story

STUB = REPO / "python" / "storyboard" / "__init__.pyi"
PACKAGE = REPO / "python" / "storyboard" / "__init__.py"

#: Operator and protocol methods a class may define that the stub must type too (object's own are left out).
TYPED_DUNDERS = {
    "__add__",
    "__radd__",
    "__sub__",
    "__rsub__",
    "__lt__",
    "__le__",
    "__gt__",
    "__ge__",
    "__float__",
    "__len__",
    "__iter__",
    "__contains__",
    "__getitem__",
    "__bool__",
}

INTROSPECT = """
import json

import _sbsim

TYPED_DUNDERS = {dunders!r}


def members(cls):
    names = set()
    for klass in cls.__mro__:
        # Python's own bases (object, the exceptions' BaseException...) are typed by typeshed.
        if klass.__module__ in ("builtins", "pybind11_builtins"):
            continue
        names |= {{n for n in vars(klass) if not n.startswith("_") or n in TYPED_DUNDERS}}
    return sorted(names)


def createStories(board):
    out = {{}}
    for name in dir(_sbsim):
        if name.startswith("_"):
            continue
        value = getattr(_sbsim, name)
        if isinstance(value, type):
            kind = "alias" if value.__name__ != name else "class"
            out[name] = {{"kind": kind, "of": value.__name__, "members": members(value)}}
        else:
            out[name] = {{"kind": "function" if callable(value) else "value"}}
    with open({dump!r}, "w") as f:
        json.dump(out, f)
"""


def module_api(tmp_path: Path, cfg: Path) -> dict[str, dict[str, object]]:
    dump = tmp_path / "api.json"
    story = write_story(tmp_path, INTROSPECT.format(dunders=sorted(TYPED_DUNDERS), dump=str(dump)))
    result = run(cfg, story=story, end=1.0, quiet=True)
    assert result.returncode == 0, result.stderr
    return json.loads(dump.read_text(encoding="utf-8"))


def stub_api() -> tuple[dict[str, set[str]], dict[str, str], set[str]]:
    """Classes (with their typed members), aliases (name -> target) and functions of the stub."""
    tree = ast.parse(STUB.read_text(encoding="utf-8"))
    classes: dict[str, set[str]] = {}
    aliases: dict[str, str] = {}
    functions: set[str] = set()
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            members: set[str] = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    members.add(item.name)
                elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
                    members.add(item.target.id)
            classes[node.name] = {m for m in members if not m.startswith("_") or m in TYPED_DUNDERS}
        elif isinstance(node, ast.Assign) and isinstance(node.value, ast.Name):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    aliases[target.id] = node.value.id
        elif isinstance(node, ast.FunctionDef):
            functions.add(node.name)
    return classes, aliases, functions


def inherited(classes: dict[str, set[str]], name: str) -> set[str]:
    """A stub class's members with those of its stub bases (Condition, Effect)."""
    tree = ast.parse(STUB.read_text(encoding="utf-8"))
    bases = {
        node.name: [b.id for b in node.bases if isinstance(b, ast.Name)]
        for node in tree.body
        if isinstance(node, ast.ClassDef)
    }
    out = set(classes[name])
    for base in bases.get(name, []):
        if base in classes:
            out |= inherited(classes, base)
    return out


def python_helpers() -> set[str]:
    """Names the package defines in Python itself (helpers such as all_of), typed in the stub as well."""
    tree = ast.parse(PACKAGE.read_text(encoding="utf-8"))
    return {node.name for node in tree.body if isinstance(node, ast.FunctionDef) and not node.name.startswith("_")}


def test_stub_matches_the_compiled_module(tmp_path: Path, loops_cfg: Path) -> None:
    module = module_api(tmp_path, loops_cfg)
    classes, aliases, functions = stub_api()
    assert len(module) > 20, "the introspection saw the story API"

    missing = sorted(name for name in module if name not in classes and name not in aliases and name not in functions)
    assert not missing, f"bound in C++ but not typed in {STUB.name}: {missing}"

    for name, info in module.items():
        if info["kind"] == "class":
            assert name in classes, f"{name} is a class in the module but not in the stub"
            typed = inherited(classes, name)
            bound = set(info["members"])  # type: ignore[arg-type]
            assert bound <= typed, f"{name}: members bound but not typed: {sorted(bound - typed)}"
            assert typed <= bound, f"{name}: members typed but not bound: {sorted(typed - bound)}"
        elif info["kind"] == "alias":
            assert aliases.get(name) == info["of"], f"{name} is an alias of {info['of']} in the module"

    helpers = python_helpers()
    stale = sorted(
        name
        for name in [*classes, *aliases, *functions]
        if not name.startswith("_") and name not in module and name not in helpers and name not in {"Seconds", "Point"}
    )
    assert not stale, f"typed in {STUB.name} but neither bound in C++ nor defined in __init__.py: {stale}"
