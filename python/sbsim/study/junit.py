"""The study's JUnit file (``junit.xml``): one test suite per run, named by its parameters and seed, with a
test case per criterion its story registered (``board.registerCriterion``), read from the run's summary.

A run that failed (an exit code other than 0 and 3) is one test case ``run`` with an ``<error>``: its exit
code and stderr tail. The file is XML 1.0 whatever the names and values hold: the characters XML 1.0
forbids (control characters other than tab, line feed and carriage return; lone surrogates; U+FFFE and
U+FFFF) are written as escapes (``\\x01``, ``\\ud800``), so every JUnit reader parses it.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from sbsim.study.spec import Run, StudySpec
from sbsim.study.tables import COMPLETE
from sbsim.summary import SummaryError, read_summary

__all__ = ["JUNIT", "suite_name", "write_junit", "xml_text"]

#: The study's JUnit file, in its output folder.
JUNIT = "junit.xml"

#: What XML 1.0 does not allow in a document (its Char production's complement).
_FORBIDDEN = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def _escape(match: re.Match[str]) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def xml_text(value: object) -> str:
    """``value`` as text XML 1.0 can hold: each forbidden character as a visible escape."""
    return _FORBIDDEN.sub(_escape, str(value))


def suite_name(run: Run) -> str:
    """``"rain_speed=5, seed=1"``: the run's parameters in the study file's order, then its seed."""
    return ", ".join([*(f"{name}={value}" for name, value in run.parameters), f"seed={run.seed}"])


def _criteria(folder: Path) -> list[dict[str, Any]] | None:
    """The run's criteria as its summary has them; None if the summary cannot be read."""
    try:
        entries = read_summary(folder / "summary.json").get("criteria", [])
    except (OSError, SummaryError):
        return None
    if not isinstance(entries, list):
        return None
    return [e for e in entries if isinstance(e, dict)]


def _suite(parent: ET.Element, spec: StudySpec, run: Run, row: Mapping[str, Any]) -> tuple[int, int, int]:
    """Adds the run's test suite under parent; returns its (tests, failures, errors)."""
    name = xml_text(suite_name(run))
    suite = ET.SubElement(parent, "testsuite", name=name)
    properties = ET.SubElement(suite, "properties")
    for key, value in [*run.parameters, ("seed", run.seed), ("run", run.id), ("exit_code", row.get("exit_code"))]:
        ET.SubElement(properties, "property", name=xml_text(key), value=xml_text(value))
    code = row.get("exit_code")
    criteria = _criteria(spec.directory / "runs" / run.id) if code in COMPLETE else None
    tests = failures = errors = 0
    if criteria is None:
        # The run did not end as a run ends (or left no summary): one error says how it ended.
        case = ET.SubElement(suite, "testcase", name="run", classname=name)
        tail = str(row.get("stderr_tail") or "")
        error = ET.SubElement(case, "error", message=xml_text(f"exit code {code}"), type="run")
        error.text = xml_text(tail)
        tests, errors = 1, 1
    else:
        for criterion in criteria:
            text = xml_text(f"actual: {criterion.get('actual')}; expected: {criterion.get('expected')}")
            case = ET.SubElement(suite, "testcase", name=xml_text(criterion.get("name")), classname=name)
            tests += 1
            if criterion.get("passed") is True:
                ET.SubElement(case, "system-out").text = text
            else:
                failures += 1
                failure = ET.SubElement(case, "failure", message=text, type="criterion")
                failure.text = text
    suite.set("tests", str(tests))
    suite.set("failures", str(failures))
    suite.set("errors", str(errors))
    suite.set("time", str(row.get("wall_s") or 0))
    return tests, failures, errors


def write_junit(spec: StudySpec, runs: Sequence[Run], rows: Sequence[Mapping[str, Any]]) -> Path:
    """Writes ``junit.xml`` into the study's folder (through a rename: never half written) and returns its path."""
    root = ET.Element("testsuites", name=xml_text(spec.directory.name))
    totals = [0, 0, 0]
    for run, row in zip(runs, rows, strict=True):
        for k, n in enumerate(_suite(root, spec, run, row)):
            totals[k] += n
    root.set("tests", str(totals[0]))
    root.set("failures", str(totals[1]))
    root.set("errors", str(totals[2]))
    ET.indent(root)
    path = spec.directory / JUNIT
    tmp = path.with_name(f"{JUNIT}.tmp")
    ET.ElementTree(root).write(tmp, encoding="utf-8", xml_declaration=True)
    tmp.replace(path)
    return path
