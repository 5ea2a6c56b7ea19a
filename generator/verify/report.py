"""What a verify run prints and writes: the table, the summary, JSON, a self-contained HTML page.

Every file is written to a temporary name beside its target and renamed into
place, so an interrupted run never leaves a half-written report.
"""

from __future__ import annotations

import base64
import html
import json
from collections import defaultdict
from pathlib import Path
from urllib.parse import urlencode

import numpy as np

from generator.files import write_files
from generator.verify.judge import APPROX, FAIL, NOT_RUN, PASS
from generator.verify.report_assets import SCRIPT, STYLE
from generator.verify.run import Verification

COLUMNS = ("check", "item", "engine", "max", "p99", "tolerance", "verdict")
#: The verdicts in the order the report counts them.
VERDICTS = (PASS, APPROX, FAIL, NOT_RUN)


def _figure(value: float) -> str:
    return "-" if not np.isfinite(value) and not np.isinf(value) else f"{value:.3g}"


def rows(verification: Verification, everything: bool = True) -> list[tuple[str, ...]]:
    """One row per check and engine (only those not passing unless ``everything``)."""
    return [
        (
            o.check.kind,
            o.check.title,
            o.engine,
            _figure(o.worst),
            _figure(o.p99),
            f"{o.check.tolerance:g} {o.check.metric}",
            o.verdict,
        )
        for o in verification.outcomes
        if everything or o.verdict != PASS
    ]


def table(verification: Verification, everything: bool = True) -> str:
    """The rows as aligned plain text."""
    body = rows(verification, everything)
    widths = [max([len(c)] + [len(r[i]) for r in body]) for i, c in enumerate(COLUMNS)]
    lines = ["  ".join(c.ljust(w) for c, w in zip(COLUMNS, widths))]
    lines += ["  ".join(v.ljust(w) for v, w in zip(r, widths)) for r in body]
    return "\n".join(lines)


def groups(verification: Verification) -> dict:
    """(engine, kind, metric) -> counts by verdict and the worst row's max, p99 and tolerance: the
    row whose error is the largest part of its tolerance (a group mixes tolerances, so the largest
    error beside the largest tolerance could read as within it while rows failed, and another
    row's p99 could exceed the max shown). A row run but not computed (a file OCIO could not
    load) makes the worst NaN: "-", not a number."""
    out: defaultdict[tuple[str, str, str], dict[str, float]] = defaultdict(
        lambda: {"checks": 0, PASS: 0, FAIL: 0, APPROX: 0, NOT_RUN: 0, "max": 0.0, "p99": 0.0, "tolerance": 0.0}
    )
    share: dict[tuple[str, str, str], float] = {}
    for o in verification.outcomes:
        key = (o.engine, o.check.kind, o.check.metric)
        entry = out[key]
        entry["checks"] += 1
        entry[o.verdict] += 1
        if o.verdict == NOT_RUN:
            continue
        computed = bool(np.isfinite(o.worst) | np.isinf(o.worst))
        part = float(o.worst) / o.check.tolerance if computed else float("inf")
        if key not in share or part > share[key] or (part == share[key] and not computed):
            share[key] = part
            entry["max"] = float(o.worst) if computed else float("nan")
            entry["p99"] = float(o.p99) if computed and np.isfinite(o.p99) else float("nan")
            entry["tolerance"] = o.check.tolerance
    return dict(out)


def _against(o) -> str:
    """A failing or explained row's figure against its tolerance: over it, within it (the
    verdict comes from elsewhere: the non-finite policy), or not computed."""
    if not (np.isfinite(o.worst) or np.isinf(o.worst)):
        return "not computed"
    return f"{_figure(o.worst)} {'>' if o.worst > o.check.tolerance else 'within'} {o.check.tolerance:g}"


