"""storyboard.sumo_polygon: a polygon SUMO loaded from the sumocfg's additional files, used as a
PolygonCondition's area (SUMO frame), checked against SUMO's FCD output; an unknown id is bad input."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from sbsim.runner import read_events, run
from sbsim_helpers import (
    STORIES,
    StoryRun,
    active_timeline,
    assert_no_crash,
    read_fcd,
    run_story,
    write_story,
)

LIMIT = 13.89  # the grid's speed limit (make_grid's default)
STEP = 1.0
# In the middle of the 4 x 4 grid (0..600 m): the junctions at (200, 200) .. (400, 400).
DISTRICT = [(190.0, 190.0), (410.0, 190.0), (410.0, 410.0), (190.0, 410.0)]

POLYGONS = f"""<additional>
    <poly id="district" color="0,0,255" fill="1" shape="{" ".join(f"{x},{y}" for x, y in DISTRICT)}"/>
    <poly id="pond" color="0,255,255" shape="0,0 5,0 5,5"/>
</additional>
"""

STORY = """
    import storyboard as sb

    def createStories(board):
        shape = sb.sumo_polygon("district")
        assert shape == [(190.0, 190.0), (410.0, 190.0), (410.0, 410.0), (190.0, 410.0)], shape
        district = sb.PolygonCondition(shape)
        board.registerStory(sb.Story(district, [sb.SpeedFactorEffect(0.3)], "district"))
"""


@pytest.fixture(scope="module")
def polygon_cfg(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The trips scenario with an additional file of two polygons listed in its sumocfg."""
    out = tmp_path_factory.mktemp("polygons")
    for f in trips_cfg.parent.iterdir():
        shutil.copy(f, out / f.name)
    (out / "district.poly.xml").write_text(POLYGONS, encoding="utf-8")
    cfg = out / trips_cfg.name
    text = cfg.read_text(encoding="utf-8")
    inputs = '<route-files value="routes.rou.xml" />'
    assert inputs in text
    cfg.write_text(text.replace(inputs, inputs + '\n        <additional-files value="district.poly.xml" />'))
    return cfg


@pytest.fixture(scope="module")
def district_run(polygon_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    return run_story(polygon_cfg, STORY, tmp_path_factory.mktemp("district"), end=200, fcd=True)


def inside(point: tuple[float, float]) -> bool:
    return 190 < point[0] < 410 and 190 < point[1] < 410


def test_vehicles_inside_the_sumo_polygon_slow_down(district_run: StoryRun) -> None:
    fcd = district_run.fcd
    assert fcd is not None
    timeline = active_timeline(district_run.events, "district", fcd.times)
    checked = 0
    for t in fcd.times:
        for v in fcd.running[t]:
            # The board sees the position after the step: active exactly while inside.
            assert (v in timeline[t]) == inside(fcd.pos[v][t]), f"{v} at {t}: {fcd.pos[v][t]}"
        # A factor set after one step shows from the next on; a fast vehicle brakes for a few steps.
        earlier = [timeline.get(round(t - k * STEP, 3), frozenset()) for k in (1, 2, 3, 4)]
        for v in earlier[0] & earlier[1] & earlier[2] & earlier[3] & timeline[t]:
            assert fcd.speed[v][t] <= 0.3 * LIMIT + 0.01, f"{v} at {t}: {fcd.speed[v][t]} m/s under a 0.3 factor"
            checked += 1
    assert checked > 100
    # Outside it, cars drive well above the district's cap.
    outside = [fcd.speed[v][t] for t in fcd.times for v in fcd.running[t] if not inside(fcd.pos[v][t])]
    assert max(outside) > 0.3 * LIMIT + 5


def test_an_unknown_polygon_is_bad_input(polygon_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.Story(sb.PolygonCondition(sb.sumo_polygon("distrikt")), [sb.SpeedFactorEffect(0.3)]))
        """,
    )
    message = f"{story}:4: ValueError: SUMO has no polygon 'distrikt' (it has: district, pond)"
    # As every story error: the traceback, then one line naming the script's line and the id.
    for args in (["--end", "5"], ["check"]):  # `sbsim check` loads SUMO as well
        result = run(polygon_cfg, story=story, extra=args, timeout=120)
        assert_no_crash(result)
        assert result.returncode == 2, result.stderr
        assert result.stdout == ""
        summary = [line for line in result.stderr.splitlines() if line.startswith("sbsim")]
        assert len(summary) == 1 and message in summary[0], result.stderr
        assert result.stderr.strip().splitlines()[-1] == summary[0]


def test_check_reads_the_polygon(polygon_cfg: Path, tmp_path: Path) -> None:
    story = write_story(tmp_path, STORY)
    result = run(polygon_cfg, story=story, extra=["check", "--strict"], timeout=120)
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    assert "PolygonCondition(4 points, SUMO frame: (190, 190) (410, 190) (410, 410) (190, 410))" in result.stdout


def test_the_weather_front_story_slows_the_vehicles_under_the_front(tmp_path: Path) -> None:
    folder = STORIES / "weather-front"
    events, fcd_path = tmp_path / "ev.jsonl", tmp_path / "fcd.xml"
    result = run(
        folder / "weather-front.sumocfg",
        story=folder / "story.py",
        events=events,
        end=220,
        sumo_options=[f"--fcd-output {fcd_path}", "--precision 6"],
        timeout=120,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    log = read_events(events)
    assert min(e["t"] for e in log) == 150  # the front arrives
    fcd = read_fcd(fcd_path)
    timeline = active_timeline(log, "weather-front", fcd.times)
    checked = 0
    for t in fcd.times:
        for v in fcd.running[t]:
            x, y = fcd.pos[v][t]
            assert (v in timeline[t]) == (t >= 150 and 700 < x + y < 1100), f"{v} at {t}: {(x, y)}"
        earlier = [timeline.get(round(t - k * STEP, 3), frozenset()) for k in (1, 2, 3, 4, 5)]
        for v in frozenset.intersection(*earlier, timeline[t]):
            assert fcd.speed[v][t] <= 0.5 * LIMIT + 0.01, f"{v} at {t}: {fcd.speed[v][t]} m/s under the front"
            checked += 1
    assert checked > 500
