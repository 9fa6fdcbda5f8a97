"""The sbsim program: default run, options, determinism, pass-through to SUMO, installation."""

from __future__ import annotations

import re
import signal
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from sbsim.runner import executable, run
from sbsim_helpers import (
    REPO,
    assert_bad_input,
    assert_no_crash,
    env_without,
    stable_stdout,
    wait_for_file,
    write_story,
)

SUMMARY_KEYS = ("end", "steps", "vehicles seen", "peak running", "wall time", "real-time factor")


def fcd_body(path: Path) -> str:
    """The FCD file from its first timestep on (the header holds the generation time)."""
    text = path.read_text(encoding="utf-8")
    start = text.find("<timestep")
    assert start >= 0, f"no timestep in {path}"
    return text[start:]


# --------------------------------------------------------------------------- default run, --version, --help


def test_no_arguments_runs_the_bundled_scenario() -> None:
    result = run(timeout=120)
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    summary = result.summary()
    for key in SUMMARY_KEYS:
        assert key in summary, f"summary lacks {key!r}:\n{result.stdout}"
    assert "grid-rain.sumocfg" in result.stdout.splitlines()[0]
    # stories/grid-rain: 600 s, 400 trips (veh0 ... veh399).
    assert summary["steps"] == "600"
    assert summary["vehicles seen"] == "400"
    assert summary["end"].startswith("600 s")
    assert 0 < int(summary["peak running"]) <= 400
    assert float(summary["wall time"].removesuffix(" s")) > 0
    assert float(summary["real-time factor"]) > 0


def test_version() -> None:
    result = run(extra=["--version"])
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("sbsim ")
    assert result.stdout.split()[1][0].isdigit(), result.stdout


def test_help_lists_the_options() -> None:
    result = run(extra=["--help"])
    assert result.returncode == 0, result.stderr
    for option in ("--sumocfg", "--story", "--events", "--end", "--seed", "--sumo-option", "--quiet", "--version"):
        assert option in result.stdout, f"--help does not mention {option}"


#: Every option of sbsim [options], its short form, and the default --help names for it (None: none shown).
OPTIONS: dict[str, tuple[str | None, str | None]] = {
    "--sumocfg": ("-c", None),
    "--story": (None, None),
    "--scenario": (None, None),
    "--bind": (None, None),
    "--end": (None, None),
    "--seed": (None, None),
    "--warmup": (None, "0"),
    "--sumo-option": (None, None),
    "--services": (None, None),
    "--plugin": (None, None),
    "--param": (None, None),
    "--summary": (None, None),
    "--statistics": (None, None),
    "--junit": (None, None),
    "--middleware-interval": (None, "0.1"),
    "--v2x-range": (None, "500"),
    "--v2x-latency": (None, "0.001"),
    "--v2x-fade-start": (None, None),
    "--gn-forwarding": (None, "on"),
    "--gn-hop-limit": (None, "10"),
    "--radio": (None, None),
    "--messages": (None, None),
    "--messages-range": (None, None),
    "--messages-types": (None, None),
    "--messages-events": (None, None),
    "--messages-max-bytes": (None, "2G"),
    "--penetration": (None, "1"),
    "--storyboard-equipped-only": (None, None),
    "--events": (None, None),
    "--threads": (None, "0"),
    "--no-snapshot": (None, None),
    "--gui": (None, None),
    "--gui-delay": (None, None),
    "--gui-screenshot": (None, None),
    "--sumo-log": (None, None),
    "--verbose": ("-v", None),
    "--quiet": ("-q", None),
    "--version": (None, None),
    "--help": ("-h", None),
}


def help_entries(text: str) -> dict[str, tuple[str | None, str]]:
    """--help's option entries: long name -> (short name, text including its continuation lines)."""
    entries: dict[str, tuple[str | None, str]] = {}
    current = None
    for line in text.splitlines():
        m = re.match(r"  (?:(-\w),)?(--[\w-]+)(?: \S+)?\s{2,}(\S.*)$", line)
        if m:
            current = m.group(2)
            assert current not in entries, f"{current} listed twice"
            entries[current] = (m.group(1), m.group(3))
        elif current and line.startswith(" " * 20) and line.strip():
            short, description = entries[current]
            entries[current] = (short, f"{description} {line.strip()}")
        else:
            current = None
    return entries


