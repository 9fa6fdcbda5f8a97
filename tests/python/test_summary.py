"""sbsim.summary: the --summary JSON read once, its figures as the report and a study use them, checked
against the same run's text summary on stdout."""

from __future__ import annotations

from pathlib import Path

import pytest
from sbsim.runner import run
from sbsim.summary import SummaryError, end_time, read_summary, run_figures, story_figures, table_columns
from sbsim_helpers import write_story

STORY = """
    import storyboard

    def createStories(board):
        fast = storyboard.SpeedConditionGreater(8.0)
        board.registerStory(storyboard.Story(fast, [storyboard.SignalEffect("fast")], name="fast"))
        never = storyboard.SpeedConditionGreater(1000.0)
        board.registerStory(storyboard.Story(never, [storyboard.SpeedEffect(4.0)], name="never"))
"""


def test_figures_agree_with_the_text_summary(trips_cfg: Path, tmp_path: Path) -> None:
    out = tmp_path / "summary.json"
    result = run(trips_cfg, story=write_story(tmp_path, STORY), end=60, seed=3, extra=["--summary", str(out)])
    assert result.returncode == 0, result.stderr
    text = result.summary()
    summary = read_summary(out)

    stories = story_figures(summary)
    assert list(stories) == ["fast", "never"]  # registration order
    assert stories["fast"].activations == int(text["activations fast"]) > 0
    assert stories["never"].activations == 0 and stories["never"].active_vehicle_seconds == 0
    assert end_time(summary) == 60.0 and text["end"] == "60 s (end time reached)"

    row = table_columns(summary)
    assert row["steps"] == int(text["steps"]) == 60
    assert row["vehicles_seen"] == int(text["vehicles seen"])
    assert row["peak_running"] == int(text["peak running"])
    assert row["end_reason"] == "end time reached"
    assert row["activations:fast"] == stories["fast"].activations
    assert row["active_vehicle_s:fast"] == stories["fast"].active_vehicle_seconds > 0
    # Every activation of "fast" signals once.
    assert row["signals:fast"] == stories["fast"].activations
    assert row["sumo_s"] > 0 and row["storyboard_s"] >= 0

    figures = run_figures(summary)
    assert list(figures)[:3] == ["sumocfg", "SUMO", "seed"] and figures["seed"] == 3
    assert figures["end"] == {"time": 60.0, "reason": "end time reached"}


def test_without_a_usable_story_list_there_are_no_story_figures() -> None:
    assert story_figures(None) == {} and end_time(None) is None
    assert story_figures({"stories": "rain"}) == {}
    assert list(story_figures({"stories": [{"activations": 3}, {"name": "rain"}]})) == ["rain"]
    assert story_figures({"stories": [{"name": "rain"}]})["rain"].activations is None
    assert end_time({"end": {"time": True}}) is None


@pytest.mark.parametrize(
    ("content", "message"),
    [
        (b'{\n"steps": 3,\n}\n', r"s\.json:3: bad JSON"),
        (b"[1, 2]", r"s\.json: not an sbsim summary \(not a JSON object\)"),
        (b'{"sumocfg": "r\xe9gen"}', r"s\.json: not UTF-8 text"),
    ],
)
def test_a_file_that_is_not_a_summary_is_one_error_naming_it(tmp_path: Path, content: bytes, message: str) -> None:
    path = tmp_path / "s.json"
    path.write_bytes(content)
    with pytest.raises(SummaryError, match=message):
        read_summary(path)
