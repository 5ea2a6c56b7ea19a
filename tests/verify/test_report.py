"""What verify prints and writes: the summary's rows agree with their FAIL counts; report.html
opens with the verdict, and Chromium draws it with every failure on the first screen."""

from __future__ import annotations

import html
import re
from pathlib import Path

import PyOpenColorIO as ocio

from generator.verify.check import ITP, Check
from generator.verify.checks import LUT, TO_REFERENCE, VIEW
from generator.verify.judge import PASS, Outcome
from generator.verify.report import groups, html_page, sentence, summary
from generator.verify.run import Verification, verify
from tests.verify.conftest import chromium, parsed


def _group_rows_failing(result) -> list[tuple]:
    return [(key, g["max"], g["tolerance"]) for key, g in groups(result).items() if g["FAIL"]]


def test_a_group_with_failures_shows_a_worst_over_its_own_tolerance(config_copy):
    """An HDR display's matrix raised by 1.4e-4: its analytic views (0.01 ΔE ITP) fail, and the
    group row had shown the largest error beside the baked views' 0.035, as though within it."""
    cfg = ocio.Config.CreateFromFile(str(config_copy))
    space = cfg.getColorSpace("Rec.2100-PQ - Display")
    group = space.getTransform(ocio.COLORSPACE_DIR_FROM_REFERENCE)
    matrix = next(t for t in group if isinstance(t, ocio.MatrixTransform))
    matrix.setMatrix([v * 1.00014 if i % 4 < 3 and i < 12 else v for i, v in enumerate(matrix.getMatrix())])
    space.setTransform(group, ocio.COLORSPACE_DIR_FROM_REFERENCE)
    cfg.addColorSpace(space)
    config_copy.write_text(cfg.serialize(), encoding="utf-8")
    result = verify(config_copy, ("ocio",), density="quick", kinds=(VIEW,), only="Rec.2100-PQ")
    rows = _group_rows_failing(result)
    assert rows and all(worst > tolerance for _, worst, tolerance in rows), rows


def test_a_group_shows_the_max_p99_and_tolerance_of_one_row():
    """A group of two rows of different tolerances: the closer to its tolerance (an ACES view at
    0.01) is shown whole; the other's larger p99 (a Scale file at 0.035) had been shown beside
    the first's max, a p99 above the max."""
    view = Check(VIEW, "ACES 2.0", "ACES2065-1", metric=ITP, tolerance=0.01)
    scale = Check(VIEW, "Scale", "ACES2065-1", metric=ITP, tolerance=0.035)
    outcomes = (
        Outcome(view, "ocio default", PASS, worst=0.0011, p99=0.0004),
        Outcome(scale, "ocio default", PASS, worst=0.0022, p99=0.0014),
    )
    result = Verification(Path("config.ocio"), None, (view, scale), outcomes)
    (group,) = groups(result).values()
    assert (group["max"], group["p99"], group["tolerance"]) == (0.0011, 0.0004, 0.01)
    row = next(line for line in summary(result).splitlines() if "ocio default" in line and "view" in line)
    assert row.split()[-3:] == ["0.0011", "0.0004", "0.01"], row


def test_a_row_not_computed_says_so(config_copy):
    """A LUT file OCIO cannot read fails without a number: its line had read '- > 0.0001'."""
    lut = config_copy.parent / "luts" / "n_log_to_linear.spi1d"
    lines = lut.read_text().splitlines()
    lines[len(lines) // 2] = "not a number"
    lut.write_text("\n".join(lines) + "\n")
    result = verify(config_copy, ("ocio",), density="quick", kinds=(LUT, TO_REFERENCE), only="n_log")
    text = summary(result)
    failing = [line for line in text.splitlines() if line.startswith("FAIL:")]
    assert failing and all(": not computed" in line for line in failing), failing
    assert not any(" - > " in line for line in text.splitlines())


# The report page: the verdict first, figures, every result to filter; checked in Chromium.


def test_the_page_opens_with_the_verdict_and_a_sentence_per_failure(failing_report):
    result, path = failing_report
    page = path.read_text(encoding="utf-8")
    assert parsed(page).first == "section#verdict"
    assert page.index("verify FAILED") < page.index("data:image/png") < page.index('id="results"')
    assert "8 of 48 results failing" in page
    told = html.unescape(re.sub(r"<[^>]+>", "", page[: page.index("</section>")]))
    assert all(sentence(o) in told for o in result.failures)
    assert page.index("<details><summary>The summary") > page.index('id="results"')


def test_the_page_needs_no_network_and_is_the_same_every_time(failing_report):
    result, path = failing_report
    page = path.read_text(encoding="utf-8")
    assert "<script src" not in page and "<link" not in page and "@import" not in page and "url(" not in page
    assert not re.findall(r'(?:src|href)="(?!data:|#)', page)
    assert html_page(result, {}) == html_page(result, {})
    assert page == html_page(result, _figures_of(page))


def _figures_of(page: str) -> dict[str, bytes]:
    import base64

    found = re.findall(r'<figcaption>([^<]*)</figcaption><img alt="[^"]*" src="data:image/png;base64,([^"]*)"', page)
    return {html.unescape(title): base64.b64decode(data) for title, data in found}


def test_a_passing_page_says_passed_and_lists_no_failure(config_copy):
    result = verify(config_copy, ("ocio",), density="quick", kinds=(TO_REFERENCE,), only="ACEScg")
    page = html_page(result, {})
    assert "verify passed" in page and "none failing" in page and "What failed" not in page
    assert 'class="passed"' in page


def test_chromium_draws_the_report(failing_report, tmp_path):
    _, path = failing_report
    shot = tmp_path / "report.png"
    chromium(tmp_path, f"--screenshot={shot}", path.as_uri())
    from PIL import Image

    with Image.open(shot) as image:
        assert image.size == (1280, 800)
        colours = image.convert("RGB").getcolors(maxcolors=1 << 20)
    assert colours is not None and len(colours) > 100  # text, the verdict's band, a figure: not blank
    red = sum(n for n, (r, g, b) in colours if r > 180 and g < 80 and b < 80)
    assert red > 1000  # the failed verdict's red band


PROBE = """<script>
var v = document.getElementById("verdict"), h = v.querySelector("h1").getBoundingClientRect();
var last = v.querySelector("li:last-of-type").getBoundingClientRect();
document.body.setAttribute("data-probe", [h.top, h.bottom, last.bottom, innerWidth, innerHeight,
  document.documentElement.scrollWidth].join(" "));
</script></body>"""


def test_the_verdict_and_every_failure_are_on_the_first_screen(failing_report, tmp_path):
    """Measured by a script added to a copy of the page: the verdict's heading and the last
    failure's sentence lie within 800 pixels, and nothing is wider than the window."""
    _, path = failing_report
    probe = tmp_path / "probe.html"
    probe.write_text(path.read_text(encoding="utf-8").replace("</body>", PROBE), encoding="utf-8")
    dom = chromium(tmp_path, "--dump-dom", probe.as_uri()).stdout
    assert parsed(dom).first == "section#verdict"
    top, bottom, last, width, height, scroll = map(float, re.search(r'data-probe="([^"]*)"', dom).group(1).split())
    # --dump-dom's window keeps some of its 800 pixels for itself (657 measured); the screenshot has them all
    assert 600 <= height <= 800 and 0 <= top < bottom < last <= height, (top, bottom, last, height)
    assert scroll <= width
