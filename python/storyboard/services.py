"""V2X applications in Python: services running in-process on sbsim's middleware, radio and facilities.

A service is a class derived from :class:`Service`, named in the services file Artery-style::

    <service type="python:warner.py:Warner" threshold="8"/>   <!-- a file beside the services file -->
    <service type="python:mypkg.apps:Warner"/>                 <!-- a module on the story's path -->

with filters, ``--penetration`` and roadside units exactly as for C++ services. sbsim makes one instance per
station and calls the methods the class defines (a method it leaves to this base class is not called at all):

- ``initialize()`` when the station departs; ``finish()`` when it arrives or the run ends;
- ``trigger()`` every middleware interval, on the station's own clock (as the C++ ``Service::trigger``);
- ``receive_signal(signal)`` for a storyboard signal;
- ``indicate(message)`` for every message received, when it is received; or, if the class defines
  ``indicate_batch(messages)``, the messages received since the last batch in one call, in the order a C++
  service's ``indicate`` gets them, right before ``trigger()`` (and ``finish()``): one call per interval
  instead of one per message, with the batch's columns as numpy arrays;
- ``on_cam(cam)`` / ``on_denm(denm)`` after the station's facilities took a CAM or DENM in.

A service that sends DENMs (:meth:`Service.send_denm`) says so with the class attribute ``sends_denms = True``:
the run then counts it as a DENM source (a ``WarnedBefore`` criterion is accepted), and ``send_denm`` refuses to
run in a class that does not declare it.

Everything a service asks and commands goes to the C++ service it runs in (the same middleware clock, local
dynamic map, DENM memory, effect stack and statistics as a C++ service's). An exception ends the run with
exit code 2, naming the service, the station, the simulated time and the Python file and line.
"""

from __future__ import annotations

import inspect
import math
from collections.abc import Callable, Iterator, Mapping, Sequence
from types import MappingProxyType
from typing import TYPE_CHECKING, Any, ClassVar, Protocol

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    FloatArray = npt.NDArray[np.float64]

__all__ = ["Cam", "Denm", "Message", "Messages", "Service", "Signal"]


class Cam(Protocol):
    """A CAM's content (EN 302 637-2), as the station received it."""

    station: str
    generation_time: float  # s
    position: tuple[float, float]  # SUMO network frame, m
    speed: float  # m/s
    heading: float  # degrees, 0 = north, clockwise
    acceleration: float
    length: float
    width: float
    yaw_rate: float
    roadside_unit: bool


class Denm(Protocol):
    """A DENM's content (EN 302 637-3)."""

    action: str  # "station:sequence"
    station: str
    cause: int
    subcause: int
    event_position: tuple[float, float]
    detection_time: float
    reference_time: float
    expiry: float
    terminated: bool


class Message(Protocol):
    """One received message: its header, and its content when sbsim knows the type."""

    type: str
    sender: str
    sent_at: float
    received_at: float
    sequence: int
    size: int  # bytes of the message itself
    frame_bytes: int  # the whole 802.11 frame
    payload: Any  # a Python service's message: what it sent (frozen); None for others
    cam: Cam | None
    denm: Denm | None


class Messages(Protocol):
    """The messages of one batch, in reception order; numeric columns are read-only numpy arrays."""

    def __len__(self) -> int: ...
    def __getitem__(self, index: int) -> Message: ...
    def __iter__(self) -> Iterator[Message]: ...

    types: list[str]
    senders: list[str]
    received_at: FloatArray
    sent_at: FloatArray
    sizes: FloatArray
    cam_positions: FloatArray  # (n, 2); NaN for messages that are not CAMs
    cam_speeds: FloatArray
    cam_headings: FloatArray


class Signal(Protocol):
    """A storyboard signal (a story's SignalEffect)."""

    cause: str
    story: str
    ego: str
    others: list[str]
    on_exit: bool


