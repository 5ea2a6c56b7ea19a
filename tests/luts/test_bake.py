"""Baked LUT files: they read back in OCIO (and colour-science where it has a reader)
to the stored node values, meet the measured accuracy bounds, and are reproducible."""

from __future__ import annotations

import numpy as np
import pytest

from generator import reference, tolerances
from generator.luts import bake, lattice, probes
from generator.luts.axes import LogAxis


def _request(spec, fmt, method="clip", size=17, source="ACEScct", display="sRGB - Display", shaper="auto"):
    return bake.request(spec, source, display, method, fmt, size, shaper)


def _write(tmp_path, req, name="lut"):
    files = bake.paths(bake.bake(req), tmp_path / f"{name}{bake.FORMATS[req.fmt].suffix}")
    bake.write(files)
    return list(files)


def _transform(paths):
    import PyOpenColorIO as ocio

    steps = [ocio.FileTransform(str(p), interpolation=ocio.INTERP_TETRAHEDRAL) for p in reversed(paths)]
    return steps[0] if len(steps) == 1 else ocio.GroupTransform(steps)


def _node_inputs(req, lat, picks=(0, 3, 9, 16)):
    """Input values landing on lattice nodes, and the outputs there."""
    coordinates = lattice.preimages(lat.size, lat.shaper, lat.domain)
    index = np.array([(i, j, k) for i in picks for j in picks for k in picks])
    values = coordinates[index]
    if lat.pre is not None:  # display layout: input is source code; invert pre-shaper and matrix
        linear = lat.pre.position(values) if isinstance(lat.pre, LogAxis) else lat.pre.inverse(values)
        values = req.source.curve.encode(reference.apply_matrix(np.linalg.inv(lat.matrix), linear))
    outputs = lat.cube[index[:, 0], index[:, 1], index[:, 2]]
    if lat.post is not None:
        outputs = np.interp(outputs, np.linspace(0.0, 1.0, lat.post.size), lat.post)
    return values, outputs


@pytest.mark.parametrize("fmt", ("resolve_cube", "iridas_cube", "spi3d", "clf"))
def test_files_read_back_in_ocio_at_the_nodes(default_spec, tmp_path, fmt):
    req = _request(default_spec, fmt, method="desaturate")
    lat = bake.build_lattice(req)
    paths = _write(tmp_path, req)
    inputs, expected = _node_inputs(req, lat)
    actual = probes.ocio_apply(_transform(paths))(inputs)
    bound = tolerances.LUT_CLF_NODE_ABSOLUTE if fmt == "clf" else tolerances.LUT_NODE_ABSOLUTE
    np.testing.assert_allclose(actual, expected, rtol=0, atol=bound)


@pytest.mark.parametrize("fmt", ("resolve_cube", "iridas_cube", "spi3d"))
def test_colour_science_reads_the_same_table(default_spec, tmp_path, fmt):
    import colour

    req = _request(default_spec, fmt, source="ACEScg" if fmt != "iridas_cube" else "ACEScct")
    lat = bake.build_lattice(req)
    paths = _write(tmp_path, req)
    lut = colour.read_LUT(str(paths[0]))
    table = lut[-1].table if isinstance(lut, colour.LUTSequence) else lut.table
    np.testing.assert_allclose(table, lat.cube, rtol=0, atol=tolerances.LUT_NODE_ABSOLUTE)
    if fmt == "resolve_cube":
        np.testing.assert_allclose(lut[0].table[:, 0], lat.shaper, atol=tolerances.LUT_NODE_ABSOLUTE)
        np.testing.assert_allclose(lut[0].domain[:, 0], lat.domain)
    if fmt == "spi3d":
        shaper = colour.read_LUT(str(paths[1]))
        np.testing.assert_allclose(shaper.table, lat.shaper, atol=tolerances.LUT_NODE_ABSOLUTE)


@pytest.mark.parametrize("method", ("clip", "scale"))
@pytest.mark.parametrize("source", ("ACEScg", "ACEScct"))
def test_clf_clip_and_scale_meet_the_targets_on_every_probe_set(default_spec, tmp_path, method, source):
    """Exact but for float32 from linear input; within a code when OCIO's Log op decodes."""
    req = _request(default_spec, "clf", method=method, size=33, source=source)
    figures = probes.measure(
        default_spec, req.source, req.display, method, probes.ocio_apply(_transform(_write(tmp_path, req))), count=1024
    )
    assert figures["in_gamut"].maximum <= tolerances.LUT_CLF_IN_GAMUT_CODES
    bound = tolerances.LUT_CLF_EXACT_CODES if source == "ACEScg" else tolerances.LUT_CLF_EVERY_SET_CODES
    assert max(f.maximum for f in figures.values()) <= bound


