"""SUMO's warnings: the first few of each kind on stderr, all of them counted and in --sumo-log."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

from sbsim.runner import read_summary, run
from sbsim_helpers import assert_bad_input

# Teleports after 2 s of waiting: plenty of warnings of two kinds on the small grid.
NOISY = ["--no-warnings false --time-to-teleport 2"]


def warning_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if line.startswith("Warning: ")]


def test_warnings_are_summarised_counted_and_logged(trips_cfg: Path, tmp_path: Path) -> None:
    log, summary = tmp_path / "sumo.log", tmp_path / "s.json"
    result = run(trips_cfg, end=120, sumo_options=NOISY, extra=["--sumo-log", str(log), "--summary", str(summary)])
    assert result.returncode == 0, result.stderr
    logged = warning_lines(log.read_text(encoding="utf-8"))
    figures = read_summary(summary)["sumo_warnings"]
    assert figures["total"] == len(logged) > 10
    assert sum(kind["count"] for kind in figures["kinds"]) == figures["total"]
    counts = [kind["count"] for kind in figures["kinds"]]
    assert counts == sorted(counts, reverse=True)
    # On stderr: at most 3 of each kind, each followed by one note once the kind is cut short.
    shown = warning_lines(result.stderr)
    per_kind = Counter("teleporting on edge" in line for line in shown)
    assert all(n <= 3 for n in per_kind.values()), result.stderr
    assert len(shown) < len(logged)
    cut = [kind for kind in figures["kinds"] if kind["count"] > 3]
    assert result.stderr.count("are only counted") == len(cut)
    assert f"sumo warnings: {figures['total']} of {len(figures['kinds'])} kinds" in result.stdout


def test_verbose_shows_every_warning(trips_cfg: Path, tmp_path: Path) -> None:
    summary = tmp_path / "s.json"
    result = run(trips_cfg, end=120, sumo_options=NOISY, extra=["--verbose", "--summary", str(summary)])
    assert result.returncode == 0, result.stderr
    assert len(warning_lines(result.stderr)) == read_summary(summary)["sumo_warnings"]["total"]
    assert "only counted" not in result.stderr


def test_sumo_log_is_an_output_like_the_others(trips_cfg: Path) -> None:
    assert_bad_input(run(trips_cfg, end=5, extra=["--sumo-log", str(trips_cfg)]), "--sumo-log")
    assert_bad_input(run(trips_cfg, end=5, extra=["--quiet", "--verbose"]), "--verbose")
