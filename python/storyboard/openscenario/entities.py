"""ScenarioObjects as SUMO vehicle types: vehicles, catalog references with parameter assignments, and
MiscObjects as obstacles (a SUMO vehicle of the object's bounding box, held at speed 0)."""

from __future__ import annotations

from typing import Any

from .errors import ScenarioError, where
from .model import Entity
from .parameters import Scope
from .reader import Reader

# vehicleCategory -> SUMO vehicle class.
VEHICLE_CLASSES = {
    "car": "passenger",
    "van": "delivery",
    "truck": "truck",
    "trailer": "trailer",
    "semitrailer": "trailer",
    "bus": "bus",
    "motorbike": "motorcycle",
    "bicycle": "bicycle",
}


class EntityReader(Reader):
    def read_object(self, obj: Any, scope: Scope) -> None:
        name = self.text(obj, "name", scope)
        if obj.find("MiscObject") is not None:
            self.read_misc_object(obj.find("MiscObject"), name, scope)
            return
        self.only(obj, {"Vehicle", "CatalogReference", "ObjectController"})
        controller = obj.find("ObjectController")
        if controller is not None and len(controller):
            self.problems.add(controller, "controllers (SUMO's driver model drives)")
        vehicle = obj.find("Vehicle")
        local = scope
        reference = obj.find("CatalogReference")
        if reference is not None:
            vehicle, local = self.catalog_entry(reference, scope, "Vehicle")
        if vehicle is None:
            if reference is None and not any(c.tag not in ("Vehicle", "ObjectController") for c in obj):
                self.problems.add(obj, "only Vehicle entities")
            return
        local = local.declare(vehicle.find("ParameterDeclarations"), self.path)
        self.only(vehicle, {"ParameterDeclarations", "Performance", "BoundingBox", "Axles", "Properties"})
        category = self.text(vehicle, "vehicleCategory", local)
        if category not in VEHICLE_CLASSES:
            self.problems.add(vehicle, f"vehicleCategory '{category}'")
            return
        dims = vehicle.find("BoundingBox/Dimensions")
        perf = vehicle.find("Performance")
        length = self.number(dims, "length", local) if dims is not None else 4.5
        width = self.number(dims, "width", local) if dims is not None else 1.8
        height = self.number(dims, "height", local) if dims is not None else 1.5
        sumo_id = self.binds.get(name, name)
        self.entities[name] = Entity(
            name,
            sumo_id,
            VEHICLE_CLASSES[category],
            length,
            width,
            height,
            self.number(perf, "maxSpeed", local) if perf is not None else 70.0,
            self.number(perf, "maxAcceleration", local) if perf is not None else 2.6,
            self.number(perf, "maxDeceleration", local) if perf is not None else 4.5,
            name in self.binds,
        )

    def read_misc_object(self, misc: Any, name: str, scope: Scope) -> None:
        """An obstacle on the road: a SUMO vehicle (vClass `ignoring`, so that any lane takes it) of the
        object's bounding box, held at speed 0 from its Init position on. Other vehicles brake for it
        and may change lanes around it as for a standing vehicle."""
        local = scope.declare(misc.find("ParameterDeclarations"), self.path)
        self.only(misc, {"ParameterDeclarations", "BoundingBox", "Properties"})
        dims = misc.find("BoundingBox/Dimensions")
        if dims is None:
            raise ScenarioError(f"{where(self.path, misc)}: a MiscObject needs BoundingBox/Dimensions")
        self.entities[name] = Entity(
            name,
            self.binds.get(name, name),
            "ignoring",
            self.number(dims, "length", local),
            self.number(dims, "width", local),
            self.number(dims, "height", local),
            1.0,  # SUMO needs a positive maxSpeed; the hold keeps it at 0
            2.6,
            4.5,
            name in self.binds,
            obstacle=True,
        )
