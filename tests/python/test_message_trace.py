"""The message trace at scale (--messages): filters by event and message type, lost receptions only when
asked for, a byte budget that ends the trace (not the run), Parquet written a row group at a time with the
JSON Lines trace's content, and sbsim.read_messages reading either by columns and filters. On a generated
grid: vehicles beacon CAMs, a roadside unit announces an event by DENM from 5 s to 25 s, and the disc model
fades beyond 150 m (so some receptions are lost)."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pandas as pd
import pytest
from sbsim.messages import read_message_lines, read_messages
from sbsim.runner import RunResult, executable, run
from sbsim.scenarios.grid import make_grid
from sbsim_helpers import assert_bad_input, assert_no_crash

END = 30.0
SERVICES = """<services>
    <service type="CaService"/>
    <rsu id="rsu0" x="300" y="300">
        <service type="RsuDenService" cause="3" subcause="7" from="5" until="25" interval="1" area="250"/>
    </rsu>
</services>"""
#: Columns both formats carry for every line of this run (the disc model: no cbr, power or SINR).
NUMERIC = ("t", "seq", "bytes", "frame_bytes", "x", "y", "distance", "delay", "cause", "subcause")
TEXT = ("event", "type", "station", "sender", "reason", "phase", "action")


@pytest.fixture(scope="module")
def grid(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("trace")
    cfg = make_grid(folder, grid=4, end=END, seed=3, period=1.0)
    (folder / "services.xml").write_text(SERVICES, encoding="utf-8")
    return cfg


def trace_run(grid: Path, out: Path, *extra: str, summary: Path | None = None) -> RunResult:
    args = ["--services", str(grid.parent / "services.xml"), "--v2x-range", "300", "--v2x-fade-start", "150"]
    args += ["--messages", str(out), *extra]
    if summary is not None:
        args += ["--summary", str(summary)]
    result = run(grid, end=END, extra=args, quiet=True, timeout=300)
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return result


@pytest.fixture(scope="module")
def full(grid: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Every event, no budget worth the name: the reference trace."""
    out = tmp_path_factory.mktemp("full") / "m.jsonl"
    trace_run(grid, out, "--messages-events", "tx,rx,lost,denm", "--messages-max-bytes", "none")
    return out


def test_the_default_trace_has_no_lost_lines(grid: Path, full: Path, tmp_path: Path) -> None:
    lines = read_message_lines(full)
    assert {line["event"] for line in lines} == {"tx", "rx", "lost", "denm"}
    out = tmp_path / "m.jsonl"
    trace_run(grid, out)
    default = read_message_lines(out)
    # Lost receptions only when asked for; everything else as in the full trace, in the same order.
    assert default == [line for line in lines if line["event"] != "lost"]
    # --messages-range alone keeps its meaning: lost receptions this close to the sender.
    ranged = tmp_path / "r.jsonl"
    trace_run(grid, ranged, "--messages-range", "200")
    lost = [line for line in read_message_lines(ranged) if line["event"] == "lost"]
    assert lost and all(line["distance"] <= 200 for line in lost)
    assert lost == [line for line in lines if line["event"] == "lost" and line["distance"] <= 200]


def test_filters_keep_the_types_and_events_named(grid: Path, full: Path, tmp_path: Path) -> None:
    lines = read_message_lines(full)
    out = tmp_path / "denm.jsonl"
    trace_run(grid, out, "--messages-types", "DENM")
    denm = read_message_lines(out)
    assert denm == [line for line in lines if line.get("type", "DENM") == "DENM" and line["event"] != "lost"]
    assert {line["event"] for line in denm} == {"tx", "rx", "denm"}
    out = tmp_path / "rx.jsonl"
    trace_run(grid, out, "--messages-events", "rx,lost", "--messages-types", "CAM,DENM")
    assert read_message_lines(out) == [line for line in lines if line["event"] in ("rx", "lost")]


def test_a_type_no_station_sent_is_warned_of(grid: Path, tmp_path: Path) -> None:
    result = trace_run(grid, tmp_path / "m.jsonl", "--messages-types", "DENM,Cam")
    assert "--messages-types Cam: no Cam message was sent (sent: CAM, DENM)" in result.stderr
    assert (tmp_path / "m.jsonl").stat().st_size > 0


