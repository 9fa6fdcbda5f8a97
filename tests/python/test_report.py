"""sbsim.report: figures and page drawn from a real grid-rain run, checked against its event log."""

from __future__ import annotations

import base64
import io
import json
import os
import re
import shutil
import subprocess
import sys
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from matplotlib.axes import Axes
from matplotlib.collections import PathCollection
from matplotlib.colors import to_rgb
from matplotlib.image import imread
from matplotlib.patches import Polygon, StepPatch
from sbsim import report
from sbsim.runner import read_events, read_summary, run
from sbsim_helpers import REPO, STORIES, FcdTrace, active_timeline, assert_no_crash, read_fcd

SCENARIO = STORIES / "grid-rain"
SUMOCFG = SCENARIO / "grid-rain.sumocfg"
STORY = SCENARIO / "story.py"
END = 500.0
#: stories/grid-rain/story.py's DISTRICT: a square from 390 to 810 m on both axes.
DISTRICT = (390.0, 810.0)
#: Its corners in SUMO's frame, in the script's order.
DISTRICT_CORNERS = [(390.0, 390.0), (810.0, 390.0), (810.0, 810.0), (390.0, 810.0)]
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@dataclass
class RainRun:
    events_path: Path
    fcd_path: Path
    summary_path: Path
    events: list[dict[str, Any]]
    summary: dict[str, Any]
    trace: FcdTrace
    fcd: Any  # report.read_fcd's DataFrame


