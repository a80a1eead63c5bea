"""Self-contained HTML report: one file with inline CSS and plots as base64 PNG, to open or mail as is."""
from __future__ import annotations

import base64
from collections.abc import Sequence
from functools import cache
from pathlib import Path

from grader.report import SubmissionReport, TaskReport
from grader.reports.cause import criterion_feedback, criterion_measured, lead_lines, noticed
from grader.reports.escape import html_text as escape
from grader.reports.plots import Plot
from grader.reports.replay import Replay
from grader.reports.text import NOTICED_HEADING, fmt_points, foxglove_help, percent, watch_first

HERE = Path(__file__).parent

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;max-width:60rem;margin:2rem auto;padding:0 1rem;color:#222}
h1{font-size:1.5rem}h2{font-size:1.2rem;margin-top:2rem;border-bottom:1px solid #ddd;padding-bottom:.2rem}
table{border-collapse:collapse;width:100%;margin:.5rem 0}th,td{border:1px solid #ddd;padding:.35rem .5rem;text-align:left;vertical-align:top}
th{background:#f4f4f4}.pass{color:#176f2c}.fail{color:#b3261e}.score{font-size:1.2rem;font-weight:600}
.warn{background:#fff4e5;border-left:4px solid #f0a020;padding:.5rem .75rem}figure{margin:1rem 0}
figure img{max-width:100%;border:1px solid #eee}figcaption{font-size:.85rem;color:#555}code{background:#f4f4f4;padding:0 .2rem}
th,td{overflow-wrap:anywhere}@media (max-width:40rem){body{margin:1rem auto;padding:0 .5rem}table{font-size:.85rem}th,td{padding:.25rem}}
"""


def data_uri(png: bytes) -> str:
    """A PNG as a data: URI, so the page needs no other file."""
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


@cache
def _asset(name: str) -> str:
    """A file shipped beside this module (the replay's script and style), pasted into the page."""
    return (HERE / name).read_text(encoding="utf-8")


def _jump(task: TaskReport, criterion_id: str, scenario: str | None, replays: Sequence[Replay]) -> str:
    """A link to the moment a criterion was decided, in the replay of the run that decided it."""
    for replay in replays:
        if replay.task == task.id and replay.scenario == scenario:
            at = dict(replay.moments).get(criterion_id)
            if at is not None:
                return (f'<br><a class="rp-jump" href="#{replay.anchor}" data-replay="{replay.anchor}" '
                        f'data-t="{at:.2f}">▶ watch at {at:.2f} s ({escape(scenario)})</a>')
    return ""


def _replay_html(replay: Replay, first: bool) -> str:
    """One replay: the picture, what the node was doing then, and the controls (the script makes them work)."""
    label = f"{replay.task}, scenario {replay.scenario}"
    heading = f"Replay of scenario '{escape(replay.scenario)}'" + (" (watch this one first)" if first else "")
    data = replay.data.replace("<", "\\u003c")  # no "</script>" inside the script element
    return f"""<section class="replay" id="{replay.anchor}" aria-label="Replay of {escape(label)}">
<h3>{heading}</h3>
<div class="rp-main"><div><canvas class="rp-view" width="480" height="480" tabindex="0" role="img" aria-label="The world seen from above at the chosen time"></canvas></div>
<div class="rp-side"><p class="rp-pose"></p><p class="rp-command"></p>
<p><b>Your node's output until then</b></p><ol class="rp-log" aria-label="Output lines until the chosen time"></ol></div></div>
<div class="rp-controls"><button type="button" class="rp-play" aria-label="Play">▶ Play</button>
<span role="group" aria-label="Speed"><button type="button" class="rp-speed" data-speed="1" aria-pressed="true">1×</button>
<button type="button" class="rp-speed" data-speed="4" aria-pressed="false">4×</button>
<button type="button" class="rp-speed" data-speed="16" aria-pressed="false">16×</button></span>
<div class="rp-timeline"><label for="{replay.anchor}-time">Time in the run</label>
<input type="range" class="rp-time" id="{replay.anchor}-time" min="0" max="1" step="0.01" value="0">
<div class="rp-marks" aria-hidden="true"></div></div><output class="rp-clock" for="{replay.anchor}-time"></output></div>
<p class="rp-hint">Keys: space plays or pauses, ← and → step one second (with Shift, five).</p>
<p><b>What happened</b> (click to see that moment)</p><ul class="rp-events"></ul>
<script type="application/json" class="rp-data">{data}</script>
</section>"""


def _task_html(task: TaskReport, plots: Sequence[Plot], replays: Sequence[Replay] = (),
               first: tuple[str, str] | None = None) -> list[str]:
    parts = [f"<h2>{escape(task.title or task.id)} <code>{escape(task.id)}</code>: {fmt_points(task.score, task.max_score)}</h2>"]
    parts += [f'<p class="warn">{escape(line)}</p>' for line in lead_lines(task)]
    if task.criteria:
        parts.append("<table><tr><th></th><th>Criterion</th><th>Points</th><th>Measured</th><th>Feedback</th></tr>")
        for c in task.criteria:
            css, sign = ("pass", "✔") if c.passed else ("fail", "✘")
            parts.append(
                f'<tr><td class="{css}">{sign}</td><td>{escape(c.title or c.id)}</td>'
                f"<td>{fmt_points(c.score, c.max_score)}</td><td>{escape(criterion_measured(task, c))}"
                f"{_jump(task, c.id, c.scenario, replays)}</td>"
                f"<td>{escape(criterion_feedback(task, c))}</td></tr>"
            )
        parts.append("</table>")
    if task.diagnostics:
        parts.append(f"<p>{NOTICED_HEADING}:</p><ul>")
        parts += [f"<li>{escape(d)}</li>" for d in noticed(task)]
        parts.append("</ul>")
    parts += [_replay_html(r, (r.task, r.scenario) == first) for r in replays if r.task == task.id]
    for plot in (p for p in plots if p.task == task.id):
        parts.append(
            f'<figure><img alt="{escape(plot.title)}" src="{data_uri(plot.png)}">'
            f"<figcaption>{escape(plot.title)}</figcaption></figure>"
        )
    if task.recordings:
        parts.append("<p>Recordings: " + ", ".join(f"<code>{escape(r)}</code>" for r in task.recordings) + "</p>")
    return parts


def render_html(report: SubmissionReport, plots: Sequence[Plot] = (), notes: Sequence[str] = (),
                replays: Sequence[Replay] = ()) -> str:
    """The whole report as one HTML page, with a replay of each run (its script and style inline: no network)."""
    worst = watch_first(report)
    first = None if worst is None else (worst[0].id, worst[1])
    watched = next((r for r in replays if (r.task, r.scenario) == first), None)
    title = f"rosgrade report: {report.submission}"
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{escape(title)}</title><style>{_CSS}{_asset('replay.css') if replays else ''}</style></head><body>",
        f"<h1>{escape(title)}</h1>",
        f'<p class="score">Score: {fmt_points(report.score, report.max_score)} ({percent(report):.0f} %)</p>',
    ]
    if report.isolation:  # as on the console: a weaker mode stands out
        css = ' class="warn"' if "rlimits" in report.isolation else ""
        parts.append(f"<p{css}>Nodes isolated by {escape(report.isolation)}.</p>")
    parts += [
        "<table><tr><th>Task</th><th>Status</th><th>Points</th></tr>",
    ]
    parts += [
        f"<tr><td>{escape(t.title or t.id)}</td><td>{escape(t.status)}</td><td>{fmt_points(t.score, t.max_score)}</td></tr>"
        for t in report.tasks
    ]
    parts.append("</table>")
    if watched is not None:
        parts.append(f'<p>Watch first: <a href="#{watched.anchor}">the replay of {escape(watched.task)}, scenario '
                     f"'{escape(watched.scenario)}'</a>.</p>")
    for task in report.tasks:
        parts += _task_html(task, plots, replays, first)
    if notes:
        parts.append("<h2>Notes</h2><ul>" + "".join(f"<li>{escape(n)}</li>" for n in notes) + "</ul>")
    recordings = [r for t in report.tasks for r in t.recordings]
    if recordings:
        parts.append("<h2>Looking at a recording</h2><ul>")
        parts += [f"<li>{escape(line)}</li>" for line in foxglove_help(recordings[0])]
        parts.append("</ul>")
    parts.append(f"<p><small>rosgrade {escape(report.rosgrade_version)}</small></p>")
    if replays:
        parts.append(f"<script>{_asset('replay.js')}</script>")
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"