def summary(verification: Verification, explained: bool = True) -> str:
    """Per engine and check type: counts, worst max and p99; then engines, failures and (unless
    ``explained`` is False: ``verify --summary``) one line per departure OCIO's default flags explain."""
    lines = [
        f"{verification.config}: {len(verification.checks)} checks, "
        f"{len(verification.outcomes)} results in {verification.seconds:.1f} s"
    ]
    for run in verification.engines:
        runs = f" ({run.version})" if run.version else ""
        state = f"not run{runs}: {run.skipped}" if run.skipped else f"{run.seconds:.1f} s, {run.version}"
        lines.append(f"  engine {run.name}: {state}")
    found = groups(verification)
    width = max([24, *(len(engine) for engine, _, _ in found)])  # "oiiotool system (TIFF uint16)"
    lines.append(
        f"  {'engine':<{width}} {'check':<15} {'metric':<16} {'n':>4} {'pass':>5} {'approx':>6} {'FAIL':>5} "
        f"{'max':>9} {'p99':>9} {'tolerance':>9}"
    )
    for (engine, kind, metric), g in found.items():
        if g[NOT_RUN] == g["checks"]:  # an engine that did not run compared nothing: no figures of 0
            lines.append(f"  {engine:<{width}} {kind:<15} {metric:<16} {g['checks']:>4}  not run")
            continue
        lines.append(
            f"  {engine:<{width}} {kind:<15} {metric:<16} {g['checks']:>4} {g[PASS]:>5} {g[APPROX]:>6} "
            f"{g[FAIL]:>5} {_figure(g['max']):>9} {_figure(g['p99']):>9} {g['tolerance']:>9.3g}"
        )
    for o in verification.outcomes:
        if o.verdict == FAIL or (o.verdict == APPROX and explained):
            where = f"; worst input {o.worst_input}" if o.worst_input else ""
            lines.append(
                f"{o.verdict}: {o.check.kind} {o.check.title} [{o.engine}]: {_against(o)}"
                f"{where}{'; ' + o.note if o.note else ''}"
            )
    verdict = "passed" if verification.passed else "FAILED"
    nothing = "" if verification.compared else "nothing compared (no engine ran a check), "
    approx = sum(o.verdict == APPROX for o in verification.outcomes)
    lines.append(
        f"verify {verdict}: {nothing}{len(verification.failures)} failing, "
        f"{approx} explained by OCIO's default flags"
        + (" (each named without --summary, and in --report's files)" if approx and not explained else "")
        + (f", {_not_run(verification)}: {', '.join(verification.missing)}" if verification.missing else "")
    )
    return "\n".join(lines)


def _not_run(verification: Verification) -> str:
    """How the summary names the engines that did not run: asked for, they fail the run."""
    return "not run (asked for by --engines)" if verification.strict else "not run"


def to_json(verification: Verification) -> dict:
    """The verification as plain data: config, engines, timings, one row per outcome (NaN as null)."""

    def number(value):
        return None if not np.isfinite(value) else float(value)

    return {
        "config": str(verification.config),
        "spec": verification.spec.name,
        "ocio_version": ".".join(map(str, verification.spec.ocio_version)),
        "passed": verification.passed,
        "seconds": verification.seconds,
        "engines": [
            {"name": e.name, "version": e.version, "seconds": e.seconds, "not_run": e.skipped or None}
            for e in verification.engines
        ],
        "groups": [
            {
                "engine": k[0],
                "check": k[1],
                "metric": k[2],
                **{n: (number(v) if isinstance(v, float) else v) for n, v in g.items()},
            }
            for k, g in groups(verification).items()
        ],
        "results": [
            {
                "check": o.check.kind,
                "item": o.check.item,
                "title": o.check.title,
                "engine": o.engine,
                "metric": o.check.metric,
                "max": number(o.worst),
                "p99": number(o.p99),
                "tolerance": o.check.tolerance,
                "verdict": o.verdict,
                "worst_input": o.worst_input,
                "compared": o.compared,
                "undefined": o.undefined,
                "policy_violations": o.violations,
                "note": o.note,
            }
            for o in verification.outcomes
        ],
    }


#: At most this many failures are told in the verdict, a sentence each; the table has them all.
TOLD = 20


def _cell(value, css: str = "") -> str:
    return f'<td class="{css}">{html.escape(str(value))}</td>' if css else f"<td>{html.escape(str(value))}</td>"


