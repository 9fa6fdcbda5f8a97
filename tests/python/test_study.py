"""sbsim.study: a 2 x 3 study on a 2-worker LocalCluster, its tables, resuming, failures."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pandas as pd
import pytest
from sbsim import study
from sbsim.runner import run
from sbsim_helpers import write_story

STORY = """
    import storyboard

    def createStories(board):
        fast = storyboard.SpeedConditionGreater(float(board.parameter("threshold", 5)))
        board.registerStory(storyboard.Story(fast, [storyboard.SignalEffect("fast", on_exit="slow")], name="fast"))
        picked = storyboard.LikelihoodCondition(board.getRandomNumberGenerator(), 0.3)
        board.registerStory(storyboard.Story(picked, [storyboard.SpeedEffect(4.0)], name="picked"))
"""


@pytest.fixture(scope="module")
def cluster_env(monkeypatch_module: pytest.MonkeyPatch) -> None:
    """Dask workers import sbsim.study: they must see this tree's python/ folder."""
    root = Path(__file__).resolve().parents[2] / "python"
    monkeypatch_module.setenv("PYTHONPATH", f"{root}:{__import__('os').environ.get('PYTHONPATH', '')}")


@pytest.fixture(scope="module")
def monkeypatch_module() -> pytest.MonkeyPatch:
    with pytest.MonkeyPatch.context() as mp:
        yield mp


def make_spec(trips_cfg: Path, folder: Path, **changes: object) -> study.StudySpec:
    story = write_story(folder, STORY)
    data: dict[str, object] = {
        "sumocfg": str(trips_cfg),
        "story": str(story),
        "seeds": {"first": 1, "count": 3},
        "end": 40,
        "args": ["--threads", "1"],
        "parameters": {"threshold": [5, 20.0]},
        "outputs": {"directory": str(folder / "results")},
    }
    data.update(changes)
    return study.StudySpec.from_dict(data, base=folder)


def test_study_on_two_workers_writes_both_tables_like_sequential_runs(
    trips_cfg: Path, tmp_path: Path, cluster_env: None
) -> None:
    spec = make_spec(trips_cfg, tmp_path)
    result = study.run(spec, workers=2, progress=False)
    assert result.ran == 6 and not result.failed

    runs = pd.read_parquet(spec.directory / "runs.parquet")
    assert len(runs) == 6
    assert sorted(zip(runs["threshold"], runs["seed"], strict=True)) == [
        (5.0, 1), (5.0, 2), (5.0, 3), (20.0, 1), (20.0, 2), (20.0, 3)
    ]  # fmt: skip
    assert (runs["exit_code"] == 0).all()
    assert {"activations:fast", "activations:picked", "active_vehicle_s:fast", "steps", "wall_s"} <= set(runs.columns)
    assert (runs["steps"] == 40).all()
    # The parameter reaches the story: nobody drives above 20 m/s on this grid (13.89 m/s limit).
    by = runs.set_index(["threshold", "seed"])["activations:fast"]
    assert all(by[(20.0, s)] == 0 < by[(5.0, s)] for s in (1, 2, 3))
    seconds = runs.set_index(["threshold", "seed"])["active_vehicle_s:fast"]
    assert all(seconds[(20.0, s)] == 0 < seconds[(5.0, s)] for s in (1, 2, 3))
    # Seeds matter for the random story.
    assert runs[runs["threshold"] == 5]["activations:picked"].nunique() > 1

    events = pd.read_parquet(spec.directory / "events.parquet")
    assert {"run", "threshold", "seed", "t", "type", "story", "vehicle"} <= set(events.columns)
    # Every field of every event, not only the first event's (an activation has no cause).
    assert {"cause", "others", "reason", "phase"} <= set(events.columns), events.columns
    signals = events[events["type"] == "signal"]
    assert set(signals["cause"]) == {"fast", "slow"} and set(signals["phase"].dropna()) == {"exit"}
    assert set(events[events["type"] == "deactivate"]["reason"]) >= {"condition"}
    assert set(events["run"]) == set(runs["run"])

    # Every run's event log is byte for byte that of the same run made by hand, one after another.
    for r in spec.runs():
        alone = tmp_path / f"alone-{r.id}.jsonl"
        direct = run(
            trips_cfg, story=spec.story, events=alone, end=40, quiet=True, extra=[*r.arguments(), "--threads", "1"]
        )
        assert direct.returncode == 0, direct.stderr
        assert (spec.directory / "runs" / r.id / "events.jsonl").read_bytes() == alone.read_bytes(), r.id


def test_interrupted_study_runs_only_what_is_missing(trips_cfg: Path, tmp_path: Path, cluster_env: None) -> None:
    spec = make_spec(trips_cfg, tmp_path, parameters={"threshold": [5]})
    first = study.run(spec, workers=2, progress=False)
    assert first.ran == 3
    # As if stopped half-way: one run never finished, one never started.
    ids = [r.id for r in spec.runs()]
    (spec.directory / "runs" / ids[0] / "result.json").unlink()
    shutil.rmtree(spec.directory / "runs" / ids[2])
    kept = (spec.directory / "runs" / ids[1] / "result.json").stat().st_mtime_ns
    again = study.run(spec, workers=2, progress=False)
    assert again.ran == 2
    assert (spec.directory / "runs" / ids[1] / "result.json").stat().st_mtime_ns == kept
    assert len(pd.read_parquet(spec.directory / "runs.parquet")) == 3


