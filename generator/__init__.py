"""ocioforge: OpenColorIO configs and LUTs from a declarative spec, checked by numbers."""

# First, before anything loads numpy: the same numbers on every machine.
from generator import backends  # noqa: F401

__version__ = "0.1.0"
