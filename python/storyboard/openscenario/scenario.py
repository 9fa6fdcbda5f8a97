"""Reads an OpenSCENARIO 1.x file into what sbsim runs: entities, their initial state, and the
storyboard as a tree of elements whose triggers and actions are recipes for storyboard conditions
and effects (built inside sbsim by :mod:`.stories`). Whatever is not supported is collected, and
one error lists every such element with its line."""

from __future__ import annotations

import importlib.util
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from lxml import etree

from .actions import ActionReader
from .conditions import ConditionReader
from .entities import EntityReader
from .errors import ScenarioError, where
from .init import InitReader
from .model import Build, Element, Scenario, Trigger
from .network import Network
from .parameters import Scope
from .reader import parse_file

# The catalogs entities and maneuver groups can name (CatalogLocations).
CATALOGS = ("VehicleCatalog", "ManeuverCatalog")

__all__ = ["Build", "Element", "Scenario", "Trigger", "logic_file", "read"]


def schema_for(root: Any) -> Path | None:
    """The ASAM OpenSCENARIO XSD of the file's revision, as the scenariogeneration package ships it."""
    spec = importlib.util.find_spec("scenariogeneration")
    if spec is None or spec.origin is None:
        return None
    schemas = Path(spec.origin).parent.parent / "schemas"
    header = root.find("FileHeader")
    minor = header.get("revMinor", "2") if header is not None else "2"
    name = {"0": "OpenSCENARIO_1_0.xsd", "1": "OpenSCENARIO_1_1.xsd", "2": "OpenSCENARIO_1_2.xsd"}.get(
        minor, "OpenSCENARIO_1_3_1.xsd"
    )
    return schemas / name if (schemas / name).exists() else None


def validate(path: Path, tree: Any) -> bool:
    """Checks the file against the ASAM schema when one is available; False when none is."""
    xsd = schema_for(tree.getroot())
    if xsd is None:
        return False
    schema = etree.XMLSchema(etree.parse(str(xsd)))
    if not schema.validate(tree):
        error = schema.error_log[0]
        raise ScenarioError(f"{path}:{error.line}: fails the ASAM schema ({xsd.name}): {error.message}")
    return True


