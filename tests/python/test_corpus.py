"""The hostile-input corpus (tests/corpus/): every case is a folder with its inputs and a case.json.

case.json keys:
- ``args``: sbsim's arguments, run in a scratch copy of the folder (paths relative to it);
- ``exit``: the expected exit code; ``message``: a regular expression the one message line must match;
- ``scenario`` (optional): "trips" copies the small generated grid (grid.sumocfg, net.net.xml,
  routes.rou.xml) in first; the case's own files override it;
- ``setup`` (optional): shell lines run in the scratch folder before (FIFOs, truncated files, symlinks);
- ``interrupt`` (optional): ``{"signal": "SIGINT", "ready": "<file>", "repeat": n}``: the signal is sent once the
  run has created ``ready`` (the case's story touches it where the signal is to land), never after a fixed time,
  so the case holds on any machine; a run that could end before the signal is made long by its story (a sleep per
  step) and bounded by ``--end``. ``repeat``: signals sent while the run goes on (a second one ends it at once);
- ``outputs`` (optional): files the run may leave complete (a successful run's event log);
- ``message_lost`` (optional): the case closes stderr itself, so no message line can arrive;
- ``produces`` (optional): files the run must leave (a finished log that must not be lost).

Every case must give the expected exit within the timeout, one message line on stderr (warnings and,
for story errors, the Python traceback before it aside),
no crash, leave every input byte for byte as it was, and leave no other output that looks complete
(only ``*.incomplete`` files may appear).
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
from pathlib import Path
from typing import Any

import pytest
from sbsim.runner import executable
from sbsim_helpers import CRASH_MARKERS, REPO, wait_for_file

CORPUS = REPO / "tests" / "corpus"
CASES = sorted(p.parent.name for p in CORPUS.glob("*/case.json"))
TIMEOUT = 60.0
# With ``repeat``, how long a signal may take to end the run before the next is sent.
REPEAT_AFTER = 1.0


def snapshot(folder: Path) -> dict[str, str]:
    """Hash of every regular file under ``folder`` (FIFOs and devices are not read)."""
    hashes = {}
    for path in sorted(folder.rglob("*")):
        if path.is_symlink() or not path.is_file():
            continue
        hashes[str(path.relative_to(folder))] = hashlib.sha256(path.read_bytes()).hexdigest()
    return hashes


def message_lines(stderr: str) -> list[str]:
    """stderr's lines that are not warnings (SUMO's or sbsim's), not blank, and not part of the Python
    traceback a story error prints before its one line (for the script's author)."""
    lines = []
    in_traceback = False
    for line in stderr.splitlines():
        if line.startswith("Traceback (most recent call last):"):
            in_traceback = True
        if line.startswith("sbsim:"):
            in_traceback = False
        if in_traceback or not line.strip() or re.match(r"^(sbsim: )?warning:|^Warning:", line, re.IGNORECASE):
            continue
        lines.append(line)
    return lines


def run_case(case: dict[str, Any], work: Path) -> tuple[int, str, str]:
    command = [str(executable()), *case["args"]]
    proc = subprocess.Popen(
        command, cwd=work, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    interrupt = case.get("interrupt")
    if interrupt is not None:
        assert "when" not in interrupt, "a signal after a fixed time depends on the machine's speed: use 'ready'"
        wait_for_file(proc, work / interrupt["ready"], TIMEOUT)
        for _ in range(int(interrupt.get("repeat", 1))):
            if proc.poll() is not None:
                break
            proc.send_signal(getattr(signal, interrupt["signal"]))
            # Two signals sent at once may arrive as one: the next goes once this one had time to
            # act (the run ending, which ends the loop, is what a single signal does).
            try:
                proc.wait(timeout=REPEAT_AFTER)
            except subprocess.TimeoutExpired:
                pass
    try:
        out, err = proc.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        pytest.fail(f"sbsim did not end within {TIMEOUT:.0f} s")
    return proc.returncode, out, err


def test_no_case_signals_after_a_fixed_time() -> None:
    # A signal sent after a fixed sleep lands after the run's end on a fast machine (issue 29).
    for name in CASES:
        interrupt = json.loads((CORPUS / name / "case.json").read_text(encoding="utf-8")).get("interrupt")
        if interrupt is not None:
            assert set(interrupt) <= {"signal", "ready", "repeat"} and "ready" in interrupt, name
            story = (CORPUS / name / "story.py").read_text(encoding="utf-8")
            assert interrupt["ready"] in story, f"{name}: its story never creates {interrupt['ready']}"


@pytest.fixture(scope="session")
def corpus_scenario(trips_cfg: Path) -> Path:
    return trips_cfg.parent


@pytest.mark.parametrize("name", CASES)
def test_corpus_case(name: str, tmp_path: Path, corpus_scenario: Path) -> None:
    source = CORPUS / name
    case = json.loads((source / "case.json").read_text(encoding="utf-8"))
    work = tmp_path / name
    work.mkdir()
    if case.get("scenario") == "trips":
        for f in corpus_scenario.iterdir():
            if f.is_file():
                shutil.copy(f, work / f.name)
    for f in source.iterdir():
        if f.name != "case.json":
            shutil.copy(f, work / f.name)
    env = dict(os.environ)
    for line in case.get("setup", []):
        subprocess.run(line, shell=True, cwd=work, check=True, env=env)
    before = snapshot(work)

    code, out, err = run_case(case, work)

    for marker in CRASH_MARKERS:
        assert marker not in err, f"crash marker {marker!r}:\n{err}"
    assert code >= 0, f"killed by signal {-code}:\n{err}"
    assert code == case["exit"], f"exit {code}, expected {case['exit']}:\n{err}"
    lines = message_lines(err)
    if case.get("message_lost"):
        assert not lines, f"stderr was closed, yet:\n{err}"
    elif case["exit"] != 0:
        assert len(lines) == 1, f"expected one message line, got {len(lines)}:\n{err}"
        assert re.search(case["message"], lines[0]), f"{lines[0]!r} does not match {case['message']!r}"
    elif "message" in case:
        assert re.search(case["message"], err), f"stderr does not match {case['message']!r}:\n{err}"

    after = snapshot(work)
    for path, digest in before.items():
        assert after.get(path) == digest, f"input {path} was changed or removed"
    allowed = set(case.get("outputs", []))
    if "interrupt" in case:
        allowed.add(case["interrupt"]["ready"])  # the story's own marker
    for path in set(after) - set(before):
        assert path.endswith(".incomplete") or path in allowed, f"{path} was written and looks complete"
    for path in case.get("produces", []):
        assert path in after, f"{path} was not written"