@pytest.mark.parametrize(
    ("extra", "needles"),
    [
        (["--messages-events", "tx,received"], ["--messages-events", "received", "tx, rx, lost, denm"]),
        (["--messages-types", "CAM, "], ["--messages-types"]),
        (["--messages-max-bytes", "12Q"], ["--messages-max-bytes", "12Q"]),
        (["--messages-max-bytes", "-5M"], ["--messages-max-bytes", "-5M"]),
        (["--messages-max-bytes", "10"], ["--messages-max-bytes", "at least 1000"]),
        (["--messages-range", "100", "--messages-events", "tx,rx"], ["--messages-range", "lost"]),
    ],
)
def test_bad_trace_options_are_one_line_usage_errors(
    grid: Path, tmp_path: Path, extra: list[str], needles: list[str]
) -> None:
    out = tmp_path / "m.jsonl"
    args = ["--services", str(grid.parent / "services.xml"), "--messages", str(out), *extra]
    assert_bad_input(run(grid, end=2.0, extra=args, timeout=120), *needles)
    assert not out.exists()


def test_filter_options_need_a_trace(grid: Path) -> None:
    result = run(grid, end=2.0, extra=["--services", str(grid.parent / "services.xml"), "--messages-types", "CAM"])
    assert_bad_input(result, "--messages-types", "--messages")


def summary_trace(path: Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))["message_trace"]


def test_the_budget_ends_the_trace_not_the_run(grid: Path, full: Path, tmp_path: Path) -> None:
    budget = 60_000
    out, summary = tmp_path / "m.jsonl", tmp_path / "summary.json"
    result = trace_run(
        grid, out, "--messages-events", "tx,rx,lost,denm", "--messages-max-bytes", "60k", summary=summary
    )
    warnings = [line for line in result.stderr.splitlines() if "--messages-max-bytes" in line]
    assert len(warnings) == 1, result.stderr  # once
    whole = full.read_bytes()
    kept = out.read_bytes()
    # The trace is the full trace up to the first line that would have passed the budget.
    assert len(kept) <= budget < len(whole)
    assert whole.startswith(kept)
    next_line = whole[len(kept) :].split(b"\n", 1)[0]
    assert len(kept) + len(next_line) + 1 > budget
    trace = summary_trace(summary)
    assert trace["truncated"] is True
    assert trace["truncated_at"] == json.loads(next_line)["t"]
    assert trace["bytes"] == len(kept) and trace["max_bytes"] == budget
    assert trace["lines"] == kept.count(b"\n")
    assert f"at t={json.loads(next_line)['t']} s; the run goes on" in warnings[0]
    # The run itself went to its end: the same summary figures as the untruncated run.
    data = json.loads(summary.read_text(encoding="utf-8"))
    assert data["end"]["time"] == pytest.approx(END)


def test_a_whole_trace_says_so_in_the_summary(grid: Path, tmp_path: Path) -> None:
    out, summary = tmp_path / "m.jsonl", tmp_path / "summary.json"
    trace_run(grid, out, summary=summary)
    trace = summary_trace(summary)
    assert trace == {
        "format": "jsonl",
        "lines": len(out.read_bytes().splitlines()),
        "bytes": out.stat().st_size,
        "max_bytes": 2_000_000_000,
        "truncated": False,
        "truncated_at": None,
    }


def assert_same_trace(jsonl: pd.DataFrame, parquet: pd.DataFrame) -> None:
    assert len(jsonl) == len(parquet)
    for column in TEXT:
        left = jsonl[column].astype(object).where(jsonl[column].notna(), None).tolist()
        right = parquet[column].astype(object).where(parquet[column].notna(), None).tolist()
        assert left == right, column
    for column in NUMERIC:
        left, right = jsonl[column].astype("float64"), parquet[column].astype("float64")
        assert (left.isna() == right.isna()).all(), column
        # JSON Lines rounds positions and distances to 0.01 m; Parquet keeps full precision.
        assert ((left - right).abs().fillna(0) <= 0.005 + 1e-9).all(), column


