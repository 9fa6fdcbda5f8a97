"""Bad story scripts: exit code 2 with the Python traceback or a line naming the script file and line."""

from __future__ import annotations

from pathlib import Path

import pytest
from sbsim.runner import RunResult, run
from sbsim_helpers import assert_no_crash, write_story


def _run(cfg: Path, tmp_path: Path, source: str, end: float = 60) -> tuple[RunResult, Path]:
    story = write_story(tmp_path, source)
    result = run(cfg, story=story, events=tmp_path / "ev.jsonl", end=end, timeout=120)
    assert_no_crash(result)
    return result, story


def _line_of(story: Path, marker: str) -> int:
    for number, line in enumerate(story.read_text().splitlines(), start=1):
        if marker in line:
            return number
    raise AssertionError(f"{marker!r} not in {story}")


def assert_story_error(result: RunResult, story: Path, marker: str | None, *needles: str) -> str:
    """Exit 2; stderr names the script (and the line holding ``marker``) and every needle; returns stderr."""
    assert result.returncode == 2, f"exit {result.returncode}\nstdout:\n{result.stdout}\nstderr:\n{result.stderr}"
    where = str(story) if marker is None else f"{story}:{_line_of(story, marker)}"
    assert where in result.stderr, f"{where!r} not in stderr:\n{result.stderr}"
    for needle in needles:
        assert needle in result.stderr, f"{needle!r} not in stderr:\n{result.stderr}"
    last = result.stderr.strip().splitlines()[-1]
    assert last.startswith("sbsim") and str(story) in last, f"the last line should name the script: {last!r}"
    return result.stderr


def test_syntax_error(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        import storyboard
        def createStories(board):
            board.registerStory(storyboard.Story(storyboard.TimeCondition(1), []))
        x = = 1
    """,
    )
    assert_story_error(result, story, "x = = 1", "SyntaxError")


def test_missing_create_stories(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        import storyboard
        def create_story(board):
            pass
    """,
    )
    assert_story_error(result, story, None, "createStories")


def test_exception_inside_create_stories(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        import storyboard

        def helper():
            raise RuntimeError("no rain today")  # MARK

        def createStories(board):
            helper()
    """,
    )
    err = assert_story_error(result, story, "# MARK", "RuntimeError", "no rain today")
    assert "Traceback" in err


def test_exception_at_import_time(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        import storyboard
        import no_such_module_for_sbsim  # MARK
        def createStories(board):
            pass
    """,
    )
    assert_story_error(result, story, "# MARK", "no_such_module_for_sbsim")


def test_exception_inside_a_custom_condition_during_the_run(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        import storyboard

        class Picky(storyboard.Condition):
            def test(self, vehicle):
                if vehicle.time >= 20:
                    raise KeyError("no such lane")  # MARK
                return False

        def createStories(board):
            board.registerStory(storyboard.Story(Picky(), [], "picky"))
    """,
    )
    assert_story_error(result, story, "# MARK", "KeyError", "no such lane")


def test_exception_inside_a_vectorised_condition(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        import storyboard

        class Broken(storyboard.Condition):
            def test_all(self, snapshot):
                return snapshot.speeds / 0 > snapshot.no_such_column  # MARK

        def createStories(board):
            board.registerStory(storyboard.Story(Broken(), []))
    """,
    )
    assert_story_error(result, story, "# MARK", "AttributeError", "no_such_column")


BAD_CUSTOM_CLASSES = {
    "test_returns_an_int": ("Condition", "def test(self, vehicle):\n        return 1"),
    "test_returns_a_str": ("Condition", "def test(self, vehicle):\n        return 'veh1'"),
    "test_returns_a_list_of_ints": ("Condition", "def test(self, vehicle):\n        return [1]"),
    "test_all_wrong_length": (
        "Condition",
        "def test_all(self, snapshot):\n        return np.ones(len(snapshot) + 1, bool)",
    ),
    "test_all_returns_none": ("Condition", "def test_all(self, snapshot):\n        return None"),
    "condition_without_test": ("Condition", "pass"),
    "effect_without_apply": ("Effect", "def remove(self, vehicle):\n        pass"),
}


