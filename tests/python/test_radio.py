"""The 802.11p channel model (--radio) end to end on small SUMO highways made here with netconvert:
a building between two vehicles blocks their beacons, the message trace agrees with the summary,
and the trace is byte-identical with one thread and two.
"""

from __future__ import annotations

import hashlib
import json
import re
import subprocess
from pathlib import Path

import pytest
from sbsim.runner import RunResult, read_message_lines, read_messages, run
from sbsim.sumo import sumo_binary
from sbsim_helpers import STORIES, assert_bad_input, assert_no_crash, message_counts


def highway(
    folder: Path, positions: list[float], speed: float, *, building: bool, length: float = 600.0, lanes: int = 2
) -> Path:
    """A straight one-way road along y = 0 with vehicles at `positions` (m from its start), each
    beaconing (190 bytes, 10 Hz); with `building`, a 30 m deep block across the road at x 110..140."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "h.nod.xml").write_text(f'<nodes><node id="a" x="0" y="0"/><node id="b" x="{length:g}" y="0"/></nodes>')
    (folder / "h.edg.xml").write_text(f'<edges><edge id="e" from="a" to="b" numLanes="{lanes}" speed="30"/></edges>')
    subprocess.run(
        [
            str(sumo_binary("netconvert")),
            "-n",
            str(folder / "h.nod.xml"),
            "-e",
            str(folder / "h.edg.xml"),
            "-o",
            str(folder / "h.net.xml"),
        ],
        check=True,
        capture_output=True,
    )
    vehicles = "\n".join(
        f'<vehicle id="v{k:04d}" type="car" depart="0" route="r" departLane="{k % lanes}" departPos="{x:.2f}" '
        f'departSpeed="{speed:g}"/>'
        for k, x in enumerate(positions)
    )
    (folder / "h.rou.xml").write_text(
        f'<routes><vType id="car" maxSpeed="{speed:g}" sigma="0" speedDev="0" lcStrategic="-1" lcSpeedGain="0" '
        f'lcKeepRight="0"/><route id="r" edges="e"/>\n{vehicles}\n</routes>'
    )
    additional = ""
    if building:
        (folder / "b.add.xml").write_text(
            '<additional><poly id="block" type="building" color="1,0,0" fill="true" '
            'shape="110,-60 140,-60 140,60 110,60"/><poly id="park" type="park" color="0,1,0" '
            'shape="300,-60 330,-60 330,60 300,60"/></additional>'
        )
        additional = '<additional-files value="b.add.xml"/>'
    (folder / "h.services.xml").write_text('<services><service type="Beacon" interval="0.1" bytes="190"/></services>')
    cfg = folder / "h.sumocfg"
    cfg.write_text(
        f'<configuration><input><net-file value="h.net.xml"/><route-files value="h.rou.xml"/>{additional}</input>'
        '<time><step-length value="0.1"/></time><report><no-step-log value="true"/></report></configuration>'
    )
    return cfg


def beacon_run(cfg: Path, out: Path, *extra: str, end: float = 3.0) -> RunResult:
    result = run(
        cfg,
        end=end,
        extra=["--services", str(cfg.parent / "h.services.xml"), "--radio", str(out / "radio.toml"), *extra],
        timeout=300,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return result


@pytest.fixture
def radio_file(tmp_path: Path) -> Path:
    # The defaults, plus buildings of type "building" (also the default), written out.
    (tmp_path / "radio.toml").write_text(
        '[phy]\npower_dbm = 23\n[propagation]\npath_loss = "winner-b1"\nshadowing_sigma_db = 3\n'
        '[obstacles]\npolygon_type = "building"\nwall_db = 9\nper_metre_db = 0.4\n[trace]\ntrace_range = 500\n'
    )
    return tmp_path / "radio.toml"


@pytest.mark.parametrize("building", [False, True])
def test_a_building_between_two_vehicles_blocks_them(tmp_path: Path, radio_file: Path, building: bool) -> None:
    # 150 m apart at 1 m/s, either side of x 110..140 (the park polygon at 300 m is not a building).
    cfg = highway(tmp_path / "road", [50.0, 200.0], 1.0, building=building)
    messages = tmp_path / "messages.jsonl"
    result = beacon_run(cfg, tmp_path, "--messages", str(messages), "--messages-events", "tx,rx,lost")
    lines = read_message_lines(messages)
    rx = [line for line in lines if line["event"] == "rx"]
    lost = [line for line in lines if line["event"] == "lost"]
    tx = [line for line in lines if line["event"] == "tx"]
    assert len(tx) >= 50  # two vehicles, 10 Hz, 3 s
    if building:
        # 2 walls (18 dB) + 30 m inside (12 dB) below −74 dBm: far under the −85 dBm threshold.
        assert rx == []
        assert {line["reason"] for line in lost} == {"sensing"}
        assert len(lost) == len(tx)
    else:
        assert len(rx) >= len(tx) - 2  # about 0.1 % FER at ~20 dB SNR
        assert all(abs(line["distance"] - 150.0) < 1.0 for line in rx)
        assert all(-80 < line["power_dbm"] < -65 for line in rx)
    sent, delivered = message_counts(result.stdout)["Beacon"]
    assert delivered == len(rx)


def test_trace_counts_agree_with_the_summary(tmp_path: Path, radio_file: Path) -> None:
    positions = [10.0 + 12.0 * k for k in range(40)]  # 40 vehicles over 470 m
    cfg = highway(tmp_path / "road", positions, 10.0, building=False)
    messages = tmp_path / "messages.jsonl"
    summary = tmp_path / "summary.json"
    result = beacon_run(
        cfg,
        tmp_path,
        "--messages",
        str(messages),
        "--messages-events",
        "tx,rx,lost",
        "--summary",
        str(summary),
        end=2.0,
    )
    lines = read_message_lines(messages)
    times = [line["t"] for line in lines]
    assert times == sorted(times)
    counts = {event: sum(line["event"] == event for line in lines) for event in ("tx", "rx", "lost")}
    queue_drops = sum(line.get("reason") == "queue" for line in lines)
    data = json.loads(summary.read_text())
    beacon = data["messages"]["Beacon"]
    # Every beacon sent is transmitted, dropped from a full queue, or still waiting at the end.
    assert beacon["sent"] - len(positions) <= counts["tx"] + queue_drops <= beacon["sent"]
    assert beacon["delivered"] == counts["rx"]
    assert sum(b["received"] for b in beacon["delivery_ratio"]) == counts["rx"]
    assert beacon["mean_receivers"] == pytest.approx(counts["rx"] / beacon["sent"])
    assert 0 < data["channel_busy_ratio"]["mean"] <= data["channel_busy_ratio"]["max"] <= 1
    # Near and far: the delivery ratio falls with distance.
    ratios = {b["from_m"]: b["ratio"] for b in beacon["delivery_ratio"]}
    assert ratios[0] > 0.9 > ratios[400]
    assert re.search(r"^delivery ratio Beacon by metres: 0: 0\.\d+", result.stdout, re.M)
    assert re.search(r"^channel busy ratio: mean 0\.\d+, max [01]\.\d+", result.stdout, re.M)


def test_traces_are_identical_with_one_thread_and_two(tmp_path: Path, radio_file: Path) -> None:
    # Dense enough, with small chunks, that a frame's links are split over the pool.
    cfg = highway(tmp_path / "road", [5.0 + 5.0 * k for k in range(490)], 5.0, building=False, length=2500.0, lanes=4)
    digests = []
    for threads in ("1", "2"):
        messages = tmp_path / f"messages{threads}.jsonl"
        beacon_run(
            cfg,
            tmp_path,
            "--messages",
            str(messages),
            "--messages-events",
            "tx,rx,lost",
            "--threads",
            threads,
            "--param",
            "radio_trace_range=30",
            "--param",
            "radio_links_per_chunk=64",
            end=0.4,
        )
        digests.append(hashlib.sha256(messages.read_bytes()).hexdigest())
        assert messages.stat().st_size > 1_000_000
    assert digests[0] == digests[1]


def test_bad_radio_files_are_one_line_errors(tmp_path: Path) -> None:
    cfg = highway(tmp_path / "road", [50.0], 1.0, building=False)
    services = str(cfg.parent / "h.services.xml")
    cases = {
        "[phy]\npower = 23\n": "[phy] power: is not a radio setting",
        "[phy]\nrate_mbps = 7\n": "rate_mbps must be one of",
        '[propagation]\npath_loss = "moon"\n': "path_loss: must be 3gpp-highway, 3gpp-urban, 3gpp-urban-nlos, free-",
        '[frame]\nsecurity = "maybe"\n': "[frame] security: must be signed or none",
        "[phy\n": "radio.toml:1",
    }
    for text, needle in cases.items():
        (tmp_path / "radio.toml").write_text(text)
        result = run(cfg, end=1.0, extra=["--services", services, "--radio", str(tmp_path / "radio.toml")])
        assert_bad_input(result, needle)
    (tmp_path / "radio.toml").write_text("")
    result = run(
        cfg,
        end=1.0,
        extra=["--services", services, "--radio", str(tmp_path / "radio.toml"), "--param", "radio_power_dbm=hot"],
    )
    assert_bad_input(result, "radio_power_dbm", "must be a number")
    assert_bad_input(run(cfg, end=1.0, extra=["--radio", str(tmp_path / "radio.toml")]), "--radio", "--services")


def test_the_disc_model_traces_range_and_fade_losses(tmp_path: Path) -> None:
    scenario = STORIES / "highway-police"
    messages = tmp_path / "messages.jsonl"
    result = run(
        scenario / "highway.sumocfg",
        story=scenario / "story.py",
        end=40.0,
        extra=[
            "--services",
            str(scenario / "services.xml"),
            "--v2x-fade-start",
            "300",
            "--messages",
            str(messages),
            "--messages-range",
            "800",
        ],
        timeout=300,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    lines = read_message_lines(messages)
    times = [line["t"] for line in lines]
    assert times == sorted(times)
    rx = [line for line in lines if line["event"] == "rx"]
    lost = [line for line in lines if line["event"] == "lost"]
    assert {line["reason"] for line in lost} == {"range", "fade"}
    assert all(line["distance"] > 500 for line in lost if line["reason"] == "range")
    assert all(300 < line["distance"] <= 500 for line in lost if line["reason"] == "fade")
    assert all(line["delay"] == pytest.approx(0.001) and line["distance"] <= 500 for line in rx)
    # The disc model has no airtime but frames its messages all the same: ClearLane messages are
    # single-hop broadcasts signed with the certificate every time (82 bytes of headers and an
    # envelope of 6 + length + 11 + 151 + 66).
    tx = [line for line in lines if line["event"] == "tx"]
    for line in tx:
        payload = 40 + line["bytes"]
        envelope = 6 + (1 if payload < 128 else 2) + 11 + 151 + 66
        assert line["frame_bytes"] == line["bytes"] + 82 + envelope
    sent, delivered = message_counts(result.stdout)["ClearLane"]
    assert delivered == len(rx)
    assert sent == sum(line["event"] == "tx" for line in lines)


def test_a_study_sweeps_radio_power_and_keeps_the_messages(tmp_path: Path, radio_file: Path) -> None:
    import pandas as pd
    from storyboard import study
    from storyboard.runner import executable

    cfg = highway(tmp_path / "road", [50.0 + 40.0 * k for k in range(10)], 10.0, building=False)
    spec = study.StudySpec.from_dict(
        {
            "sumocfg": str(cfg),
            "services": str(cfg.parent / "h.services.xml"),
            "radio": str(radio_file),
            "seeds": [1],
            "end": 1.5,
            "parameters": {"radio_power_dbm": [10, 30]},
            "outputs": {"directory": str(tmp_path / "results"), "messages": True},
        }
    )
    runs = spec.runs()
    rows = [study.execute(spec, r, str(executable()), timeout=120) for r in runs]
    assert [row["exit_code"] for row in rows] == [0, 0], [row["stderr_tail"] for row in rows]
    study.write_tables(spec, runs, rows)
    table = pd.read_parquet(tmp_path / "results" / "runs.parquet")
    assert set(table.columns) >= {"sent:Beacon", "delivered:Beacon", "mean_receivers:Beacon", "cbr_mean", "cbr_max"}
    low, high = (table[table["radio_power_dbm"] == p].iloc[0] for p in (10, 30))
    assert high["mean_receivers:Beacon"] > low["mean_receivers:Beacon"]  # more power, more range
    # One Parquet dataset of the runs' traces, partitioned by run; parameters from runs.parquet.
    assert sorted(p.name for p in (tmp_path / "results" / "messages").iterdir()) == sorted(f"run={r.id}" for r in runs)
    assert set(read_messages(tmp_path / "results" / "messages", columns=["event"])["event"]) >= {"tx", "rx"}
    received = read_messages(tmp_path / "results" / "messages", columns=["run", "t"], filters=[("event", "==", "rx")])
    per_run = received.merge(table[["run", "radio_power_dbm"]], on="run").groupby("radio_power_dbm").size()
    assert per_run[10] == low["delivered:Beacon"] and per_run[30] == high["delivered:Beacon"]


def test_frames_carry_their_headers_and_a_signature_with_the_certificate_once_a_second(
    tmp_path: Path, radio_file: Path
) -> None:
    # Beacons are framed and signed as CAMs: 190 bytes + MAC 26, LLC/SNAP 8, GeoNetworking basic 4,
    # common 8 and SHB 28, BTP-B 4, FCS 4 (82), plus the envelope around the 230-byte payload:
    # head 6 + a two-byte length, header info 11, signature 66 and the signer: digest 9 (366 in
    # all) or certificate 151 (508).
    cfg = highway(tmp_path / "road", [50.0, 200.0], 1.0, building=False)
    messages = tmp_path / "messages.jsonl"
    beacon_run(cfg, tmp_path, "--messages", str(messages), end=4.0)
    tx = [line for line in read_message_lines(messages) if line["event"] == "tx"]
    assert {line["bytes"] for line in tx} == {190}
    assert {line["frame_bytes"] for line in tx} == {366, 508}
    for station in ("v0000", "v0001"):
        frames = [(line["t"], line["frame_bytes"]) for line in tx if line["station"] == station]
        assert frames[0][1] == 508
        full = [t for t, size in frames if size == 508]
        # Once a second (Vanetza's 950 ms), once more after hearing the other station for the first time.
        assert 4 <= len(full) <= 5, frames
        gaps = [b - a for a, b in zip(full, full[1:], strict=False)]
        # (t is the frame's start, after channel access: a fraction of a millisecond after signing.)
        assert all(gap < 1.001 for gap in gaps), gaps
        assert sum(gap < 0.9 for gap in gaps) <= 1, gaps  # only the new neighbour's
    # Unsecured: the headers alone.
    (tmp_path / "radio.toml").write_text('[frame]\nsecurity = "none"\n')
    beacon_run(cfg, tmp_path, "--messages", str(messages), end=1.0)
    tx = [line for line in read_message_lines(messages) if line["event"] == "tx"]
    assert tx and {line["frame_bytes"] for line in tx} == {190 + 82}


@pytest.mark.parametrize("correlation", [0, 25])
def test_losses_come_in_bursts_with_correlated_shadowing(tmp_path: Path, radio_file: Path, correlation: int) -> None:
    # Two vehicles 285 m apart, both at 20 m/s: near the sensing edge (about 291 m at the mean), so
    # the shadowing decides. Each moves 2 m a frame, the pair 4 m: with d_corr = 25 m consecutive
    # frames share ρ = 0.85 of their shadowing, and a loss makes the next one likelier.
    cfg = highway(tmp_path / "road", [20.0, 305.0], 20.0, building=False, length=2000.0, lanes=1)
    messages = tmp_path / "messages.jsonl"
    beacon_run(
        cfg,
        tmp_path,
        "--messages",
        str(messages),
        "--messages-events",
        "tx,rx,lost",
        "--param",
        f"radio_shadowing_correlation_m={correlation}",
        end=80.0,
    )
    lines = read_message_lines(messages)
    outcome: dict[int, bool] = {}  # v0000's frames at v0001: lost?
    for line in lines:
        if line["event"] in ("rx", "lost") and line["sender"] == "v0000" and line["station"] == "v0001":
            outcome[line["seq"]] = line["event"] == "lost"
    seqs = sorted(outcome)
    assert len(seqs) > 600
    lost = [outcome[s] for s in seqs]
    p_loss = sum(lost) / len(lost)
    pairs = [(a, b) for a, b, sa, sb in zip(lost, lost[1:], seqs, seqs[1:], strict=False) if sb == sa + 1]
    after_loss = [b for a, b in pairs if a]
    p_loss_after_loss = sum(after_loss) / len(after_loss)
    assert 0.1 < p_loss < 0.9, p_loss
    if correlation:
        assert p_loss_after_loss > p_loss + 0.2, (p_loss, p_loss_after_loss)
    else:
        assert abs(p_loss_after_loss - p_loss) < 0.08, (p_loss, p_loss_after_loss)


@pytest.mark.parametrize(
    ("law", "reaches"),
    [("3gpp-highway", True), ("3gpp-urban", True), ("3gpp-urban-nlos", False)],
)
def test_the_3gpp_path_loss_laws_are_radio_file_choices(tmp_path: Path, law: str, reaches: bool) -> None:
    # 150 m at 5.89 GHz without shadowing: highway LOS 91.3 dB and urban LOS 89.1 dB leave -68 and
    # -66 dBm; urban NLOS (116.7 dB) leaves -94 dBm, below the -85 dBm sensing threshold.
    (tmp_path / "radio.toml").write_text(f'[propagation]\npath_loss = "{law}"\nshadowing_sigma_db = 0\n')
    cfg = highway(tmp_path / "road", [50.0, 200.0], 1.0, building=False)
    messages = tmp_path / "messages.jsonl"
    beacon_run(cfg, tmp_path, "--messages", str(messages), "--messages-events", "tx,rx,lost", end=1.0)
    lines = read_message_lines(messages)
    rx = [line for line in lines if line["event"] == "rx"]
    assert bool(rx) == reaches
    if reaches:
        assert all(-75 < line["power_dbm"] < -60 for line in rx)
    else:
        assert {line["reason"] for line in lines if line["event"] == "lost"} == {"sensing"}


def test_dcc_state_changes_enter_the_trace(tmp_path: Path, radio_file: Path) -> None:
    # 60 vehicles 5 m apart beaconing 500 bytes every 20 ms load the channel far past 0.19: their DCC
    # leaves Relaxed, and each change is one dcc line naming the station, its new state, the busy
    # ratio that moved it and the interval the state allows.
    cfg = highway(tmp_path / "road", [5.0 * k for k in range(60)], 1.0, building=False, length=400.0)
    (cfg.parent / "h.services.xml").write_text(
        '<services><service type="Beacon" interval="0.02" bytes="500"/></services>'
    )
    messages = tmp_path / "messages.jsonl"
    beacon_run(cfg, tmp_path, "--messages", str(messages), "--messages-events", "dcc", end=4.0)
    lines = read_message_lines(messages)
    assert lines and {line["event"] for line in lines} == {"dcc"}
    intervals = {"relaxed": 0.06, "active1": 0.1, "active2": 0.18, "active3": 0.26, "active4": 0.34, "active5": 0.42}
    last: dict[str, str] = {}
    for line in lines:
        assert line["state"] in (*intervals, "restrictive")
        assert line["interval"] == pytest.approx(intervals.get(line["state"], 0.46))
        assert line["state"] != last.get(line["station"], "relaxed"), "only changes are traced"
        assert round(line["t"] * 10, 6) % 1 == 0, "at the 100 ms samples"
        last[line["station"]] = line["state"]
    assert len(last) > 30 and any(state != "relaxed" for state in last.values())
