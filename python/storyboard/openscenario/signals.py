"""OpenSCENARIO traffic signals on SUMO traffic lights: which light and links a signal `name` is, and
which SUMO letters a `state` is.

A `name` is, in this order:
- `tlsId:linkIndex`: one link of a SUMO traffic light (its letter in the light's state string);
- an OpenDRIVE signal id, on a network netconvert converted from OpenDRIVE: netconvert names each
  light for its junction and records which OpenDRIVE signal drives each link (the tlLogic's
  `linkSignalID:<link>` parameters); the signal is those links;
- a SUMO traffic light id: the whole light.
A state, for links: one word (red, yellow, green, off, redYellow; case aside), three lamps
`red;yellow;green` each on or off as OpenDRIVE's three-lamp signal (type 1000001) and esmini write
them ("off;off;on" is green), or one SUMO letter (GgrsuyYoO). For a whole light: SUMO's state string,
one letter per link ("GrGr"), or one word for every link. A name or state the network does not have
is an error naming it."""

from __future__ import annotations

from .errors import ScenarioError
from .network import Network

LETTERS = "GgrsuyYoO"  # SUMO's signal states
WORDS = {"red": "r", "yellow": "y", "amber": "y", "green": "G", "off": "O", "redyellow": "u"}
LAMPS = {  # red;yellow;green lamps on or off
    ("on", "off", "off"): "r",
    ("off", "on", "off"): "y",
    ("off", "off", "on"): "G",
    ("on", "on", "off"): "u",
    ("off", "off", "off"): "O",
}


def signal_links(network: Network, name: str, what: str) -> tuple[str, list[int]]:
    """The SUMO traffic light and the links (none: the whole light) signal `name` is."""
    if ":" in name:
        tls, _, index = name.rpartition(":")
        light = network.lights.get(tls)
        if light is not None:
            if not index.isdigit() or int(index) >= light.links:
                raise ScenarioError(
                    f"{what}: traffic light '{tls}' has no link '{index}' (links 0 to {light.links - 1})"
                )
            return tls, [int(index)]
    if name in network.signals:
        tls, links = network.signals[name]
        return tls, sorted(links)
    if name in network.lights:
        return name, []
    known = ", ".join(sorted(network.lights)[:10]) or "none"
    raise ScenarioError(
        f"{what}: no traffic signal '{name}' in {network.path.name}: not a SUMO traffic light ({known}), "
        "'tlsId:linkIndex', nor an OpenDRIVE signal id netconvert kept"
    )


def link_letter(state: str, what: str) -> str:
    """The SUMO letter of one link's `state` (a word, three lamps or a letter)."""
    word = state.strip().replace("-", "").replace("_", "").lower()
    if word in WORDS:
        return WORDS[word]
    lamps = tuple(part.strip().lower() for part in state.split(";"))
    if lamps in LAMPS:
        return LAMPS[lamps]
    if len(state) == 1 and state in LETTERS:
        return state
    raise ScenarioError(
        f"{what}: state '{state}' is none of red, yellow, green, off, redYellow, three lamps "
        f"'red;yellow;green' of on/off, or a SUMO letter ({LETTERS})"
    )


def signal_state(network: Network, tls: str, links: list[int], state: str, what: str) -> str:
    """SUMO's letters for `state`: one letter for links, else one per link of the light."""
    if links:
        return link_letter(state, what)
    count = network.lights[tls].links
    if len(state) == count and all(letter in LETTERS for letter in state):
        return state
    try:
        return link_letter(state, what) * count  # one word (or letter) for every link
    except ScenarioError:
        example = network.lights[tls].phases[0][1] if network.lights[tls].phases else ""
        raise ScenarioError(
            f"{what}: state '{state}' is not a state of traffic light '{tls}': {count} SUMO letters "
            f"({LETTERS}, one per link, e.g. '{example}'), or one word for every link"
        ) from None


def phase_index(network: Network, tls: str, phase: str, what: str) -> int:
    """The index of phase `phase` (its name, or its index if no phase is so named) of light `tls`'s
    programme in the network file."""
    light = network.lights.get(tls)
    if light is None:
        known = ", ".join(sorted(network.lights)[:10]) or "none"
        raise ScenarioError(f"{what}: no traffic light '{tls}' in {network.path.name} ({known})")
    named = [i for i, (name, _) in enumerate(light.phases) if name == phase]
    if not named and phase.isdigit() and int(phase) < len(light.phases):
        named = [int(phase)]
    if not named:
        names = [name or str(i) for i, (name, _) in enumerate(light.phases)]
        raise ScenarioError(f"{what}: traffic light '{tls}' has no phase '{phase}' (it has {', '.join(names)})")
    return named[0]


def phase_state(network: Network, tls: str, phase: str, what: str) -> str:
    """The state of phase `phase` of light `tls` (see phase_index)."""
    index = phase_index(network, tls, phase, what)  # first: it names a light the network lacks
    return network.lights[tls].phases[index][1]
