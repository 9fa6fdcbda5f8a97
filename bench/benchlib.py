"""Shared pieces of the benchmarks: scenario cache, timed runs, medians and tables."""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from sbsim.scenarios.grid import make_preset
from sbsim.sumo import sumo_binary

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "bench" / "out"


def scenario(preset: str) -> Path:
    """The preset's .sumocfg, generated once into bench/out/<preset>/."""
    folder = OUT / preset
    cfg = folder / f"{preset}.sumocfg"
    if not cfg.exists():
        print(f"generating {preset} scenario in {folder} ...", flush=True)
        make_preset(folder, preset)
    return cfg


def saved_state(preset: str, at: float) -> Path:
    """A SUMO state of the preset at `at` s, saved once into bench/out/<preset>/ by plain `sumo` at the
    preset's own step (a run may load it with another --step-length)."""
    cfg = scenario(preset)
    state = cfg.parent / f"state{at:g}.xml.gz"
    if not state.exists():
        print(f"saving {preset}'s state at {at:g} s ...", flush=True)
        subprocess.run(
            [sumo(), "-c", str(cfg), "--end", repr(at + 1), "--save-state.times", repr(at)]
            + ["--save-state.files", str(state)],
            check=True,
            stdout=subprocess.DEVNULL,
        )
    return state


@dataclass(frozen=True)
class Window:
    """Which part of a preset's run a benchmark runs: `end` s from 0, or `end` s from a state saved
    at `state_at`; optionally with SUMO's step set to `step` s."""

    preset: str
    end: float
    step: float | None = None
    state_at: float | None = None

    def sumo_options(self) -> list[str]:
        """SUMO's options for the window, besides -c and --end (which end_time() gives)."""
        out = [] if self.step is None else ["--step-length", repr(self.step)]
        if self.state_at is not None:
            out += ["--load-state", str(saved_state(self.preset, self.state_at)), "--begin", repr(self.state_at)]
        return out

    def end_time(self) -> float:
        return self.end + (self.state_at or 0.0)

    def sumo_command(self) -> list[str]:
        return [sumo(), "-c", str(scenario(self.preset)), "--end", repr(self.end_time()), *self.sumo_options()]

    def sbsim_command(self, exe: str, *options: str) -> list[str]:
        """exe over the window with sbsim's `options`; SUMO's own come after `--`."""
        cmd = [exe, "--sumocfg", str(scenario(self.preset)), "--end", repr(self.end_time()), *options]
        return cmd + (["--", *self.sumo_options()] if self.sumo_options() else [])

    def describe(self) -> str:
        start = f"from a state at {self.state_at:g} s" if self.state_at is not None else "from 0 s"
        step = f", step {self.step:g} s" if self.step is not None else ""
        return f"{self.preset}, {self.end:g} s simulated {start}{step}"


def sumo() -> str:
    return str(sumo_binary("sumo"))


def sbsim() -> str:
    """The installed program (run ./sbsim once to build it), or $SBSIM_EXECUTABLE."""
    override = os.environ.get("SBSIM_EXECUTABLE")
    if override:
        return override
    candidate = Path(sys.prefix) / "bin" / "sbsim"
    if not candidate.exists():
        sys.exit("sbsim is not installed in this Python's environment: run ./sbsim once first")
    return str(candidate)


@dataclass(frozen=True)
class Run:
    wall: float  # seconds
    cpu: float  # user + system seconds of the process
    rss_mb: float  # peak resident memory
    stdout: str


def timed(cmd: Sequence[str]) -> Run:
    """Runs cmd to completion; os.wait4 gives this child's own CPU time and peak memory."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        start = time.perf_counter()
        proc = subprocess.Popen(cmd, stdout=out, stderr=err, text=True)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        if proc.returncode != 0:
            sys.exit(f"command failed ({proc.returncode}): {' '.join(cmd)}\n{err.read()[-2000:]}")
        return Run(wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0, out.read())


def alternate(commands: dict[str, Sequence[str]], runs: int) -> dict[str, list[Run]]:
    """Runs each command `runs` times, interleaved (A B C A B C ...), so drift hits all alike."""
    results: dict[str, list[Run]] = {name: [] for name in commands}
    for i in range(runs):
        for name, cmd in commands.items():
            r = timed(cmd)
            results[name].append(r)
            print(f"  run {i + 1}/{runs} {name:<28} wall {r.wall:7.2f} s  cpu {r.cpu:7.2f} s", flush=True)
    return results


def median(values: Sequence[float]) -> float:
    return statistics.median(values)


def mean_se(values: Sequence[float]) -> tuple[float, float]:
    """The mean and its standard error (sample sd / √n; NaN for fewer than two values)."""
    m = statistics.fmean(values)
    return m, statistics.stdev(values) / len(values) ** 0.5 if len(values) > 1 else float("nan")


def paired_ratio(results: dict[str, list[Run]], name: str, base: str = "sumo") -> tuple[float, float, float]:
    """Median, min and max over rounds of name's wall time / base's in the same round: interleaved
    runs share the machine's drift, so a ratio per round is steadier than a ratio of medians."""
    ratios = [a.wall / b.wall for a, b in zip(results[name], results[base], strict=True)]
    return statistics.median(ratios), min(ratios), max(ratios)


# Allocators a command can run with instead of glibc's (LD_PRELOAD: the same effect as linking
# them, for every library of the process); Debian's libjemalloc2 and libmimalloc2.0.
PRELOADS = {"jemalloc": "libjemalloc.so.2", "mimalloc": "libmimalloc.so.2"}


def preloaded(allocator: str, cmd: Sequence[str]) -> list[str]:
    """cmd run with `allocator` (a PRELOADS key) preloaded."""
    for folder in (Path("/usr/lib/x86_64-linux-gnu"), Path("/usr/lib/aarch64-linux-gnu"), Path("/usr/lib")):
        library = folder / PRELOADS[allocator]
        if library.exists():
            return ["env", f"LD_PRELOAD={library}", *cmd]
    sys.exit(f"{PRELOADS[allocator]} not found (Debian: apt-get install lib{allocator}2*)")


def summary_value(stdout: str, key: str) -> float:
    """A number from sbsim's summary line `key: <number> ...`."""
    for line in stdout.splitlines():
        if line.startswith(key + ":"):
            return float(line.split(":", 1)[1].split()[0])
    raise KeyError(key)
