"""A report as one self-contained HTML page (figures embedded as PNGs), or its figures as PNG files."""

from __future__ import annotations

import base64
import html
import io
import os
from pathlib import Path

from matplotlib.figure import Figure

from sbsim.report.compose import Report

CAPTIONS = {
    "activity": "Vehicles under each story over time (stacked).",
    "durations": "How long vehicles stayed under each story (completed stays).",
    "map": "The network, the stories' areas (with --story) and where vehicles were when each story activated "
    "(from the FCD output).",
    "speeds": "Mean speed of the vehicles under each story against the other running vehicles.",
    "messages": "Messages sent per type and second (the --messages trace).",
    "delivery": "Packet delivery ratio against the sender-receiver distance, per message type (50 m bins; "
    "losses as far as the trace keeps them, --messages-range).",
    "busy_ratio": "Channel busy ratio the senders measured, mean and max per second (802.11p channel model).",
    "denm_speeds": "Mean speed of the vehicles that had received a DENM against the others (trace and FCD).",
}


def _ratio(value: float) -> str:
    return f"{value:.3f}"


def png(figure: Figure) -> bytes:
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=100)
    return buffer.getvalue()


def write_pngs(report: Report, directory: str | os.PathLike[str]) -> list[Path]:
    """Writes each figure as ``<name>.png`` into ``directory`` (created if missing)."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    out = []
    for name, figure in report.figures.items():
        path = directory / f"{name}.png"
        path.write_bytes(png(figure))
        out.append(path)
    return out


def to_html(report: Report) -> str:
    """One self-contained page: the tables and the figures as embedded PNGs."""
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{html.escape(report.title)}</title>",
        "<style>body{font-family:sans-serif;margin:2em;max-width:70em}"
        "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:.2em .6em;text-align:right}"
        "img{max-width:100%}figure{margin:1.5em 0}</style>",
        "</head><body>",
        f"<h1>{html.escape(report.title)}</h1>",
        "<h2>Stories</h2>",
        report.stories.to_html(classes="stories", float_format=lambda v: f"{v:.1f}", na_rep="-"),
    ]
    if report.run is not None:
        parts += ["<h2>Run</h2>", report.run.to_html(classes="run")]
    if "delivery" in report.v2x and not report.v2x["delivery"].empty:
        table = report.v2x["delivery"].set_index(["type", "distance"])
        parts += ["<h2>Delivery ratio by distance</h2>", table.to_html(classes="delivery", float_format=_ratio)]
    for name, figure in report.figures.items():
        data = base64.b64encode(png(figure)).decode("ascii")
        caption = html.escape(CAPTIONS.get(name, name))
        parts.append(
            f'<figure id="{name}"><img src="data:image/png;base64,{data}" alt="{caption}">'
            f"<figcaption>{caption}</figcaption></figure>"
        )
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
