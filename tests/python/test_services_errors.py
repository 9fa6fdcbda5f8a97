"""Bad services input: exit code 2 and one clear stderr line naming the problem, never a crash.

Services files are checked before SUMO starts (format, filters, service types); a service's own
parameters are read when the service initializes, i.e. at its vehicle's departure.
"""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from sbsim.runner import RunResult, run
from sbsim_helpers import REPO, STORIES, assert_bad_input, assert_no_crash

HIGHWAY = STORIES / "highway-police"
CFG = HIGHWAY / "highway.sumocfg"
SERVICES = HIGHWAY / "services.xml"


def sbsim(*extra: str) -> RunResult:
    return run(CFG, extra=list(extra), timeout=120)


def services_file(directory: Path, body: str, name: str = "services.xml") -> Path:
    path = directory / name
    path.write_text(textwrap.dedent(body).lstrip("\n"), encoding="utf-8")
    return path


def line_of(path: Path, marker: str) -> int:
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        if marker in line:
            return number
    raise AssertionError(f"{marker!r} not in {path}")


def assert_services_error(path: Path, marker: str, *needles: str) -> str:
    """sbsim --services path fails as bad input, naming the file and the line holding ``marker``."""
    return assert_bad_input(sbsim("--services", str(path)), "--services", f"{path}:{line_of(path, marker)}", *needles)


# --- the services file -----------------------------------------------------------------------------


def test_the_highway_services_file_is_valid() -> None:
    """The reference file passes (so the failures below come from what each one changes)."""
    result = sbsim("--services", str(SERVICES), "--end", "1")
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""


def test_unknown_service_type(tmp_path: Path) -> None:
    path = services_file(
        tmp_path,
        """
        <?xml version="1.0" encoding="UTF-8"?>
        <services>
            <service type="ClearLaneService"/>
            <service type="NoSuchService" speed="25"/>
        </services>
        """,
    )
    line = assert_services_error(path, "NoSuchService", "unknown service type 'NoSuchService'")
    # ... and which types there are.
    assert "ClearLaneService" in line and "PoliceService" in line, line


def test_a_plugins_service_type_without_the_plugin() -> None:
    path = REPO / "examples" / "service-module" / "services.xml"
    assert_services_error(path, "<service ", "unknown service type 'BrakeLightService'")


@pytest.mark.parametrize("pattern", ["car(0", "[a-", "*police", "police\\"])
def test_bad_regex_pattern(tmp_path: Path, pattern: str) -> None:
    path = services_file(
        tmp_path,
        f"""
        <services>
            <service type="ClearLaneService">
                <filters>
                    <name pattern="police0" match="inverse"/>
                    <type pattern="{pattern}"/>
                </filters>
            </service>
        </services>
        """,
    )
    assert_services_error(path, f'pattern="{pattern}"', f"invalid pattern '{pattern}'")


@pytest.mark.parametrize(
    ("body", "marker", "needle"),
    [
        # a <service> never closed: the parser names the mismatched end tag's line
        ('<services>\n  <service type="ClearLaneService">\n</services>\n', "</services>", "</service>"),
        ('<services>\n  <service type="ClearLaneService"/>\n', "<services>", "never closed"),
        ('<services>\n  <service type="ClearLaneService\n  </service>\n</services>\n', "<service ", "unterminated"),
        ('<services>\n  <service type="A" type="B"/>\n</services>\n', "<service ", "duplicate attribute"),
        ('<services>\n  <service type="ClearLaneService"/>\n</services>\n<services/>\n', "<services/>", ""),
    ],
    ids=["mismatched-end-tag", "unclosed-root", "unterminated-quote", "duplicate-attribute", "two-roots"],
)
def test_malformed_xml(tmp_path: Path, body: str, marker: str, needle: str) -> None:
    path = services_file(tmp_path, body)
    assert_services_error(path, marker, needle)


def test_empty_file(tmp_path: Path) -> None:
    path = services_file(tmp_path, "")
    assert_bad_input(sbsim("--services", str(path)), "--services", str(path))


def test_missing_services_file(tmp_path: Path) -> None:
    missing = tmp_path / "nope.xml"
    assert_bad_input(sbsim("--services", str(missing)), "--services", str(missing), "no such file")


def test_services_file_is_a_directory(tmp_path: Path) -> None:
    assert_bad_input(sbsim("--services", str(tmp_path)), "--services", str(tmp_path), "director")


@pytest.mark.parametrize(
    ("filters", "marker", "needle"),
    [
        ('<speed pattern="police0"/>', "<speed", "unknown filter <speed>"),
        ('<penetration rate="0.5"/>', "<penetration", "<penetration>"),
        ('<name pattern="police0" rate="0.5"/>', "rate=", "'rate'"),
        ('<name pattern="police0" match="invert"/>', "match=", "'invert'"),
        ('<name regex="police0"/>', "regex=", "'regex'"),
        ("<name/>", "<name/>", "no 'pattern'"),
    ],
    ids=["unknown-element", "penetration", "rate", "bad-match", "unknown-attribute", "no-pattern"],
)
def test_bad_filter(tmp_path: Path, filters: str, marker: str, needle: str) -> None:
    path = services_file(
        tmp_path,
        f"""
        <services>
            <service type="ClearLaneService" speed="25">
                <filters>
                    {filters}
                </filters>
            </service>
        </services>
        """,
    )
    assert_services_error(path, marker, needle)


