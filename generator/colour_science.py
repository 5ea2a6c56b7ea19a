"""Importing colour-science without its plotting package, unless a command plots.

colour-science imports ``colour.plotting`` (and so matplotlib) unconditionally,
which is most of its second of import time. Commands that never plot install a
placeholder for that one module before colour-science is first imported;
:func:`plotting` swaps the real package in when a figure is drawn.
"""

from __future__ import annotations

import importlib
import sys
import types

_PLACEHOLDER = types.ModuleType(
    "colour.plotting", "Placeholder: ocioforge imports colour-science's plotting on demand."
)


def skip_plotting() -> None:
    """Make a later ``import colour`` skip ``colour.plotting`` (no effect once colour is imported)."""
    if "colour" not in sys.modules:
        sys.modules.setdefault("colour.plotting", _PLACEHOLDER)


def plotting():
    """colour-science's real plotting package, imported now if the placeholder stood in."""
    if sys.modules.get("colour.plotting") is _PLACEHOLDER:
        del sys.modules["colour.plotting"]
        colour = importlib.import_module("colour")
        colour.__dict__.pop("plotting", None)
    module = importlib.import_module("colour.plotting")
    sys.modules["colour"].plotting = module
    return module
