"""Built-in conditions, checked step by step against SUMO's own FCD output."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path

import pytest
from sbsim_helpers import (
    OFFSET_BOUNDARY,
    FcdTrace,
    StoryRun,
    active_timeline,
    assert_active_as_predicted,
    byte_key,
    run_story,
)

# --------------------------------------------------------------------------- speed conditions

SPEED_STORY = """
    import storyboard
    def createStories(board):
        board.registerStory(storyboard.Story(storyboard.SpeedConditionGreater(0), [], "moving"))
        board.registerStory(storyboard.Story(storyboard.SpeedConditionGreater(10.5), [], "fast"))
        board.registerStory(storyboard.Story(storyboard.SpeedConditionLess(0), [], "negative"))
        board.registerStory(storyboard.Story(storyboard.SpeedConditionLess(3), [], "slow"))
        board.registerStory(storyboard.Story(storyboard.SpeedDifferenceConditionFaster(4.0),
                                             [storyboard.SignalEffect("faster")], "faster"))
        board.registerStory(storyboard.Story(storyboard.SpeedDifferenceConditionSlower(2.0, 60),
                                             [storyboard.SignalEffect("slower")], "slower_near"))
        board.registerStory(storyboard.Story(storyboard.TtcCondition(4.0, 50),
                                             [storyboard.SignalEffect("ttc")], "ttc"))
