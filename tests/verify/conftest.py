"""Shared by the verify tests: the default config's resolved spec, a copy of its config that a
test may break and the ways to break it, a host verifying a small build, and a failing report
with the helpers that read it back."""

from __future__ import annotations

import shutil
import subprocess
from html.parser import HTMLParser

import PyOpenColorIO as ocio
import pytest

from generator.spec import resolved
from generator.verify.check import KINDS
from generator.verify.judge import FAIL
from generator.verify.report import write_report
from generator.verify.run import verify
from tests.conftest import require_program


@pytest.fixture(scope="session")
def spec(build_config):
    """The resolved spec stored beside the default config (OCIO 2.1)."""
    return resolved.read_beside(build_config((2, 1)))


@pytest.fixture
def config_copy(build_config, tmp_path):
    """A fresh copy of the default config folder (OCIO 2.1); returns its config path."""
    source = build_config((2, 1)).parent
    target = tmp_path / source.name
    shutil.copytree(source, target)
    return target / "config.ocio"


def dim_output_table(clf, factor: float) -> None:
    """Scale the output table (the first LUT1D) of the CLF at ``clf`` by ``factor``."""
    lines = clf.read_text(encoding="utf-8").splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if line.startswith("<LUT1D")) + 2
    end = next(i for i in range(start, len(lines)) if lines[i].startswith("</Array>"))
    lines[start:end] = [f"{float(line) * factor!r}\n" for line in lines[start:end]]
    clf.write_text("".join(lines), encoding="utf-8")


def failing_items(config_path, kinds) -> set[str]:
    """The items failing the PyOpenColorIO engines on quick probes, among checks of ``kinds``."""
    result = verify(config_path, ("ocio",), density="quick", kinds=kinds)
    return {o.check.item for o in result.outcomes if o.verdict == FAIL}


def rewrite(config_path, change) -> None:
    """The config at ``config_path`` loaded, ``change(cfg)`` applied and written back."""
    cfg = ocio.Config.CreateFromFile(str(config_path))
    change(cfg)
    config_path.write_text(cfg.serialize(), encoding="utf-8")


#: The items failing in the unbroken default config, by kinds (each verified once a session).
_BEFORE: dict[tuple, set[str]] = {}


def newly_failing(config_path, corrupt, kinds=KINDS) -> set[str]:
    """The items that fail once ``corrupt(config_path)`` has run, and did not before
    (the unbroken copy is verified once per set of kinds)."""
    if kinds not in _BEFORE:
        _BEFORE[kinds] = failing_items(config_path, kinds)
    corrupt(config_path)
    return failing_items(config_path, kinds) - _BEFORE[kinds]


def nudge_nodes(clf, nodes, amount: float) -> None:
    """Add ``amount`` to every value at lattice ``nodes`` ((r, g, b) indices) of a 33³ CLF."""
    lines = clf.read_text(encoding="utf-8").splitlines(keepends=True)
    start = next(i for i, line in enumerate(lines) if 'dim="33 33 33 3"' in line) + 1
    for r, g, b in nodes:
        row = start + (r * 33 + g) * 33 + b  # blue fastest
        lines[row] = " ".join(f"{float(v) + amount:.5f}" for v in lines[row].split()) + "\n"
    clf.write_text("".join(lines), encoding="utf-8")


def scale_view_matrix(name: str, direction, entry: int, factor: float):
    """A change multiplying one entry of view transform ``name``'s matrix in ``direction``."""

    def change(cfg):
        vt = cfg.getViewTransform(name)
        matrix = vt.getTransform(direction)
        values = list(matrix.getMatrix())
        values[entry] *= factor
        matrix.setMatrix(values)
        vt.setTransform(matrix, direction)
        cfg.addViewTransform(vt)

    return change


