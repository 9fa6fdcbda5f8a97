"""--penetration, <equipped> filters and --storyboard-equipped-only on real runs.

Which vehicles are equipped is seen from two sides that do not share code paths beyond the draw:
the services the manager created (summary) and the egos of a story that fires for every vehicle
the storyboard sees (event log).
"""

from __future__ import annotations

from pathlib import Path

from sbsim.runner import read_events, read_summary, run
from sbsim_helpers import assert_bad_input, write_story

EVERYONE = """
    import storyboard

    def createStories(board):
        board.registerStory(storyboard.Story(storyboard.TimeCondition(0), [storyboard.SignalEffect("hi")], name="all"))
"""

SERVICES = """<?xml version="1.0"?>
<services>
    <service type="ClearLaneService">{filters}</service>
</services>
"""


def services_file(directory: Path, filters: str = "") -> Path:
    path = directory / f"services{abs(hash(filters))}.xml"
    path.write_text(SERVICES.format(filters=filters), encoding="utf-8")
    return path


def equipped_run(
    cfg: Path, tmp_path: Path, *options: str, filters: str = "", seed: int = 3, name: str = "run"
) -> tuple[set[str], dict[str, object]]:
    """(the egos the storyboard saw, the summary) of a 300 s run with a story on every vehicle."""
    story = write_story(tmp_path, EVERYONE)
    events, summary = tmp_path / f"{name}.jsonl", tmp_path / f"{name}.json"
    extra = ["--services", str(services_file(tmp_path, filters)), "--summary", str(summary), *options]
    result = run(cfg, story=story, events=events, end=300, seed=seed, quiet=True, extra=extra)
    assert result.returncode == 0, result.stderr
    # The one warning such a run may give: a story signalled a vehicle its filters left without
    # services (counted in the summary as "signals without services").
    others = [line for line in result.stderr.splitlines() if "which has no services" not in line]
    assert not any("warning" in line for line in others), result.stderr
    lines = read_events(events)
    egos = {e["vehicle"] for e in lines if e["type"] == "activate"}
    figures = read_summary(summary)
    # Signals are counted per cause in the summary, one per signal line of the log.
    assert figures["signals"] == {"hi": sum(e["type"] == "signal" for e in lines)}
    return egos, figures


def test_equipped_vehicles_get_services_and_are_all_the_storyboard_sees(trips_cfg: Path, tmp_path: Path) -> None:
    egos, summary = equipped_run(trips_cfg, tmp_path, "--penetration", "0.5", "--storyboard-equipped-only")
    seen = summary["vehicles_seen"]
    assert isinstance(seen, int) and seen > 100
    # The same vehicles on both sides: one service per equipped vehicle, one story activation each.
    assert summary["services_created"] == len(egos)
    assert 0.3 * seen < len(egos) < 0.7 * seen, (len(egos), seen)


def test_the_same_seed_equips_the_same_vehicles_and_a_higher_share_only_adds(trips_cfg: Path, tmp_path: Path) -> None:
    only = "--storyboard-equipped-only"
    half, _ = equipped_run(trips_cfg, tmp_path, "--penetration", "0.5", only, name="half")
    again, _ = equipped_run(trips_cfg, tmp_path, "--penetration", "0.5", only, name="again")
    quarter, _ = equipped_run(trips_cfg, tmp_path, "--penetration", "0.25", only, name="quarter")
    other_seed, _ = equipped_run(trips_cfg, tmp_path, "--penetration", "0.5", only, seed=4, name="other")
    assert half == again
    assert quarter < half
    assert other_seed != half


def test_without_the_flag_stories_see_everybody_and_inverse_services_go_to_the_others(
    trips_cfg: Path, tmp_path: Path
) -> None:
    equipped, _ = equipped_run(
        trips_cfg, tmp_path, "--penetration", "0.5", "--storyboard-equipped-only", name="equipped"
    )
    everybody, summary = equipped_run(
        trips_cfg, tmp_path, "--penetration", "0.5", filters='<filters><equipped match="inverse"/></filters>'
    )
    assert len(everybody) == summary["vehicles_seen"]
    assert summary["services_created"] == len(everybody) - len(equipped)
    _, summary_any = equipped_run(
        trips_cfg, tmp_path, "--penetration", "0.5", filters='<filters><equipped match="any"/></filters>', name="any"
    )
    assert summary_any["services_created"] == summary_any["vehicles_seen"]


def test_penetration_and_radio_options_can_be_study_parameters(trips_cfg: Path, tmp_path: Path) -> None:
    only = "--storyboard-equipped-only"
    by_option, _ = equipped_run(trips_cfg, tmp_path, "--penetration", "0.5", only, name="option")
    by_param, summary = equipped_run(
        trips_cfg, tmp_path, "--param", "penetration=0.5", "--param", "v2x_range=120", only, name="param"
    )
    assert by_param == by_option
    assert summary["parameters"] == {"penetration": 0.5, "v2x_range": 120}


def test_bad_penetration_is_bad_input(trips_cfg: Path) -> None:
    assert_bad_input(run(trips_cfg, end=5, extra=["--penetration", "1.5"]), "--penetration", "1.5")
    assert_bad_input(run(trips_cfg, end=5, extra=["--penetration", "nan"]), "--penetration")
    assert_bad_input(run(trips_cfg, end=5, extra=["--param", "penetration=-0.1"]), "--param penetration=-0.1")
    assert_bad_input(run(trips_cfg, end=5, extra=["--param", "v2x_range=far"]), "--param v2x_range=far")
    assert_bad_input(
        run(trips_cfg, end=5, extra=["--param", "penetration=0.5", "--penetration", "0.4"]),
        "--param penetration=0.5",
        "--penetration",
    )
