"""ocioforge: OpenColorIO configs and LUTs from a declarative spec, checked by numbers.

Layers, from the bottom; a module imports from its own layer and those below, never above,
and no two modules import each other (tests/test_layers.py holds the package to this):

1. tolerances, files (leftovers: what a killed build left), backends, colour_science, heap,
   avx_state: small modules every layer may use;
2. colorimetry: the colour-space library, matrices, CATs, transfer functions, spectra;
3. gamut, rendering: gamut mapping; the ACES output transforms in float64;
4. spec: the frozen description, checked against the library (spec.allowed: what it may ask for);
5. reference, metrics: the one float64 evaluation of a spec's paths, and errors against it;
6. luts: lattices, fits and LUT files sampled from the reference;
7. ocio: PyOpenColorIO objects: the config, and view LUTs as it runs them (ocio.view_luts);
8. verify: probes, engines, checks and report against the reference;
9. convert: image conversion through a config, verified;
10. cli: one module per command.

An import inside a function is for start-up time only, with a comment saying so.
"""

# First, before anything loads numpy: the same numbers on every machine.
from generator import backends  # noqa: F401

__version__ = "0.1.0"
