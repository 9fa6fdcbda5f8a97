"""sbsim --gui for real: sumo-gui inside sbsim under a virtual X server (xvfb-run), checked by its pictures.

A story with an area given in Artery's canvas frame (Coord) on a net whose canvas frame is not SUMO's:
the screenshot taken while the story is active must show the area's fill and, inside it and nowhere
else, vehicles in the story's colour; one taken before the story starts shows the fill but no such
vehicle. The event log is the one of the same run without --gui. Set SBSIM_GUI_PICTURE=FILE to keep
the picture (the README's docs/gui-story.png is made that way).
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from matplotlib.image import imread
from sbsim.runner import executable
from sbsim_helpers import OFFSET_BOUNDARY, write_story

XVFB_RUN = shutil.which("xvfb-run")
needs_xvfb = pytest.mark.skipif(
    XVFB_RUN is None,
    reason="xvfb-run is missing: install the Debian packages xvfb and xauth (./run-tests does as root)",
)

#: matplotlib's C0, the first story's colour (storyboard.StoryPalette) and the area fill's alpha (GuiWatch).
STORY_RGB = np.array([31, 119, 180])
FILL_ALPHA = 70 / 255
#: On white, the fill shows as the story's colour at that alpha.
FILL_RGB = np.round(255 * (1 - FILL_ALPHA) + STORY_RGB * FILL_ALPHA)
#: sumo-gui's window, and the view inside it (the window less its frame, tool bars and message area).
WINDOW = "810,815"
VIEW_SIZE = (800, 600)

# The district around the grid's centre junction, SUMO (150..450, 150..450), written in the canvas
# frame: Coord(x, y) is SUMO (x + xmin, ymax - y).
XMIN, YMAX = OFFSET_BOUNDARY[0], OFFSET_BOUNDARY[3]
STORY = f"""
    import storyboard
    from storyboard import Coord, PolygonCondition, SpeedConditionLess, Story, TimeCondition

    def createStories(board):
        corners = [(150, 150), (450, 150), (450, 450), (150, 450)]
        district = PolygonCondition([Coord(x - {XMIN}, {YMAX} - y) for x, y in corners])
        board.registerStory(Story(storyboard.all_of(district, TimeCondition(100, 300)), [], name="district"))
        board.registerStory(Story(SpeedConditionLess(0.1), [], name="standing"))
"""

#: Vehicles drawn five times their size: at a zoom showing the whole net they are a few pixels otherwise.
VIEW_SETTINGS = """<viewsettings>
    <scheme name="sbsim test">
        <vehicles vehicleQuality="0" vehicle_exaggeration="5" vehicle_minSize="1"/>
    </scheme>
</viewsettings>
"""


def near(image: np.ndarray, rgb: np.ndarray, tolerance: int = 2) -> np.ndarray:
    return np.all(np.abs(image[:, :, :3].astype(int) - rgb) <= tolerance, axis=2)


def read_rgb(path: Path) -> np.ndarray:
    return np.round(imread(path)[:, :, :3] * 255).astype(int)


@needs_xvfb
def under_xvfb(command: list[str], tmp_path: Path) -> subprocess.CompletedProcess[str]:
    """Runs `command` on a virtual display. xvfb-run fails on its own now and then (its xauth or Xvfb
    start, under `set -e`: exit 1 and nothing on stderr, its messages in its error file); only such
    a start is tried again. sbsim's own failures always say a line on stderr, so they count."""
    for attempt in range(3):
        errors = tmp_path / f"xvfb-{attempt}.log"
        run = subprocess.run(
            [str(XVFB_RUN), "-a", "-e", str(errors), "-s", "-screen 0 1280x1024x24", *command],
            capture_output=True,
            text=True,
            timeout=300,
        )
        if not (run.returncode == 1 and not run.stderr and errors.exists() and errors.read_text().strip()):
            return run
    run.stderr = f"xvfb-run failed to start three times; its last errors: {errors.read_text()}"
    return run


def test_gui_shows_the_area_and_the_story_colour_and_only_watches(offset_cfg: Path, tmp_path: Path) -> None:
    story = write_story(tmp_path, STORY)
    settings = tmp_path / "view.xml"
    settings.write_text(VIEW_SETTINGS, encoding="utf-8")
    before, during = tmp_path / "t60.png", tmp_path / "t200.png"
    common = ["--sumocfg", str(offset_cfg), "--story", str(story), "-q"]

    plain = subprocess.run(
        [str(executable()), *common, "--events", str(tmp_path / "plain.jsonl")],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert plain.returncode == 0, plain.stderr
    gui = under_xvfb(
        [
            str(executable()),
            *common,
            "--events",
            str(tmp_path / "gui.jsonl"),
            "--gui",
            "--gui-delay",
            "0",
            "--sumo-option",
            f"--start --quit-on-end --window-size {WINDOW} --gui-settings-file {settings}",
            "--gui-screenshot",
            f"60:{before}",
            "--gui-screenshot",
            f"200:{during}",
        ],
        tmp_path,
    )
    assert gui.returncode == 0, gui.stderr
    # libsumo's GUI sometimes never returns from closing; sbsim's watchdog then ends the run with
    # its exit code (README: "Known limits"). Any other warning is a failure.
    warnings = [w for w in gui.stderr.splitlines() if "sbsim: warning" in w and "did not close within" not in w]
    assert not warnings, gui.stderr
    # The GUI only watches: the same events, byte for byte.
    assert (tmp_path / "gui.jsonl").read_bytes() == (tmp_path / "plain.jsonl").read_bytes()

    image = read_rgb(during)
    assert (image.shape[1], image.shape[0]) == VIEW_SIZE
    fill = near(image, FILL_RGB)
    assert fill.sum() > 5000, "no area fill in the picture"
    rows, cols = np.nonzero(fill)
    top, bottom, left, right = rows.min(), rows.max(), cols.min(), cols.max()
    painted = near(image, STORY_RGB)
    inner = painted[top + 6 : bottom - 6, left + 6 : right - 6]  # inside the outline
    assert inner.sum() >= 20, "no vehicle in the story's colour inside its area"
    # Vehicles take the colour only inside the area: the area is drawn where the story acts.
    # (Its outline has the colour too, and a painted vehicle may stick out of the area by its length.)
    margin = 20
    outside = painted.copy()
    outside[max(top - margin, 0) : bottom + margin, max(left - margin, 0) : right + margin] = False
    assert outside.sum() == 0, "pixels of the story's colour away from its area"

    early = read_rgb(before)
    assert (early.shape[1], early.shape[0]) == VIEW_SIZE
    assert near(early, FILL_RGB).sum() > 5000, "the area is drawn from the start"
    assert near(early, STORY_RGB)[top + 6 : bottom - 6, left + 6 : right - 6].sum() == 0, (
        "a vehicle in the story's colour before the story starts"
    )

    if keep := os.environ.get("SBSIM_GUI_PICTURE"):
        shutil.copy(during, keep)


def test_gui_without_a_display_is_one_line_and_exit_2(tmp_path: Path) -> None:
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    result = subprocess.run([str(executable()), "--gui", "-q"], capture_output=True, text=True, env=env, timeout=60)
    assert result.returncode == 2
    assert result.stderr.strip().splitlines() == [
        "sbsim: --gui: no X display (DISPLAY is not set); run on a desktop, or under xvfb-run"
    ]