def verified_on(tmp_path, program: str, text: str, **options):
    """Build the spec ``text`` (beside files already in ``tmp_path``) for OCIO 2.1 and verify it
    with ``program`` alone, which must have run."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load

    require_program(program)
    (tmp_path / "show.toml").write_text(text)
    folder = tmp_path / "show"
    build(for_folder(load.load(tmp_path / "show.toml"), folder, (2, 1)), folder)
    result = verify(folder / "config.ocio", (program,), **options)
    assert result.outcomes and not [e for e in result.engines if e.skipped]
    return result


TINY = """
colour_spaces = ["ACES2065-1", "ACEScg", "ACEScct", "sRGB Encoded Rec.709 (sRGB)", "Raw"]
display_view_spaces = false

[[display]]
name = "sRGB - Display"
views = ["Colorimetric", "Scale", "Raw"]

[roles]
scene_linear = "ACEScg"
"""


@pytest.fixture(scope="session")
def failing_report(tmp_path_factory):
    """A small config built in tmp, its Scale view's LUT dimmed by a tenth (8 rows fail on the
    two ocio engines), verified with figures: the verification and its report.html."""
    from generator.ocio.write import build, for_folder
    from generator.spec import load
    from generator.verify.figures import report_figures

    folder = tmp_path_factory.mktemp("report")
    (folder / "spec.toml").write_text(TINY, encoding="utf-8")
    config = folder / "tiny"
    build(for_folder(load.load(folder / "spec.toml"), config, (2, 1)), config)
    dim_output_table(config / "luts" / "view_srgb_display_scale_17.clf", 0.9)
    result = verify(config / "config.ocio", ("ocio",), density="quick")
    write_report(result, folder / "report", report_figures(result))
    return result, folder / "report" / "report.html"


class Rows(HTMLParser):
    """The result rows of a page: (engine, verdict, item, hidden)."""

    def __init__(self):
        super().__init__()
        self.rows: list[tuple[str, str, str, bool]] = []
        self.first: str | None = None
        self._in_body = False

    def handle_starttag(self, tag, attrs):
        found = dict(attrs)
        if tag == "body":
            self._in_body = True
        elif self._in_body and self.first is None:
            self.first = f"{tag}#{found.get('id', '')}"
        if tag == "tr" and "data-engine" in found:
            self.rows.append((found["data-engine"], found["data-verdict"], found["data-item"], "hidden" in found))


def parsed(page: str) -> Rows:
    """The rows and first element of ``page``."""
    parser = Rows()
    parser.feed(page)
    return parser


def chromium(tmp_path, *args: str) -> subprocess.CompletedProcess:
    """Debian's Chromium, headless, in a window of 1280 x 800 (CI installs it: see .ci/run)."""
    program = require_program("chromium")
    profile = tmp_path / "chromium-profile"
    command = [program, "--headless", "--disable-gpu", "--no-sandbox", f"--user-data-dir={profile}"]
    command += ["--no-first-run", "--window-size=1280,800", *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=180, check=True)


#: The view checks :func:`blender_run` asks Blender for: (source space, display, view).
BLENDER_ASKED = (
    ("ACEScg", "sRGB - Display", "Colorimetric"),
    ("ACEScg", "sRGB - Display", "Raw"),
    ("ACEScct", "sRGB - Display", "Raw"),
    ("ACEScg", "sRGB - Display", "No Such View"),
    ("ACEScct", "Rec.1886 Rec.709 - Display", "Colorimetric"),
)


@pytest.fixture(scope="session")
def blender_run(build_config, spec, tmp_path_factory):
    """Debian's Blender run once, as verify runs it, on the default config's checks of
    :data:`BLENDER_ASKED` (quick code probes and the non-finite ones): the checks, Blender's
    outputs and the working folder holding its request, status and renders."""
    from generator.verify import checks, paths, probes
    from generator.verify.blender import BlenderEngine

    require_program("blender")
    ends = paths.LazyEndpoints(spec)
    inputs = probes.Probes((*probes.code_families(0.0, 1.0, probes.SIZES["quick"]), probes.non_finite()))
    asked = [checks.conversion_check(spec, ends, inputs, src, display=d, view=v) for src, d, v in BLENDER_ASKED]
    workdir = tmp_path_factory.mktemp("blender")
    return asked, BlenderEngine().run(build_config((2, 1)), asked, workdir), workdir
