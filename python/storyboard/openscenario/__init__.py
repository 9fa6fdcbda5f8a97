"""sbsim's OpenSCENARIO 1.x importer: `sbsim --scenario X.xosc` runs the scenario's storyboard as
sbsim stories (see README, "OpenSCENARIO"). :mod:`.prepare` runs before SUMO starts (network,
vehicle types, the story script), :mod:`.stories` inside sbsim."""

from __future__ import annotations

from .errors import ScenarioError

__all__ = ["ScenarioError"]