def test_parquet_holds_the_json_lines_content(grid: Path, full: Path, tmp_path: Path) -> None:
    out, summary = tmp_path / "m.parquet", tmp_path / "summary.json"
    trace_run(grid, out, "--messages-events", "tx,rx,lost,denm", summary=summary)
    import pyarrow.parquet as pq

    meta = pq.ParquetFile(out).metadata
    assert meta.num_rows == len(read_message_lines(full))
    assert meta.row_group(0).column(0).compression == "ZSTD"
    trace = summary_trace(summary)
    assert trace["format"] == "parquet" and trace["bytes"] == out.stat().st_size and not trace["truncated"]
    assert out.stat().st_size * 4 < full.stat().st_size  # columnar and compressed
    assert_same_trace(read_messages(full, columns=[*NUMERIC, *TEXT]), read_messages(out, columns=[*NUMERIC, *TEXT]))


def test_a_parquet_trace_keeps_its_row_groups_within_the_budget(grid: Path, full: Path, tmp_path: Path) -> None:
    out, summary = tmp_path / "m.parquet", tmp_path / "summary.json"
    budget = 40_000
    result = trace_run(
        grid, out, "--messages-events", "tx,rx,lost,denm", "--messages-max-bytes", "40k", summary=summary
    )
    assert result.stderr.count("--messages-max-bytes") == 1, result.stderr
    assert out.stat().st_size <= budget
    trace = summary_trace(summary)
    assert trace["truncated"] is True and trace["bytes"] == out.stat().st_size
    kept = read_messages(out, columns=[*NUMERIC, *TEXT])
    reference = read_messages(full, columns=[*NUMERIC, *TEXT])
    assert 0 < len(kept) < len(reference)
    # A prefix of the whole trace, ending before the line the summary names.
    assert_same_trace(reference.iloc[: len(kept)].reset_index(drop=True), kept)
    assert reference["t"].iloc[len(kept)] == pytest.approx(trace["truncated_at"])
    assert kept["t"].max() <= trace["truncated_at"]


def test_an_empty_parquet_trace_has_its_columns(grid: Path, tmp_path: Path) -> None:
    out = tmp_path / "m.parquet"
    trace_run(grid, out, "--messages-types", "NoSuchMessage")
    frame = read_messages(out)
    assert len(frame) == 0 and {"t", "event", "type", "station"} <= set(frame.columns)


@pytest.mark.parametrize("suffix", [".jsonl", ".parquet"])
def test_read_messages_by_columns_and_filters(grid: Path, full: Path, tmp_path: Path, suffix: str) -> None:
    out = tmp_path / f"m{suffix}"
    trace_run(grid, out, "--messages-events", "tx,rx,lost,denm")
    lines = read_message_lines(full)
    frame = read_messages(
        out, columns=["t", "station", "sender"], filters=[("event", "==", "rx"), ("type", "==", "DENM")]
    )
    assert list(frame.columns) == ["t", "station", "sender"]
    expected = [line for line in lines if line["event"] == "rx" and line["type"] == "DENM"]
    assert len(expected) > 0
    assert frame["station"].tolist() == [line["station"] for line in expected]
    assert frame["t"].tolist() == pytest.approx([line["t"] for line in expected])
    # Alternatives (a list of lists), ranges, in / not in, and a column the trace lacks (all null).
    frame = read_messages(
        out,
        columns=["event", "distance", "power_dbm"],
        filters=[[("event", "==", "lost"), ("distance", ">", 250)], [("event", "in", ["denm"])]],
    )
    expected = [
        line for line in lines if (line["event"] == "lost" and line["distance"] > 250) or line["event"] == "denm"
    ]
    assert frame["event"].tolist() == [line["event"] for line in expected]
    assert frame["power_dbm"].isna().all()
    frame = read_messages(out, columns=["event"], filters=[("event", "not in", ["tx", "rx", "lost"])])
    assert set(frame["event"]) == {"denm"}
    whole = read_messages(out)
    assert len(whole) == len(lines) and {"t", "event", "station", "reason", "phase"} <= set(whole.columns)


