"""--param NAME=VALUE: typed values in board.parameters, the summary, unread warnings, bad input."""

from __future__ import annotations

from pathlib import Path

from sbsim.runner import run
from sbsim_helpers import assert_bad_input, assert_no_crash, write_story

READER = """
    import storyboard

    def createStories(board):
        p = board.parameters
        seen = {name: (type(p[name]).__name__, p[name]) for name in p}
        assert seen == {
            "rain_speed": ("int", 10),
            "factor": ("float", 0.8),
            "wet": ("bool", True),
            "label": ("str", "heavy rain"),
        }, seen
        assert "rain_speed" in p and "nope" not in p and len(p) == 4
        assert board.parameter("nope", 7) == 7 and p.get("nope") is None
        try:
            p["nope"]
        except KeyError:
            pass
        else:
            raise AssertionError("a missing parameter must raise KeyError")
        slow = storyboard.SpeedConditionGreater(p["rain_speed"])
        board.registerStory(storyboard.Story(slow, [storyboard.SpeedEffect(5.0)], name="rain"))
"""


def test_parameters_reach_the_story_typed_and_the_summary(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(tmp_path, READER)
    params = ["--param", "rain_speed=10", "--param", "factor=0.8", "--param", "wet=true", "--param", "label=heavy rain"]
    result = run(trips_cfg, story=story, end=30, seed=5, extra=params)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert "seed: 5" in lines
    for line in (
        "parameter factor: 0.8",
        "parameter label: heavy rain",
        "parameter rain_speed: 10",
        "parameter wet: true",
    ):
        assert line in lines, result.stdout
    assert "warning" not in result.stderr, result.stderr


def test_a_parameter_nobody_reads_is_a_warning(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        import storyboard
        def createStories(board):
            board.parameter("used")
            board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [storyboard.SignalEffect("x")]))
        """,
    )
    result = run(trips_cfg, story=story, end=5, extra=["--param", "used=1", "--param", "rian=5"])
    assert result.returncode == 0, result.stderr
    assert result.stderr.strip() == "sbsim: warning: --param rian was never read by the story or a service"


def test_parameters_are_read_only(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(tmp_path, "def createStories(board):\n    board.parameters['x'] = 2\n")
    result = run(trips_cfg, story=story, end=5, extra=["--param", "x=1"])
    assert_no_crash(result)
    assert result.returncode == 2
    assert "story.py:2" in result.stderr and "TypeError" in result.stderr


def test_bad_param_is_bad_input(trips_cfg: Path) -> None:
    assert_bad_input(run(trips_cfg, extra=["--param", "rain"]), "--param", "NAME=VALUE")
    assert_bad_input(run(trips_cfg, extra=["--param", "x=1", "--param", "x=2"]), "--param", "'x' is given twice")


def test_summary_json_has_the_figures_a_table_needs(trips_cfg: Path, tmp_path: Path) -> None:
    from sbsim.runner import read_summary

    story = write_story(tmp_path, READER)
    out = tmp_path / "summary.json"
    params = ["--param", "rain_speed=10", "--param", "factor=0.8", "--param", "wet=true", "--param", "label=heavy rain"]
    result = run(trips_cfg, story=story, end=30, seed=5, extra=[*params, "--summary", str(out)])
    assert result.returncode == 0, result.stderr
    summary = read_summary(out)
    assert summary["seed"] == 5 and summary["steps"] == 30
    assert summary["parameters"] == {"factor": 0.8, "label": "heavy rain", "rain_speed": 10, "wet": True}
    assert summary["end"] == {"time": 30.0, "reason": "end time reached"}
    assert summary["sumo"].startswith("SUMO")
    assert "--summary" in summary["command"]
    (rain,) = summary["stories"]
    text = result.summary()
    assert rain["name"] == "rain" and rain["activations"] == int(text["activations rain"])
    # Vehicle-seconds under the story: at most the active vehicles x the 29 s between the first and last step.
    assert 0 < rain["active_vehicle_seconds"] <= 29 * int(text["peak running"])
    assert not (tmp_path / "summary.json.incomplete").exists()