def _verdict_class(verdict: str) -> str:
    return "v-" + verdict.replace(" ", "-")


def _link(**query: str) -> str:
    """A fragment that filters the table of every result (see report_assets.SCRIPT)."""
    return "#" + urlencode({k: v for k, v in query.items() if v})


def sentence(o) -> str:
    """What a failing or explained row says, in one sentence: the check, the engine, the worst
    error against its tolerance, where, and the judge's note."""
    if not (np.isfinite(o.worst) or np.isinf(o.worst)):
        figure = "nothing computed"
    else:
        over = "over" if o.worst > o.check.tolerance else "within"
        figure = f"worst error {_figure(o.worst)} {over} the tolerance of {o.check.tolerance:g} {o.check.metric}"
    where = f" at input {o.worst_input}" if o.worst_input else ""
    note = f"; {o.note}" if o.note else ""
    return f"{o.check.kind} {o.check.title} on {o.engine}: {figure}{where}{note}."


def headline(verification: Verification) -> tuple[str, str]:
    """The verdict ("passed" or "FAILED") and one sentence of counts and reasons."""
    total, failing = len(verification.outcomes), len(verification.failures)
    approx = sum(o.verdict == APPROX for o in verification.outcomes)
    ran = sum(not e.skipped for e in verification.engines)
    parts = [f"{failing} of {total} results failing" if failing else f"{total} results, none failing"]
    parts.append(f"{ran} of {len(verification.engines)} engines ran")
    if not verification.compared:
        parts.append("nothing compared (no engine ran a check)")
    if verification.missing:
        parts.append(f"{_not_run(verification)}: {', '.join(verification.missing)}")
    if approx:
        parts.append(f"{approx} explained by OCIO's default flags")
    return ("passed" if verification.passed else "FAILED"), "; ".join(parts) + "."


def _engine_table(verification: Verification) -> str:
    """Counts by verdict per engine, with its version or why it did not run."""
    counts: dict[str, dict[str, int]] = {}
    for o in verification.outcomes:
        counts.setdefault(o.engine, dict.fromkeys(VERDICTS, 0))[o.verdict] += 1
    runs = {e.name: e for e in verification.engines}
    body = ""
    for name in dict.fromkeys([*runs, *counts]):
        run, found = runs.get(name), counts.get(name, dict.fromkeys(VERDICTS, 0))
        about = (f"not run: {run.skipped}" if run.skipped else run.version) if run else ""
        cells = "".join(
            f'<td class="n{" " + _verdict_class(v) if found[v] and v != PASS else ""}">{found[v]}</td>'
            for v in VERDICTS
        )
        body += f'<tr><td><a href="{_link(engine=name)}">{html.escape(name)}</a></td>{cells}{_cell(about)}</tr>'
    head = "".join(f"<th>{html.escape(h)}</th>" for h in ("engine", *VERDICTS, "version"))
    return f'<table id="engines"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>'


def _told(outcomes, limit: int | None) -> str:
    """A list of sentences, each a link to its rows; past ``limit``, how many more."""
    shown = outcomes if limit is None else outcomes[:limit]
    items = "".join(
        "<li>"
        + html.escape(sentence(o)).replace(
            html.escape(o.check.title),
            f'<a href="{_link(engine=o.engine, item=o.check.title, verdict=o.verdict)}">'
            f"{html.escape(o.check.title)}</a>",
            1,
        )
        + "</li>"
        for o in shown
    )
    more = len(outcomes) - len(shown)
    rest = f'<p><a href="{_link(verdict=FAIL)}">{more} more in the table below.</a></p>' if more else ""
    return f"<ul>{items}</ul>{rest}"


def _verdict_section(verification: Verification) -> str:
    """The page's first block: the verdict, counts per engine, each failure and explained row."""
    verdict, why = headline(verification)
    failing = verification.failures
    explained = [o for o in verification.outcomes if o.verdict == APPROX]
    out = (
        f'<section id="verdict" class="{"passed" if verification.passed else "failed"}">'
        f"<h1>verify {verdict}: {html.escape(verification.spec.name)}</h1><p>{html.escape(why)}</p>"
        f"<p>{html.escape(str(verification.config))}, OCIO "
        f"{'.'.join(map(str, verification.spec.ocio_version))} config</p>{_engine_table(verification)}"
    )
    if failing:
        out += f"<h2>What failed</h2>{_told(failing, TOLD)}"
    if explained:
        out += (
            f"<details><summary>{len(explained)} departures explained by OCIO's default flags "
            f"(approx)</summary>{_told(explained, None)}</details>"
        )
    return out + "</section>"