def readme_option_rows() -> dict[str, list[str]]:
    """The README's option table: long option -> its cells (option, meaning, default)."""
    section = (REPO / "README.md").read_text(encoding="utf-8").split("## The program", 1)[1].split("\n## ", 1)[0]
    rows: dict[str, list[str]] = {}
    for line in section.splitlines():
        if line.startswith("| `"):
            cells = [c.strip() for c in line.strip("|").split("|")]
            rows[re.findall(r"--[\w-]+", cells[0])[0]] = cells
    return rows


def test_help_lists_every_option_with_its_meaning_and_default() -> None:
    result = run(extra=["--help"])
    assert result.returncode == 0, result.stderr
    entries = help_entries(result.stdout)
    assert set(entries) == set(OPTIONS)
    for option, (short, default) in OPTIONS.items():
        help_short, description = entries[option]
        assert help_short == short, f"{option}: short form {help_short!r}, expected {short!r}"
        assert len(description) > 10, f"{option} has no meaning in --help: {description!r}"
        if default is not None:
            assert description.endswith(f"(default: {default})"), f"{option}: {description!r}"
    # The words after -- are explained too.
    assert "[-- SUMO-OPTION...]" in result.stdout
    assert "-c FILE" in result.stdout.split("Words after --", 1)[1]


def test_readme_option_table_matches_the_help() -> None:
    rows = readme_option_rows()
    assert set(rows) == set(OPTIONS)
    for option, (short, default) in OPTIONS.items():
        if short is not None:
            assert f"`{short}`" in rows[option][0], f"README lacks {short} for {option}"
        if default is not None:
            assert rows[option][2] == default, f"README's default for {option}: {rows[option][2]!r}"


def test_help_names_every_default_the_readme_names() -> None:
    entries = help_entries(run(extra=["--help"]).stdout)
    for option, cells in readme_option_rows().items():
        if cells[2] not in ("", "none", "off"):
            assert "(default: " in entries[option][1], f"--help does not give {option}'s default ({cells[2]})"


