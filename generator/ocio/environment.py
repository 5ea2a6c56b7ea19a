"""OpenColorIO's environment variables that change what a config shows or how it evaluates.

A pipeline TD's shell often holds a show's OCIO_ACTIVE_DISPLAYS, OCIO_ACTIVE_VIEWS or
OCIO_INACTIVE_COLORSPACES, or OCIO_OPTIMIZATION_FLAGS. OpenColorIO applies them to every
config it loads: validating a build against a display it does not define failed with a
traceback, hosts that verify ran lost the displays and spaces it checks (120 to 136 checks
failed on a good config), and the optimisation flags replaced the ones verify names in its
report. ocioforge writes and checks a config as written, so its commands, and the hosts
verify runs (inside :func:`~generator.verify.run.verify`), see none of them.
"""

from __future__ import annotations

import os
from contextlib import contextmanager

#: The variables set aside (OCIO itself, the config's path, is set where a host needs it).
OVERRIDES = (
    "OCIO_ACTIVE_DISPLAYS",
    "OCIO_ACTIVE_VIEWS",
    "OCIO_INACTIVE_COLORSPACES",
    "OCIO_OPTIMIZATION_FLAGS",
    "OCIO_USER_CATEGORIES",
)


@contextmanager
def set_aside(environ=os.environ):
    """:data:`OVERRIDES` removed from ``environ`` (the process's own: OpenColorIO reads it as it
    goes) while the block runs, put back after."""
    kept = {key: environ.pop(key) for key in OVERRIDES if key in environ}
    try:
        yield
    finally:
        environ.update(kept)
