"""The LUT format writers, a lattice to bytes (generator/luts/formats.py), read back by OCIO and
colour-science."""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio
import pytest

from generator.colorimetry import transfer
from generator.luts import bake, formats, lattice, numbers
from generator.ocio.curves import decode_transforms

RNG_SEED = 7


def _request(spec, fmt, method="clip", size=17, source="ACEScct", display="sRGB - Display", shaper="auto"):
    return bake.request(spec, source, display, method, fmt, size, shaper)


def _lattice(size=5, domain=(0.0, 1.0), shaper=None, decimals=lattice.CUBE_DECIMALS) -> lattice.Lattice:
    """A lattice of random node values, rounded as written: no two nodes alike, so an order
    mixed up shows."""
    cube = numbers.rounded(np.random.default_rng(RNG_SEED).uniform(-0.5, 2.0, (size, size, size, 3)), decimals)
    return lattice.Lattice(None, None, "clip", None, None, None, domain, shaper, cube, decimals=decimals)


def _read(path, values, interpolation=ocio.INTERP_TETRAHEDRAL) -> np.ndarray:
    pixels = np.ascontiguousarray(values, dtype=np.float32).reshape(-1, 3)
    transform = ocio.FileTransform(str(path), interpolation=interpolation)
    processor = ocio.Config.CreateRaw().getProcessor(transform)
    processor.getOptimizedCPUProcessor(ocio.OPTIMIZATION_LOSSLESS).applyRGB(pixels)
    return pixels.astype(np.float64)


def _written(folder, name: str, data: bytes):
    (folder / name).write_bytes(data)
    return folder / name