def test_a_failing_run_is_recorded_not_fatal(trips_cfg: Path, tmp_path: Path, cluster_env: None) -> None:
    # The story refuses one parameter value: those runs fail (exit 2), the others go on.
    story = write_story(
        tmp_path,
        """
        import storyboard
        def createStories(board):
            if board.parameter("mode") == "broken":
                raise RuntimeError("this mode is broken")
            board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [storyboard.SignalEffect("x")]))
        """,
        name="modes.py",
    )
    spec = make_spec(trips_cfg, tmp_path, story=str(story), parameters={"mode": ["fine", "broken"]})
    result = study.run(spec, workers=2, progress=False)
    runs = pd.read_parquet(spec.directory / "runs.parquet")
    assert len(runs) == 6 and len(result.failed) == 3
    failed = runs[runs["mode"] == "broken"]
    assert (failed["exit_code"] == 2).all()
    assert failed["stderr_tail"].str.contains("this mode is broken").all()
    assert (runs[runs["mode"] == "fine"]["exit_code"] == 0).all()


def test_bad_study_files_are_one_line(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text('sumocfg = "x.sumocfg"\nseeds = []\n')
    with pytest.raises(study.StudyError, match="seeds must be"):
        study.StudySpec.load(bad)
    bad.write_text('sumocfg = "x.sumocfg"\nrain = 5\n')
    with pytest.raises(study.StudyError, match="unknown key 'rain'"):
        study.StudySpec.load(bad)
    bad.write_text("sumocfg = \n")
    with pytest.raises(study.StudyError, match="bad.toml"):
        study.StudySpec.load(bad)
    assert study.main([str(bad)]) == 2


def test_a_resumed_study_redoes_runs_whose_folders_are_corrupted(
    trips_cfg: Path, tmp_path: Path, cluster_env: None
) -> None:
    spec = make_spec(trips_cfg, tmp_path, parameters={}, seeds=[1, 2, 3, 4, 5, 6], end=20)
    first = study.run(spec, workers=2, progress=False)
    assert first.ran == 6 and not first.failed
    runs = spec.directory / "runs"
    assert sorted(p.name for p in runs.iterdir()) == [f"seed-{s}" for s in range(1, 7)]
    written = {s: (runs / f"seed-{s}" / "events.jsonl").read_bytes() for s in range(1, 7)}
    kept = (runs / "seed-1" / "result.json").stat().st_mtime_ns
    # seed-1 stays as it was; each other folder is damaged in one way.
    events = runs / "seed-2" / "events.jsonl"
    events.write_bytes(written[2][:-10])  # truncated
    (runs / "seed-3" / "summary.json").unlink()  # missing
    (runs / "seed-4" / "summary.json.incomplete").write_text("{", encoding="utf-8")  # a leftover
    record = runs / "seed-5" / "result.json"
    record.write_text(record.read_text(encoding="utf-8")[:40], encoding="utf-8")  # a truncated record
    (runs / "seed-6" / "events.jsonl").unlink()
    (runs / "seed-6" / "events.jsonl.incomplete").write_bytes(written[6][:100])  # stopped half-way

    again = study.run(spec, workers=2, progress=False)
    assert again.ran == 5 and not again.failed
    assert (runs / "seed-1" / "result.json").stat().st_mtime_ns == kept
    # Redone, each run wrote again what it wrote the first time, and no stale partial output is left.
    assert {s: (runs / f"seed-{s}" / "events.jsonl").read_bytes() for s in range(1, 7)} == written
    assert not list(runs.glob("*/*.incomplete"))
    table = pd.read_parquet(spec.directory / "runs.parquet")
    assert list(table["run"]) == [f"seed-{s}" for s in range(1, 7)] and (table["steps"] == 20).all()
    # Sound again: nothing more to do.
    assert study.run(spec, workers=2, progress=False).ran == 0


def test_a_run_whose_folder_cannot_be_made_fails_alone(trips_cfg: Path, tmp_path: Path) -> None:
    spec = make_spec(trips_cfg, tmp_path, parameters={}, seeds=[1])
    (spec.directory / "runs").mkdir(parents=True)
    (spec.directory / "runs" / "seed-1").write_text("a file where the run's folder should be", encoding="utf-8")
    (r,) = spec.runs()
    row = study.execute(spec, r, "/nonexistent/sbsim")
    assert row["exit_code"] == 2 and "the run's folder" in row["stderr_tail"] and "File exists" in row["stderr_tail"]
    assert study.result_of(spec.directory / "runs" / "seed-1") is None


def test_a_resumed_study_checks_the_outputs_content_not_their_size(
    trips_cfg: Path, tmp_path: Path, cluster_env: None
) -> None:
    # A damaged statistics.parquet or trace of the right size is no finished run (issue 29).
    services = tmp_path / "s.xml"
    services.write_text('<services><service type="CaService"/></services>\n', encoding="utf-8")
    spec = make_spec(
        trips_cfg,
        tmp_path,
        parameters={},
        seeds=[1, 2, 3],
        end=20,
        services=str(services),
        outputs={"directory": str(tmp_path / "results"), "statistics": True, "messages": True},
    )
    assert study.run(spec, workers=2, progress=False).ran == 3
    runs = spec.directory / "runs"
    kept = (runs / "seed-1" / "result.json").stat().st_mtime_ns
    for seed, name in ((2, "statistics.parquet"), (3, "messages.parquet")):
        damaged = bytearray((runs / f"seed-{seed}" / name).read_bytes())
        damaged[len(damaged) // 2] ^= 0xFF  # one byte flipped: the same size
        (runs / f"seed-{seed}" / name).write_bytes(bytes(damaged))
        assert study.result_of(runs / f"seed-{seed}") is None
    again = study.run(spec, workers=2, progress=False)
    assert again.ran == 2 and not again.failed
    assert (runs / "seed-1" / "result.json").stat().st_mtime_ns == kept


def test_radio_mistakes_of_the_study_file_end_it_before_the_first_run(
    trips_cfg: Path, tmp_path: Path, cluster_env: None
) -> None:
    services = tmp_path / "s.xml"
    services.write_text('<services><service type="CaService"/></services>\n', encoding="utf-8")
    radio = tmp_path / "radio.toml"
    radio.write_text("[phy]\npower_dbm = 20\n", encoding="utf-8")
    with pytest.raises(study.StudyError, match="'radio' needs 'services'"):
        make_spec(trips_cfg, tmp_path, radio=str(radio))
    with pytest.raises(study.StudyError, match="parameter 'radio_power_dbm' .* needs 'radio'"):
        make_spec(trips_cfg, tmp_path, services=str(services), parameters={"radio_power_dbm": [10]})
    # One value of the sweep sbsim refuses: the study ends at once, no run started.
    spec = make_spec(
        trips_cfg,
        tmp_path,
        services=str(services),
        radio=str(radio),
        parameters={"radio_queue_limit": [4, 2.5]},
        seeds=[1],
    )
    with pytest.raises(study.StudyError, match=r"radio_queue_limit=2\.5: .*queue_limit: must be a whole number"):
        study.run(spec, workers=1, progress=False)
    assert not (spec.directory / "runs").exists()


def test_the_command_refuses_a_radio_value_before_making_any_folder(
    trips_cfg: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "s.xml").write_text('<services><service type="CaService"/></services>\n', encoding="utf-8")
    (tmp_path / "radio.toml").write_text("[mac]\naifsn = 3\n", encoding="utf-8")
    (tmp_path / "study.toml").write_text(
        f'sumocfg = "{trips_cfg}"\nservices = "s.xml"\nradio = "radio.toml"\nseeds = [1, 2]\n'
        "[parameters]\nradio_aifsn = [2, 99]\n",
        encoding="utf-8",
    )
    assert study.main([str(tmp_path / "study.toml")]) == 2
    [line] = capsys.readouterr().err.splitlines()
    assert re.fullmatch(
        r"study: radio_aifsn=99: --param radio_aifsn: must be a whole number from 1 to 15, got 99", line
    )
    assert not (tmp_path / "results").exists()


def test_check_reads_the_whole_study_file_and_runs_nothing(
    trips_cfg: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Issue "results at scale": a study file is checked like a run's inputs — here a story parameter whose
    # value the story refuses only for one combination of the sweep.
    write_story(
        tmp_path,
        """
        import storyboard

        def createStories(board):
            if board.parameter("mode") == "broken":
                raise ValueError("mode 'broken' has no stories")
        """,
    )
    (tmp_path / "study.toml").write_text(
        f'sumocfg = "{trips_cfg}"\nstory = "story.py"\nseeds = [1, 2, 3]\nend = 10\n'
        '[parameters]\nmode = ["fine", "other"]\n',
        encoding="utf-8",
    )
    assert study.main([str(tmp_path / "study.toml"), "--check"]) == 0
    assert capsys.readouterr().out.strip().endswith("6 runs, every parameter combination checked")
    assert not (tmp_path / "results").exists()
    (tmp_path / "study.toml").write_text(
        f'sumocfg = "{trips_cfg}"\nstory = "story.py"\nseeds = [1]\n[parameters]\nmode = ["fine", "broken"]\n',
        encoding="utf-8",
    )
    assert study.main([str(tmp_path / "study.toml"), "--check"]) == 2
    [line] = capsys.readouterr().err.splitlines()
    assert line.startswith("study: run mode-broken") and "mode 'broken' has no stories" in line, line
    assert not (tmp_path / "results").exists()
