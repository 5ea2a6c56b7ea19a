"""Every numerical tolerance of the project, named once.

Relative errors are ``|a - b| / max(|b|, RELATIVE_FLOOR)``.
"""

#: Floor of the denominator of relative errors, so values near zero are compared absolutely.
RELATIVE_FLOOR = 0.1

#: An analytic OCIO path against the float64 reference evaluation.
ANALYTIC_RELATIVE = 1e-4

#: A colour space to the reference and back through OCIO.
ROUND_TRIP_RELATIVE = 1e-5

#: A baked 1D LUT standing in for a curve OCIO cannot express for the target version.
BAKED_CURVE_RELATIVE = 1e-4

#: A derived matrix against the 4-to-10-decimal matrix its standard publishes.
PUBLISHED_MATRIX_ABSOLUTE = 1e-4

#: Chromaticity derived from spectra against tabulated xy.
SPECTRAL_XY_ABSOLUTE = 1e-4

#: A transfer function against values printed in the vendor's paper.
PUBLISHED_CURVE_ABSOLUTE = 1e-4
