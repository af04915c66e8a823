"""Evaluation reports: a printed table, and a Markdown (with a PNG chart) or HTML (inline SVG) file
listing every miss and why."""

from __future__ import annotations

import html
import json
from collections.abc import Sequence
from pathlib import Path
from typing import Final

from PIL import Image, ImageDraw

from langnav.eval.metrics import CaseResult, Summary

CHART_W: Final = 640
CHART_ROW_H: Final = 28
CHART_LABEL_W: Final = 200
_BAR_COLOURS: Final = {"precision": "#4e79a7", "recall": "#f28e2b", "f1": "#59a14f"}


def _fmt(v: float | None) -> str:
    return "n/a" if v is None else f"{v:.4f}"


def table(summary: Summary, translator: str, seconds: float) -> str:
    """The figures as a plain-text table."""
    s = summary
    lines = [f"translator {translator}: {s.cases} cases in {seconds:.2f} s "
             f"({1000 * seconds / max(s.cases, 1):.1f} ms per prompt)",
             f"{'prompt accuracy':22s} {s.prompt_accuracy:.4f}  ({s.right}/{s.cases})",
             f"{'command precision':22s} {s.overall.precision:.4f}",
             f"{'command recall':22s} {s.overall.recall:.4f}",
             f"{'command F1':22s} {s.overall.f1:.4f}",
             f"{'NTP pose validity':22s} {_fmt(s.ntp_validity)}  ({s.ntp_valid}/{s.ntp_all})",
             f"{'Move end validity':22s} {_fmt(s.move_validity)}  ({s.move_valid}/{s.move_all})",
             "",
             f"{'command':22s} {'matched':>8s} {'produced':>9s} {'expected':>9s} {'P':>7s} {'R':>7s} {'F1':>7s}"]
    for name, t in s.by_type.items():
        lines.append(f"{name:22s} {t.matched:8d} {t.produced:9d} {t.expected:9d} "
                     f"{t.precision:7.3f} {t.recall:7.3f} {t.f1:7.3f}")
    return "\n".join(lines)


def _chart_rows(summary: Summary) -> list[tuple[str, float, float, float]]:
    rows = [("all commands", summary.overall.precision, summary.overall.recall, summary.overall.f1)]
    rows += [(k, v.precision, v.recall, v.f1) for k, v in summary.by_type.items()]
    return rows


def chart_svg(summary: Summary) -> str:
    """Precision / recall / F1 per command type as horizontal bars (inline SVG)."""
    rows = _chart_rows(summary)
    bar_w = CHART_W - CHART_LABEL_W - 60
    h = 30 + len(rows) * CHART_ROW_H * 1.2
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{CHART_W}" height="{h:.0f}" font-family="sans-serif" '
           'font-size="12">']
    x = CHART_LABEL_W
    for i, key in enumerate(_BAR_COLOURS):
        out.append(f'<rect x="{x + i * 90}" y="4" width="12" height="12" fill="{_BAR_COLOURS[key]}"/>'
                   f'<text x="{x + i * 90 + 16}" y="15">{key}</text>')
    for r, (name, p, rec, f1) in enumerate(rows):
        y0 = 28 + r * CHART_ROW_H * 1.2
        out.append(f'<text x="4" y="{y0 + 14:.0f}">{html.escape(name)}</text>')
        for i, (key, v) in enumerate(zip(_BAR_COLOURS, (p, rec, f1), strict=True)):
            y = y0 + i * (CHART_ROW_H / 3)
            out.append(f'<rect x="{x}" y="{y:.1f}" width="{v * bar_w:.1f}" height="{CHART_ROW_H / 3 - 1:.1f}" '
                       f'fill="{_BAR_COLOURS[key]}"/>')
            out.append(f'<text x="{x + v * bar_w + 4:.1f}" y="{y + 8:.1f}" font-size="9">{v:.2f}</text>')
    out.append("</svg>")
    return "".join(out)


