"""What `sbsim --scenario` does before SUMO starts: reads and checks the .xosc, finds or converts
its network, writes the vehicle types of its entities and the story script that builds its
stories inside sbsim. Run by sbsim as `python -m storyboard.openscenario prepare ...`."""

from __future__ import annotations

import hashlib
import json
import os
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr

from lxml import etree

from .errors import ScenarioError
from .network import Network, convert_opendrive
from .scenario import Scenario, logic_file, read


def cache_dir(xosc: Path) -> Path:
    """Where the converted network and the generated files are kept: beside the scenario."""
    return xosc.parent / ".sbsim"


def sumocfg_inputs(sumocfg: Path) -> tuple[Path, list[Path]]:
    """The network and the additional files a SUMO configuration names (absolute)."""
    try:
        root = etree.parse(str(sumocfg)).getroot()
    except (OSError, etree.XMLSyntaxError) as e:
        raise ScenarioError(f"{sumocfg}: cannot read the SUMO configuration: {e}") from None
    net = root.find("input/net-file")
    if net is None or not net.get("value"):
        raise ScenarioError(f"{sumocfg}: names no net-file")
    additional = root.find("input/additional-files")
    files = []
    if additional is not None and additional.get("value"):
        files = [(sumocfg.parent / f.strip()).resolve() for f in additional.get("value", "").split(",") if f.strip()]
    return (sumocfg.parent / net.get("value", "")).resolve(), files


def write_atomically(path: Path, text: str) -> None:
    if path.exists() and path.read_text() == text:
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(f".{path.name}.{os.getpid()}")
    temporary.write_text(text)
    temporary.replace(path)


def vehicle_types(scenario: Scenario) -> str:
    lines = ['<?xml version="1.0" encoding="UTF-8"?>', "<additional>"]
    for e in scenario.entities.values():
        if e.bound:
            continue
        # A speed factor lets the entity depart at its Init speed above the lane's limit.
        start = next((s for s in scenario.starts if s.entity == e.name), None)
        factor = 1.0
        if start is not None and start.lane is not None and start.speed is not None:
            limit = scenario.network.speed_limits.get(start.lane.id, start.speed)
            factor = max(1.0, start.speed / limit * 1.01) if limit > 0 else 1.0
        lines.append(
            f'    <vType id={quoteattr(e.vtype)} vClass={quoteattr(e.vclass)} length="{e.length:g}" '
            f'width="{e.width:g}" height="{e.height:g}" maxSpeed="{e.max_speed:g}" accel="{e.max_accel:g}" '
            f'decel="{e.max_decel:g}" speedFactor="{factor:g}" speedDev="0" '
            # An entity keeps its lane unless a LaneChangeAction moves it, as the standard's do:
            # SUMO's lane changes for speed, keeping right and cooperation are off for it.
            'lcSpeedGain="0" lcKeepRight="0" lcCooperative="0"/>'
        )
    lines.append("</additional>")
    return "\n".join(lines) + "\n"


def story_script(xosc: Path, net: Path, binds: Mapping[str, str]) -> str:
    return (
        f'"""The stories of {xosc.name}, built by sbsim\'s OpenSCENARIO importer (generated)."""\n\n'
        "from storyboard.openscenario import stories\n\n\n"
        "def createStories(board):\n"
        f"    stories.create(board, {str(xosc)!r}, {str(net)!r}, {dict(binds)!r})\n"
    )


def prepare(xosc: Path, sumocfg: Path | None, params: Mapping[str, str], binds: Mapping[str, str]) -> dict[str, Any]:
    xosc = xosc.resolve()
    if not xosc.is_file():
        raise ScenarioError(f"--scenario: {xosc} does not exist")
    cache = cache_dir(xosc)
    additional: list[Path] = []
    if sumocfg is not None:
        sumocfg = sumocfg.resolve()
        net_path, additional = sumocfg_inputs(sumocfg)
    else:
        xodr = logic_file(xosc)
        if xodr is None:
            raise ScenarioError(
                f"{xosc}: names no OpenDRIVE network (RoadNetwork/LogicFile); give a SUMO one with --sumocfg"
            )
        if not xodr.is_file():
            raise ScenarioError(f"{xosc}: its RoadNetwork/LogicFile {xodr} does not exist")
        net_path, command = convert_opendrive(xodr, cache)
        print("sbsim: network: " + " ".join(command), file=sys.stderr)
    scenario = read(xosc, Network.read(net_path), params, binds)
    for s in scenario.starts:
        if scenario.entities[s.entity].bound and s.lane is not None:
            print(
                f"sbsim: note: {s.entity} is SUMO's vehicle {scenario.entities[s.entity].sumo_id}: "
                "its Init position is where SUMO has it (the TeleportAction is not applied)",
                file=sys.stderr,
            )
    types = vehicle_types(scenario)
    key = hashlib.sha256((types + json.dumps(sorted(binds.items()))).encode()).hexdigest()[:10]
    types_file = cache / f"{xosc.stem}.{key}.vtypes.add.xml"
    write_atomically(types_file, types)
    story = cache / f"{xosc.stem}.{key}.story.py"
    write_atomically(story, story_script(xosc, net_path, binds))
    if sumocfg is None:
        sumocfg = cache / f"{xosc.stem}.sumocfg"
        write_atomically(
            sumocfg,
            '<?xml version="1.0" encoding="UTF-8"?>\n<configuration>\n'
            f"    <input><net-file value={quoteattr(str(net_path))}/></input>\n"
            '    <time><begin value="0"/><step-length value="0.1"/></time>\n</configuration>\n',
        )
    files = ",".join(str(f) for f in [*additional, types_file])
    return {"sumocfg": str(sumocfg), "story": str(story), "sumo_options": ["--additional-files", files]}