"""


@pytest.fixture(scope="module")
def speed_run(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    return run_story(trips_cfg, SPEED_STORY, tmp_path_factory.mktemp("speed"), end=200, fcd=True)


def _near(a: float, b: float) -> bool:
    return abs(a - b) < 1e-4


@pytest.mark.parametrize(
    ("story", "predicate", "threshold"),
    [
        ("moving", lambda s: s > 0, 0.0),
        ("fast", lambda s: s > 10.5, 10.5),
        ("slow", lambda s: s < 3, 3.0),
    ],
)
def test_speed_conditions_are_strict(
    speed_run: StoryRun, story: str, predicate: Callable[[float], bool], threshold: float
) -> None:
    fcd = speed_run.fcd
    assert fcd is not None
    n = assert_active_as_predicted(
        speed_run,
        story,
        lambda v, t: predicate(fcd.speed[v][t]),
        ambiguous=lambda v, t: threshold != 0 and _near(fcd.speed[v][t], threshold),
    )
    assert n > 20


def test_standing_vehicles_are_neither_moving_nor_below_zero(speed_run: StoryRun) -> None:
    fcd = speed_run.fcd
    assert fcd is not None
    standing = sum(1 for t in fcd.times for v in fcd.running[t] if fcd.speed[v][t] == 0)
    assert standing > 20, "the scenario needs vehicles standing at red lights"
    assert speed_run.result.summary()["activations negative"] == "0"


def _others_faster(
    fcd: FcdTrace, v: str, t: float, delta: float, distance: float | None, ego_faster: bool
) -> tuple[set[str], bool]:
    """(others, ambiguous) for SpeedDifferenceConditionFaster/Slower from FCD."""
    ego = fcd.speed[v][t]
    others: set[str] = set()
    ambiguous = False
    for o in fcd.running[t] - {v}:
        if distance is not None:
            d = math.dist(fcd.pos[v][t], fcd.pos[o][t])
            if abs(d - distance) < 1e-3:
                ambiguous = True
            if d > distance:
                continue
        diff = ego - fcd.speed[o][t] if ego_faster else fcd.speed[o][t] - ego
        if abs(diff - delta) < 1e-4:
            ambiguous = True
        elif diff > delta:
            others.add(o)
    return others, ambiguous


@pytest.mark.parametrize(
    ("story", "delta", "distance", "ego_faster"), [("faster", 4.0, None, True), ("slower_near", 2.0, 60.0, False)]
)
def test_speed_difference_conditions(
    speed_run: StoryRun, story: str, delta: float, distance: float | None, ego_faster: bool
) -> None:
    fcd = speed_run.fcd
    assert fcd is not None
    cache: dict[tuple[str, float], tuple[set[str], bool]] = {}

    def others(v: str, t: float) -> tuple[set[str], bool]:
        if (v, t) not in cache:
            cache[(v, t)] = _others_faster(fcd, v, t, delta, distance, ego_faster)
        return cache[(v, t)]

    n = assert_active_as_predicted(
        speed_run, story, lambda v, t: bool(others(v, t)[0]), ambiguous=lambda v, t: others(v, t)[1]
    )
    assert n > 20
    signals = speed_run.of(type="signal", story=story)
    assert len(signals) == len(speed_run.of(type="activate", story=story))
    checked = 0
    for s in signals:
        expected, ambiguous = others(s["vehicle"], float(s["t"]))
        assert s["others"] == sorted(s["others"], key=byte_key)
        if not ambiguous:
            assert set(s["others"]) == expected, s
            checked += 1
    assert checked > 10


def test_ttc_condition_names_nearby_others(speed_run: StoryRun) -> None:
    fcd = speed_run.fcd
    assert fcd is not None
    signals = speed_run.of(type="signal", story="ttc")
    assert signals, "no time-to-collision conflict in 200 s of grid traffic"
    for s in signals:
        v, t, others = s["vehicle"], float(s["t"]), s["others"]
        assert others and v not in others
        assert others == sorted(set(others), key=byte_key)
        for o in others:
            assert o in fcd.running[t]
            assert math.dist(fcd.pos[v][t], fcd.pos[o][t]) <= 50 + 12 + 1e-3  # distance + a truck's length
    # Never two vehicles that both stand still.
    for s in signals:
        t = float(s["t"])
        assert not all(fcd.speed[x][t] == 0 for x in [s["vehicle"], *s["others"]]), s


# --------------------------------------------------------------------------- polygons and the canvas frame

XMIN, _YMIN, _XMAX, YMAX = OFFSET_BOUNDARY


def canvas(x: float, y: float) -> tuple[float, float]:
    return x - XMIN, YMAX - y


POLYGON_STORY = """
    import json
    import storyboard
    from storyboard import Coord

    def createStories(board):
        # One region, SUMO x and y in (150, 450), given three ways.
        canvas = [Coord({c00}), Coord({c10}), Coord({c11}), Coord({c01})]
        sumo = [(150, 150), (450, 150), (450, 450), (150, 450)]
        converted = [board.convertTraciPosition(x, y) for x, y in sumo]
        with open({out!r}, "w") as f:
            json.dump([[c.x, c.y] for c in converted], f)
        board.registerStory(storyboard.Story(storyboard.PolygonCondition(canvas), [], "canvas"))
        board.registerStory(storyboard.Story(storyboard.PolygonCondition(sumo), [], "sumo"))
        board.registerStory(storyboard.Story(storyboard.PolygonCondition(converted), [], "converted"))
        # A triangle (SUMO frame): x > 200, y > 200, x + y < 700.
        board.registerStory(storyboard.Story(storyboard.PolygonCondition([(200, 200), (500, 200), (200, 500)]),
                                             [], "triangle"))
        # Its lower edge lies on the lane at y = 401.6 (west-bound, x 207.2 .. 392.8): on the boundary is outside.
        board.registerStory(storyboard.Story(
            storyboard.PolygonCondition([(210, 401.6), (390, 401.6), (390, 420), (210, 420)]), [], "edge"))
        board.registerStory(storyboard.Story(
            storyboard.PolygonCondition([(210, 401.5), (390, 401.5), (390, 420), (210, 420)]), [], "just_inside"))
