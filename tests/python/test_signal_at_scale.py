"""SIGTERM during a CA run on a 1,000-vehicle grid (issue "results at scale": signals in every phase). A
run of this size spends its time in the radio's events between SUMO steps — hundreds of thousands of
receptions a step — and in the trace writer, not in the storyboard: the stop request must be honoured
there too. The signal is sent once the story's marker says the grid holds hundreds of vehicles (never
after a fixed time); the run must end with 130 and one line, its outputs left ``*.incomplete`` and none
under its final name."""

from __future__ import annotations

import signal
import subprocess
from pathlib import Path

from sbsim.runner import executable
from sbsim.scenarios.grid import make_preset
from sbsim_helpers import wait_for_file, write_story

STORY = """
    from pathlib import Path
    import storyboard

    class Crowded(storyboard.Condition):
        columns = ("speed",)

        def test_all(self, snapshot):
            if len(snapshot.speeds) >= 600 and not Path("crowded").exists():
                # The test's cue: the grid is full of stations; the time, to measure how far the
                # run went on after the signal in simulated time (not in seconds of this machine).
                Path("crowded.tmp").write_text(repr(snapshot.time))
                Path("crowded.tmp").rename("crowded")
            return snapshot.speeds < 0

    def createStories(board):
        board.registerStory(storyboard.Story(Crowded(), []))
"""


def test_sigterm_stops_a_city_ca_run_mid_step(tmp_path: Path) -> None:
    cfg = make_preset(tmp_path / "grid", "bench1k")
    services = tmp_path / "ca.xml"
    services.write_text('<services><service type="artery.application.CaService"/></services>\n')
    write_story(tmp_path, STORY)
    outputs = [tmp_path / "events.jsonl", tmp_path / "messages.jsonl", tmp_path / "summary.json"]
    cmd = [
        str(executable()),
        "--sumocfg", str(cfg),
        "--story", "story.py",
        "--services", str(services),
        "--end", "3600",
        "--events", str(outputs[0]),
        "--messages", str(outputs[1]),
        "--summary", str(outputs[2]),
        "--quiet",
    ]  # fmt: skip
    proc = subprocess.Popen(cmd, cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        wait_for_file(proc, tmp_path / "crowded", timeout=300)
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=300)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 130, err
    assert "interrupted" in err and "Traceback" not in err, err
    for output in outputs:
        assert not output.exists(), f"{output.name} committed by an interrupted run"
        assert output.with_name(output.name + ".incomplete").exists(), output.name
    # Stopped within the step the signal came in (or the next, had it just begun): not steps later.
    signalled_at = float((tmp_path / "crowded").read_text())
    last = tmp_path / "messages.jsonl.incomplete"
    with last.open("rb") as trace:
        trace.seek(max(0, last.stat().st_size - 4096))
        tail = trace.read().decode(errors="replace").splitlines()[-2]
    reached = float(tail.split('"t":', 1)[1].split(",", 1)[0])
    assert reached <= signalled_at + 2.0, (signalled_at, reached)
