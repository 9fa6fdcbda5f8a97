"""Bad input: exit code 2 and one clear line on stderr naming the problem, never a crash."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
from sbsim.runner import run
from sbsim_helpers import assert_bad_input, write_story

OK_STORY = """
    import storyboard
    def createStories(board):
        board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [storyboard.SignalEffect("x")]))
"""


def test_missing_sumocfg(tmp_path: Path) -> None:
    missing = tmp_path / "nope.sumocfg"
    assert_bad_input(run(missing), str(missing), "--sumocfg")


def test_sumocfg_is_a_directory(tmp_path: Path) -> None:
    line = assert_bad_input(run(tmp_path), str(tmp_path))
    assert "director" in line


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads files whatever their mode")
def test_unreadable_sumocfg(trips_cfg: Path, tmp_path: Path) -> None:
    cfg = tmp_path / "locked.sumocfg"
    shutil.copy(trips_cfg, cfg)
    cfg.chmod(0)
    try:
        assert_bad_input(run(cfg), str(cfg))
    finally:
        cfg.chmod(0o644)


def test_sumocfg_pointing_to_a_missing_net(trips_cfg: Path, tmp_path: Path) -> None:
    cfg = tmp_path / "broken.sumocfg"
    cfg.write_text(trips_cfg.read_text(encoding="utf-8").replace("net.net.xml", str(tmp_path / "gone.net.xml")))
    # SUMO's own message names the file it could not open.
    line = assert_bad_input(run(cfg), "broken.sumocfg", "gone.net.xml")
    assert "not accessible" in line or "No such file" in line, line


def test_malformed_sumocfg_xml(tmp_path: Path) -> None:
    cfg = tmp_path / "bad.sumocfg"
    cfg.write_text('<configuration><input><net-file value="net.net.xml"/></input')
    line = assert_bad_input(run(cfg), "bad.sumocfg")
    # SUMO's XML parser message, with its position.
    assert "line" in line.lower(), line


def test_malformed_net_xml(trips_cfg: Path, tmp_path: Path) -> None:
    (tmp_path / "net.net.xml").write_text('<net version="1.20"><edge id="a"')
    shutil.copy(trips_cfg.parent / "routes.rou.xml", tmp_path)
    cfg = tmp_path / "grid.sumocfg"
    shutil.copy(trips_cfg, cfg)
    assert_bad_input(run(cfg), "grid.sumocfg", "net.net.xml")


def test_unknown_option() -> None:
    assert_bad_input(run(extra=["--no-such-option"]), "--no-such-option")


@pytest.mark.parametrize("option", ["--no-such-option=3", "-x", "--Sumocfg"])
def test_unknown_option_spellings(option: str) -> None:
    assert_bad_input(run(extra=[option]), option)


def test_unexpected_argument() -> None:
    assert_bad_input(run(extra=["stray"]), "stray")


def test_option_missing_its_value() -> None:
    assert_bad_input(run(extra=["--sumocfg"]), "--sumocfg")


@pytest.mark.parametrize("option", ["--story", "--end", "--plugin", "--sumo-option", "--threads"])
def test_options_missing_their_value(option: str) -> None:
    assert_bad_input(run(extra=[option]), option)


@pytest.mark.parametrize(
    ("option", "value"),
    [
        ("--threads", "300"),
        ("--threads", "-1"),
        ("--threads", "two"),
        ("--seed", "1.5"),
        ("--seed", "99999999999999999999"),
        ("--v2x-latency", "soon"),
        ("--v2x-fade-start", "nan"),
        ("--end", "1e10"),
    ],
)
def test_bad_value_names_its_option(trips_cfg: Path, option: str, value: str) -> None:
    assert_bad_input(run(trips_cfg, extra=[option, value]), option, f"'{value}'")


@pytest.mark.parametrize("other", [["--story", "s.py"], ["--services", "services.xml"]])
def test_no_snapshot_with_a_reader_of_the_snapshot(trips_cfg: Path, other: list[str]) -> None:
    assert_bad_input(run(trips_cfg, extra=["--no-snapshot", *other]), "--no-snapshot", other[0])


@pytest.mark.parametrize("value", ["abc", "-5", "nan", "inf", "", "10s"])
def test_bad_end_value(trips_cfg: Path, value: str) -> None:
    assert_bad_input(run(trips_cfg, extra=["--end", value]), "--end")


def test_bad_seed_value(trips_cfg: Path) -> None:
    assert_bad_input(run(trips_cfg, extra=["--seed", "twelve"]), "--seed", "twelve")


def test_unterminated_quote_in_sumo_option(trips_cfg: Path) -> None:
    line = assert_bad_input(run(trips_cfg, sumo_options=['--tripinfo-output "unterminated']), "--sumo-option")
    assert "quote" in line


def test_sumo_option_runs_no_command(trips_cfg: Path, tmp_path: Path) -> None:
    marker = tmp_path / "ran"
    for text in (f"--fcd-output $(touch {marker})", f"--fcd-output `touch {marker}`"):
        line = assert_bad_input(run(trips_cfg, sumo_options=[text]), "--sumo-option", "command substitution")
        assert text in line
    assert not marker.exists()


@pytest.mark.parametrize(("word", "needle"), [("a;b.xml", "special character"), ("$SBSIM_NO_SUCH_VARIABLE", "unset")])
def test_sumo_option_shell_errors(trips_cfg: Path, tmp_path: Path, word: str, needle: str) -> None:
    assert_bad_input(run(trips_cfg, sumo_options=[f"--fcd-output {tmp_path}/{word}"]), "--sumo-option", needle)


def test_unknown_sumo_option(trips_cfg: Path) -> None:
    line = assert_bad_input(run(trips_cfg, sumo_options=["--no-such-sumo-option 1"]), "no-such-sumo-option")
    assert "grid.sumocfg" in line


def test_bad_sumo_option_value(trips_cfg: Path) -> None:
    assert_bad_input(run(trips_cfg, sumo_options=["--begin soon"]), "soon")


def test_missing_story(trips_cfg: Path, tmp_path: Path) -> None:
    missing = tmp_path / "nope.py"
    assert_bad_input(run(trips_cfg, story=missing), "--story", str(missing))


def test_story_is_a_directory(trips_cfg: Path, tmp_path: Path) -> None:
    assert_bad_input(run(trips_cfg, story=tmp_path), "--story", str(tmp_path))


@pytest.mark.parametrize("where", ["missing_dir", "directory"])
def test_unwritable_events(trips_cfg: Path, tmp_path: Path, where: str) -> None:
    story = write_story(tmp_path, OK_STORY)
    events = tmp_path / "no" / "such" / "dir" / "ev.jsonl" if where == "missing_dir" else tmp_path
    assert_bad_input(run(trips_cfg, story=story, events=events), "--events", str(events))


def _routes_with(trips_cfg: Path, tmp_path: Path, vehicle: str, first: bool) -> Path:
    """The trips scenario with one more vehicle, before the others (``first``) or after them."""
    for f in ("net.net.xml", trips_cfg.name):
        shutil.copy(trips_cfg.parent / f, tmp_path / f)
    routes = (trips_cfg.parent / "routes.rou.xml").read_text(encoding="utf-8")
    if first:
        at = routes.index("<vehicle ")
        routes = routes[:at] + vehicle + "\n    " + routes[at:]
    else:
        routes = routes.replace("</routes>", vehicle + "\n</routes>")
    (tmp_path / "routes.rou.xml").write_text(routes, encoding="utf-8")
    return tmp_path / trips_cfg.name


def test_sumo_route_error_at_load_is_one_line(trips_cfg: Path, tmp_path: Path) -> None:
    # SUMO reads the first routes while loading: its message ("The edge 'nowhere' within the route for
    # vehicle 'lost' is not known.\n The route can not be build.") spans two lines.
    cfg = _routes_with(
        trips_cfg, tmp_path, '<vehicle id="lost" depart="0"><route edges="nowhere"/></vehicle>', first=True
    )
    line = assert_bad_input(run(cfg), "grid.sumocfg", "nowhere", "lost")
    assert "route can not be build" in line


def test_sumo_error_during_the_run_is_bad_input_in_one_line(trips_cfg: Path, tmp_path: Path) -> None:
    # SUMO reads routes departing after its first look-ahead (200 s) only while running; the error is
    # still the input's: exit 2, one line naming the file, the time and SUMO's reason.
    cfg = _routes_with(
        trips_cfg, tmp_path, '<vehicle id="late" depart="250"><route edges="nowhere"/></vehicle>', first=False
    )
    line = assert_bad_input(run(cfg, timeout=120), "grid.sumocfg", "nowhere", "late")
    assert "at t=" in line