"""


@pytest.fixture(scope="module")
def polygon_run(offset_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    d = tmp_path_factory.mktemp("polygon")
    corners = {"c00": canvas(150, 150), "c10": canvas(450, 150), "c11": canvas(450, 450), "c01": canvas(150, 450)}
    source = POLYGON_STORY.format(
        out=str(d / "converted.json"), **{k: f"{x!r}, {y!r}" for k, (x, y) in corners.items()}
    )
    return run_story(offset_cfg, source, d, end=200, fcd=True)


def test_convert_traci_position_gives_canvas_coords(polygon_run: StoryRun) -> None:
    converted = json.loads(polygon_run.story.with_name("converted.json").read_text())
    expected = [canvas(x, y) for x, y in [(150, 150), (450, 150), (450, 450), (150, 450)]]
    for got, want in zip(converted, expected, strict=True):
        assert got == pytest.approx(want, abs=1e-9)


@pytest.mark.parametrize("story", ["canvas", "sumo", "converted"])
def test_polygon_in_either_frame(polygon_run: StoryRun, story: str) -> None:
    fcd = polygon_run.fcd
    assert fcd is not None

    def inside(v: str, t: float) -> bool:
        x, y = fcd.pos[v][t]
        return 150 < x < 450 and 150 < y < 450

    def ambiguous(v: str, t: float) -> bool:
        x, y = fcd.pos[v][t]
        return min(abs(x - 150), abs(x - 450), abs(y - 150), abs(y - 450)) < 1e-3

    assert assert_active_as_predicted(polygon_run, story, inside, ambiguous=ambiguous) > 50


def test_polygon_triangle(polygon_run: StoryRun) -> None:
    fcd = polygon_run.fcd
    assert fcd is not None

    def inside(v: str, t: float) -> bool:
        x, y = fcd.pos[v][t]
        return x > 200 and y > 200 and x + y < 700

    def ambiguous(v: str, t: float) -> bool:
        x, y = fcd.pos[v][t]
        return min(abs(x - 200), abs(y - 200), abs(x + y - 700)) < 1e-3

    assert assert_active_as_predicted(polygon_run, "triangle", inside, ambiguous=ambiguous) > 20


def test_polygon_boundary_is_outside(polygon_run: StoryRun) -> None:
    fcd = polygon_run.fcd
    assert fcd is not None
    on_edge = [
        (v, t) for t in fcd.times for v in fcd.running[t] if fcd.pos[v][t][1] == 401.6 and 210 < fcd.pos[v][t][0] < 390
    ]
    assert on_edge, "no vehicle drove along the lane at y = 401.6"
    summary = polygon_run.result.summary()
    assert summary["activations edge"] == "0"
    assert int(summary["activations just_inside"]) > 0
    timeline = active_timeline(polygon_run.events, "just_inside", fcd.times)
    assert all(v in timeline[t] for v, t in on_edge)


# --------------------------------------------------------------------------- And / Or


def test_and_or_evaluate_lazily_and_combine_sets(trips_cfg: Path, tmp_path: Path) -> None:
    log = tmp_path / "calls.jsonl"
    run = run_story(
        trips_cfg,
        f"""
        import json
        import storyboard

        class Probe(storyboard.Condition):
            def __init__(self, name, result):
                super().__init__()
                self.name, self.result = name, result
            def test(self, vehicle):
                with open({str(log)!r}, "a") as f:
                    f.write(json.dumps([self.name, vehicle.time, vehicle.id]) + "\\n")
                return self.result(vehicle.id)

        def even(vid):
            return int(vid[3:]) % 2 == 0

        def createStories(board):
            T = storyboard.TimeCondition
            board.registerStory(storyboard.Story(storyboard.AndCondition(T(50, 52), Probe("and", lambda v: True)),
                                                 [], "and"))
            board.registerStory(storyboard.Story(storyboard.OrCondition(T(0, 96), Probe("or", lambda v: False)),
                                                 [], "or"))
            A = Probe("a", lambda v: {{"veh1", "veh2", "nobody"}})
            B = Probe("b", lambda v: {{"veh1", "veh3"}})
            board.registerStory(storyboard.Story(storyboard.AndCondition(T(60, 60), storyboard.AndCondition(A, B)),
                                                 [storyboard.SignalEffect("and")], "and_sets"))
            C = Probe("c", lambda v: {{"veh3", "veh4"}} if even(v) else set())
            D = Probe("d", lambda v: {{"veh5"}})
            board.registerStory(storyboard.Story(storyboard.AndCondition(T(61, 61), storyboard.OrCondition(C, D)),
                                                 [storyboard.SignalEffect("or")], "or_sets"))
            E = Probe("e", lambda v: set())
            F = Probe("f", lambda v: True)
            board.registerStory(storyboard.Story(storyboard.AndCondition(T(62, 62), storyboard.OrCondition(E, F)),
                                                 [storyboard.SignalEffect("empty")], "empty_or_true"))
    """,
        tmp_path,
        end=100,
    )
    calls = [json.loads(line) for line in log.read_text().splitlines()]
    times = {name: {t for n, t, _ in calls if n == name} for name in "and or a b c d e f".split()}
    # b only when a is true, for And; b only when a is false, for Or.
    assert times["and"] == {50, 51, 52}
    assert times["or"] == {97, 98, 99, 100}
    assert times["a"] == times["b"] == {60}
    assert times["c"] == times["d"] == {61}
    assert times["e"] == times["f"] == {62}
    s = run.result.summary()
    assert int(s["activations and"]) > 0 and int(s["activations or"]) > 0
    # Within a story, calls follow the evaluation order: vehicles ascending by byte order.
    for name in ("and", "or", "a", "c"):
        for t in times[name]:
            ids = [v for n, tt, v in calls if n == name and tt == t]
            assert ids == sorted(ids, key=byte_key)
            assert len(ids) == len(set(ids))

    def called(name: str) -> list[str]:
        return [v for n, _, v in calls if n == name]

    running = set(called("a"))  # at t = 60
    assert {"veh1", "veh2", "veh3", "veh4", "veh5", "veh6"} <= running, "the scenario changed"
    # Sets exclude the ego and vehicles not running; set AND set = intersection, true iff non-empty:
    # veh1 gets {veh2} and {veh3} -> empty -> false; all others get {veh1}.
    assert called("b") == called("a")
    signals = run.of(type="signal", story="and_sets")
    assert {e["vehicle"] for e in signals} == running - {"veh1"}
    assert all(e["others"] == ["veh1"] for e in signals)
    # Or: d only where c's set is empty (odd ids); set OR set = union; even: {veh3, veh4} - ego, odd: {veh5} - ego.
    running = set(called("c"))  # at t = 61
    assert set(called("d")) == {v for v in running if int(v[3:]) % 2}
    expected = {}
    for v in running:
        others = ({"veh3", "veh4"} if int(v[3:]) % 2 == 0 else {"veh5"}) - {v}
        if others:
            expected[v] = sorted(others, key=byte_key)
    assert {e["vehicle"]: e["others"] for e in run.of(type="signal", story="or_sets")} == expected
    assert "veh5" not in expected
    # An empty set is false, so Or falls through to a plain true: every vehicle, no others.
    assert called("e") == called("f")
    empty = run.of(type="signal", story="empty_or_true")
    assert [e["vehicle"] for e in empty] == called("f")
    assert all(e["others"] == [] for e in empty)


# --------------------------------------------------------------------------- Limit, Likelihood, Deferring

REGION = (150.0, 450.0)


def _in_region(pos: tuple[float, float]) -> bool:
    return all(REGION[0] < c < REGION[1] for c in pos)


def test_limit_condition_admits_the_first_n_vehicles(trips_cfg: Path, tmp_path: Path) -> None:
    run = run_story(
        trips_cfg,
        """
        import storyboard
        def createStories(board):
            region = storyboard.PolygonCondition([(150, 150), (450, 150), (450, 450), (150, 450)])
            board.registerStory(storyboard.Story(storyboard.AndCondition(region, storyboard.LimitCondition(3)),
                                                 [storyboard.SpeedEffect(20)], "three"))
            board.registerStory(storyboard.Story(storyboard.LimitCondition(0), [], "none"))
            board.registerStory(storyboard.Story(storyboard.LimitCondition(5), [], "five"))
    """,
        tmp_path,
        end=250,
        fcd=True,
    )
    fcd = run.fcd
    assert fcd is not None
    three = set(run.activated("three"))
    assert len(three) == 3
    # The first three to be inside, in evaluation order (time, then id byte order).
    order = [v for t in fcd.times for v in sorted(fcd.running[t], key=byte_key) if _in_region(fcd.pos[v][t])]
    first = list(dict.fromkeys(order))[:3]
    assert three == set(first)
    # Each admitted vehicle stays admitted: active exactly while inside.
    assert_active_as_predicted(
        run,
        "three",
        lambda v, t: v in three and _in_region(fcd.pos[v][t]),
        ambiguous=lambda v, t: min(abs(c - b) for c in fcd.pos[v][t] for b in REGION) < 1e-3,
    )
    assert run.result.summary()["activations none"] == "0"
    assert len(set(run.activated("five"))) == 5
    first_five = list(dict.fromkeys(v for t in fcd.times for v in sorted(fcd.running[t], key=byte_key)))[:5]
    assert set(run.activated("five")) == set(first_five)


LIKELIHOOD_STORY = """
    import storyboard
    def createStories(board):
        rng = board.getRandomNumberGenerator(0)
        board.registerStory(storyboard.Story(storyboard.LikelihoodCondition(rng, 0.5), [], "half"))
        board.registerStory(storyboard.Story(storyboard.LikelihoodCondition(rng, 0.0), [], "never"))
        board.registerStory(storyboard.Story(storyboard.LikelihoodCondition(board.getRandomNumberGenerator(1), 1.0),
                                             [], "always"))