def test_read_messages_names_a_bad_line_and_a_bad_file(tmp_path: Path) -> None:
    from sbsim.events import EventLogError

    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"t":1,"event":"tx","type":"CAM","station":"a","seq":0,"bytes":1,"x":0,"y":0}\n{"t":2}\n')
    with pytest.raises(EventLogError, match=r"bad\.jsonl:2: not a message trace line"):
        read_messages(bad, columns=["t"])
    broken = tmp_path / "broken.parquet"
    broken.write_bytes(b"PAR1 but not really")
    with pytest.raises(EventLogError, match="broken.parquet: not a readable message trace"):
        read_messages(broken)


def test_missing_pyarrow_for_a_parquet_trace_is_one_line(grid: Path, tmp_path: Path) -> None:
    fake = tmp_path / "site" / "pyarrow"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text("raise ImportError('pyarrow is broken here')\n", encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": str(tmp_path / "site")}
    out = tmp_path / "m.parquet"
    args = [str(executable()), "--sumocfg", str(grid), "--end", "5", "--services", str(grid.parent / "services.xml")]
    done = subprocess.run([*args, "--messages", str(out)], capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 2, done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "--messages" in lines[0] and "pip install pyarrow" in lines[0], done.stderr
    assert done.stdout == ""
    assert not out.exists()


def test_the_report_reads_a_parquet_trace(grid: Path, full: Path, tmp_path: Path) -> None:
    from sbsim.report.compose import build

    out, events = tmp_path / "m.parquet", tmp_path / "events.jsonl"
    args = ["--services", str(grid.parent / "services.xml"), "--v2x-range", "300", "--v2x-fade-start", "150"]
    args += ["--messages", str(out), "--messages-events", "tx,rx,lost,denm"]
    result = run(grid, end=END, events=events, extra=args, quiet=True, timeout=300)
    assert result.returncode == 0, result.stderr
    from_parquet = build(events, grid, messages=out)
    from_jsonl = build(events, grid, messages=full)
    pd.testing.assert_frame_equal(from_parquet.v2x["messages"], from_jsonl.v2x["messages"])
    left, right = from_parquet.v2x["delivery"], from_jsonl.v2x["delivery"]
    assert len(left) > 3 and left["lost"].sum() > 0
    # JSON Lines rounds distances to 0.01 m: a reception on a bin's edge may fall on its other side.
    assert left["received"].sum() + left["lost"].sum() == right["received"].sum() + right["lost"].sum()
    assert (left["pdr"] - right["pdr"]).abs().max() < 0.05


def test_an_interrupted_parquet_trace_is_left_closed_and_readable(grid: Path, tmp_path: Path) -> None:
    """SIGINT mid-run: exit 130, no FILE.parquet, and FILE.parquet.incomplete a whole Parquet file with what
    was traced (the writer ignores the signal; sbsim ends its input and it writes the footer)."""
    import signal

    import pyarrow.parquet as pq
    from sbsim_helpers import wait_for_file, write_story

    marker = tmp_path / "ready"
    # At its 12th step the story says it is under way, then waits for the signal (KeyboardInterrupt).
    story = write_story(
        tmp_path,
        f"""
        import time
        import numpy as np
        import storyboard

        class Waits(storyboard.Condition):
            steps = 0

            def test_all(self, snapshot):
                Waits.steps += 1
                if Waits.steps == 12:
                    open({str(marker)!r}, "w").close()
                    while True:  # until the signal's KeyboardInterrupt (Python checks between sleeps)
                        time.sleep(0.01)
                return np.zeros(len(snapshot), bool)

        def createStories(board):
            board.registerStory(storyboard.Story(Waits(), []))
        """,
    )
    out = tmp_path / "m.parquet"
    args = [str(executable()), "--sumocfg", str(grid), "--story", str(story), "--quiet"]
    args += ["--services", str(grid.parent / "services.xml"), "--messages", str(out)]
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        wait_for_file(proc, marker, timeout=120)
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=60)
    finally:
        proc.kill()
    assert proc.returncode == 130, err
    assert not out.exists()
    left = Path(f"{out}.incomplete")
    table = pq.read_table(left)
    assert table.num_rows > 0 and {"t", "event", "station"} <= set(table.column_names)
    assert set(table.column("event").to_pylist()) >= {"tx", "rx"}
    assert max(table.column("t").to_pylist()) <= 12.0
