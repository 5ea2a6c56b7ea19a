"""The baked ACES 2.0 view's axes: AP1's chromaticity and luminance."""

import numpy as np
import pytest

from generator.luts import aces_chroma
from generator.luts.aces_chroma import HDR_WARP, SDR_WARP, chroma_axes
from generator.rendering import views

SDR = views.catalogue()["ACES 2.0 - SDR 100 nits (Rec.709)"]


def test_ap1s_faces_are_the_tables_faces_and_its_diagonal_plane():
    """Blue, red and green at (0, 0), (1, 0) and (1, 1): G = 0 on q = 0, B = 0 on p = 1, R = 0 on p = q
    (within what BLACK_OFFSET moves colours of 0.1 and more: 1e-8 of a chromaticity)."""
    axes = chroma_axes(SDR, 81, 2.0**-7, SDR_WARP)
    corners = axes.coordinate(np.eye(3)[[2, 0, 1]] * 0.5)[:, :2]
    assert np.allclose(corners, [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], atol=1e-6)
    rng = np.random.default_rng(1)
    faces = 0.1 + rng.random((3000, 3)) * 4.0
    faces[np.arange(3000), np.arange(3000) % 3] = 0.0
    u = axes.coordinate(faces)
    on_g, on_b, on_r = (u[i::3] for i in (1, 2, 0))
    assert np.allclose(on_g[:, 1], 0.0, atol=1e-7) and np.allclose(on_b[:, 0], 1.0, atol=1e-7)
    assert np.allclose(on_r[:, 0], on_r[:, 1], atol=1e-7)


@pytest.mark.parametrize("shape", [SDR_WARP, HDR_WARP])
def test_values_invert_coordinates_inside_ap1(shape):
    axes = chroma_axes(SDR, 65, 2.0**-9, shape)
    ap1 = np.random.default_rng(2).random((2000, 3)) * 10 ** np.random.default_rng(3).uniform(-3, 2, (2000, 1))
    assert np.allclose(axes.values(axes.coordinate(ap1)), ap1, rtol=1e-9, atol=1e-12)


def test_node_values_are_the_values_of_every_node_pair_by_level():
    """A table's nodes computed per (p, q) pair and per level are, bit for bit, :meth:`values`
    of the nodes listed whole (pairs outer), on both halves of the table."""
    axes = chroma_axes(SDR, 17, 2.0**-7, SDR_WARP)
    nodes = np.linspace(0.0, 1.0, 17)
    p, q = np.nonzero(np.ones((17, 17), dtype=bool))
    whole = np.stack([np.repeat(nodes[p], 17), np.repeat(nodes[q], 17), np.tile(nodes, p.size)], axis=1)
    assert np.array_equal(axes.node_values(np.stack([nodes[p], nodes[q]], axis=1), nodes), axes.values(whole))


def test_the_warp_rises_from_0_to_1_and_crowds_the_faces():
    t = np.linspace(0.0, 1.0, 1001)
    for shape in (SDR_WARP, HDR_WARP):
        w = aces_chroma.warp(t, *shape)
        assert w[0] == 0.0 and abs(w[-1] - 1.0) < 1e-12 and np.all(np.diff(w) > 0.0)
        slope = np.diff(w) / np.diff(t)
        assert slope[0] > 2.0 * slope[500] and slope[-1] > 2.0 * slope[500]


def test_greys_sit_on_a_node_of_p_and_q():
    for size in (17, 81):
        axes = chroma_axes(SDR, size, 2.0**-7, SDR_WARP)
        u = axes.coordinate(np.array([[0.01] * 3, [1.0] * 3, [300.0] * 3]))[:, :2] * (size - 1)
        assert np.max(np.abs(u - np.array(axes.grey_nodes(size)))) < 1e-4