def test_unknown_filter_operator(tmp_path: Path) -> None:
    path = services_file(
        tmp_path,
        """
        <services>
            <service type="ClearLaneService">
                <filters operator="xor"><name pattern="car0"/></filters>
            </service>
        </services>
        """,
    )
    assert_services_error(path, "operator=", "'xor'")


@pytest.mark.parametrize(
    ("body", "marker", "needle"),
    [
        ("<services><service/></services>", "<service/>", "no 'type'"),
        ('<services><service type=" "/></services>', "<service ", "empty 'type'"),
        ('<service type="ClearLaneService"/>', "<service ", "root element must be <services>"),
        ('<services><servce type="ClearLaneService"/></services>', "<servce", "<servce>"),
        ('<services>\n<service type="ClearLaneService"><filter/></service>\n</services>', "<filter/>", "<filter>"),
    ],
    ids=["no-type", "blank-type", "wrong-root", "misspelt-service", "misspelt-filters"],
)
def test_bad_structure(tmp_path: Path, body: str, marker: str, needle: str) -> None:
    path = services_file(tmp_path, body)
    assert_services_error(path, marker, needle)


# --- service parameters (read when the service initializes) ---------------------------------------


def non_numeric_speed(tmp_path: Path) -> tuple[Path, RunResult]:
    path = services_file(
        tmp_path,
        """
        <services>
            <service type="PoliceService">
                <filters><name pattern="police0"/></filters>
            </service>
            <service type="ClearLaneService" speed="fast">
                <filters><name pattern="police0" match="inverse"/></filters>
            </service>
        </services>
        """,
    )
    return path, sbsim("--services", str(path))


def test_non_numeric_parameter_is_one_clear_line(tmp_path: Path) -> None:
    path, result = non_numeric_speed(tmp_path)
    assert_no_crash(result)
    assert result.returncode != 0
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, result.stderr
    line = lines[0]
    assert line.startswith("sbsim"), line
    for needle in (f"{path}:{line_of(path, 'speed=')}", "'speed'", "ClearLaneService", "'fast'", "a number"):
        assert needle in line, f"{needle!r} not in {line!r}"
    # It surfaces at the first departure (t = 0 here), before any summary.
    assert result.stdout == "", result.stdout


def test_non_numeric_parameter_exit_code(tmp_path: Path) -> None:
    _, result = non_numeric_speed(tmp_path)
    assert result.returncode == 2, result.stderr


# --- plugins ---------------------------------------------------------------------------------------


def test_plugin_missing(tmp_path: Path) -> None:
    missing = tmp_path / "libnope.so"
    assert_bad_input(sbsim("--plugin", str(missing)), "--plugin", str(missing), "no such file")


def test_plugin_checked_before_the_services_file(tmp_path: Path) -> None:
    """A services file naming the plugin's types is not blamed for the plugin that is missing."""
    missing = tmp_path / "libnope.so"
    path = REPO / "examples" / "service-module" / "services.xml"
    line = assert_bad_input(sbsim("--plugin", str(missing), "--services", str(path)), "--plugin", str(missing))
    assert "BrakeLightService" not in line


@pytest.mark.parametrize(
    "content", [b"not a library\n", b"\x7fELF" + b"\0" * 60, b""], ids=["text", "truncated-elf", "empty"]
)
def test_plugin_not_a_shared_library(tmp_path: Path, content: bytes) -> None:
    fake = tmp_path / "libfake.so"
    fake.write_bytes(content)
    assert_bad_input(sbsim("--plugin", str(fake)), "--plugin", str(fake), "cannot load")


def test_plugin_is_a_directory(tmp_path: Path) -> None:
    assert_bad_input(sbsim("--plugin", str(tmp_path)), "--plugin", str(tmp_path), "director")


# --- radio and middleware options -----------------------------------------------------------------


@pytest.mark.parametrize(
    ("option", "value", "needle"),
    [
        ("--v2x-range", "-1", "> 0"),
        ("--v2x-range", "0", "> 0"),
        ("--v2x-range", "inf", "> 0"),
        ("--v2x-range", "far", "'far'"),
        ("--middleware-interval", "0", "> 0"),
        ("--middleware-interval", "-0.1", "> 0"),
        ("--middleware-interval", "nan", "> 0"),
        ("--middleware-interval", "often", "'often'"),
        ("--v2x-latency", "-0.001", ">= 0"),
        ("--v2x-fade-start", "-5", ">= 0"),
    ],
)
def test_bad_radio_option(option: str, value: str, needle: str) -> None:
    # Without and with a services file (the option is checked either way, before anything runs), in
    # both spellings.
    assert_bad_input(sbsim(option, value), option, needle)
    assert_bad_input(sbsim("--services", str(SERVICES), f"{option}={value}"), option, needle)


def test_fade_start_beyond_the_range() -> None:
    line = assert_bad_input(sbsim("--services", str(SERVICES), "--v2x-range", "50", "--v2x-fade-start", "100"))
    assert "fade start" in line.lower(), line


@pytest.mark.parametrize("value", ["1e-10", "1e300"])
def test_middleware_interval_out_of_simtime_range(value: str) -> None:
    assert_bad_input(sbsim("--services", str(SERVICES), "--middleware-interval", value), "--middleware-interval")