class Snapshot:
    """The current step's vehicles: ids and numpy columns.

    A column is a read-only view of the snapshot's own array, not a copy (``flags.owndata`` is False), the same
    array for every read and every Python service in the step; one kept past its step stays valid and keeps that
    step's values, as sbsim writes the next steps elsewhere while it is held (read the snapshot again for the new
    step's).
    """

    def __init__(self, host: Any) -> None:
        self._host = host

    @property
    def time(self) -> float:
        return float(self._host.snapshot_time())

    @property
    def ids(self) -> list[str]:
        return list(self._host.snapshot_ids())

    def __len__(self) -> int:
        return self._host.snapshot_size()  # type: ignore[no-any-return]

    def index_of(self, vehicle_id: str) -> int | None:
        return self._host.snapshot_index_of(vehicle_id)  # type: ignore[no-any-return]

    def _column(self, name: str) -> FloatArray:
        return self._host.snapshot_column(name)  # type: ignore[no-any-return]

    positions = property(lambda self: self._column("positions"), doc="(n, 2) x, y in m")
    speeds = property(lambda self: self._column("speeds"), doc="m/s")
    angles = property(lambda self: self._column("angles"), doc="degrees, 0 = north, clockwise")
    accelerations = property(lambda self: self._column("accelerations"), doc="m/s²")
    lengths = property(lambda self: self._column("lengths"), doc="m")
    widths = property(lambda self: self._column("widths"), doc="m")


#: The callbacks sbsim calls, with how many arguments besides self.
CALLBACKS: Mapping[str, int] = MappingProxyType(
    {
        "initialize": 0,
        "trigger": 0,
        "receive_signal": 1,
        "indicate": 1,
        "indicate_batch": 1,
        "on_cam": 1,
        "on_denm": 1,
        "finish": 0,
    }
)

#: The kinds a services-file attribute may be declared as (Service.attributes).
ATTRIBUTE_KINDS: tuple[type, ...] = (str, int, float, bool)

_SECURITY = {"cam": True, "other": False}


def _convert(kind: type, text: str) -> Any:
    if kind is bool:
        value = text.strip()
        if value in ("true", "1"):
            return True
        if value in ("false", "0"):
            return False
        raise ValueError(f"must be true or false, got {text!r}")
    if kind is str:
        return text
    try:
        return kind(text.strip())
    except ValueError:
        raise ValueError(f"must be {'a whole number' if kind is int else 'a number'}, got {text!r}") from None


