"""Who is V2X-equipped, visible on real runs: the event log's equipped lines, the summary (text and JSON),
the statistics file's equipped column, EquippedCondition and the criteria's equipped_only.

The equipped vehicles are seen from sides that share nothing but the penetration draw: the services the
manager created (one per equipped vehicle), the event log's equipped lines, the summary's list, the
activations of a story on EquippedCondition, and the rows board.record marks.
"""

from __future__ import annotations

import math
from pathlib import Path

import pandas as pd
from sbsim.runner import read_events, read_summary, run
from sbsim_helpers import write_story

#: A service the manager gives every equipped vehicle (the default filter: equipped ones only).
SERVICES = """<?xml version="1.0"?>
<services>
    <service type="ClearLaneService"/>
</services>
"""

#: A story on EquippedCondition; every vehicle records a value as it activates "all", and one value has no vehicle.
STORY = """
    import storyboard

    class Mark(storyboard.Effect):
        def __init__(self, board):
            super().__init__()
            self.board = board

        def apply(self, vehicle):
            self.board.record("departed", 1.0, vehicle=vehicle.id, story="all")

        def remove(self, vehicle):
            pass

    def createStories(board):
        board.registerStory(storyboard.Story(storyboard.EquippedCondition(), [storyboard.SignalEffect("eq")],
                                             name="equipped"))
        board.registerStory(storyboard.Story(storyboard.TimeCondition(0), [Mark(board)], name="all"))
        board.record("no_vehicle", 3.0)
"""


def services_file(directory: Path) -> Path:
    path = directory / "services.xml"
    path.write_text(SERVICES, encoding="utf-8")
    return path


def test_the_event_log_summary_statistics_and_condition_agree_on_who_is_equipped(
    trips_cfg: Path, tmp_path: Path
) -> None:
    story = write_story(tmp_path, STORY)
    events, summary_path, stats = tmp_path / "events.jsonl", tmp_path / "summary.json", tmp_path / "stats.parquet"
    extra = ["--services", str(services_file(tmp_path)), "--penetration", "0.5", "--summary", str(summary_path)]
    extra += ["--statistics", str(stats)]
    result = run(trips_cfg, story=story, events=events, end=120, seed=3, extra=extra)
    assert result.returncode == 0, result.stderr
    lines = read_events(events)
    summary = read_summary(summary_path)

    # The event log: one equipped line per equipped vehicle, of no story.
    logged = {e["vehicle"]: e["t"] for e in lines if e["type"] == "equipped"}
    assert all(e["story"] is None for e in lines if e["type"] == "equipped")
    assert len(logged) == sum(e["type"] == "equipped" for e in lines), "one line per vehicle"
    seen = summary["vehicles_seen"]
    assert 0.3 * seen < len(logged) < 0.7 * seen, (len(logged), seen)
    # The services the manager created: one per equipped vehicle.
    assert summary["services_created"] == len(logged)

    # EquippedCondition holds for exactly those vehicles, from the step they departed (their equipped time).
    first = {}
    for e in lines:
        if e["type"] == "activate" and e["story"] == "equipped":
            first.setdefault(e["vehicle"], e["t"])
    assert first == logged
    departed = {}
    for e in lines:
        if e["type"] == "activate" and e["story"] == "all":
            departed.setdefault(e["vehicle"], e["t"])
    assert set(departed) > set(logged)
    assert all(departed[v] == t for v, t in logged.items())
    # An equipped line comes before anything else the log says of its vehicle.
    order = [(e["type"], e["vehicle"]) for e in lines]
    assert all(order.index(("equipped", v)) < order.index(("activate", v)) for v in logged)

    # The summary names them, in the order they became equipped, with when.
    equipped = summary["equipped"]
    assert equipped["penetration"] == 0.5 and equipped["of"] == seen and equipped["count"] == len(logged)
    assert [(e["vehicle"], e["since"]) for e in equipped["vehicles"]] == list(logged.items())
    # The text summary counts them and names the first ten.
    line = result.summary()["equipped vehicles"]
    assert line.startswith(f"{len(logged)} of {seen} (penetration 0.5): "), line
    first_vehicle, first_time = next(iter(logged.items()))
    assert f"{first_vehicle} at t={first_time:g} s" in line
    assert line.endswith(f" and {len(logged) - 10} more"), line

    # The statistics file marks each row's vehicle: equipped or not, null for a value of no vehicle.
    table = pd.read_parquet(stats)
    assert list(table.columns) == ["vehicle", "source", "name", "time", "value", "equipped"]
    rows = table[table["name"] == "departed"]
    assert set(rows["vehicle"]) == set(departed)
    assert {v for v, e in zip(rows["vehicle"], rows["equipped"], strict=True) if e} == set(logged)
    assert rows["equipped"].notna().all()
    [alone] = table[table["name"] == "no_vehicle"]["equipped"].to_list()
    assert alone is None or (isinstance(alone, float) and math.isnan(alone))