def _nodes(size: int, lo: float = 0.0, hi: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Every node's index (n³, 3) and its input value, ``[r, g, b]``."""
    index = np.indices((size, size, size)).reshape(3, -1).T
    return index, lo + (hi - lo) * index / (size - 1)


def test_writers_refuse_what_a_format_cannot_hold(default_spec):
    lat = bake.build_lattice(_request(default_spec, "resolve_cube"))
    with pytest.raises(ValueError):
        formats.iridas_cube(lat, "t")


@pytest.mark.parametrize(
    "curve",
    [
        transfer.Power(2.4),
        transfer.PiecewisePower(2.4, 0.055),
        transfer.PiecewisePower(2.4, 0.055, mirror=True),
        transfer.LogCamera(
            base=2.0,
            log_side_slope=1 / 17.52,
            log_side_offset=9.72 / 17.52,
            lin_side_slope=1.0,
            lin_side_offset=0.0,
            lin_side_break=0.0078125,
        ),
    ],
    ids=repr,
)
def test_a_clf_decodes_a_curve_with_the_configs_transforms(curve):
    """One translation: a CLF's decoding of an analytic curve is the config's, parameter for parameter
    (a mirrored sRGB-like curve was monCurveFwd in a CLF, mirrored in the config)."""
    config = decode_transforms("x", curve, (2, 1), {})
    written = formats.decode_steps("x", curve)
    assert [str(t) for t in written] == [str(t) for t in config]


def test_a_resolve_cube_is_red_fastest_and_holds_its_shaper(tmp_path):
    """colour-science and OCIO read the shaper, its range and every node where they were."""
    import colour

    shaper = numbers.rounded(np.sort(np.random.default_rng(1).random(64)), lattice.SHAPER_DECIMALS)
    shaper[0], shaper[-1] = 0.0, 1.0
    lat = _lattice(shaper=shaper, domain=(-0.0078125, 3.5))
    data = formats.resolve_cube(lat, "a title", ["a note"])
    assert data.startswith(b"# a title\n# a note\nLUT_1D_SIZE 64\nLUT_1D_INPUT_RANGE -0.0078125 3.5\n")
    rows = data.decode("ascii").splitlines()[-(lat.size**3) :]
    assert [float(v) for v in rows[1].split()] == list(lat.cube[1, 0, 0])
    path = _written(tmp_path, "t.cube", data)
    lut = colour.read_LUT(str(path))
    np.testing.assert_array_equal(lut[0].table[:, 0], shaper)
    np.testing.assert_array_equal(lut[0].domain[:, 0], lat.domain)
    np.testing.assert_array_equal(lut[1].table, lat.cube)
    index, _ = _nodes(lat.size)
    code = lattice.preimages(lat.size, shaper, lat.domain)[index]
    np.testing.assert_allclose(_read(path, code), lat.cube[tuple(index.T)], rtol=0, atol=2e-6)


def test_an_iridas_cube_holds_its_domain_and_nodes(tmp_path):
    import colour

    lat = _lattice(domain=(-0.25, 4.0))
    path = _written(tmp_path, "t.cube", formats.iridas_cube(lat, 'a "quoted" title', ["a note"]))
    assert path.read_text().startswith("TITLE \"a 'quoted' title\"\n# a note\nLUT_3D_SIZE 5\n")
    lut = colour.read_LUT(str(path))
    np.testing.assert_array_equal(lut.domain, [[-0.25] * 3, [4.0] * 3])
    np.testing.assert_array_equal(lut.table, lat.cube)
    index, code = _nodes(lat.size, *lat.domain)
    np.testing.assert_allclose(_read(path, code), lat.cube[tuple(index.T)], rtol=0, atol=2e-6)


def test_an_spi3d_names_each_node_and_is_blue_fastest(tmp_path):
    import colour

    lat = _lattice(decimals=lattice.LOG_DECIMALS)
    data = formats.spi3d(lat, ["a note"])
    lines = data.decode("ascii").splitlines()
    assert lines[:4] == ["SPILUT 1.0", "3 3", "5 5 5", "# a note"]
    for line in lines[4:]:
        i, j, k, *values = line.split()
        assert [float(v) for v in values] == list(lat.cube[int(i), int(j), int(k)])
    assert [line.split()[:3] for line in lines[4:6]] == [["0", "0", "0"], ["0", "0", "1"]]
    path = _written(tmp_path, "t.spi3d", data)
    np.testing.assert_array_equal(colour.read_LUT(str(path)).table, lat.cube)
    index, code = _nodes(lat.size)
    np.testing.assert_allclose(_read(path, code), lat.cube[tuple(index.T)], rtol=0, atol=2e-6)


def test_an_spi3d_over_another_domain_has_a_straight_shaper_beside_it(tmp_path):
    """Without a table, the .spi1d takes the domain's ends to 0 and 1, linearly."""
    lat = _lattice(domain=(-1.0, 3.0))
    assert formats.needs_spi1d(lat) and not formats.needs_spi1d(_lattice())
    path = _written(tmp_path, "t.spi1d", formats.spi1d_shaper(lat, ["a note"]))
    assert path.read_text().splitlines()[:3] == ["Version 1", "# a note", "From -1 3"]
    code = np.linspace(-1.0, 3.0, 41)
    np.testing.assert_allclose(_read(path, np.repeat(code[:, None], 3, axis=1))[:, 0], (code + 1.0) / 4.0, atol=1e-7)


def test_a_source_layout_clf_is_range_shaper_and_lattice(tmp_path):
    shaper = np.linspace(0.0, 1.0, 32) ** 0.5
    lat = _lattice(shaper=shaper, domain=(-0.5, 2.0))
    path = _written(tmp_path, "t.clf", formats.clf(lat, "ocioforge:t", "a test"))
    config = ocio.Config.CreateRaw()
    ops = config.getProcessor(ocio.FileTransform(str(path))).createGroupTransform()
    assert [type(op).__name__ for op in ops] == ["RangeTransform", "Lut1DTransform", "Lut3DTransform"]
    assert (ops[0].getMinInValue(), ops[0].getMaxInValue()) == lat.domain
