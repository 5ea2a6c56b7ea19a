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

import numpy as np

from generator.files import write_files
from generator.verify.judge import APPROX, FAIL, NOT_RUN, PASS
from generator.verify.run import Verification

COLUMNS = ("check", "item", "engine", "max", "p99", "tolerance", "verdict")


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
    """(engine, kind, metric) -> counts by verdict, the largest p99, and the worst error with its
    own tolerance: those of the row whose error is the largest part of its tolerance (a group
    mixes tolerances, so the largest error beside the largest tolerance could read as within it
    while rows failed). A row run but not computed (a file OCIO could not load) makes the worst
    NaN: "-", not a number."""
    out = defaultdict(
        lambda: {"checks": 0, PASS: 0, FAIL: 0, APPROX: 0, NOT_RUN: 0, "max": 0.0, "p99": 0.0, "tolerance": 0.0}
    )
    share = {}
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
            entry["max"], entry["tolerance"] = (float(o.worst) if computed else float("nan")), o.check.tolerance
        if computed:
            entry["p99"] = max(entry["p99"], float(o.p99) if np.isfinite(o.p99) else 0.0)
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
            f"{g[FAIL]:>5} {_figure(g['max']):>9} {g['p99']:>9.3g} {g['tolerance']:>9.3g}"
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


def _html_table(header, body) -> str:
    head = "".join(f"<th>{html.escape(h)}</th>" for h in header)
    cells = "".join(
        "<tr>" + "".join(f'<td class="{html.escape(str(c))}">{html.escape(str(c))}</td>' for c in r) + "</tr>"
        for r in body
    )
    return f"<table><tr>{head}</tr>{cells}</table>"


STYLE = (
    "body{font-family:sans-serif;margin:2em;max-width:80em}table{border-collapse:collapse;font-size:90%}"
    "td,th{border:1px solid #ccc;padding:2px 6px;text-align:left}.FAIL{background:#f6c0c0}"
    ".approx{background:#f6e6b0}.pass{background:#d8f0d8}img{max-width:100%}"
)


def html_page(verification: Verification, figures: dict[str, bytes]) -> str:
    """The report: summary, engines, explanations, figures (inline PNG) and every result."""
    images = "".join(
        f'<h2>{html.escape(title)}</h2><img alt="{html.escape(title)}" '
        f'src="data:image/png;base64,{base64.b64encode(png).decode()}">'
        for title, png in figures.items()
    )
    notes = [
        (o.verdict, o.check.title, o.engine, o.worst_input, o.note)
        for o in verification.outcomes
        if o.verdict in (FAIL, APPROX)
    ]
    return (
        f'<!DOCTYPE html><html><head><meta charset="utf-8"><title>ocioforge verify: '
        f"{html.escape(verification.spec.name)}</title><style>{STYLE}</style></head><body>"
        f"<h1>ocioforge verify: {html.escape(str(verification.config))}</h1>"
        f"<pre>{html.escape(summary(verification))}</pre>"
        f"<h2>Failures and explained departures</h2>"
        f"{_html_table(('verdict', 'check', 'engine', 'worst input', 'note'), notes)}{images}"
        f"<h2>Every result</h2>{_html_table(COLUMNS, rows(verification))}</body></html>"
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