@pytest.mark.parametrize("method", ("clip", "scale"))
def test_clf_into_hlg_within_its_bound(default_spec, tmp_path, method):
    req = _request(default_spec, "clf", method=method, size=33, source="ACEScg", display="Rec.2100-HLG - Display")
    figures = probes.measure(
        default_spec, req.source, req.display, method, probes.ocio_apply(_transform(_write(tmp_path, req))), count=1024
    )
    assert max(f.maximum for f in figures.values()) <= tolerances.LUT_CLF_HLG_DELTA_E_ITP


@pytest.mark.parametrize("method", ("clip", "scale"))
def test_clf_into_an_extended_range_display(default_spec, tmp_path, method):
    """Display P3 HDR: sRGB's curve extended to ten times white (code 2.6 at the peak), whose
    code values once ran past what the writer holds beyond the peak (a crash, not a bound)."""
    req = _request(default_spec, "clf", method=method, size=33, source="ACEScg", display="Display P3 HDR - Display")
    figures = probes.measure(
        default_spec, req.source, req.display, method, probes.ocio_apply(_transform(_write(tmp_path, req))), count=1024
    )
    assert max(f.maximum for f in figures.values()) <= tolerances.LUT_VIEW_HDR_SCALE_DELTA_E_ITP
    assert figures["in_gamut"].maximum <= tolerances.LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP


@pytest.mark.parametrize("pair", list(tolerances.OCIOBAKELUT_P99))
def test_resolve_cube_halves_ociobakelut_p99_on_every_set(default_spec, tmp_path, pair):
    """Clip at 33³, against ociobakelut's best bake (bench/lut_accuracy.py)."""
    req = _request(default_spec, "resolve_cube", size=33, source=pair[0], display=pair[1])
    figures = probes.measure(
        default_spec, req.source, req.display, "clip", probes.ocio_apply(_transform(_write(tmp_path, req)))
    )
    for name, theirs in tolerances.OCIOBAKELUT_P99[pair].items():
        assert figures[name].p99 * tolerances.LUT_CUBE_P99_RATIO <= theirs, name


@pytest.mark.parametrize("fmt", ("resolve_cube", "clf", "spi3d"))
def test_same_input_same_bytes(default_spec, fmt):
    req = _request(default_spec, fmt, method="scale", source="ARRI LogC4", display="Rec.2100-PQ - Display")
    assert bake.bake(req) == bake.bake(req)