def test_a_run_without_services_logs_and_summarises_no_equipment(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(tmp_path, STORY)
    events, summary_path = tmp_path / "events.jsonl", tmp_path / "summary.json"
    result = run(trips_cfg, story=story, events=events, end=30, seed=3, extra=["--summary", str(summary_path)])
    assert result.returncode == 0, result.stderr
    lines = read_events(events)
    assert not any(e["type"] == "equipped" for e in lines)
    assert "equipped" not in read_summary(summary_path)
    assert "equipped vehicles" not in result.summary()
    # Everyone is equipped at the default penetration of 1: EquippedCondition holds for every vehicle.
    assert {e["vehicle"] for e in lines if e["story"] == "equipped"} == {e["vehicle"] for e in lines}


CRITERIA = """
    import storyboard

    def createStories(board):
        board.registerCriterion(storyboard.MaxSpeed(0.5, equipped_only=True), name="equipped")
        board.registerCriterion(storyboard.MaxSpeed(0.5), name="everyone")
"""


def criteria(cfg: Path, directory: Path, penetration: str) -> tuple[dict[str, dict[str, object]], set[str]]:
    """The criteria's entries of the summary by name, and the equipped vehicles of the event log."""
    story = write_story(directory, CRITERIA, name=f"criteria{penetration}.py")
    events, summary = directory / f"{penetration}.jsonl", directory / f"{penetration}.json"
    extra = ["--services", str(services_file(directory)), "--penetration", penetration, "--summary", str(summary)]
    result = run(cfg, story=story, events=events, end=60, seed=3, quiet=True, extra=extra)
    assert result.returncode == 3, result.stderr  # "everyone" fails: vehicles drive faster than 0.5 m/s
    verdicts = {c["name"]: c for c in read_summary(summary)["criteria"]}
    return verdicts, {e["vehicle"] for e in read_events(events) if e["type"] == "equipped"}


def test_equipped_only_criteria_judge_only_the_equipped(trips_cfg: Path, tmp_path: Path) -> None:
    nobody, equipped = criteria(trips_cfg, tmp_path, "0")
    assert not equipped
    assert nobody["equipped"]["passed"] is True and nobody["equipped"]["actual"] == "no vehicle seen"
    assert nobody["everyone"]["passed"] is False
    half, equipped = criteria(trips_cfg, tmp_path, "0.5")
    assert half["equipped"]["passed"] is False
    # The fastest equipped vehicle is named: one of those the log says are equipped.
    named = str(half["equipped"]["actual"]).split("(")[1].split(" at ")[0]
    assert named in equipped, (named, sorted(equipped)[:5])


def test_equipped_only_must_be_a_bool(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        import storyboard

        def createStories(board):
            board.registerCriterion(storyboard.WarnedBefore("a", equipped_only="yes"))
        """,
    )
    result = run(trips_cfg, story=story, end=5)
    assert result.returncode == 2, result.stderr
    # The story's error: its traceback, then one line naming the script's line and what is wrong.
    last = result.stderr.strip().splitlines()[-1]
    assert last.startswith(f"sbsim: {story}:5: TypeError: WarnedBefore equipped_only must be True or False"), last
    assert "'yes'" in last