@pytest.mark.parametrize("case", sorted(BAD_CUSTOM_CLASSES))
def test_custom_class_breaking_the_contract_names_the_script(trips_cfg: Path, tmp_path: Path, case: str) -> None:
    base, body = BAD_CUSTOM_CLASSES[case]
    condition, effects = ("Bad()", "[]") if base == "Condition" else ("storyboard.CarSetCondition('veh1')", "[Bad()]")
    source = (
        "import numpy as np\nimport storyboard\n\n"
        f"class Bad(storyboard.{base}):\n    {body}\n\n"
        "def createStories(board):\n"
        f"    board.registerStory(storyboard.Story({condition}, {effects}, 'bad'))\n"
    )
    story = tmp_path / "story.py"
    story.write_text(source)
    result = run(trips_cfg, story=story, end=30, timeout=120)
    assert_no_crash(result)
    assert result.returncode == 2, f"exit {result.returncode}: {result.stderr}"
    assert str(story) in result.stderr, result.stderr
    assert "Bad" in result.stderr, result.stderr


def test_exception_inside_a_custom_effect(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        import storyboard

        class Flaky(storyboard.Effect):
            def apply(self, vehicle):
                raise ValueError("cannot apply to " + vehicle.id)  # MARK
            def remove(self, vehicle):
                pass

        def createStories(board):
            board.registerStory(storyboard.Story(storyboard.CarSetCondition("veh3"), [Flaky()], "flaky"))
    """,
    )
    assert_story_error(result, story, "# MARK", "ValueError", "cannot apply to veh3")


@pytest.mark.parametrize(
    ("statement", "needle"),
    [
        ('storyboard.SpeedEffect("fast")  # MARK', "fast"),
        ("storyboard.SpeedEffect(-3)  # MARK", "SpeedEffect"),
        ("storyboard.PolygonCondition([(0, 0), (100, 100)])  # MARK", "3"),
        ("storyboard.LimitCondition(-1)  # MARK", "-1"),
        ("storyboard.LimitCondition(2.5)  # MARK", "LimitCondition"),
        ("storyboard.TimeCondition(20, 10)  # MARK", "TimeCondition"),
        ('storyboard.TimeCondition("soon")  # MARK', "soon"),
        ("storyboard.TtcCondition(0)  # MARK", "ttc"),
        ("storyboard.Story(None, [])  # MARK", "None"),
        ('storyboard.Story(storyboard.TimeCondition(1), ["fast"])  # MARK', "fast"),
        ("storyboard.CarSetCondition([1, 2])  # MARK", "1"),
        ("storyboard.DeferringCondition(board.getRandomNumberGenerator(), 10, 5)  # MARK", "DeferringCondition"),
        ("storyboard.PolygonCondition([(0, 0), (100, 0), (0, 100, 5)])  # MARK", "polygon"),
    ],
)
def test_bad_arguments_name_the_line(trips_cfg: Path, tmp_path: Path, statement: str, needle: str) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        f"""
        import storyboard

        def createStories(board):
            x = {statement}
            board.registerStory(storyboard.Story(storyboard.TimeCondition(1), []))
    """,
    )
    assert_story_error(result, story, "# MARK", needle)


def test_register_story_with_none(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        def createStories(board):
            board.registerStory(None)  # MARK
    """,
    )
    assert_story_error(result, story, "# MARK")


def test_no_story_registered_warns_and_runs(trips_cfg: Path, tmp_path: Path) -> None:
    result, story = _run(
        trips_cfg,
        tmp_path,
        """
        import storyboard
        def createStories(board):
            pass
    """,
        end=30,
    )
    assert result.returncode == 0, result.stderr
    assert "warning" in result.stderr and str(story) in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1, result.stderr
    summary = result.summary()
    assert summary["steps"] == "30"
    assert not [k for k in summary if k.startswith("activations")]
    assert (tmp_path / "ev.jsonl").read_text() == ""


def test_create_stories_with_and_without_the_board_parameter(trips_cfg: Path, tmp_path: Path) -> None:
    for i, signature in enumerate(["createStories(board)", "createStories()", "createStories(b=None)"]):
        d = tmp_path / str(i)
        d.mkdir()
        result, _ = _run(
            trips_cfg,
            d,
            f"""
            import storyboard
            def {signature}:
                board.registerStory(storyboard.Story(storyboard.CarSetCondition("veh1"), [], "one"))
        """,
            end=30,
        )
        assert result.returncode == 0, f"{signature}: {result.stderr}"
        assert result.summary()["activations one"] == "1", signature