def chart_png(summary: Summary, path: Path) -> None:
    rows = _chart_rows(summary)
    bar_w = CHART_W - CHART_LABEL_W - 60
    h = int(30 + len(rows) * CHART_ROW_H * 1.2)
    img = Image.new("RGB", (CHART_W, h), "white")
    d = ImageDraw.Draw(img)
    for i, key in enumerate(_BAR_COLOURS):
        d.rectangle([CHART_LABEL_W + i * 90, 4, CHART_LABEL_W + i * 90 + 12, 16], fill=_BAR_COLOURS[key])
        d.text((CHART_LABEL_W + i * 90 + 16, 4), key, fill="black")
    for r, (name, p, rec, f1) in enumerate(rows):
        y0 = 28 + r * CHART_ROW_H * 1.2
        d.text((4, y0 + 4), name, fill="black")
        for i, (key, v) in enumerate(zip(_BAR_COLOURS, (p, rec, f1), strict=True)):
            y = y0 + i * (CHART_ROW_H / 3)
            d.rectangle([CHART_LABEL_W, y, CHART_LABEL_W + max(v * bar_w, 1), y + CHART_ROW_H / 3 - 2],
                        fill=_BAR_COLOURS[key])
            d.text((CHART_LABEL_W + v * bar_w + 4, y - 1), f"{v:.2f}", fill="black")
    img.save(path)


def _misses(results: Sequence[CaseResult]) -> list[CaseResult]:
    return [r for r in results if not r.right]


def markdown(summary: Summary, results: Sequence[CaseResult], translator: str, seconds: float,
             chart_name: str) -> str:
    out = [f"# langnav evaluation ({translator})", "", "```", table(summary, translator, seconds), "```", "",
           f"![precision, recall and F1 per command type]({chart_name})", "",
           f"## Misses ({len(_misses(results))} of {summary.cases})", ""]
    for r in _misses(results):
        out.append(f"### {r.id}: {r.prompt}")
        out.extend(f"- {w}" for w in r.why)
        out.append(f"- produced: `{json.dumps(r.produced_cmds)}`")
        if r.clarification:
            out.append(f"- clarification: {r.clarification}")
        out.append(f"- expected: `{json.dumps(r.expected_cmds)}`")
        out.append("")
    if not _misses(results):
        out.append("None.")
    return "\n".join(out) + "\n"


def html_report(summary: Summary, results: Sequence[CaseResult], translator: str, seconds: float) -> str:
    e = html.escape
    rows = []
    for r in _misses(results):
        rows.append(f"<tr><td>{e(r.id)}</td><td>{e(r.prompt)}</td><td><ul>"
                    + "".join(f"<li>{e(w)}</li>" for w in r.why)
                    + f"</ul></td><td><code>{e(json.dumps(r.produced_cmds))}</code>"
                    + (f"<br><i>{e(r.clarification)}</i>" if r.clarification else "")
                    + f"</td><td><code>{e(json.dumps(r.expected_cmds))}</code></td></tr>")
    return ("<!doctype html><html><head><meta charset='utf-8'><title>langnav evaluation</title>"
            "<style>body{font-family:sans-serif;margin:2em}td,th{border:1px solid #ccc;padding:4px;"
            "vertical-align:top}table{border-collapse:collapse}code{font-size:11px}</style></head><body>"
            f"<h1>langnav evaluation ({e(translator)})</h1><pre>{e(table(summary, translator, seconds))}</pre>"
            f"{chart_svg(summary)}<h2>Misses ({len(rows)} of {summary.cases})</h2>"
            "<table><tr><th>id</th><th>prompt</th><th>why</th><th>produced</th><th>expected</th></tr>"
            + "".join(rows) + "</table></body></html>\n")


def write_report(path: Path, summary: Summary, results: Sequence[CaseResult], translator: str,
                 seconds: float) -> list[Path]:
    """Write a .md (+ .png chart beside it) or .html report; returns the files written."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.suffix.lower() in (".html", ".htm"):
        path.write_text(html_report(summary, results, translator, seconds), encoding="utf-8")
        return [path]
    png = path.with_suffix(".png")
    chart_png(summary, png)
    path.write_text(markdown(summary, results, translator, seconds, png.name), encoding="utf-8")
    return [path, png]
