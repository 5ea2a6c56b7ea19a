"""colour-science imported without its plotting package until a figure needs it (in a fresh
interpreter, whose imports are its own), and left alone once imported."""

from __future__ import annotations

import json
import subprocess
import sys

from generator import colour_science

SKIPPED = """
import json, sys
from generator import colour_science
colour_science.skip_plotting()
import colour
before = {
    "matplotlib": "matplotlib" in sys.modules,
    "placeholder": sys.modules["colour.plotting"] is colour_science._PLACEHOLDER,
    "models": hasattr(colour, "RGB_to_ICtCp"),
}
plotting = colour_science.plotting()
after = {
    "matplotlib": "matplotlib" in sys.modules,
    "real": hasattr(plotting, "plot_chromaticity_diagram_CIE1931"),
    "attribute": sys.modules["colour"].plotting is plotting and colour.plotting is plotting,
    "module": sys.modules["colour.plotting"] is plotting,
    "again": colour_science.plotting() is plotting,
}
print(json.dumps([before, after]))
"""


def run(script: str):
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout.strip().splitlines()[-1])


def test_colour_imports_without_matplotlib_and_plots_on_demand():
    before, after = run(SKIPPED)
    assert before == {"matplotlib": False, "placeholder": True, "models": True}
    assert after == {"matplotlib": True, "real": True, "attribute": True, "module": True, "again": True}


def test_skipping_after_colour_is_imported_changes_nothing():
    """Here colour is imported whole (as any import without the placeholder does)."""
    import colour

    real = sys.modules["colour.plotting"]
    assert real is not colour_science._PLACEHOLDER and hasattr(real, "plot_chromaticity_diagram_CIE1931")
    colour_science.skip_plotting()
    assert sys.modules["colour.plotting"] is real
    assert colour_science.plotting() is real and colour.plotting is real
