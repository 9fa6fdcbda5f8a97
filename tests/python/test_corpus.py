"""The hostile-input corpus (tests/corpus/): every case is a folder with its inputs and a case.json.

case.json keys:
- ``args``: sbsim's arguments, run in a scratch copy of the folder (paths relative to it);
- ``exit``: the expected exit code; ``message``: a regular expression the one message line must match;
- ``scenario`` (optional): "trips" copies the small generated grid (grid.sumocfg, net.net.xml,
  routes.rou.xml) in first; the case's own files override it;
- ``setup`` (optional): shell lines run in the scratch folder before (FIFOs, truncated files, symlinks);
- ``interrupt`` (optional): ``{"signal": "SIGINT", "when": "<regex on stdout+stderr>" | seconds, "repeat": n}``;
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
import time
from pathlib import Path
from typing import Any

import pytest
from sbsim.runner import executable
from sbsim_helpers import CRASH_MARKERS, REPO

CORPUS = REPO / "tests" / "corpus"
CASES = sorted(p.parent.name for p in CORPUS.glob("*/case.json"))
TIMEOUT = 60.0


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
        # Wait the given time, then send the signal (repeat times, 0.3 s apart).
        time.sleep(float(interrupt["when"]))
        for _ in range(int(interrupt.get("repeat", 1))):
            if proc.poll() is not None:
                break
            proc.send_signal(getattr(signal, interrupt["signal"]))
            time.sleep(0.3)
    try:
        out, err = proc.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        pytest.fail(f"sbsim did not end within {TIMEOUT:.0f} s")
    return proc.returncode, out, err


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
    for path in set(after) - set(before):
        assert path.endswith(".incomplete") or path in allowed, f"{path} was written and looks complete"
    for path in case.get("produces", []):
        assert path in after, f"{path} was not written"
