"""Reliability promises the corpus cannot express: a reader that goes away, the summary's lines."""

from __future__ import annotations

import subprocess
from pathlib import Path

from sbsim.runner import executable
from sbsim_helpers import write_story


def test_stdout_reader_gone_is_not_a_failure(trips_cfg: Path) -> None:
    """``sbsim ... | true``: the summary has no reader; the run still ends with 0, not 141 (SIGPIPE)."""
    proc = subprocess.Popen(
        [str(executable()), "--sumocfg", str(trips_cfg), "--end", "20"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    assert proc.stdout is not None
    proc.stdout.close()  # the reader leaves before sbsim writes anything
    err = proc.stderr.read() if proc.stderr else ""
    assert proc.wait(timeout=60) == 0, err
    assert "error" not in err


def test_story_name_with_newline_keeps_summary_lines(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        import storyboard
        def createStories(board):
            board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [storyboard.SignalEffect("x")],
                                                 name="a\\nb"))
        """,
    )
    proc = subprocess.run(
        [str(executable()), "--sumocfg", str(trips_cfg), "--end", "20", "--story", str(story)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert any(line.startswith("activations a\\nb: ") for line in lines), proc.stdout
    assert not any(line.startswith("b: ") for line in lines), proc.stdout
