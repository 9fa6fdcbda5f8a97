"""Fuzzing the program's two parsers of user text, the command line and the services file, with
hypothesis driving the real program (a fixed number of examples, derandomized so CI sees the same
inputs every time). Whatever the input: exit 0 or 2, never a crash or a hang, and a failure is one line.
Crashes found this way become cases of tests/corpus/.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from sbsim.runner import executable
from sbsim_helpers import CRASH_MARKERS
from test_corpus import message_lines

FUZZ = settings(
    max_examples=40,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)

OPTIONS = [
    "--end", "--seed", "--story", "--services", "--plugin", "--events", "--threads", "--middleware-interval",
    "--v2x-range", "--v2x-latency", "--v2x-fade-start", "--sumo-option", "--quiet", "--no-snapshot", "--version",
    "--", "-c", "--begin", "--step-length", "--sumocfg",
]  # fmt: skip
VALUES = st.one_of(
    st.sampled_from(["0", "-1", "1e-9", "1e300", "nan", "inf", "3", "0.5", "", "'", '"', "$HOME", "$(true)", "`x`"]),
    st.integers(-(2**70), 2**70).map(str),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.text(st.characters(blacklist_categories=["Cs"], blacklist_characters="\x00"), max_size=12),
)
WORDS = st.lists(st.one_of(st.sampled_from(OPTIONS), VALUES), max_size=6)


def check(args: list[str], cwd: Path) -> None:
    try:
        proc = subprocess.run(
            [str(executable()), *args], cwd=cwd, capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL
        )
    except subprocess.TimeoutExpired as e:
        raise AssertionError(f"sbsim hung on {args!r}") from e
    for marker in CRASH_MARKERS:
        assert marker not in proc.stderr, f"{args!r}: crash marker {marker!r}:\n{proc.stderr}"
    assert proc.returncode in (0, 2), f"{args!r}: exit {proc.returncode}:\n{proc.stderr}"
    if proc.returncode == 2:
        lines = message_lines(proc.stderr)
        assert len(lines) == 1, f"{args!r}: {len(lines)} message lines:\n{proc.stderr}"


@FUZZ
@given(words=WORDS)
@example(words=["\r"])  # found in CI: the error quoted the argument and split into two lines
@example(words=["--story", "a\nb\x1b"])
def test_command_line_never_crashes(words: list[str], trips_cfg: Path, tmp_path: Path) -> None:
    # Always a valid scenario and a short run first, so the fuzzed words are what decides.
    check(["--sumocfg", str(trips_cfg), "--end", "3", *words], tmp_path)


VALID_SERVICES = """<?xml version="1.0"?>
<services>
    <service type="PoliceService" name="police">
        <filters operator="and">
            <name pattern="veh1\\d*"/>
            <type pattern="car|truck" match="inverse"/>
        </filters>
    </service>
    <service type="ClearLaneService" interval="0.5"/>
</services>
"""


@st.composite
def mutated_services(draw: st.DrawFn) -> str:
    """The valid file with a few characters deleted, replaced or inserted (XML's own and random ones)."""
    text = VALID_SERVICES
    for _ in range(draw(st.integers(1, 4))):
        at = draw(st.integers(0, len(text)))
        kind = draw(st.sampled_from(["delete", "replace", "insert"]))
        piece = draw(st.one_of(st.sampled_from(list("<>/=\"'&;![]-? \n") + ["&amp;", "<!--", "]]>", "\x01", "é"]),
                               st.text(max_size=8)))  # fmt: skip
        cut = draw(st.integers(0, 12))
        if kind == "delete":
            text = text[:at] + text[at + cut :]
        elif kind == "replace":
            text = text[:at] + piece + text[at + len(piece) :]
        else:
            text = text[:at] + piece + text[at:]
    return text


@FUZZ
@given(text=mutated_services())
def test_services_file_never_crashes(text: str, trips_cfg: Path, tmp_path: Path) -> None:
    services = tmp_path / "services.xml"
    services.write_text(text.replace("\x00", ""), encoding="utf-8", errors="surrogatepass")
    check(["--sumocfg", str(trips_cfg), "--end", "3", "--services", str(services)], tmp_path)
