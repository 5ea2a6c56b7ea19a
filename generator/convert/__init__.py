"""Batch image conversion through a config (``ocioforge convert``): frames, formats, one frame's
conversion, its verification against the spec's reference, and runs here, in a process pool or on
a Dask cluster."""