def test_quiet_prints_no_summary(trips_cfg: Path) -> None:
    result = run(trips_cfg, end=20, quiet=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""


def test_summary_counts_a_small_scenario(trips_cfg: Path) -> None:
    result = run(trips_cfg, timeout=120)
    assert result.returncode == 0, result.stderr
    summary = result.summary()
    # make_grid: one trip every 2 s from 0 to 300 s -> 150 vehicles; sumocfg end 300 s, step 1 s.
    assert summary["vehicles seen"] == "150"
    assert summary["steps"] == "300"
    assert summary["end"].startswith("300 s")


# --------------------------------------------------------------------------- determinism

RANDOM_STORY = """
    import storyboard
    def createStories(board):
        rng = board.getRandomNumberGenerator()
        board.registerStory(storyboard.Story(storyboard.LikelihoodCondition(rng, 0.5),
                                             [storyboard.SpeedEffect(5.0)], "half"))
        board.registerStory(storyboard.Story(
            storyboard.AndCondition(storyboard.TimeCondition(30), storyboard.DeferringCondition(rng, 5, 40)),
            [storyboard.SignalEffect("late")], "deferred"))
"""


def _seeded_run(cfg: Path, directory: Path, seed: int) -> tuple[str, bytes, str]:
    directory.mkdir()
    story = write_story(directory, RANDOM_STORY)
    result = run(
        cfg,
        story=story,
        events=directory / "ev.jsonl",
        seed=seed,
        end=150,
        sumo_options=[f"--fcd-output {directory / 'fcd.xml'}"],
        timeout=120,
    )
    assert result.returncode == 0, result.stderr
    return stable_stdout(result.stdout), (directory / "ev.jsonl").read_bytes(), fcd_body(directory / "fcd.xml")


def test_same_seed_gives_identical_output(trips_cfg: Path, tmp_path: Path) -> None:
    out1, events1, fcd1 = _seeded_run(trips_cfg, tmp_path / "a", seed=7)
    out2, events2, fcd2 = _seeded_run(trips_cfg, tmp_path / "b", seed=7)
    assert events1, "the story logged no event"
    assert out1 == out2
    assert events1 == events2
    assert fcd1 == fcd2


def test_different_seed_can_differ(trips_cfg: Path, tmp_path: Path) -> None:
    _, events1, fcd1 = _seeded_run(trips_cfg, tmp_path / "a", seed=7)
    _, events2, fcd2 = _seeded_run(trips_cfg, tmp_path / "b", seed=8)
    assert fcd1 != fcd2, "SUMO did not get the seed"
    assert events1 != events2, "the storyboard's random generators did not get the seed"


def test_seed_reaches_sumo_without_a_story(trips_cfg: Path, tmp_path: Path) -> None:
    bodies = []
    for seed in (1, 1, 2):
        out = tmp_path / f"trip{len(bodies)}.xml"
        result = run(trips_cfg, seed=seed, end=150, sumo_options=[f"--tripinfo-output {out}"])
        assert result.returncode == 0, result.stderr
        text = out.read_text(encoding="utf-8")
        bodies.append(text[text.find("<tripinfo ") :])
    assert bodies[0] == bodies[1]
    assert bodies[0] != bodies[2]


# --------------------------------------------------------------------------- --end


@pytest.mark.parametrize("end", [0, 1, 50, 123])
def test_end_stops_at_the_step_reaching_it(trips_cfg: Path, end: int) -> None:
    result = run(trips_cfg, end=end)
    assert result.returncode == 0, result.stderr
    summary = result.summary()
    assert summary["steps"] == str(end)
    assert summary["end"].split()[0] == str(end)
    assert "end time" in summary["end"]


def test_end_between_steps_runs_the_step_reaching_it(trips_cfg: Path) -> None:
    # Step length 1 s: t = 10 has not reached 10.5 s yet; the step to 11 s reaches it (as SUMO's own --end).
    result = run(trips_cfg, end=10.5)
    assert result.returncode == 0, result.stderr
    summary = result.summary()
    assert summary["end"].split()[0] == "11"
    assert summary["steps"] == "11"


def test_end_after_the_last_vehicle_stops_when_no_vehicle_is_left(trips_cfg: Path) -> None:
    result = run(trips_cfg, end=5000, sumo_options=["--end 5000"])
    assert result.returncode == 0, result.stderr
    summary = result.summary()
    assert "no more vehicles" in summary["end"]
    assert 300 <= int(summary["steps"]) < 5000
    assert summary["vehicles seen"] == "150"


# --------------------------------------------------------------------------- --sumo-option


def test_sumo_option_tripinfo_output_is_written(trips_cfg: Path, tmp_path: Path) -> None:
    out = tmp_path / "tripinfo.xml"
    result = run(trips_cfg, end=100, sumo_options=[f"--tripinfo-output {out}"])
    assert result.returncode == 0, result.stderr
    trips = ET.parse(out).getroot().findall("tripinfo")
    assert trips, "no vehicle arrived within 100 s"
    assert all(float(t.attrib["arrival"]) <= 100 for t in trips)


def test_sumo_option_begin_shifts_the_start(trips_cfg: Path) -> None:
    result = run(trips_cfg, end=100, sumo_options=["--begin 50"])
    assert result.returncode == 0, result.stderr
    summary = result.summary()
    assert summary["steps"] == "50"
    assert summary["end"].split()[0] == "100"


def test_sumo_option_is_repeatable_and_quoted_like_a_shell(trips_cfg: Path, tmp_path: Path) -> None:
    spaced = tmp_path / "dir with space"
    spaced.mkdir()
    trip, fcd = spaced / "trip info.xml", tmp_path / "fcd.xml"
    result = run(trips_cfg, end=60, sumo_options=[f"--tripinfo-output '{trip}'", f"--fcd-output {fcd}", "--begin 10"])
    assert result.returncode == 0, result.stderr
    assert trip.is_file()
    times = [float(ts.attrib["time"]) for ts in ET.parse(fcd).getroot().iter("timestep")]
    assert times and min(times) == 10 and max(times) < 60
    assert result.summary()["steps"] == "50"


def test_sumo_option_overrides_the_sumocfg_end(trips_cfg: Path) -> None:
    result = run(trips_cfg, sumo_options=["--end 40"])
    assert result.returncode == 0, result.stderr
    assert result.summary()["steps"] == "40"


def test_sumo_option_double_quotes_and_backslashes(trips_cfg: Path, tmp_path: Path) -> None:
    fcd, trip = tmp_path / "f c d.xml", tmp_path / "trip info.xml"
    escaped = str(trip).replace(" ", "\\ ")
    result = run(trips_cfg, end=20, sumo_options=[f'--fcd-output "{fcd}"', f"--tripinfo-output {escaped}"])
    assert result.returncode == 0, result.stderr
    assert fcd.is_file()
    assert trip.is_file()


# --------------------------------------------------------------------------- words after --


def test_words_after_double_dash_go_to_sumo_as_they_are(trips_cfg: Path, tmp_path: Path) -> None:
    # No shell splitting after --: a space and a quote stay in the file name.
    directory = tmp_path / "it's here"
    directory.mkdir()
    fcd = directory / "f c d.xml"
    result = run(end=60, extra=["--", "-c", str(trips_cfg), "--begin", "10", "--fcd-output", str(fcd)])
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[0].endswith(f": {trips_cfg.name}")
    assert result.summary()["steps"] == "50"
    times = [float(ts.attrib["time"]) for ts in ET.parse(fcd).getroot().iter("timestep")]
    assert times and min(times) == 10 and max(times) < 60


@pytest.mark.parametrize("spelling", [["-c"], ["--configuration-file"], ["--configuration-file="]])
def test_configuration_file_after_double_dash_is_the_sumocfg(trips_cfg: Path, spelling: list[str]) -> None:
    words = [spelling[0] + str(trips_cfg)] if spelling[0].endswith("=") else [*spelling, str(trips_cfg)]
    result = run(end=20, extra=["--", "--begin", "5", *words])
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[0].endswith(f": {trips_cfg.name}")
    assert result.summary()["steps"] == "15"


def test_double_dash_after_sumocfg_and_sumo_option(trips_cfg: Path, tmp_path: Path) -> None:
    trip = tmp_path / "trip.xml"
    result = run(trips_cfg, end=40, sumo_options=["--begin 10"], extra=["--", "--tripinfo-output", str(trip)])
    assert result.returncode == 0, result.stderr
    assert result.summary()["steps"] == "30"
    assert trip.is_file()


def test_sumocfg_given_twice() -> None:
    line = assert_bad_input(run("a.sumocfg", extra=["--", "-c", "b.sumocfg"]), "--sumocfg", "a.sumocfg", "b.sumocfg")
    assert "twice" in line


def test_configuration_file_after_double_dash_without_a_file() -> None:
    assert_bad_input(run(extra=["--", "--begin", "5", "-c"]), "configuration-file")


def test_words_after_double_dash_are_not_sbsims(trips_cfg: Path) -> None:
    # --story after -- is SUMO's (unknown to it), not sbsim's: SUMO's refusal names it.
    assert_bad_input(run(trips_cfg, extra=["--", "--story", "x.py"]), "story", "grid.sumocfg")


# --------------------------------------------------------------------------- installation


def test_runs_without_ld_library_path_and_story_sees_numpy(trips_cfg: Path, tmp_path: Path) -> None:
    marker = tmp_path / "numpy.txt"
    story = write_story(
        tmp_path,
        f"""
        import numpy as np
        import storyboard

        class Fast(storyboard.Condition):
            def test_all(self, snapshot):
                speeds = np.asarray(snapshot.speeds)
                with open({str(marker)!r}, "w") as f:
                    f.write(np.__version__)
                return speeds > 1.0

        def createStories(board):
            board.registerStory(storyboard.Story(Fast(), [storyboard.SignalEffect("moving")], "fast"))
    """,
    )
    env = env_without("LD_LIBRARY_PATH", "PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV", "SUMO_HOME")
    env["PATH"] = "/usr/bin:/bin"
    done = subprocess.run(
        [str(executable()), "--sumocfg", str(trips_cfg), "--story", str(story), "--end", "30"],
        capture_output=True,
        text=True,
        env=env,
        cwd="/",
        timeout=120,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert marker.read_text(encoding="utf-8")[0].isdigit()
    assert "activations fast:" in done.stdout
    assert int(done.stdout.split("activations fast:")[1].split()[0]) > 0


def test_threads_do_not_change_the_result(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        import storyboard
        def createStories(board):
            rng = board.getRandomNumberGenerator()
            board.registerStory(storyboard.Story(storyboard.LikelihoodCondition(rng, 0.5), [], "half"))
            board.registerStory(storyboard.Story(storyboard.SpeedDifferenceConditionFaster(3.0, 80),
                                                 [storyboard.SignalEffect("faster")], "faster"))
            board.registerStory(storyboard.Story(storyboard.TtcCondition(3.0),
                                                 [storyboard.SignalEffect("ttc")], "ttc"))
    """,
    )
    outputs = []
    for threads in ("1", "2", "0"):
        events = tmp_path / f"ev{threads}.jsonl"
        result = run(trips_cfg, story=story, events=events, seed=3, end=200, extra=["--threads", threads])
        assert result.returncode == 0, result.stderr
        outputs.append((stable_stdout(result.stdout), events.read_bytes()))
    assert outputs[0][1], "no events"
    assert outputs[0] == outputs[1] == outputs[2]


def test_story_without_sumocfg_runs_on_the_bundled_scenario(tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        import storyboard
        def createStories(board):
            board.registerStory(storyboard.Story(storyboard.CarSetCondition("veh399"), [], "last"))
    """,
    )
    result = run(story=story, timeout=120)
    assert result.returncode == 0, result.stderr
    assert "grid-rain.sumocfg" in result.stdout.splitlines()[0]
    assert result.summary()["activations last"] == "1"


def test_ctrl_c_stops_after_the_step_and_closes_sumo(trips_cfg: Path, tmp_path: Path) -> None:
    # A story that tells it is stepping (the marker file) and makes every step take at least 20 ms
    # whatever the machine, so the run (300 steps) is still going when SIGINT arrives.
    marker = tmp_path / "stepping"
    story = write_story(
        tmp_path,
        f"""
        import time
        from pathlib import Path
        import numpy as np
        import storyboard

        class Slow(storyboard.Condition):
            def test_all(self, snapshot):
                Path({str(marker)!r}).touch()
                time.sleep(0.02)
                return np.zeros(len(snapshot), bool)

        def createStories(board):
            board.registerStory(storyboard.Story(Slow(), []))
        """,
    )
    tripinfo = tmp_path / "tripinfo.xml"
    proc = subprocess.Popen(
        [
            str(executable()),
            "--sumocfg",
            str(trips_cfg),
            "--story",
            str(story),
            "--end",
            "300",
            "--sumo-option",
            f"--tripinfo-output {tripinfo} --tripinfo-output.write-unfinished",
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        wait_for_file(proc, marker)
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=30)
    finally:
        proc.kill()
    assert proc.returncode == 130, err
    assert "(interrupted)" in out
    assert "sbsim: interrupted at t=" in err
    # SUMO was closed properly: its output file is complete XML.
    ET.parse(tripinfo)
