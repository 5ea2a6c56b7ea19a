"""The baked ACES 2.0 view: OCIO runs the file as its float64 evaluation says."""

import tempfile
from pathlib import Path

import numpy as np
import PyOpenColorIO as ocio

from generator.luts import aces_lattice
from generator.ocio.emit import matrix_transform
from generator.rendering import views

#: OCIO's float32 run of the file against its float64 evaluation, display light relative
#: to the peak (the table's values are written as float32).
FILE_RELATIVE = 1e-4


def test_ocio_runs_the_file_as_its_float64_evaluation():
    view = views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"]
    lat = aces_lattice.bake(view, 17)
    steps = [matrix_transform(views.tables(view).ap0_to_ap1),
             ocio.RangeTransform(minInValue=0.0, maxInValue=lat.upper, minOutValue=0.0, maxOutValue=lat.upper)]
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / "v.clf").write_bytes(aces_lattice.ocio_file(lat))
        cfg = ocio.Config.CreateRaw()
        cfg.setSearchPath(folder)
        group = ocio.GroupTransform([*steps, ocio.FileTransform("v.clf", interpolation=ocio.INTERP_TETRAHEDRAL),
                                     ocio.RangeTransform(minInValue=0.0, maxInValue=1.0, minOutValue=0.0, maxOutValue=1.0),
                                     matrix_transform(aces_lattice.to_xyz(view))])
        rgb = np.random.default_rng(3).random((4000, 3)) * np.array([[1.0], [8.0]]).repeat(2000, 0)
        out = rgb.astype(np.float32)
        cfg.getProcessor(group).getDefaultCPUProcessor().applyRGB(out)
    expected = aces_lattice.evaluate(lat, rgb)
    assert np.max(np.abs(out - expected)) < FILE_RELATIVE


def test_the_lattice_holds_the_reference_at_its_nodes():
    """On a node the table is the reference: a grey on the axis's nodes comes out as the view's."""
    view = views.catalogue()["ACES 2.0 - HDR 1000 nits (P3 D65)"]
    lat = aces_lattice.bake(view, 17)
    ap1 = aces_lattice.axis_value(np.linspace(0.0, 1.0, 17), lat.upper, lat.toe)[:, None].repeat(3, 1)
    aces = ap1 @ views.tables(view).ap1_to_ap0.T
    assert np.allclose(aces_lattice.evaluate(lat, aces), views.evaluate(view, aces), rtol=1e-9, atol=1e-9)
