"""A study's file: the scenario, the seeds and the parameter values, and the runs they make."""

from __future__ import annotations

import hashlib
import itertools
import json
import math
import os
import string
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

#: The most runs a study may make (seeds x parameter values): checked before any run starts.
MAX_RUNS = 100_000

#: A parameter value as sbsim's --param types it.
Value = bool | int | float | str


class StudyError(ValueError):
    """A study file that cannot be run as it is (one line saying what and where)."""


#: The placeholders a study's ``args`` and string parameter values may hold, filled in per run.
PLACEHOLDERS = ("run_dir",)


def check_placeholders(text: str, where: str) -> None:
    """Raises StudyError unless every ``{...}`` in text is a known placeholder (``{{``/``}}``: braces)."""
    shown = json.dumps(text, ensure_ascii=False)  # one line whatever the text holds
    try:
        fields = [(name, spec, conversion) for _, name, spec, conversion in string.Formatter().parse(text)]
    except ValueError as e:
        raise StudyError(f"{where} {shown}: {e} (write {{{{ and }}}} for braces)") from e
    for name, spec, conversion in fields:
        if name is None:
            continue
        if name not in PLACEHOLDERS or spec or conversion:
            field = "{" + name + (f"!{conversion}" if conversion else "") + (f":{spec}" if spec else "") + "}"
            known = ", ".join("{" + p + "}" for p in PLACEHOLDERS)
            raise StudyError(f"{where} {shown}: unknown placeholder {field} (known: {known}; {{{{ and }}}} for braces)")


def fill(text: str, run_dir: Path) -> str:
    """text with its placeholders filled in for one run (checked by check_placeholders first)."""
    return text.format(run_dir=str(run_dir))


def resolve_word(word: str, base: Path) -> str:
    """A word of ``args`` that names an existing file relative to the study file's folder, alone or as the
    value of ``--option=value``, made absolute: runs work in their own folders. Other words (options,
    numbers, outputs that do not exist yet, absolute paths, words with placeholders) stay as written."""
    option, equals, value = word.partition("=") if word.startswith("-") else ("", "", word)
    if not value or value.startswith("-") or "{" in value or Path(value).is_absolute():
        return word
    try:
        path = base / value
        if not path.is_file():
            return word
    except (OSError, ValueError):
        return word
    absolute = str(path.resolve()).replace("{", "{{").replace("}", "}}")  # filled in like any word
    return f"{option}{equals}{absolute}"


@dataclass(frozen=True)
class Run:
    """One run of a study: its parameter values and seed."""

    parameters: tuple[tuple[str, Value], ...]
    seed: int

    @property
    def id(self) -> str:
        """Readable and stable: the values and seed, with a short hash so odd values stay unique;
        ``seed-<n>`` in a study without parameters (seeds are unique already)."""
        if not self.parameters:
            return f"seed-{self.seed}"
        text = json.dumps([list(self.parameters), self.seed])
        readable = "_".join(f"{k}-{v}" for k, v in self.parameters) + f"_seed-{self.seed}"
        safe = "".join(c if c.isalnum() or c in "-_." else "+" for c in readable)[:80]
        return f"{safe}_{hashlib.sha1(text.encode()).hexdigest()[:8]}"

    def arguments(self, run_dir: Path | None = None) -> list[str]:
        """--seed and one --param per parameter; with run_dir, placeholders in string values filled in."""
        out = ["--seed", str(self.seed)]
        for name, value in self.parameters:
            if isinstance(value, bool):
                text = str(value).lower()
            elif isinstance(value, str) and run_dir is not None:
                text = fill(value, run_dir)
            else:
                text = str(value)
            out += ["--param", f"{name}={text}"]
        return out


