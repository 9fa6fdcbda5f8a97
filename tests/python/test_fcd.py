"""sbsim.fcd: SUMO's FCD output in sbsim's time, on small hand-written files whose values are known."""

from __future__ import annotations

from pathlib import Path

import pytest
from sbsim.fcd import FcdError, Timestep, VehicleState, read_fcd, read_timesteps

FCD = """<?xml version="1.0" encoding="UTF-8"?>
<fcd-export xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
    <timestep time="0.00">
        <vehicle id="a" x="1.5" y="2.0" angle="90.00" type="car" speed="3.25" pos="5.10" lane="e1_0" slope="0.00"/>
    </timestep>
    <timestep time="0.50"/>
    <timestep time="1.00">
        <vehicle id="a" x="2.5" y="2.0" speed="4.00" lane="e1_0"/>
        <person id="p" x="0" y="0" speed="1"/>
        <vehicle id="b" x="7" y="-1.25" speed="0"/>
    </timestep>
</fcd-export>
"""


def write(tmp_path: Path, text: str, name: str = "fcd.xml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_timesteps_are_in_sbsim_time_with_the_files_own_spacing(tmp_path: Path) -> None:
    steps = read_timesteps(write(tmp_path, FCD))
    # FCD time T is sbsim time T + step; the step is the smallest spacing of the file's times (0.5 s).
    assert [s.t for s in steps] == [0.5, 1.0, 1.5]
    assert steps[0] == Timestep(0.5, (VehicleState("a", 1.5, 2.0, 3.25, "e1_0", "car"),))
    assert steps[1].vehicles == ()  # a step with nobody running is kept
    # Persons are not vehicles; attributes SUMO left out are None.
    assert steps[2].vehicles == (
        VehicleState("a", 2.5, 2.0, 4.0, "e1_0", None),
        VehicleState("b", 7.0, -1.25, 0.0, None, None),
    )


def test_a_given_step_wins_and_a_single_timestep_takes_the_fallback(tmp_path: Path) -> None:
    assert [s.t for s in read_timesteps(write(tmp_path, FCD), step=0.1)] == [0.1, 0.6, 1.1]
    single = write(
        tmp_path,
        '<fcd-export><timestep time="10"><vehicle id="v" x="0" y="0" speed="1"/></timestep></fcd-export>',
        "one.xml",
    )
    assert [s.t for s in read_timesteps(single, fallback_step=0.25)] == [10.25]
    assert [s.t for s in read_timesteps(single)] == [11.0]


def test_the_table_has_one_row_per_vehicle_state(tmp_path: Path) -> None:
    table = read_fcd(write(tmp_path, FCD))
    assert list(table.columns) == ["t", "vehicle", "x", "y", "speed"]
    assert table.values.tolist() == [[0.5, "a", 1.5, 2.0, 3.25], [1.5, "a", 2.5, 2.0, 4.0], [1.5, "b", 7.0, -1.25, 0.0]]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ('{"steps": 3}', r"x\.xml: not SUMO FCD output \(not XML"),
        ("<routes><vehicle id='v'/></routes>", r"x\.xml: not SUMO FCD output \(no <fcd-export>\)"),
        (
            '<fcd-export><timestep time="1"><vehicle id="v" x="1" y="2" speed="fast"/></timestep></fcd-export>',
            r"<vehicle v> 'speed' is not numeric \('fast'\)",
        ),
        ('<fcd-export><timestep time="1"><vehicle id="v" x="1" speed="2"/></timestep></fcd-export>', "has no 'y'"),
        ('<fcd-export>\n<timestep time="1">\n<vehicle id="v" x="1" y="2" speed="3"/>\n', r"x\.xml:4: bad XML"),
    ],
)
def test_a_file_that_is_not_fcd_is_one_error_naming_it(tmp_path: Path, text: str, message: str) -> None:
    with pytest.raises(FcdError, match=message):
        read_timesteps(write(tmp_path, text, "x.xml"))


def test_a_missing_file_is_an_os_error(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError):
        read_timesteps(tmp_path / "none.xml")