def test_clf_decodes_every_curve_family(default_spec, tmp_path):
    """Analytic Log and Exponent operators, and a baked LUT1D for a function curve."""
    for name in ("S-Log3 S-Gamut3.Cine", "sRGB Encoded Rec.709 (sRGB)", "Gamma 2.2 Encoded AP1", "ACEScc"):
        req = _request(default_spec, "clf", source=name, display="Rec.1886 Rec.709 - Display")
        lat = bake.build_lattice(req)
        inputs, expected = _node_inputs(req, lat, picks=(lat.cube.shape[0] // 2,))
        paths = _write(tmp_path, req, name=name.replace(" ", "_"))
        np.testing.assert_allclose(
            probes.ocio_apply(_transform(paths))(inputs), expected, atol=tolerances.LUT_CLF_NODE_ABSOLUTE
        )


def test_clf_loads_in_ocio_2_1(default_spec, tmp_path):
    import subprocess

    from tests.conftest import require_program

    program = require_program("ociochecklut")
    req = _request(default_spec, "clf", source="ACEScct")
    path = _write(tmp_path, req)[0]
    done = subprocess.run([program, str(path), "0.4", "0.4", "0.4"], capture_output=True, text=True, check=True)
    expected = probes.ocio_apply(_transform([path]))(np.array([[0.4, 0.4, 0.4]]))[0]
    np.testing.assert_allclose([float(v) for v in done.stdout.split()[-3:]], expected, atol=1e-5)


def test_an_spi3d_and_its_shaper_say_how_they_chain_and_load_in_ocio_2_1(default_spec, tmp_path):
    """Nothing in either file had said the .spi3d alone is hundreds of codes off: each now
    says to apply the .spi1d first, in comments OCIO 2.1, 2.6 and colour-science all skip."""
    import subprocess

    import colour

    from tests.conftest import require_program

    program = require_program("ociochecklut")
    paths = _write(tmp_path, _request(default_spec, "spi3d", source="ACEScg"))
    assert [p.suffix for p in paths] == [".spi3d", ".spi1d"]
    for path in paths:
        lut = colour.read_LUT(str(path))
        assert any("Apply the .spi1d of the same name first" in line for line in lut.comments), lut.comments
        value = {".spi1d": [0.4] * 3, ".spi3d": [0.5] * 3}[path.suffix]
        done = subprocess.run([program, str(path), *map(str, value)], capture_output=True, text=True, check=True)
        expected = probes.ocio_apply(_transform([path]))(np.array([value]))[0]
        np.testing.assert_allclose([float(v) for v in done.stdout.split()[-3:]], expected, atol=1e-5)


@pytest.mark.parametrize("method", ("desaturate", "perceptual"))
def test_an_extended_range_clf_follows_the_displays_toe(default_spec, tmp_path, method):
    """An extended-range display (Display P3 HDR: sRGB's curve, code 1 at 100 cd/m², peak 1000)
    in the display layout: the pre-shaper is the display's own curve of its light, so the
    shaper table is linear and dark greys are exact (they were 15 codes off at 0.5 cd/m²)."""
    req = _request(default_spec, "clf", method=method, size=33, source="ACEScg", display="Display P3 HDR - Display")
    apply = probes.ocio_apply(_transform(_write(tmp_path, req)))
    greys = np.repeat(np.geomspace(1e-4, 10.0, 200)[:, None], 3, axis=1)  # scene-linear ACEScg greys
    expected = reference.mapped_view(
        default_spec, req.display, method, reference.to_reference(default_spec, req.source, greys)
    )
    error = probes.errors(req.display, apply(greys), expected)[0]
    assert error.max() <= tolerances.LUT_VIEW_HDR_IN_GAMUT_DELTA_E_ITP


@pytest.mark.parametrize("method", ("desaturate", "rgc", "perceptual"))
def test_every_size_from_the_smallest_bakes(default_spec, method):
    """A display-layout CLF of every size its request accepts (size 5 had rounded both its
    negative and over-range shares up and left the cube no interval)."""
    display = next(d for d in default_spec.displays if d.name == "sRGB - Display")
    smallest = bake._smallest_size(default_spec, display, default_spec.space("ACEScg"), method, "clf", "auto")
    for size in range(smallest, 12):
        lat = bake.build_lattice(_request(default_spec, "clf", method=method, size=size, source="ACEScg"))
        assert lat.size == size


def test_a_log_without_a_break_decodes_exactly_in_a_clf(tmp_path):
    """A custom pure log (log_camera without lin_side_break) is CLF's plain Log operator."""
    from generator.spec import load

    spec = load.parse(
        '[[custom_space]]\nname = "My Log"\ngamut = "Rec.2020"\ntransfer = { family = "log_camera", '
        "base = 10, log_side_slope = 0.25, log_side_offset = 0.6, lin_side_slope = 1, "
        "lin_side_offset = 0.01 }\n",
        "show.toml",
        tmp_path,
    )
    req = _request(spec, "clf", method="scale", size=17, source="My Log")
    paths = _write(tmp_path, req)
    assert 'style="logToLin"' in paths[0].read_text()
    figures = probes.measure(spec, req.source, req.display, "scale", probes.ocio_apply(_transform(paths)))
    assert max(f.maximum for f in figures.values()) <= tolerances.LUT_CLF_SCALE_CODES


def test_a_clf_says_what_its_lattice_covers_and_where_its_codes_end(default_spec):
    req = _request(
        default_spec, "clf", method="desaturate", size=17, source="ARRI LogC4", display="Display P3 HDR - Display"
    )
    text = bake.bake(req)[""].decode()
    assert "sampled over" not in text and "times the display's peak per channel" in text
    assert "code values (full range, 0 to 2.69872)" in text


def test_a_clf_root_is_clf_v3_with_its_namespace(default_spec):
    """As OCIO writes it: CLF v3 in SMPTE ST 2136-1's namespace."""
    from xml.etree import ElementTree

    root = ElementTree.fromstring(bake.bake(_request(default_spec, "clf"))[""])
    namespace = "{http://www.smpte-ra.org/ns/2136-1/2024}"
    assert root.tag == f"{namespace}ProcessList" and root.get("compCLFversion") == "3"
    assert root.find(f"{namespace}LUT3D").get("interpolation") == "tetrahedral"


def test_a_cube_header_gives_the_range_of_its_fitted_nodes(default_spec):
    req = _request(default_spec, "resolve_cube", source="ACEScg", size=17)
    lat = bake.build_lattice(req)
    low, high = lat.cube.min(), lat.cube.max()
    assert low < 0 and high > 1  # fitted nodes past the output range, which the header must say
    text = bake.bake(req)[""].decode()
    assert f"the fitted node values range from {low:.6g} to {high:.6g}." in text


def test_a_clf_into_a_tabulated_eotf_puts_the_peak_on_an_entry(tmp_path):
    """Clip and scale end in a 1D table from lattice coordinates to codes whose entries fall on
    every node's coordinate: a display with a tabulated EOTF shows white and brighter greys at
    code 1 (the peak fell between two entries, 0.73 codes low)."""
    from generator.spec import load

    (tmp_path / "curve.csv").write_text("code,linear\n0,0\n0.25,0.02\n0.5,0.1\n0.75,0.35\n1,1\n")
    spec = load.parse(
        '[[display]]\nname = "LED Tab"\ngamut = "Rec.709"\neotf = { family = "tabulated", file = "curve.csv" }\n',
        "show.toml",
        tmp_path,
    )
    req = _request(spec, "clf", method="clip", size=33, source="ACEScg", display="LED Tab")
    greys = np.repeat(np.array([1.0, 2.0, 5.0, 40.0])[:, None], 3, axis=1)
    codes = probes.ocio_apply(_transform(_write(tmp_path, req)))(greys)
    np.testing.assert_allclose(codes, 1.0, rtol=0, atol=tolerances.LUT_CLF_IN_GAMUT_CODES / 1023)


def test_an_rgc_bake_takes_the_specs_parameters(default_spec, tmp_path):
    """The spec's [rgc] table reaches the lattice: measured against the spec's own mapping the
    file is as close as ACES 1.3's bake is to ACES 1.3's, and far from ACES 1.3's mapping."""
    from generator.spec import load

    spec = load.parse(
        "[rgc]\nlimits = [1.5, 1.4, 1.3]\nthresholds = [0.6, 0.7, 0.75]\npower = 1.5", "show.toml", tmp_path
    )
    figures = {}
    for name, baked in (("own", spec), ("aces", default_spec)):
        req = _request(baked, "clf", method="rgc", size=33, source="ACEScg")
        apply = probes.ocio_apply(_transform(_write(tmp_path, req, name)))
        figures[name] = {
            against: probes.measure(s, req.source, req.display, "rgc", apply, count=1024)["in_gamut"].p99
            for against, s in (("own", spec), ("aces", default_spec))
        }
    assert figures["own"]["own"] <= 1.5 * figures["aces"]["aces"]
    assert figures["own"]["aces"] > 4 * figures["own"]["own"], figures


def test_a_scale_clf_at_its_smallest_size_is_exact(default_spec, tmp_path):
    """At three nodes a side the log axis's toe sat a few bits below the peak, and scale's
    over-range colours came out 26 ten-bit codes off: the smallest size is the first exact one."""
    req = _request(
        default_spec,
        "clf",
        method="scale",
        size=bake._smallest_size(
            default_spec, default_spec.displays[0], default_spec.space("ACEScg"), "scale", "clf", "auto"
        ),
        source="ACEScg",
    )
    assert req.size == 4
    figures = probes.measure(
        default_spec, req.source, req.display, "scale", probes.ocio_apply(_transform(_write(tmp_path, req))), count=1024
    )
    assert max(f.maximum for f in figures.values()) <= tolerances.LUT_CLF_EXACT_CODES


def test_a_failed_write_leaves_no_file(tmp_path, monkeypatch):
    from generator import files as writer

    files = {tmp_path / "a.spi3d": b"1", tmp_path / "a.spi1d": b"2"}
    real_replace = writer.os.replace
    calls = []

    def failing(src, dst):
        calls.append(dst)
        if len(calls) == 1:
            raise OSError("no space")
        real_replace(src, dst)

    monkeypatch.setattr(writer.os, "replace", failing)
    with pytest.raises(writer.CannotWrite, match="a.spi3d: cannot write: no space"):
        bake.write(files)
    assert list(tmp_path.iterdir()) == []