class Importer(ConditionReader, ActionReader, InitReader, EntityReader):
    """The whole file: the document, and the storyboard's structure (story, act, group, maneuver, event)."""

    # -- the document ----------------------------------------------------------------------
    def read(self, tree: Any) -> Scenario:
        root = tree.getroot()
        if root.tag != "OpenSCENARIO":
            raise ScenarioError(f"{where(self.path, root)}: not an OpenSCENARIO file")
        self.only(
            root, {"FileHeader", "ParameterDeclarations", "CatalogLocations", "RoadNetwork", "Entities", "Storyboard"}
        )
        scope = Scope().declare(root.find("ParameterDeclarations"), self.path, self.overrides, self.used)
        self.globals = dict(scope.values)
        catalogs = root.find("CatalogLocations")
        if catalogs is not None:
            for location in catalogs:
                directory = location.find("Directory")
                if location.tag not in CATALOGS or directory is None:
                    self.problems.add(location)
                    continue
                self.catalog_dirs[location.tag] = (self.path.parent / self.text(directory, "path", scope)).resolve()
        road = root.find("RoadNetwork")
        if road is not None:
            self.only(road, {"LogicFile", "SceneGraphFile", "TrafficSignals"})
            signals = road.find("TrafficSignals")
            if signals is not None and len(signals):
                # Declared controllers would be new SUMO programmes: sbsim runs the network's own.
                self.problems.add(
                    signals,
                    "declared traffic signal controllers (sbsim runs the SUMO network's own traffic light "
                    "programmes: refer to a SUMO traffic light id as the controller)",
                )
        entities = root.find("Entities")
        if entities is not None:
            for obj in entities:
                if obj.tag != "ScenarioObject":
                    self.problems.add(obj)
                    continue
                self.read_object(obj, scope)
        for name in self.binds:
            if name not in self.entities:
                raise ScenarioError(f"--bind {name}={self.binds[name]}: {self.path} has no entity '{name}'")
        board = root.find("Storyboard")
        if board is None:
            raise ScenarioError(f"{where(self.path, root)}: no <Storyboard>")
        starts = self.read_init(board.find("Init"), scope)
        storyboard = Element("storyboard", "Storyboard", "Storyboard")
        for child in board:
            if child.tag == "Story":
                storyboard.children.append(self.read_story(child, scope))
            elif child.tag == "StopTrigger":
                storyboard.stop = self.read_trigger(child, scope)
            elif child.tag != "Init":
                self.problems.add(child)
        self.problems.raise_if_any()
        named = {(e.kind, e.name) for e in _elements(storyboard)}
        for key, missing in self.references:
            if key not in named:
                raise ScenarioError(missing)
        positioned = {s.entity for s in starts if s.lane is not None}
        for e in self.entities.values():
            if not e.bound and e.name not in positioned and e.name not in self.added:
                raise ScenarioError(
                    f"{self.path}: entity '{e.name}' has no position in Init (a TeleportAction) and is not "
                    f"bound to a SUMO vehicle (--bind {e.name}=VEHICLE)"
                )
        return Scenario(self.path, self.network, self.entities, starts, storyboard, dict(self.globals))

    # -- Storyboard ----------------------------------------------------------------------------
    def read_story(self, story: Any, scope: Scope) -> Element:
        name = self.text(story, "name", scope)
        local = scope.declare(story.find("ParameterDeclarations"), self.path)
        element = Element("story", name, name)
        for act in story:
            if act.tag == "Act":
                element.children.append(self.read_act(act, local, name))
            elif act.tag != "ParameterDeclarations":
                self.problems.add(act)
        return element

    def read_act(self, act: Any, scope: Scope, story: str) -> Element:
        name = self.text(act, "name", scope)
        element = Element("act", name, f"{story}/{name}")
        for child in act:
            if child.tag == "ManeuverGroup":
                element.children.append(self.read_group(child, scope, element.path))
            elif child.tag == "StartTrigger":
                element.start = self.read_trigger(child, scope)
            elif child.tag == "StopTrigger":
                element.stop = self.read_trigger(child, scope)
            else:
                self.problems.add(child)
        return element

    def read_group(self, group: Any, scope: Scope, act_path: str) -> Element:
        name = self.text(group, "name", scope)
        count = int(self.number(group, "maximumExecutionCount", scope, "1"))
        if count < 1:
            raise ScenarioError(f"{where(self.path, group)}: maximumExecutionCount {count} (at least 1)")
        element = Element("maneuver_group", name, f"{act_path}/{name}", max_executions=count)
        actors = group.find("Actors")
        if actors is not None:
            element.select_triggering = self.text(actors, "selectTriggeringEntities", scope, "false") == "true"
            for ref in actors:
                if ref.tag != "EntityRef":
                    self.problems.add(ref)
                    continue
                element.actors.append(self.sumo_id(self.text(ref, "entityRef", scope), ref))
        for child in group:
            if child.tag == "Maneuver":
                element.children.append(self.read_maneuver(child, scope, act_path, element.actors))
            elif child.tag == "CatalogReference":
                maneuver, local = self.catalog_entry(child, scope, "Maneuver")
                element.children.append(self.read_maneuver(maneuver, local, act_path, element.actors))
            elif child.tag != "Actors":
                self.problems.add(child)
        for maneuver in element.children:
            for event in maneuver.children:
                event.select_triggering = element.select_triggering
        return element

    def read_maneuver(self, maneuver: Any, scope: Scope, act_path: str, actors: list[str]) -> Element:
        name = self.text(maneuver, "name", scope)
        local = scope.declare(maneuver.find("ParameterDeclarations"), self.path)
        element = Element("maneuver", name, f"{act_path}/{name}")
        for child in maneuver:
            if child.tag == "Event":
                element.children.append(self.read_event(child, local, act_path, actors))
            elif child.tag != "ParameterDeclarations":
                self.problems.add(child)
        return element

    def read_event(self, event: Any, scope: Scope, act_path: str, actors: list[str]) -> Element:
        name = self.text(event, "name", scope)
        priority = self.text(event, "priority", scope, "parallel")
        priority = {"override": "overwrite"}.get(priority, priority)  # 1.2's new name for overwrite
        if priority not in ("parallel", "overwrite", "skip"):
            self.problems.add(event, f"priority '{priority}'")
            priority = "parallel"
        element = Element(
            "event",
            name,
            f"{act_path}/{name}",
            max_executions=int(self.number(event, "maximumExecutionCount", scope, "1")),
            priority=priority,
            actors=list(actors),
        )
        for child in event:
            if child.tag == "Action":
                action = self.read_action(child, scope, actors)
                if action is not None:
                    element.actions.append(action)
            elif child.tag == "StartTrigger":
                element.start = self.read_trigger(child, scope)
            else:
                self.problems.add(child)
        return element


def _elements(root: Element) -> list[Element]:
    out = [root]
    for child in root.children:
        out += _elements(child)
    return out


def read(path: Path, network: Network, overrides: Mapping[str, Any], binds: Mapping[str, str]) -> Scenario:
    """Reads and checks `path` (schema when available, then every element) on `network`."""
    tree = parse_file(path)
    validate(path, tree)
    xodr = logic_file(path)
    return Importer(path, network, overrides, binds, xodr if xodr is not None and xodr.is_file() else None).read(tree)


def logic_file(path: Path) -> Path | None:
    """The OpenDRIVE file the scenario names (RoadNetwork/LogicFile), if any."""
    tree = parse_file(path)
    logic = tree.getroot().find("RoadNetwork/LogicFile")
    if logic is None or not logic.get("filepath"):
        return None
    scope = Scope().declare(tree.getroot().find("ParameterDeclarations"), path)
    return (path.parent / str(scope.resolve(logic.get("filepath", ""), where(path, logic)))).resolve()
