"""ocioforge: OpenColorIO configs and LUTs from a declarative spec, checked by numbers."""

__version__ = "0.1.0"