def _results_section(verification: Verification) -> str:
    """Every result, with the filters the inline script drives (hidden without it)."""
    engines = list(dict.fromkeys(o.engine for o in verification.outcomes))
    families = [f for f in dict.fromkeys(e.split(" ")[0] for e in engines) if f not in engines]
    families = [f for f in families if sum(e.startswith(f + " ") for e in engines) > 1]
    options = [("", "every engine")] + [(f, f"{f} (every {f} engine)") for f in families] + [(e, e) for e in engines]
    verdicts = [("", "every verdict")] + [
        (v, v) for v in VERDICTS if any(o.verdict == v for o in verification.outcomes)
    ]

    def select(name, choices):
        items = "".join(f'<option value="{html.escape(v)}">{html.escape(t)}</option>' for v, t in choices)
        return f'<label>{name} <select id="f-{name}">{items}</select></label>'

    controls = (
        f'<div id="filters" hidden>{select("engine", options)}'
        '<label>item <input id="f-item" type="search" placeholder="part of a check\'s text"></label>'
        f'{select("verdict", verdicts)}<span id="f-count"></span></div>'
    )
    head = "".join(f"<th>{h}</th>" for h in (*COLUMNS, "note"))
    body = "".join(
        f'<tr data-engine="{html.escape(o.engine)}" data-verdict="{html.escape(o.verdict)}" '
        f'data-item="{html.escape(f"{o.check.kind} {o.check.title}")}">'
        + "".join(_cell(v, "n" if 3 <= i <= 4 else "") for i, v in enumerate(r[:-1]))
        + _cell(o.verdict, _verdict_class(o.verdict))
        + _cell("; ".join(p for p in (f"worst input {o.worst_input}" if o.worst_input else "", o.note) if p))
        + "</tr>"
        for o, r in zip(verification.outcomes, rows(verification))
    )
    return (
        f'<h2 id="every-result">Every result</h2>{controls}'
        f'<table id="results"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>'
    )


def html_page(verification: Verification, figures: dict[str, bytes]) -> str:
    """The report: the verdict first (counts per engine, a sentence per failure), then the
    figures (inline PNG), every result in a table to filter, and the text summary folded."""
    images = "".join(
        f'<figure><figcaption>{html.escape(title)}</figcaption><img alt="{html.escape(title)}" '
        f'src="data:image/png;base64,{base64.b64encode(png).decode()}"></figure>'
        for title, png in figures.items()
    )
    return (
        '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>ocioforge verify {headline(verification)[0]}: {html.escape(verification.spec.name)}</title>"
        f"<style>{STYLE}</style></head><body>{_verdict_section(verification)}"
        f'<h2 id="figures">Figures</h2>{images}{_results_section(verification)}'
        "<details><summary>The summary as the terminal prints it</summary>"
        f"<pre>{html.escape(summary(verification))}</pre></details>"
        f"<script>{SCRIPT}</script></body></html>\n"
    )


#: The files a report folder holds.
REPORT_FILES = ("summary.json", "report.html")


def report_paths(folder: str | Path) -> list[Path]:
    """The paths of a report's files in ``folder``."""
    return [Path(folder) / name for name in REPORT_FILES]


def write_report(
    verification: Verification, folder: str | Path, figures: dict[str, bytes], force: bool = False
) -> list[Path]:
    """Write summary.json and report.html into ``folder``, both or neither (existing ones only
    with ``force``); returns their paths."""
    data = ((json.dumps(to_json(verification), indent=1) + "\n").encode(), html_page(verification, figures).encode())
    files = dict(zip(report_paths(folder), data))
    write_files(files, force)
    return list(files)
