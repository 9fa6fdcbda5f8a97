"""Every station on its own clock, from the run's begin (issue "faithful V2X", parts 0 and 2).

A run that starts from a saved state (``--load-state … --begin 60``) must schedule nothing in the
past: it makes the same number of beacons, CAMs and DENM repetitions in a window as the run from
0 s makes in that window (within one per station and timer), instead of firing every period missed
since 0 s at once. And the middlewares' triggers, hence the CAMs, spread over the 100 ms period
rather than all starting at the shared tick.
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest
from sbsim.runner import RunResult, run
from sbsim.scenarios.grid import make_grid
from sbsim_helpers import assert_no_crash

BEGIN, END = 60.0, 90.0
WINDOW = (70.0, 90.0)
SERVICES = """<services>
  <service type="Beacon" interval="0.1" bytes="190"/>
  <service type="artery.application.CaService"/>
  <rsu id="rsu0" x="150" y="150"><service type="RsuDenService" cause="3" area="2000" interval="1"/></rsu>
</services>
"""


@pytest.fixture(scope="module")
def scenario(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path, Path]:
    """A 3 x 3 grid whose 30 vehicles drive loops until the end, its state saved at BEGIN, and the services."""
    folder = tmp_path_factory.mktemp("clocks")
    cfg = make_grid(folder, grid=3, end=END, seed=3, traffic="loops", vehicles=30, ramp=30.0, step_length=0.1)
    state = folder / "state.xml"
    saved = run(
        cfg,
        end=BEGIN + 1,  # SUMO writes the state after the step at BEGIN
        sumo_options=[f"--save-state.times {BEGIN:g}", f"--save-state.files {state}", "--save-state.rng true"],
        timeout=300,
    )
    assert saved.returncode == 0, saved.stderr
    assert state.exists()
    services = folder / "services.xml"
    services.write_text(SERVICES, encoding="utf-8")
    return cfg, state, services


def traced_run(cfg: Path, services: Path, out: Path, *sumo_options: str) -> list[dict]:
    messages = out / "messages.jsonl"
    result: RunResult = run(
        cfg,
        end=END,
        sumo_options=list(sumo_options),
        extra=["--services", str(services), "--messages", str(messages), "--messages-range", "0"],
        timeout=600,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    lines = [json.loads(line) for line in messages.read_text(encoding="utf-8").splitlines()]
    return [line for line in lines if line["event"] == "tx"]


def per_station(sent: list[dict], kind: str, t0: float, t1: float) -> Counter[str]:
    """Each station's own messages of `kind` sent in [t0, t1) (GeoNetworking's forwards left out)."""
    return Counter(
        line["station"] for line in sent if line["type"] == kind and t0 <= line["t"] < t1 and line.get("hops", 1) == 1
    )


@pytest.fixture(scope="module")
def both_runs(scenario: tuple[Path, Path, Path], tmp_path_factory: pytest.TempPathFactory) -> tuple[list, list]:
    cfg, state, services = scenario
    from_zero = traced_run(cfg, services, tmp_path_factory.mktemp("zero"))
    from_state = traced_run(
        cfg, services, tmp_path_factory.mktemp("state"), f"--load-state {state}", f"--begin {BEGIN:g}"
    )
    return from_zero, from_state


def test_a_run_from_a_saved_state_fires_no_missed_period(both_runs: tuple[list, list]) -> None:
    _, from_state = both_runs
    assert min(line["t"] for line in from_state) >= BEGIN
    # 30 vehicles at 10 Hz: at most 2 beacons each in the first 0.2 s (the storm was 600 each).
    first = per_station(from_state, "Beacon", BEGIN, BEGIN + 0.2)
    assert first and max(first.values()) <= 2, first.most_common(3)
    assert sum(per_station(from_state, "DENM", BEGIN, BEGIN + 0.5).values()) <= 1


@pytest.mark.parametrize("kind, tolerance", [("Beacon", 1), ("DENM", 1), ("CAM", 1)])
def test_a_window_holds_as_many_messages_as_in_a_run_from_zero(
    both_runs: tuple[list, list], kind: str, tolerance: int
) -> None:
    from_zero, from_state = both_runs
    zero, state = per_station(from_zero, kind, *WINDOW), per_station(from_state, kind, *WINDOW)
    assert zero, f"no {kind} in the window of the run from 0 s"
    assert set(zero) == set(state)
    if kind == "CAM":
        # CAMs follow the vehicles' dynamics, checked on each station's own phase: the totals agree
        # within one per station, not each station exactly.
        assert abs(sum(zero.values()) - sum(state.values())) <= tolerance * len(zero), (zero, state)
        return
    far = {s: (zero[s], state[s]) for s in zero if abs(zero[s] - state[s]) > tolerance}
    assert not far, far


def test_cams_start_spread_over_the_period(both_runs: tuple[list, list]) -> None:
    from_zero, _ = both_runs
    cams = [line for line in from_zero if line["type"] == "CAM"]
    assert len(cams) > 2000
    # One shared tick put 99.9 % of CAMs within 5 ms of it. Own clocks: each station keeps its own
    # offset in the 100 ms period, the stations' offsets differ, and no 5 ms holds a third of the CAMs.
    offsets = {line["station"]: round(line["t"] * 1e6) % 100_000 for line in cams}
    assert len(set(offsets.values())) == len(offsets) >= 25
    per_station = {(line["station"], round(line["t"] * 1e6) % 100_000) for line in cams}
    assert len(per_station) == len(offsets), "a station's CAMs all start at its own offset"
    busiest = Counter(round(line["t"] * 1e6) % 100_000 // 5_000 for line in cams).most_common(1)[0][1]
    assert busiest < len(cams) / 3, busiest
