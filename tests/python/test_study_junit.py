"""A study's merged junit.xml (a suite per run, named by parameters and seed; well-formed whatever the
criteria's names and values hold), --fail-on-criteria's exit code 3, and runs.parquet's equipped count."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pandas as pd
import pytest
from sbsim import study
from sbsim.runner import read_summary
from sbsim_helpers import write_story

STORY = """
    import storyboard

    def createStories(board):
        if board.parameter("mode") == "broken":
            raise RuntimeError("this mode is broken")
        board.registerCriterion(storyboard.NoCollision(), name="no crash")
        # Always fails (vehicles move); its name holds characters XML 1.0 forbids and ones it escapes.
        board.registerCriterion(storyboard.MaxSpeed(0.5, equipped_only=True), name="slow\\x01\\x1b <&> \\"q\\"")
"""

#: The failing criterion's name as the JUnit file shows it: the forbidden characters escaped, visibly.
SHOWN = 'slow\\x01\\x1b <&> "q"'


@pytest.fixture
def cluster_env(monkeypatch: pytest.MonkeyPatch) -> None:
    """Dask workers import sbsim.study: they must see this tree's python/ folder."""
    root = Path(__file__).resolve().parents[2] / "python"
    monkeypatch.setenv("PYTHONPATH", f"{root}:{__import__('os').environ.get('PYTHONPATH', '')}")


def write_study(folder: Path, cfg: Path, modes: list[str]) -> Path:
    story = write_story(folder, STORY)
    services = folder / "services.xml"
    services.write_text('<services><service type="ClearLaneService"/></services>\n', encoding="utf-8")
    path = folder / "study.toml"
    lines = [
        f"sumocfg = {json.dumps(str(cfg))}",
        f"story = {json.dumps(story.name)}",
        'services = "services.xml"',
        "seeds = [1, 2]",
        "end = 40",
        'args = ["--threads", "1"]',
        "[parameters]",
        f"mode = {json.dumps(modes)}",
        "penetration = [0.5]",
        "[outputs]",
        'directory = "results"',
    ]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def test_a_study_writes_one_junit_file_and_fails_on_criteria_when_asked(
    trips_cfg: Path, tmp_path: Path, cluster_env: None, capsys: pytest.CaptureFixture[str]
) -> None:
    toml = write_study(tmp_path, trips_cfg, ["fine"])
    # Every run is complete (exit 3: a criterion failed): by default the study succeeds.
    assert study.main([str(toml), "--workers", "2"]) == 0
    err = capsys.readouterr().err
    assert "study: run mode-fine_penetration-0.5_seed-1" in err and "criteria failed" in err, err
    # Asked to, it says a criterion failed (the runs are done: nothing runs again).
    assert study.main([str(toml), "--workers", "2", "--fail-on-criteria"]) == 3
    assert "(0 run now, 0 failed)" in capsys.readouterr().out

    results = tmp_path / "results"
    root = ET.parse(results / "junit.xml").getroot()  # well-formed, whatever the names held
    assert root.tag == "testsuites"
    suites = root.findall("testsuite")
    names = [f"mode=fine, penetration=0.5, seed={seed}" for seed in (1, 2)]
    assert [s.get("name") for s in suites] == names
    assert (root.get("tests"), root.get("failures"), root.get("errors")) == ("4", "2", "0")
    runs = pd.read_parquet(results / "runs.parquet")
    for suite, seed in zip(suites, (1, 2), strict=True):
        props = {p.get("name"): p.get("value") for p in suite.findall("properties/property")}
        assert props["mode"] == "fine" and props["seed"] == str(seed) and props["exit_code"] == "3"
        cases = {c.get("name"): c for c in suite.findall("testcase")}
        assert set(cases) == {"no crash", SHOWN}
        assert cases["no crash"].find("failure") is None
        failure = cases[SHOWN].find("failure")
        assert failure is not None and failure.get("type") == "criterion"
        message = failure.get("message", "")
        assert message.startswith("actual: ") and message.endswith("expected: <= 0.5 m/s"), message
        # The equipped vehicles a run counted: in runs.parquet, as its summary has them.
        summary = read_summary(results / "runs" / props["run"] / "summary.json")
        row = runs[runs["run"] == props["run"]].iloc[0]
        assert row["equipped"] == summary["equipped"]["count"] > 0

    # A run that failed is an error case with its exit code, and the study's exit code stays 1.
    toml = write_study(tmp_path, trips_cfg, ["fine", "broken"])
    assert study.main([str(toml), "--workers", "2", "--fail-on-criteria"]) == 1
    root = ET.parse(results / "junit.xml").getroot()
    broken = [s for s in root.findall("testsuite") if s.get("name", "").startswith("mode=broken")]
    assert [s.get("name") for s in broken] == [f"mode=broken, penetration=0.5, seed={seed}" for seed in (1, 2)]
    for suite in broken:
        [case] = suite.findall("testcase")
        error = case.find("error")
        assert case.get("name") == "run" and error is not None and error.get("message") == "exit code 2"
        assert "this mode is broken" in (error.text or "")
    assert (root.get("tests"), root.get("failures"), root.get("errors")) == ("6", "2", "2")


def test_xml_text_escapes_what_xml_forbids() -> None:
    assert study.xml_text("a\x00b\x1fc\td\ne\rf\ufffeg\ud800h") == "a\\x00b\\x1fc\td\ne\rf\\ufffeg\\ud800h"
    assert study.suite_name(study.Run((("speed", 5), ("name", "x")), 7)) == "speed=5, name=x, seed=7"
    assert study.suite_name(study.Run((), 3)) == "seed=3"