"""


@pytest.fixture(scope="module")
def likelihood_runs(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, StoryRun]:
    base = tmp_path_factory.mktemp("likelihood")
    return {
        name: run_story(trips_cfg, LIKELIHOOD_STORY, base / name, seed=seed)
        for name, seed in (("a", 11), ("a2", 11), ("b", 12))
    }


def test_likelihood_activates_about_half(likelihood_runs: dict[str, StoryRun]) -> None:
    run = likelihood_runs["a"]
    seen = int(run.result.summary()["vehicles seen"])
    half = run.activated("half")
    assert len(half) == len(set(half)), "a vehicle's draw must not change while it runs"
    assert 0.3 * seen <= len(half) <= 0.7 * seen, (len(half), seen)
    assert run.result.summary()["activations never"] == "0"
    assert len(set(run.activated("always"))) == seen
    # Decided once at the vehicle's first step, kept until it leaves.
    first_step = {}
    for e in run.of(type="activate", story="always"):
        first_step[e["vehicle"]] = e["t"]
    for e in run.of(type="activate", story="half"):
        assert e["t"] == first_step[e["vehicle"]]
    assert {e["reason"] for e in run.of(type="deactivate", story="half")} <= {"vehicle_left"}


def test_likelihood_is_deterministic_per_seed(likelihood_runs: dict[str, StoryRun]) -> None:
    assert likelihood_runs["a"].events == likelihood_runs["a2"].events
    assert set(likelihood_runs["a"].activated("half")) != set(likelihood_runs["b"].activated("half"))


def test_deferring_condition(trips_cfg: Path, tmp_path: Path) -> None:
    run = run_story(
        trips_cfg,
        """
        import storyboard
        def createStories(board):
            rng = board.getRandomNumberGenerator()
            board.registerStory(storyboard.Story(storyboard.DeferringCondition(rng, 10, 20), [], "later"))
            board.registerStory(storyboard.Story(storyboard.DeferringCondition(rng, 5, 5), [], "five"))
    """,
        tmp_path,
        end=200,
        fcd=True,
    )
    fcd = run.fcd
    assert fcd is not None
    first_seen: dict[str, float] = {}
    last_seen: dict[str, float] = {}
    for t in fcd.times:
        for v in fcd.running[t]:
            first_seen.setdefault(v, t)
            last_seen[v] = t
    delays = {e["vehicle"]: float(e["t"]) - first_seen[e["vehicle"]] for e in run.of(type="activate", story="later")}
    assert len(delays) == len(run.activated("later"))
    assert delays and all(10 <= d <= 20 for d in delays.values()), delays
    assert len(set(delays.values())) > 3, "deferrals should be random"
    # Vehicles running 21 s or more have all been activated; none before 10 s.
    for v, first in first_seen.items():
        if last_seen[v] - first >= 20:
            assert v in delays, v
        if last_seen[v] - first < 10:
            assert v not in delays, v
    fives = {e["vehicle"]: float(e["t"]) - first_seen[e["vehicle"]] for e in run.of(type="activate", story="five")}
    assert fives and set(fives.values()) == {5.0}
    assert {e["reason"] for e in run.of(type="deactivate")} <= {"vehicle_left"}