def _number(what: str, value: Any) -> float:
    """A finite number of send_denm's, as a float."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"send_denm: {what} must be a finite number, got {value!r}")
    return float(value)


def _freeze(value: Any, where: str = "payload") -> Any:
    """The payload as receivers get it: plain values, lists as tuples, dicts as read-only mappings."""
    if value is None or isinstance(value, (bool, int, float, str, bytes)):
        return value
    if isinstance(value, (list, tuple)):
        return tuple(_freeze(v, where) for v in value)
    if isinstance(value, (dict, MappingProxyType)):
        return MappingProxyType({k: _freeze(v, where) for k, v in value.items()})
    raise TypeError(
        f"send: the {where} holds a {type(value).__name__}; only None, bool, int, float, str, bytes, "
        "lists, tuples and dicts of them travel"
    )


class Service:
    """Base of services written in Python (see the module's documentation).

    ``attributes`` declares the services-file attributes the service takes, each with its kind (``str``,
    ``int``, ``float`` or ``bool``); any other attribute (but Artery's ``name``) is refused before the run.
    ``sends_denms = True`` declares that it sends DENMs (:meth:`send_denm`): the run counts it as a DENM source.
    """

    attributes: ClassVar[Mapping[str, type]] = {}
    #: The service sends DENMs (send_denm): the run counts it as a DEN service, as it does DenService.
    sends_denms: ClassVar[bool] = False
    _host: Any  # set by sbsim before __init__

    # --- callbacks (override those the service needs) ---
    def initialize(self) -> None:
        """The station departed (its services were just made)."""

    def trigger(self) -> None:
        """Every middleware interval, on the station's own clock."""

    def receive_signal(self, signal: Signal) -> None:
        """A storyboard signal for this station (or any, after listen_to_all_signals())."""

    def indicate(self, message: Message) -> None:
        """A message another station sent reached this one."""

    def indicate_batch(self, messages: Messages) -> None:
        """The messages received since the last batch; by default, indicate() for each."""
        for message in messages:
            self.indicate(message)

    def on_cam(self, cam: Cam) -> None:
        """A CAM, after the local dynamic map took it in."""

    def on_denm(self, denm: Denm) -> None:
        """A DENM whose area holds this station, after the DENM memory took it in."""

    def finish(self) -> None:
        """The station arrived, or the run ended."""

    # --- what it is ---
    @property
    def station_id(self) -> str:
        """The vehicle's id, or the roadside unit's."""
        return self._host.station_id()  # type: ignore[no-any-return]

    @property
    def is_roadside_unit(self) -> bool:
        return self._host.roadside_unit()  # type: ignore[no-any-return]

    @property
    def time(self) -> float:
        """The simulated time, s."""
        return self._host.time()  # type: ignore[no-any-return]

    def attribute(self, name: str, default: Any = None) -> Any:
        """The services-file attribute ``name``, of the kind ``attributes`` declares (text if undeclared)."""
        text = self._host.parameter(name)
        if text is None:
            return default
        return _convert(type(self).attributes.get(name, str), text)

    def study_parameter(self, name: str) -> bool | int | float | str | None:
        """The run's ``--param NAME=VALUE`` (counted as used), or None."""
        return self._host.study_parameter(name)  # type: ignore[no-any-return]

    # --- its vehicle (a roadside unit has only a position) ---
    @property
    def position(self) -> tuple[float, float]:
        """Where the station is (a vehicle: the current step's front bumper), SUMO network frame, m."""
        return self._host.position()  # type: ignore[no-any-return]

    @property
    def speed(self) -> float | None:
        """m/s in the current step; None while the vehicle is not in the snapshot (or on a roadside unit)."""
        return self._host.speed()  # type: ignore[no-any-return]

    @property
    def heading(self) -> float | None:
        """Degrees, 0 = north, clockwise (SUMO's angle)."""
        return self._host.heading()  # type: ignore[no-any-return]

    @property
    def acceleration(self) -> float | None:
        return self._host.acceleration()  # type: ignore[no-any-return]

    @property
    def edge(self) -> str:
        """The road (SUMO edge) the vehicle is on."""
        return self._host.edge()  # type: ignore[no-any-return]

    @property
    def lane(self) -> str:
        return self._host.lane()  # type: ignore[no-any-return]

    @property
    def lane_index(self) -> int:
        return self._host.lane_index()  # type: ignore[no-any-return]

    def driving_distance(self, x: float, y: float) -> float | None:
        """Along the vehicle's route to the point (x, y); None if it is not on the route."""
        return self._host.driving_distance(float(x), float(y))  # type: ignore[no-any-return]

    def driving_distance_to_edge(self, edge: str, position: float = 0.0) -> float | None:
        """Along the route to ``position`` m on ``edge``; None if the edge is not on the route."""
        return self._host.driving_distance_to_edge(edge, float(position))  # type: ignore[no-any-return]

    @property
    def self_index(self) -> int | None:
        """The vehicle's row in :attr:`snapshot`."""
        return self._host.self_index()  # type: ignore[no-any-return]

    @property
    def snapshot(self) -> Snapshot:
        """All vehicles of the current step."""
        return Snapshot(self._host)

    # --- what the station heard ---
    @property
    def ldm(self) -> dict[str, Cam]:
        """The local dynamic map: the latest CAM of each station heard."""
        return self._host.ldm()  # type: ignore[no-any-return]

    @property
    def denms(self) -> list[Denm]:
        """The DENM memory: the events heard and not expired."""
        return self._host.denms()  # type: ignore[no-any-return]

    @property
    def channel_busy_ratio(self) -> float | None:
        """The share of the last 100 ms the station sensed the channel busy (the channel model), else None."""
        return self._host.channel_busy_ratio()  # type: ignore[no-any-return]

    @property
    def dcc_interval(self) -> float | None:
        """The least time between two messages congestion control allows now, s; None without DCC."""
        return self._host.dcc_interval()  # type: ignore[no-any-return]

    # --- acting ---
    def send(self, type_name: str, size_bytes: int, payload: Any = None, *, security: str = "other") -> None:
        """Broadcasts a message of type ``type_name`` and ``size_bytes`` bytes (single hop).

        The trace and the counts see its type and size; receivers' Python services read ``payload`` (plain
        values: None, bool, int, float, str, bytes, and lists, tuples and dicts of them; frozen on the way).
        ``security="cam"`` signs it as a CAM (certificate digest between certificates), ``"other"`` with the
        full certificate.
        """
        if not isinstance(type_name, str) or not type_name:
            raise ValueError("send: the type name must be a non-empty string")
        if isinstance(size_bytes, bool) or not isinstance(size_bytes, int) or not 1 <= size_bytes <= 65535:
            raise ValueError(f"send: size_bytes must be a whole number from 1 to 65535, got {size_bytes!r}")
        if security not in _SECURITY:
            raise ValueError(f"send: security must be 'cam' or 'other', got {security!r}")
        self._host.send(type_name, size_bytes, _freeze(payload), _SECURITY[security])

    def send_denm(
        self,
        cause: int,
        subcause: int = 0,
        *,
        area: float = 1000.0,
        validity: float = 600.0,
        repetition: float | None = None,
        interval: float = 1.0,
        position: tuple[float, float] | None = None,
        relevance: float | None = None,
        traffic_class: int = 1,
    ) -> str:
        """Starts a DENM event (EN 302 637-3) through the station's DEN service; returns its action id.

        The same DENM as a DenService use case's (a StoryboardEvent's defaults): detected now at ``position``
        (default the station's), geo-broadcast to a circle of ``area`` m around it through the station's
        GeoNetworking router, kept by receivers for ``validity`` s, and sent again every ``interval`` s for
        ``repetition`` s (default: as long as it is valid; 0: once). ``relevance`` is the relevance distance
        (m), ``traffic_class`` GeoNetworking's. Receivers' ``DenmCondition`` stories, ``on_denm`` and DENM memory
        see it; the trace writes it as the C++ services' DENMs. Needs ``sends_denms = True`` on the class.
        """
        name = type(self).__qualname__
        if type(self).sends_denms is not True:
            raise RuntimeError(f"send_denm: {name} does not declare sends_denms = True")
        for label, code in (("cause", cause), ("subcause", subcause)):
            if isinstance(code, bool) or not isinstance(code, int) or not 0 <= code <= 255:
                raise ValueError(f"send_denm: {label} must be a whole number from 0 to 255, got {code!r}")
        if isinstance(traffic_class, bool) or not isinstance(traffic_class, int) or not 0 <= traffic_class <= 255:
            raise ValueError(f"send_denm: traffic_class must be a whole number from 0 to 255, got {traffic_class!r}")
        area = _number("area", area)
        if not area > 0:
            raise ValueError(f"send_denm: area must be > 0 m, got {area!r}")
        validity = _number("validity", validity)
        if not 0 < validity <= 86400:
            raise ValueError(f"send_denm: validity must be from 0 to 86400 s (ETSI's range), got {validity!r}")
        repeat = validity if repetition is None else _number("repetition", repetition)
        interval = _number("interval", interval)
        if repeat > 0 and not 0 < interval:
            raise ValueError(f"send_denm: interval must be > 0 s to repeat, got {interval!r}")
        at = None
        if position is not None:
            if not isinstance(position, (tuple, list)) or len(position) != 2:
                raise ValueError(f"send_denm: position must be (x, y) in m, got {position!r}")
            at = (_number("position", position[0]), _number("position", position[1]))
        if relevance is not None:
            relevance = _number("relevance", relevance)
            if not relevance > 0:
                raise ValueError(f"send_denm: relevance must be > 0 m, got {relevance!r}")
        return self._host.send_denm(  # type: ignore[no-any-return]
            cause, subcause, area, validity, interval, repeat, at, relevance, traffic_class
        )

    def terminate_denm(self, action: str) -> bool:
        """Ends this station's event ``action`` (send_denm's answer): its repetition stops and a cancellation DENM
        goes to the same area, which makes receivers drop the event. False if the event is not live (ended, or
        not this station's)."""
        if not isinstance(action, str):
            raise TypeError(f"terminate_denm: the action id must be a str ('station:sequence'), got {action!r}")
        return self._host.terminate_denm(action)  # type: ignore[no-any-return]

    def schedule_after(self, seconds: float, callback: Callable[[], object]) -> int:
        """Calls ``callback()`` after ``seconds`` of simulated time; returns a handle for :meth:`cancel`."""
        if not callable(callback):
            raise TypeError("schedule_after: the callback must be callable")
        return self._host.schedule_after(float(seconds), callback)  # type: ignore[no-any-return]

    def cancel(self, handle: int) -> bool:
        """Cancels a pending callback; False if it ran or was cancelled already."""
        return self._host.cancel(handle)  # type: ignore[no-any-return]

    def start_phase(self, interval: float) -> float:
        """A phase in [0, interval) s drawn from the seed and the station, the one sbsim's Beacon starts at."""
        return self._host.start_phase(float(interval))  # type: ignore[no-any-return]

    def listen_to_all_signals(self) -> None:
        """From now on, also receive storyboard signals meant for other vehicles."""
        self._host.listen_to_all_signals()

    # Commands: entries on the vehicle's effect stack (they compose with the stories' effects and are
    # restored by their end_* call or when the vehicle leaves); a lane change is SUMO's timed command.
    def set_max_speed(self, mps: float) -> None:
        self._host.set_max_speed(float(mps))

    def end_max_speed(self) -> None:
        self._host.end_max_speed()

    def stop(self) -> None:
        """Holds the vehicle at standstill (a story's StopEffect's entry) until :meth:`end_stop`."""
        self._host.stop()

    def end_stop(self) -> None:
        self._host.end_stop()

    def change_lane(self, index: int, seconds: float) -> None:
        """SUMO's lane change to lane ``index`` (0: rightmost), kept for ``seconds``."""
        self._host.change_lane(int(index), float(seconds))

    def change_lane_relative(self, offset: int, seconds: float) -> None:
        self._host.change_lane_relative(int(offset), float(seconds))

    def set_speed_factor(self, factor: float) -> None:
        self._host.set_speed_factor(float(factor))

    def end_speed_factor(self) -> None:
        self._host.end_speed_factor()

    def set_color(self, r: int, g: int, b: int, a: int = 255) -> None:
        self._host.set_color(int(r), int(g), int(b), int(a))

    def end_color(self) -> None:
        self._host.end_color()

    def change_target(self, edge: str) -> None:
        self._host.change_target(edge)

    def end_route(self) -> None:
        self._host.end_route()

    # --- statistics (--statistics, the summary) ---
    def record_scalar(self, name: str, value: float) -> None:
        """A scalar of this service (typically in finish()): a row of the statistics, an aggregate in the summary."""
        self._host.record_scalar(name, float(value))

    def emit(self, name: str, value: float) -> None:
        """One value of the time series ``name`` at the current time."""
        self._host.emit(name, float(value))


def _defined(cls: type, name: str) -> bool:
    return getattr(cls, name, None) is not getattr(Service, name)


def _where(obj: Any) -> str:
    try:
        return f" (defined at {inspect.getsourcefile(obj)}:{inspect.getsourcelines(obj)[1]})"
    except (OSError, TypeError):
        return ""


def _check(cls: Any, attributes: Mapping[str, str]) -> str | None:
    """What is wrong with ``cls`` as the service of a services-file entry with ``attributes``, or None."""
    if not isinstance(cls, type) or not issubclass(cls, Service):
        return f"{getattr(cls, '__name__', cls)!s} is not a class derived from storyboard.services.Service"
    name = cls.__qualname__
    try:
        inspect.signature(cls).bind()
    except TypeError:
        return f"{name}() must be callable without arguments (sbsim makes it){_where(cls)}"
    except ValueError:
        pass  # no signature to read (a builtin __init__): nothing to check
    for method, count in CALLBACKS.items():
        if not _defined(cls, method):
            continue
        f = getattr(cls, method)
        wanted = f"{name}.{method}(self{''.join(', ' + a for a in _ARGUMENTS[method])})"
        if not callable(f):
            return f"{name}.{method} must be a method {wanted}"
        try:
            inspect.signature(f).bind(None, *([None] * count))
        except TypeError:
            return f"{name}.{method} must take {wanted}{_where(f)}"
        except ValueError:
            pass
    if not isinstance(cls.sends_denms, bool):
        return f"{name}.sends_denms must be True or False, got {cls.sends_denms!r}{_where(cls)}"
    declared = cls.attributes
    if not isinstance(declared, Mapping) or not all(
        isinstance(k, str) and v in ATTRIBUTE_KINDS for k, v in declared.items()
    ):
        return f"{name}.attributes must map attribute names to str, int, float or bool{_where(cls)}"
    for key, text in attributes.items():
        if key == "name":  # Artery's label
            continue
        if key not in declared:
            takes = ", ".join(sorted(declared)) or "none"
            return f"unknown attribute '{key}' (it takes: {takes}; declare it in {name}.attributes)"
        try:
            _convert(declared[key], text)
        except ValueError as e:
            return f"attribute '{key}' {e}"
    return None


_ARGUMENTS: Mapping[str, Sequence[str]] = MappingProxyType(
    {
        "initialize": (),
        "trigger": (),
        "receive_signal": ("signal",),
        "indicate": ("message",),
        "indicate_batch": ("messages",),
        "on_cam": ("cam",),
        "on_denm": ("denm",),
        "finish": (),
    }
)
