"""`sbsim check` reads every input a run reads (issue 29): the services file (elements, filters,
attributes, use-case files, roadside units) and the radio file (keys, types, ranges, the obstacles'
polygon type), refusing what a run refuses with the run's own one-line message. A run says how many
obstacles it loaded."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from sbsim.runner import RunResult, run
from sbsim_helpers import assert_bad_input, assert_no_crash
from test_radio import highway


def both(cfg: Path, *extra: str) -> tuple[RunResult, RunResult]:
    """The same inputs given to a run and to `sbsim check`."""
    ran = run(cfg, end=1.0, extra=list(extra), timeout=120)
    checked = run(cfg, extra=["check", *extra], timeout=120)
    assert_no_crash(ran)
    assert_no_crash(checked)
    return ran, checked


def assert_same_refusal(cfg: Path, needle: str, *extra: str) -> None:
    ran, checked = both(cfg, *extra)
    line = assert_bad_input(ran, needle)
    assert assert_bad_input(checked, needle) == line


@pytest.fixture
def road(tmp_path: Path) -> Path:
    return highway(tmp_path / "road", [50.0, 200.0], 1.0, building=True)


SERVICES = {
    # The case: <equipped> outside <filters>, which check used to pass.
    '<services><service type="Beacon" interval="0.1" bytes="190"><equipped/></service></services>': "<equipped>",
    '<services><service type="Beacon"><filters><name patern="v.*"/></filters></service></services>': "patern",
    '<services><service type="NoSuchService"/></services>': "unknown service type 'NoSuchService'",
    '<services><rsu id="r" x="1"><service type="RsuCaService"/></rsu></services>': "needs 'id', 'x' and 'y'",
    # Known only once SUMO is loaded and the units are placed, as in a run.
    '<services><rsu poiType="mast"><service type="RsuCaService"/></rsu></services>': "SUMO has no POI of that type",
    '<services><rsu id="r" x="1" y="2"><service type="CaService"/></rsu></services>': "cannot run on roadside unit",
    # An attribute a unit's service reads when it starts.
    '<services><rsu id="r" x="1" y="2"><service type="RsuCaService" generationInterval="-1"/></rsu></services>': (
        "generationInterval"
    ),
    '<services><service type="DenService" useCases="missing.xml"/></services>': "missing.xml",
}


@pytest.mark.parametrize("text", list(SERVICES))
def test_check_refuses_a_services_file_as_a_run_does(road: Path, text: str) -> None:
    services = road.parent / "s.xml"
    services.write_text(text, encoding="utf-8")
    assert_same_refusal(road, SERVICES[text], "--services", str(services))


RADIO = {
    "[phy]\npower = 23\n": "[phy] power: is not a radio setting",
    "[phy]\nrate_mbps = 7\n": "rate_mbps must be one of",
    '[phy]\npower_dbm = "high"\n': "power_dbm: must be a number",
    '[propagation]\npath_loss = "moon"\n': "path_loss: must be 3gpp-highway, 3gpp-urban, 3gpp-urban-nlos, free-",
    "[phy\n": "radio.toml:1",
    # A misspelt type used to take every building away in silence.
    '[obstacles]\npolygon_type = "buildings"\n': "polygon_type 'buildings' matches no polygon",
}


@pytest.mark.parametrize("text", list(RADIO))
def test_check_refuses_a_radio_file_as_a_run_does(road: Path, text: str) -> None:
    radio = road.parent / "radio.toml"
    radio.write_text(text, encoding="utf-8")
    assert_same_refusal(road, RADIO[text], "--services", str(road.parent / "h.services.xml"), "--radio", str(radio))


def test_an_unknown_polygon_type_names_the_types_there_are(road: Path) -> None:
    radio = road.parent / "radio.toml"
    radio.write_text('[obstacles]\npolygon_type = "Building"\n', encoding="utf-8")
    ran, _ = both(road, "--services", str(road.parent / "h.services.xml"), "--radio", str(radio))
    assert_bad_input(ran, "its polygon types: building, park")


def test_check_and_run_say_how_many_obstacles_were_loaded(road: Path, tmp_path: Path) -> None:
    radio = road.parent / "radio.toml"
    radio.write_text("", encoding="utf-8")
    summary = tmp_path / "s.json"
    services = str(road.parent / "h.services.xml")
    ran, checked = both(road, "--services", services, "--radio", str(radio), "--summary", str(summary))
    assert ran.returncode == 0, ran.stderr
    assert "obstacles: 1 (polygon type 'building')" in ran.stdout.splitlines()
    assert json.loads(summary.read_text(encoding="utf-8"))["obstacles"] == {"polygon_type": "building", "count": 1}
    assert checked.returncode == 0, checked.stderr
    assert f"{radio}: 1 obstacles (polygon type 'building')" in checked.stdout
    assert f"{services}: 1 service, 0 roadside units" in checked.stdout
    as_json = json.loads(run(road, extra=["check", "--json", "--services", services, "--radio", str(radio)]).stdout)
    assert as_json["radio"] == {"file": str(radio), "polygon_type": "building", "obstacles": 1}
    assert as_json["services"] == {"file": services, "services": 1, "roadside_units": 0}


def test_check_needs_services_for_a_radio_file(road: Path) -> None:
    radio = road.parent / "radio.toml"
    radio.write_text("", encoding="utf-8")
    story = road.parent / "story.py"
    story.write_text("def createStories(board):\n    pass\n", encoding="utf-8")
    assert_same_refusal(road, "--services", "--radio", str(radio), "--story", str(story))