@pytest.fixture(scope="module")
def rain(tmp_path_factory: pytest.TempPathFactory) -> RainRun:
    out = tmp_path_factory.mktemp("report")
    events, fcd, summary = out / "events.jsonl", out / "fcd.xml", out / "summary.json"
    result = run(
        SUMOCFG,
        story=SCENARIO / "story.py",
        events=events,
        end=END,
        sumo_options=[f"--fcd-output {fcd}"],
        extra=["--summary", str(summary)],
        quiet=True,
        timeout=120,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    log = read_events(events)
    assert {e["story"] for e in log if e["type"] == "activate"} == {"rain", "rain-warning"}
    return RainRun(events, fcd, summary, log, read_summary(summary), read_fcd(fcd), report.read_fcd(fcd))


def story_axes(figure: Any, story: str) -> Axes:
    [ax] = [ax for ax in figure.axes if ax.get_label() == story]
    return ax


def test_activity_counts_are_the_vehicles_active_per_the_log(rain: RainRun) -> None:
    figure = report.plot_activity(rain.events, end=END)
    patches = {p.get_label(): p for p in figure.axes[0].patches if isinstance(p, StepPatch)}
    assert list(patches) == ["rain", "rain-warning"]
    below = None
    for story, patch in patches.items():
        values, edges, baseline = patch.get_data()
        # Stacked: each story starts where the one before ends.
        np.testing.assert_array_equal(baseline, 0 if below is None else below)
        below = values
        assert edges[-1] == END
        # The count drawn at every step of the run is the number of vehicles the log has active then.
        times = [t for t in rain.trace.times if edges[0] <= t < END]
        expected = active_timeline(rain.events, story, times)
        drawn = (values - baseline)[np.searchsorted(edges, times, side="right") - 1]
        assert drawn.tolist() == [len(expected[t]) for t in times], story
        assert drawn.max() > 0
    # Nothing is drawn before the rain starts (120 s), and the rain story peaks well above the warnings.
    rain_values, rain_edges, _ = patches["rain"].get_data()
    assert rain_edges[0] == 120.0
    assert rain_values.max() > 20


def test_duration_histograms_hold_every_completed_stay(rain: RainRun) -> None:
    figure = report.plot_durations(rain.events)
    for story in ("rain", "rain-warning"):
        ax = story_axes(figure, story)
        completed = sum(1 for e in rain.events if e["type"] == "deactivate" and e["story"] == story)
        assert completed > 0
        assert sum(p.get_height() for p in ax.patches) == completed, story
    # The stays' lengths add up to sbsim's own count of active vehicle-seconds (the rain ends at 420 s,
    # before the run, so every stay is complete).
    stays = report.stays(rain.events)
    assert stays["end"].notna().all()
    for entry in rain.summary["stories"]:
        mine = stays[stays["story"] == entry["name"]]
        assert len(mine) == entry["activations"]
        assert mine["duration"].sum() == pytest.approx(entry["active_vehicle_seconds"])


def test_stays_still_open_when_the_log_ends_are_counted_apart(rain: RainRun) -> None:
    # The log cut at 300 s, in the middle of the rain: as if the run had ended there.
    events = [e for e in rain.events if e["t"] <= 300]
    opened = Counter(e["story"] for e in events if e["type"] == "activate")
    closed = Counter(e["story"] for e in events if e["type"] == "deactivate")
    assert opened["rain"] > closed["rain"] > 0
    figure = report.plot_durations(events)
    table = report.story_table(events)
    for story in ("rain", "rain-warning"):
        assert sum(p.get_height() for p in story_axes(figure, story).patches) == closed[story]
        assert table.loc[story, "active at the end"] == opened[story] - closed[story]
        assert table.loc[story, "completed stays"] == closed[story]
    assert "still active at the end" in story_axes(figure, "rain").get_title()


def test_map_shows_the_rain_district(rain: RainRun) -> None:
    net = report.read_net(report.read_sumocfg(SUMOCFG).net_file)
    figure = report.plot_map(net, rain.events, rain.fcd)
    ax = figure.axes[0]
    # The whole 1 km grid is drawn.
    [lanes] = [c for c in ax.collections if c.get_label() == "lanes"]
    assert len(lanes.get_segments()) > 100
    assert ax.get_xlim()[0] < 0 < 1000 < ax.get_xlim()[1]
    scatters = {c.get_label().split(" (")[0]: c for c in ax.collections if isinstance(c, PathCollection)}
    assert list(scatters) == ["rain", "rain-warning"]
    for story, points in scatters.items():
        activations = [e for e in rain.events if e["type"] == "activate" and e["story"] == story]
        offsets = points.get_offsets()
        assert len(offsets) == len(activations) > 0
        low, high = DISTRICT
        assert ((offsets >= low) & (offsets <= high)).all(), f"{story} activated outside the district"
        # Each point is where the FCD has its vehicle at the activation (read independently here).
        expected = sorted(rain.trace.pos[e["vehicle"]][float(e["t"])] for e in activations)
        assert sorted(map(tuple, offsets.tolist())) == expected


def test_story_areas_are_what_sbsim_check_reports() -> None:
    checked = run(SUMOCFG, story=STORY, extra=["check", "--json"], timeout=120)
    assert checked.returncode == 0, checked.stderr
    reported = {s["name"]: s["areas"] for s in json.loads(checked.stdout)["stories"]}
    # Both stories share the one condition holding the district: each has it once.
    assert reported == {
        story: [{"condition": "PolygonCondition", "points": [list(p) for p in DISTRICT_CORNERS]}]
        for story in ("rain", "rain-warning")
    }
    areas = report.story_areas(STORY, SUMOCFG)
    assert list(areas) == ["rain", "rain-warning"]
    for story, mine in areas.items():
        assert mine == [report.Area(story, "PolygonCondition", tuple(DISTRICT_CORNERS))]


def map_polygons(figure: Any) -> dict[str, Polygon]:
    ax = figure.axes[0]
    return {p.get_label(): p for p in ax.patches if isinstance(p, Polygon)}


def test_map_shows_each_story_area_in_its_colour(rain: RainRun) -> None:
    built = report.build(rain.events_path, SUMOCFG, fcd=rain.fcd_path, story=STORY)
    ax = built.figures["map"].axes[0]
    polygons = map_polygons(built.figures["map"])
    assert list(polygons) == ["rain", "rain-warning"]
    scatters = {c.get_label().split(" (")[0]: c for c in ax.collections if isinstance(c, PathCollection)}
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    for story, patch in polygons.items():
        xy = patch.get_xy()
        # The ring is closed: the first corner again at the end.
        assert xy[:-1].tolist() == [list(p) for p in DISTRICT_CORNERS], story
        assert xy[-1].tolist() == xy[0].tolist()
        face, edge = patch.get_facecolor(), patch.get_edgecolor()
        assert 0 < face[3] < 1 and patch.get_fill(), "a filled, semi-transparent area"
        # The story's colour: the same as its activation points'.
        np.testing.assert_allclose(face[:3], scatters[story].get_facecolor()[0][:3])
        np.testing.assert_allclose(edge[:3], face[:3])
        assert story in legend
    # The activation points are still all there, on top of the areas.
    activations = Counter(e["story"] for e in rain.events if e["type"] == "activate")
    assert {s: len(c.get_offsets()) for s, c in scatters.items()} == activations
    # Without the FCD the areas are drawn on the network alone.
    alone = report.build(rain.events_path, SUMOCFG, story=STORY).figures["map"]
    assert list(map_polygons(alone)) == ["rain", "rain-warning"]
    assert "areas" in alone.axes[0].get_title()
    # Without --story, no areas.
    assert not map_polygons(report.build(rain.events_path, SUMOCFG).figures["map"])


def test_a_story_that_never_activated_still_has_its_area_drawn(rain: RainRun, tmp_path: Path) -> None:
    story = tmp_path / "story.py"
    story.write_text(
        "from storyboard import AndCondition, Coord, DistanceCondition, PolygonCondition, SpeedEffect, Story\n\n"
        "def createStories(board):\n"
        "    board.registerStory(Story(PolygonCondition([(390, 390), (810, 390), (810, 810)]), [], name='rain'))\n"
        "    area = PolygonCondition([Coord(0, 0), Coord(100, 0), Coord(100, 100)])\n"
        "    near = DistanceCondition((500, 500), 40)\n"
        "    board.registerStory(Story(AndCondition(area, near), [SpeedEffect(1)], name='quiet'))\n",
        encoding="utf-8",
    )
    figure = report.build(rain.events_path, SUMOCFG, story=story).figures["map"]
    ax = figure.axes[0]
    polygons = map_polygons(figure)
    assert list(polygons) == ["rain", "quiet"]
    # Coord is Artery's canvas frame (y down from the net's top, here y = 1000): drawn in SUMO's.
    assert polygons["quiet"].get_xy()[:-1].tolist() == [[0, 1000], [100, 1000], [100, 900]]
    [circle] = [p for p in ax.patches if not isinstance(p, Polygon)]
    assert tuple(circle.get_center()) == (500, 500) and circle.get_radius() == 40
    np.testing.assert_allclose(circle.get_facecolor(), polygons["quiet"].get_facecolor())
    assert "rain-warning" not in polygons  # the log's story without a registered area has none


def test_speeds_under_a_story_against_the_rest(rain: RainRun) -> None:
    figure = report.plot_speeds(rain.events, rain.fcd)
    ax = story_axes(figure, "rain")
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert set(lines) == {"under rain", "others"}
    timeline = active_timeline(rain.events, "rain", rain.trace.times)
    for t in (150.0, 300.0, 400.0):
        under = timeline[t] & rain.trace.running[t]
        others = rain.trace.running[t] - timeline[t]
        assert under and others
        for label, group in (("under rain", under), ("others", others)):
            x, y = lines[label].get_data()
            [i] = np.flatnonzero(np.asarray(x) == t)
            assert y[i] == pytest.approx(np.mean([rain.trace.speed[v][t] for v in group]), abs=0.01), (label, t)
    # Outside the rain nobody is under it; during the rain its vehicles are the slow ones.
    x, y = (np.asarray(a, dtype=float) for a in lines["under rain"].get_data())
    assert np.isnan(y[(x < 120) | (x > 421)]).all()
    _, others = (np.asarray(a, dtype=float) for a in lines["others"].get_data())
    during = (x > 130) & (x <= 420)
    assert np.nanmean(y[during]) < np.nanmean(others[during])


def test_story_table_counts(rain: RainRun) -> None:
    table = report.story_table(rain.events, rain.summary)
    activations = Counter(e["story"] for e in rain.events if e["type"] == "activate")
    for story in ("rain", "rain-warning"):
        row = table.loc[story]
        assert row["activations"] == activations[story] == row["activations (summary)"]
        assert row["vehicles"] == len({e["vehicle"] for e in rain.events if e["story"] == story})
        assert row["active at the end"] == 0


def test_without_fcd_the_map_is_the_network_alone(rain: RainRun) -> None:
    built = report.build(rain.events_path, SUMOCFG)
    assert list(built.figures) == ["activity", "durations", "map"]
    assert not [c for c in built.figures["map"].axes[0].collections if isinstance(c, PathCollection)]
    assert built.run is None


def cli(*args: str | os.PathLike[str]) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(REPO / "python"), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run(
        [sys.executable, "-m", "sbsim.report", *map(str, args)],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
        check=False,
    )


def test_command_writes_a_self_contained_page_and_pngs(rain: RainRun, tmp_path: Path) -> None:
    page, pngs = tmp_path / "report.html", tmp_path / "png"
    done = cli(rain.events_path, "--sumocfg", SUMOCFG, "--fcd", rain.fcd_path, "--summary", rain.summary_path)
    assert done.returncode == 2 and "-o" in done.stderr  # the output is required
    done = cli(
        rain.events_path,
        "--sumocfg",
        SUMOCFG,
        "--fcd",
        rain.fcd_path,
        "--summary",
        rain.summary_path,
        "-o",
        page,
        "--png",
        pngs,
    )
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    text = page.read_text(encoding="utf-8")
    images = re.findall(r'src="data:image/png;base64,([A-Za-z0-9+/=]+)"', text)
    assert len(images) == 4
    assert all(base64.b64decode(image).startswith(PNG_MAGIC) for image in images)
    assert "<table" in text and "mean duration [s]" in text and "rain-warning" in text
    assert "end time reached" in text  # the summary's run figures
    assert not re.search(r'(src|href)="(?!data:)', text), "the page must not refer to other files"
    written = sorted(p.name for p in pngs.iterdir())
    assert written == ["activity.png", "durations.png", "map.png", "speeds.png"]
    assert all((pngs / name).read_bytes().startswith(PNG_MAGIC) for name in written)


def pixel(image: np.ndarray, figure: Any, x: float, y: float) -> np.ndarray:
    """The RGB of a PNG of ``figure`` (drawn at its own dpi) at the data point (x, y) of its first axes."""
    figure.canvas.draw()  # the constrained layout places the axes when drawn
    column, row = figure.axes[0].transData.transform((x, y))
    return image[image.shape[0] - 1 - round(row), round(column), :3]


def test_the_page_map_shows_the_rain_district(rain: RainRun, tmp_path: Path) -> None:
    page, pngs = tmp_path / "report.html", tmp_path / "png"
    done = cli(rain.events_path, "--sumocfg", SUMOCFG, "--story", STORY, "-o", page, "--png", pngs)
    assert done.returncode == 0, done.stderr
    text = page.read_text(encoding="utf-8")
    [embedded] = re.findall(r'<figure id="map"><img src="data:image/png;base64,([A-Za-z0-9+/=]+)"', text)
    assert (pngs / "map.png").read_bytes().startswith(PNG_MAGIC)
    # The page's own map, as a reader sees it.
    image = imread(io.BytesIO(base64.b64decode(embedded)), format="png")
    figure = report.build(rain.events_path, SUMOCFG).figures["map"]  # the same axes, to place the points
    assert image.shape[:2] == tuple(round(v) for v in figure.get_size_inches()[::-1] * 100)
    # Mid-block (no lane) inside the district: white tinted by the two stories' fills, C0 then C1
    # at 25 % each; outside it: white.
    white = np.ones(3)
    tinted = white
    for color in ("C0", "C1"):
        tinted = tinted * 0.75 + np.array(to_rgb(color)) * 0.25
    for x, y in ((500, 500), (700, 500), (500, 700)):
        np.testing.assert_allclose(pixel(image, figure, x, y), tinted, atol=0.02)
    for x, y in ((100, 100), (900, 100), (100, 900)):
        np.testing.assert_allclose(pixel(image, figure, x, y), white, atol=0.02)


def bad_case(tmp: Path, rain: RainRun, case: str) -> tuple[list[str | os.PathLike[str]], str]:
    """Arguments for one bad input and a regular expression its error line must match."""
    events: str | os.PathLike[str] = rain.events_path
    sumocfg: str | os.PathLike[str] = SUMOCFG
    extra: list[str | os.PathLike[str]] = []
    if case == "missing events":
        events, pattern = tmp / "nope.jsonl", r"nope\.jsonl: No such file"
    elif case == "bad JSON":
        events = tmp / "bad.jsonl"
        lines = rain.events_path.read_text(encoding="utf-8").splitlines()[:2]
        events.write_text("\n".join([*lines, '{"t": 3, "type":', *lines]) + "\n", encoding="utf-8")
        pattern = r"bad\.jsonl:3: bad JSON"
    elif case == "not an event":
        events = tmp / "odd.jsonl"
        events.write_text(json.dumps({"t": 1, "type": "activate", "story": "rain"}) + "\n", encoding="utf-8")
        pattern = r"odd\.jsonl:1: 'vehicle' missing"
    elif case == "events not UTF-8":
        events = tmp / "latin.jsonl"
        events.write_bytes(b'{"t": 1, "type": "activate", "story": "r\xe9gen", "vehicle": "v"}\n')
        pattern = r"latin\.jsonl: not UTF-8"
    elif case == "events a folder":
        events, pattern = tmp, re.escape(str(tmp)) + ": Is a directory"
    elif case == "missing sumocfg":
        sumocfg, pattern = tmp / "no.sumocfg", r"no\.sumocfg: No such file"
    elif case == "broken sumocfg":
        sumocfg = tmp / "broken.sumocfg"
        sumocfg.write_text("<configuration>\n<input>\n", encoding="utf-8")
        pattern = r"broken\.sumocfg:\d+: bad XML"
    elif case == "sumocfg without net":
        sumocfg = tmp / "nonet.sumocfg"
        sumocfg.write_text('<configuration><time><end value="9"/></time></configuration>\n', encoding="utf-8")
        pattern = r"nonet\.sumocfg: names no net-file"
    elif case == "missing net":
        sumocfg = tmp / "gone.sumocfg"
        sumocfg.write_text('<configuration><input><net-file value="gone.net.xml"/></input></configuration>\n')
        pattern = r"gone\.net\.xml: no such net file"
    elif case == "bad summary":
        summary = tmp / "summary.json"
        summary.write_text('{\n"steps": 3,\n}\n', encoding="utf-8")
        extra, pattern = ["--summary", summary], r"summary\.json:3: bad JSON"
    elif case == "missing FCD":
        extra, pattern = ["--fcd", tmp / "none.xml"], r"none\.xml: No such file"
    elif case == "not FCD":
        extra, pattern = ["--fcd", rain.summary_path], r"summary\.json: not SUMO FCD output"
    elif case == "missing story":
        extra, pattern = ["--story", tmp / "gone.py"], r"gone\.py: sbsim check failed \(exit 2\): .*gone\.py"
    elif case == "broken story":
        story = tmp / "broken.py"
        story.write_text("from storyboard import Story\n\ndef createStories(board):\n    Story(Nope(), [])\n")
        extra, pattern = ["--story", story], r"broken\.py: sbsim check failed \(exit 2\): .*broken\.py:4.*NameError"
    else:
        raise AssertionError(case)
    return [events, "--sumocfg", sumocfg, *extra, "-o", tmp / "out.html"], pattern


BAD_CASES = [
    "missing events",
    "bad JSON",
    "not an event",
    "events not UTF-8",
    "events a folder",
    "missing sumocfg",
    "broken sumocfg",
    "sumocfg without net",
    "missing net",
    "bad summary",
    "missing FCD",
    "not FCD",
    "missing story",
    "broken story",
]


@pytest.mark.parametrize("case", BAD_CASES)
def test_bad_input_is_one_line_and_exit_2(
    rain: RainRun, tmp_path: Path, case: str, capsys: pytest.CaptureFixture[str]
) -> None:
    args, pattern = bad_case(tmp_path, rain, case)
    assert report.main([str(a) for a in args]) == 2
    captured = capsys.readouterr()
    lines = captured.err.splitlines()
    assert len(lines) == 1, captured.err
    assert lines[0].startswith("report: ") and re.search(pattern, lines[0]), lines[0]
    assert captured.out == ""
    assert not (tmp_path / "out.html").exists()


def test_bad_input_from_the_command_line_has_no_traceback(rain: RainRun, tmp_path: Path) -> None:
    args, pattern = bad_case(tmp_path, rain, "bad JSON")
    done = cli(*args)
    assert done.returncode == 2
    assert re.fullmatch(rf"report: .*{pattern}.*\n", done.stderr), done.stderr
    assert done.stdout == ""


def test_without_sbsim_the_story_areas_are_one_error_line(
    rain: RainRun, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("SBSIM_EXECUTABLE", str(tmp_path / "no-sbsim"))
    args = [rain.events_path, "--sumocfg", SUMOCFG, "--story", STORY, "-o", tmp_path / "out.html"]
    assert report.main([str(a) for a in args]) == 2
    [line] = capsys.readouterr().err.splitlines()
    assert re.fullmatch(r"report: .*no-sbsim: No such file or directory", line), line
    assert not (tmp_path / "out.html").exists()


@pytest.mark.parametrize("named", ["events", "messages", "summary", "events-symlink"])
def test_output_naming_an_input_is_refused_and_the_input_kept(
    rain: RainRun, tmp_path: Path, named: str, capsys: pytest.CaptureFixture[str]
) -> None:
    # The page written over its own event log or trace would destroy the run it reports (issue 29).
    events, trace, summary = tmp_path / "events.jsonl", tmp_path / "m.jsonl", tmp_path / "summary.json"
    shutil.copy(rain.events_path, events)
    trace.write_text('{"t": 1.0, "event": "tx", "type": "CAM", "station": "a", "seq": 1, "bytes": 9, "x": 0, "y": 0}\n')
    shutil.copy(rain.summary_path, summary)
    before = {p: p.read_bytes() for p in (events, trace, summary)}
    output = {"events": events, "messages": trace, "summary": summary}.get(named)
    if output is None:
        output = tmp_path / "link.html"
        output.symlink_to(events)
    args = [events, "--sumocfg", SUMOCFG, "--messages", trace, "--summary", summary, "-o", output]
    assert report.main([str(a) for a in args]) == 2
    [line] = capsys.readouterr().err.splitlines()
    assert re.fullmatch(r"report: -o: .* must not overwrite its input", line), line
    assert {p: p.read_bytes() for p in before} == before
