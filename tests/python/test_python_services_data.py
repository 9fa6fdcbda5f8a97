"""What Python services read without copies: a batch's numpy columns agree with the messages one by one, and a
batch (or a column) a service keeps stays as it was while later batches reuse the service's memory; the snapshot's
columns are read-only views of the snapshot's own arrays (no copy: the data pointer is where the snapshot keeps the
column), the same object for every read and every service in a step, and a view kept from an earlier step keeps
that step's values while the snapshot is refilled elsewhere."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
from sbsim.runner import RunResult, run
from sbsim_helpers import assert_no_crash, services_file, write_file

#: Checks every batch against the CAMs on_cam saw since the last one, and keeps every third batch with copies of
#: what it held, to check at the end that none changed while later batches were filled.
BATCHES = """
import numpy as np
from storyboard.services import Service


class Keeper(Service):
    def initialize(self):
        self.seen = []  # (sender, speed, x, y) from on_cam since the last batch
        self.kept = []  # (batch, its speeds column, copies of what they held)
        self.batches = 0
        self.cams = 0

    def on_cam(self, cam):
        self.seen.append((cam.station, cam.speed, *cam.position))

    def indicate_batch(self, messages):
        speeds = messages.cam_speeds
        assert not speeds.flags.writeable
        cams = [i for i, t in enumerate(messages.types) if t == "CAM"]
        assert len(cams) == len(self.seen), (len(cams), len(self.seen))
        senders = messages.senders
        for i, (sender, speed, x, y) in zip(cams, self.seen):
            assert senders[i] == sender and speeds[i] == speed, (senders[i], sender, speeds[i], speed)
            assert tuple(messages.cam_positions[i]) == (x, y)
            assert messages[i].cam.speed == speed and messages[i].sender == sender
        assert all(np.isnan(speeds[i]) for i in range(len(messages)) if messages.types[i] != "CAM")
        self.cams += len(cams)
        self.seen = []
        if self.batches % 3 == 0:
            self.kept.append((messages, speeds, list(senders), speeds.copy(), messages.received_at.copy()))
        self.batches += 1

    def finish(self):
        # The last batch was handed over just before finish(): nothing is left unseen.
        assert not self.seen
        for messages, speeds, senders, copy, received in self.kept:
            assert messages.senders == senders
            assert np.array_equal(messages.cam_speeds, copy, equal_nan=True)
            assert np.array_equal(speeds, copy, equal_nan=True)
            assert np.array_equal(messages.received_at, received)
        self.record_scalar("batches", self.batches)
        self.record_scalar("kept", len(self.kept))
        self.record_scalar("cams", self.cams)
"""


#: Reads the snapshot at every trigger: views (not owning their data, read-only), one per column and step, that
#: point at the snapshot's own arrays and agree with the vehicle's own speed and position; keeps some from earlier
#: steps and checks they never change and are not where the snapshot writes now. A second service (Other) records
#: the addresses it was given per step, to show both services read the same memory.
SNAPSHOT = """
import numpy as np
from storyboard.services import Service

COLUMNS = ("positions", "speeds", "angles", "accelerations", "lengths", "widths")
SEEN = {}  # step time -> {column: address}, from both services


def address(column):
    return column.__array_interface__["data"][0]


def check_addresses(service):
    snapshot = service.snapshot
    here = {}
    for name in COLUMNS:
        column = getattr(snapshot, name)
        # The view's data is the snapshot's own storage for this column: nothing was copied.
        assert address(column) == service._host._snapshot_column_address(name), name
        here[name] = address(column)
    step = SEEN.setdefault(snapshot.time, here)
    assert step == here, (snapshot.time, step, here)  # every service of the step reads the same memory
    return len(set(here.values())) == len(COLUMNS) or len(snapshot) == 0


class Other(Service):
    def initialize(self):
        self.checks = 0

    def trigger(self):
        assert check_addresses(self)
        self.checks += 1

    def finish(self):
        self.record_scalar("other_checks", self.checks)


class Viewer(Service):
    def initialize(self):
        self.kept = []  # (step time, ids, speeds view, positions view, copies)
        self.checks = 0
        self.steps = set()

    def trigger(self):
        snapshot = self.snapshot
        speeds, positions = snapshot.speeds, snapshot.positions
        for column in (speeds, positions):
            assert not column.flags.owndata and column.base is not None and not column.flags.writeable
        assert speeds is self.snapshot.speeds and positions is snapshot.positions  # one view per step
        assert speeds.shape == (len(snapshot),) and positions.shape == (len(snapshot), 2)
        i = self.self_index
        if i is not None:
            assert speeds[i] == self.speed
            assert snapshot.ids[i] == self.station_id
        if snapshot.time not in self.steps and len(self.steps) % 5 == 0:
            self.kept.append((snapshot.time, snapshot.ids, speeds, positions, speeds.copy(), positions.copy()))
        self.steps.add(snapshot.time)
        assert check_addresses(self)
        now = address(speeds), address(positions)
        for time, ids, s, p, s0, p0 in self.kept:
            assert np.array_equal(s, s0) and np.array_equal(p, p0), time
            if time != snapshot.time:
                # A held view's memory is left to it: the snapshot was refilled elsewhere.
                assert s is not speeds and address(s) not in now and address(p) not in now, time
        self.checks += 1

    def finish(self):
        moved = sum(1 for t, ids, s, p, s0, p0 in self.kept[1:] if len(p) != len(self.kept[0][3]))
        self.record_scalar("kept", len(self.kept))
        self.record_scalar("checks", self.checks)
        self.record_scalar("resized", moved)
"""


def run_ok(cfg: Path, *extra: str, end: float = 40.0) -> RunResult:
    result = run(cfg, end=end, seed=7, extra=list(extra), timeout=300)
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return result


def test_batches_agree_with_each_cam_and_a_kept_batch_does_not_change(loops_cfg: Path, tmp_path: Path) -> None:
    write_file(tmp_path, "batches.py", BATCHES)
    services = services_file(tmp_path, '<service type="CaService"/>', '<service type="python:batches.py:Keeper"/>')
    stats = tmp_path / "stats.parquet"
    result = run_ok(loops_cfg, "--services", str(services), "--statistics", str(stats))
    scalars = pd.read_parquet(stats).groupby("name")["value"].sum()
    assert scalars["kept"] > 100 and scalars["batches"] > 2 * scalars["kept"]
    # Every CAM delivered reached a batch (the summary counts deliveries over all stations).
    delivered = next(line for line in result.stdout.splitlines() if line.startswith("messages CAM: sent "))
    assert scalars["cams"] == int(delivered.split(", delivered ")[1].split()[0].replace(",", ""))


def test_snapshot_columns_are_views_of_the_step_that_stay_valid(loops_cfg: Path, tmp_path: Path) -> None:
    write_file(tmp_path, "viewer.py", SNAPSHOT)
    services = services_file(
        tmp_path, '<service type="python:viewer.py:Viewer"/>', '<service type="python:viewer.py:Other"/>'
    )
    stats = tmp_path / "stats.parquet"
    run_ok(loops_cfg, "--services", str(services), "--statistics", str(stats), end=60.0)
    scalars = pd.read_parquet(stats).groupby("name")["value"].sum()
    assert scalars["checks"] > 1000 and scalars["kept"] > 50 and scalars["other_checks"] == scalars["checks"]
    assert scalars["resized"] > 0  # vehicles came and went while old views were held
