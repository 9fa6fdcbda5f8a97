"""A study's file: the scenario, the seeds and the parameter values, and the runs they make."""

from __future__ import annotations

import hashlib
import itertools
import json
import os
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

#: A parameter value as sbsim's --param types it.
Value = bool | int | float | str


class StudyError(ValueError):
    """A study file that cannot be run as it is (one line saying what and where)."""


@dataclass(frozen=True)
class Run:
    """One run of a study: its parameter values and seed."""

    parameters: tuple[tuple[str, Value], ...]
    seed: int

    @property
    def id(self) -> str:
        """Readable and stable: the values and seed, with a short hash so odd values stay unique."""
        text = json.dumps([list(self.parameters), self.seed])
        readable = "_".join(f"{k}-{v}" for k, v in self.parameters) + f"_seed-{self.seed}"
        safe = "".join(c if c.isalnum() or c in "-_." else "+" for c in readable)[:80]
        return f"{safe}_{hashlib.sha1(text.encode()).hexdigest()[:8]}"

    def arguments(self) -> list[str]:
        out = ["--seed", str(self.seed)]
        for name, value in self.parameters:
            out += ["--param", f"{name}={str(value).lower() if isinstance(value, bool) else value}"]
        return out


@dataclass(frozen=True)
class StudySpec:
    sumocfg: Path
    directory: Path
    seeds: tuple[int, ...]
    parameters: dict[str, list[Value]] = field(default_factory=dict)
    story: Path | None = None
    services: Path | None = None
    radio: Path | None = None
    messages: bool = False
    end: float | None = None
    args: tuple[str, ...] = ()

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> StudySpec:
        path = Path(path)
        try:
            data = tomllib.loads(path.read_text(encoding="utf-8"))
        except (OSError, tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
            raise StudyError(f"{path}: {e}") from e
        return cls.from_dict(data, base=path.parent, source=str(path))

    @classmethod
    def from_dict(cls, data: dict[str, Any], base: Path = Path("."), source: str = "study") -> StudySpec:
        known = {"sumocfg", "story", "services", "radio", "seeds", "end", "args", "parameters", "outputs"}
        for key in data:
            if key not in known:
                raise StudyError(f"{source}: unknown key '{key}' (known: {', '.join(sorted(known))})")
        if "sumocfg" not in data:
            raise StudyError(f"{source}: 'sumocfg' is missing")

        def file(key: str) -> Path | None:
            return (base / data[key]).resolve() if key in data else None

        seeds = data.get("seeds", [23423])
        if isinstance(seeds, dict):
            first, count = seeds.get("first", 1), seeds.get("count", 1)
            if not isinstance(first, int) or not isinstance(count, int) or count < 1:
                raise StudyError(f"{source}: seeds needs whole numbers 'first' and 'count' >= 1")
            seeds = list(range(first, first + count))
        if not isinstance(seeds, list) or not seeds or not all(isinstance(s, int) for s in seeds):
            raise StudyError(f"{source}: seeds must be a non-empty list of whole numbers or {{ first, count }}")
        parameters = data.get("parameters", {})
        for name, values in parameters.items():
            if not isinstance(values, list) or not values:
                raise StudyError(f"{source}: parameter '{name}' needs a non-empty list of values")
        outputs = data.get("outputs", {})
        directory = base / outputs.get("directory", "results")
        messages = outputs.get("messages", False)
        if not isinstance(messages, bool):
            raise StudyError(f"{source}: [outputs] messages must be true or false")
        end = data.get("end")
        if end is not None and not isinstance(end, int | float):
            raise StudyError(f"{source}: 'end' must be a number of seconds")
        return cls(
            sumocfg=file("sumocfg") or Path(),
            directory=directory.resolve(),
            seeds=tuple(seeds),
            parameters={k: list(v) for k, v in parameters.items()},
            story=file("story"),
            services=file("services"),
            radio=file("radio"),
            messages=messages,
            end=None if end is None else float(end),
            args=tuple(str(a) for a in data.get("args", [])),
        )

    def runs(self) -> list[Run]:
        """The cartesian product of the parameter values (in the file's order) x the seeds."""
        names = list(self.parameters)
        combos = itertools.product(*(self.parameters[n] for n in names)) if names else [()]
        return [Run(tuple(zip(names, combo, strict=True)), seed) for combo in combos for seed in self.seeds]

    def command(self, run: Run, folder: Path, program: str) -> list[str]:
        cmd = [program, "--sumocfg", str(self.sumocfg), "--events", str(folder / "events.jsonl")]
        cmd += ["--summary", str(folder / "summary.json"), "--quiet"]
        if self.story is not None:
            cmd += ["--story", str(self.story)]
        if self.services is not None:
            cmd += ["--services", str(self.services)]
        if self.radio is not None:
            cmd += ["--radio", str(self.radio)]
        if self.messages:
            cmd += ["--messages", str(folder / "messages.jsonl")]
        if self.end is not None:
            cmd += ["--end", repr(self.end)]
        return cmd + run.arguments() + list(self.args)