@dataclass(frozen=True)
class StudySpec:
    sumocfg: Path
    directory: Path
    seeds: tuple[int, ...]
    parameters: dict[str, list[Value]] = field(default_factory=dict)
    story: Path | None = None
    scenario: Path | None = None  # an OpenSCENARIO file (sbsim --scenario), its parameters swept as a story's
    services: Path | None = None
    radio: Path | None = None
    messages: bool = False
    statistics: bool = False
    end: float | None = None
    args: tuple[str, ...] = ()
    plugins: tuple[Path, ...] = ()

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
        known = {
            "sumocfg",
            "story",
            "scenario",
            "services",
            "radio",
            "plugins",
            "seeds",
            "end",
            "args",
            "parameters",
            "outputs",
        }
        for key in data:
            if key not in known:
                raise StudyError(f"{source}: unknown key '{key}' (known: {', '.join(sorted(known))})")
        if "sumocfg" not in data:
            raise StudyError(f"{source}: 'sumocfg' is missing")

        def existing(key: str, name: str) -> Path:
            path = (base / name).resolve()
            if not path.is_file():
                raise StudyError(f"{source}: {key} '{name}': no such file ({path})")
            return path

        def file(key: str) -> Path | None:
            if key not in data:
                return None
            if not isinstance(data[key], str) or not data[key]:
                raise StudyError(f"{source}: '{key}' must be a file name")
            return existing(key, data[key])

        def whole(value: object) -> bool:
            return isinstance(value, int) and not isinstance(value, bool)

        seeds = data.get("seeds", [23423])
        if isinstance(seeds, dict):
            first, count = seeds.get("first", 1), seeds.get("count", 1)
            if not whole(first) or not whole(count) or count < 1:
                raise StudyError(f"{source}: seeds needs whole numbers 'first' and 'count' >= 1")
            if count > MAX_RUNS:
                raise StudyError(f"{source}: seeds.count {count} is more than a study may run ({MAX_RUNS})")
            seeds = list(range(first, first + count))
        if not isinstance(seeds, list) or not seeds or not all(whole(s) for s in seeds):
            raise StudyError(f"{source}: seeds must be a non-empty list of whole numbers or {{ first, count }}")
        if len(set(seeds)) != len(seeds):
            duplicate = next(s for s in seeds if seeds.count(s) > 1)
            raise StudyError(f"{source}: seed {duplicate} is listed twice (the runs would be the same)")
        if any(not 0 <= s < 2**63 for s in seeds):
            raise StudyError(f"{source}: seeds must be from 0 to {2**63 - 1}")
        parameters = data.get("parameters", {})
        if not isinstance(parameters, dict):
            raise StudyError(f"{source}: 'parameters' must be a table of name = [values]")
        runs = len(seeds)
        for name, values in parameters.items():
            if not name.isidentifier():
                raise StudyError(f"{source}: parameter name '{name}' is not a name (letters, digits, _)")
            if not isinstance(values, list) or not values:
                raise StudyError(f"{source}: parameter '{name}' needs a non-empty list of values")
            kinds = {type(v) for v in values}
            if not kinds <= {bool, int, float, str}:
                raise StudyError(f"{source}: parameter '{name}' takes numbers, booleans or strings only")
            if len(kinds - ({int, float} if kinds <= {int, float} else set())) > 1:
                raise StudyError(
                    f"{source}: parameter '{name}' mixes value types ({', '.join(sorted(k.__name__ for k in kinds))})"
                )
            if any(isinstance(v, float) and not math.isfinite(v) for v in values):
                raise StudyError(f"{source}: parameter '{name}' has a value that is not finite")
            for v in values:
                if isinstance(v, str):
                    check_placeholders(v, f"{source}: parameter '{name}'")
            runs *= len(values)
        if runs > MAX_RUNS:
            raise StudyError(f"{source}: the study makes {runs} runs, more than a study may run ({MAX_RUNS})")
        outputs = data.get("outputs", {})
        if not isinstance(outputs, dict) or not isinstance(outputs.get("directory", "results"), str):
            raise StudyError(f"{source}: 'outputs' must be a table with a 'directory' name")
        directory = base / outputs.get("directory", "results")
        messages = outputs.get("messages", False)
        if not isinstance(messages, bool):
            raise StudyError(f"{source}: [outputs] messages must be true or false")
        statistics = outputs.get("statistics", False)
        if not isinstance(statistics, bool):
            raise StudyError(f"{source}: [outputs] statistics must be true or false")
        end = data.get("end")
        if end is not None and (not isinstance(end, int | float) or isinstance(end, bool) or not math.isfinite(end)):
            raise StudyError(f"{source}: 'end' must be a finite number of seconds")
        if end is not None and end <= 0:
            raise StudyError(f"{source}: 'end' must be > 0 seconds")
        args = data.get("args", [])
        if not isinstance(args, list) or not all(isinstance(a, str | int | float) for a in args):
            raise StudyError(f'{source}: \'args\' must be a list of words, e.g. ["--threads", "2"]')
        for a in args:
            check_placeholders(str(a), f"{source}: args")
        plugins = data.get("plugins", [])
        if not isinstance(plugins, list) or not all(isinstance(p, str) and p for p in plugins):
            raise StudyError(f"{source}: 'plugins' must be a list of file names, e.g. [\"build/libmine.so\"]")
        if "sumocfg" in data and not isinstance(data["sumocfg"], str):
            raise StudyError(f"{source}: 'sumocfg' must be a file name")
        if "story" in data and "scenario" in data:
            raise StudyError(f"{source}: 'story' and 'scenario' both given; a run has one or the other")
        if "radio" in data and "services" not in data:
            raise StudyError(f"{source}: 'radio' needs 'services' (the radio carries the services' messages)")
        for name in parameters:
            if name.startswith("radio_") and "radio" not in data:
                raise StudyError(f"{source}: parameter '{name}' sets the channel model, which needs 'radio'")
        return cls(
            sumocfg=file("sumocfg") or Path(),
            directory=directory.resolve(),
            seeds=tuple(seeds),
            parameters={k: list(v) for k, v in parameters.items()},
            story=file("story"),
            scenario=file("scenario"),
            services=file("services"),
            radio=file("radio"),
            messages=messages,
            statistics=statistics,
            end=None if end is None else float(end),
            args=tuple(resolve_word(str(a), base) for a in args),
            plugins=tuple(existing("plugin", p) for p in plugins),
        )

    def runs(self) -> list[Run]:
        """The cartesian product of the parameter values (in the file's order) x the seeds."""
        names = list(self.parameters)
        combos = itertools.product(*(self.parameters[n] for n in names)) if names else [()]
        return [Run(tuple(zip(names, combo, strict=True)), seed) for combo in combos for seed in self.seeds]

    def command(self, run: Run, folder: Path, program: str) -> list[str]:
        """The run's sbsim command line; every path in it absolute (the run works in folder)."""
        cmd = [program, "--sumocfg", str(self.sumocfg), "--events", str(folder / "events.jsonl")]
        cmd += ["--summary", str(folder / "summary.json"), "--quiet"]
        if self.story is not None:
            cmd += ["--story", str(self.story)]
        if self.scenario is not None:
            cmd += ["--scenario", str(self.scenario)]
        if self.services is not None:
            cmd += ["--services", str(self.services)]
        if self.radio is not None:
            cmd += ["--radio", str(self.radio)]
        for plugin in self.plugins:
            cmd += ["--plugin", str(plugin)]
        if self.messages:
            cmd += ["--messages", str(folder / "messages.parquet")]
        if self.statistics:
            cmd += ["--statistics", str(folder / "statistics.parquet")]
        if self.end is not None:
            cmd += ["--end", repr(self.end)]
        return cmd + run.arguments(folder) + [fill(a, folder) for a in self.args]
