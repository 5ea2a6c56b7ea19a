"""The script report.html carries inline: the page's fragment filters its table by engine (its
name or its family's), check text and verdict, in Chromium."""

from __future__ import annotations

import pytest

from tests.verify.conftest import chromium, parsed


@pytest.mark.parametrize(
    "fragment, wanted",
    [
        ("engine=ocio+lossless&verdict=FAIL", lambda o: o.engine == "ocio lossless" and o.verdict == "FAIL"),
        ("engine=ocio&item=scale", lambda o: "scale" in f"{o.check.kind} {o.check.title}".lower()),
        ("verdict=pass&item=Colorimetric", lambda o: o.verdict == "pass" and "Colorimetric" in o.check.title),
        ("", lambda o: True),
    ],
)
def test_the_fragment_filters_the_table_in_chromium(failing_report, tmp_path, fragment, wanted):
    result, path = failing_report
    dom = chromium(tmp_path, "--dump-dom", f"{path.as_uri()}#{fragment}").stdout
    rows = parsed(dom).rows
    assert len(rows) == len(result.outcomes)
    shown = [(engine, verdict, item) for engine, verdict, item, hidden in rows if not hidden]
    expected = [(o.engine, o.verdict, f"{o.check.kind} {o.check.title}") for o in result.outcomes if wanted(o)]
    assert shown == expected and expected
    assert f">{len(expected)} of {len(rows)} results shown<" in dom
    assert '<div id="filters">' in dom  # shown by the script


def test_an_engine_matches_by_its_whole_name_or_family_not_a_prefix(failing_report, tmp_path):
    """ "oci" names no engine nor family: no row is shown (it is offered as a choice, so the page
    says what it filters by), where "ocio" shows both of its family's engines."""
    result, path = failing_report
    dom = chromium(tmp_path, "--dump-dom", f"{path.as_uri()}#engine=oci").stdout
    rows = parsed(dom).rows
    assert rows and all(hidden for *_, hidden in rows)
    assert f">0 of {len(rows)} results shown<" in dom and '<option value="oci">oci</option>' in dom
    assert {o.engine for o in result.outcomes} == {"ocio default", "ocio lossless"}
