"""sbsim's storyboard package.

Inside a story run by ``sbsim --story``, ``import storyboard`` gives Artery's story API
(conditions, effects, ``Story``, ``Coord``, ``SimTime``), implemented in C++, plus Pythonic helpers
(:func:`all_of`, :func:`any_of`, :func:`seconds`, ...). The host tools (running the program, reading
its outputs, reports, studies, scenario generation) are the :mod:`sbsim` package; ``storyboard.runner``,
``storyboard.report`` and ``storyboard.study`` are their older names, kept working.
"""

from __future__ import annotations

from typing import Any

__version__ = "0.1.0"

try:  # the C++ core exists only inside the sbsim program
    import _sbsim  # type: ignore[import-not-found]
except ImportError:  # imported by a plain Python (tests, tools, the runner)
    IN_SBSIM = False
    _CORE_NAMES: list[str] = []
else:
    IN_SBSIM = True
    # Every public name of the C++ module, as it is: __init__.pyi types them, and a test checks the
    # stub against the compiled module, so a binding added without a stub fails.
    _CORE_NAMES = sorted(name for name in dir(_sbsim) if not name.startswith("_"))
    globals().update({name: getattr(_sbsim, name) for name in _CORE_NAMES})

__all__ = [*_CORE_NAMES, "IN_SBSIM", "all_of", "any_of", "milliseconds", "once", "seconds"]


def _require_sbsim(name: str) -> None:
    if not IN_SBSIM:
        raise RuntimeError(f"storyboard.{name} is only available inside a story run by sbsim --story")


def all_of(*conditions: Any) -> Any:
    """``AllCondition`` over any number of conditions, evaluated left to right, lazily."""
    _require_sbsim("all_of")
    if not conditions:
        raise ValueError("all_of needs at least one condition")
    return _sbsim.AllCondition(*conditions)


def any_of(*conditions: Any) -> Any:
    """``AnyCondition`` over any number of conditions, evaluated left to right, lazily."""
    _require_sbsim("any_of")
    if not conditions:
        raise ValueError("any_of needs at least one condition")
    return _sbsim.AnyCondition(*conditions)


def once(condition: Any) -> Any:
    """``LatchCondition(condition)``: once true for a vehicle, true for it until it leaves."""
    _require_sbsim("once")
    return _sbsim.LatchCondition(condition)


def seconds(x: float) -> Any:
    """A ``SimTime`` of ``x`` seconds (Artery's ``timeline.seconds``)."""
    _require_sbsim("seconds")
    return _sbsim.SimTime(x)


def milliseconds(x: float) -> Any:
    """A ``SimTime`` of ``x`` milliseconds (Artery's ``timeline.milliseconds``)."""
    _require_sbsim("milliseconds")
    return _sbsim.SimTime(x / 1000.0)


def __getattr__(name: str) -> Any:
    # Only reached for names not defined above: outside sbsim, say why instead of a bare AttributeError.
    if not IN_SBSIM and name[:1].isupper():
        _require_sbsim(name)
    if not IN_SBSIM and not name.startswith("_"):  # e.g. sumo_polygon: still an AttributeError, for hasattr
        raise AttributeError(
            f"module 'storyboard' has no attribute {name!r} here: the story API exists only inside a story run by "
            "sbsim --story"
        )
    raise AttributeError(f"module 'storyboard' has no attribute {name!r}")
