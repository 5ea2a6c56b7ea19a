"""Where a baked ACES 2.0 view's table puts its nodes: AP1's chromaticity and its luminance.

OCIO's XYZ_TO_xyY fixed function (from 2.0), given (R, L, B) -- AP1's red, its luminance and
its blue -- returns ``x = R / (R + L + B)``, ``y = L / (R + L + B)`` and L. The chromaticities of
AP1's colours then fill a triangle, which a matrix with offset takes to ``0 <= q <= p <= 1``:
blue to (0, 0), red to (1, 0), green to (1, 1). AP1's faces G = 0 and B = 0 are faces of the
table (q = 0, p = 1) and R = 0 is the plane p = q, which bounds tetrahedral interpolation's
tetrahedra: a colour's tetrahedron never reaches past AP1's faces, and the table's other half
(q > p) holds no colour. A per-channel Log operator and 1D table then place the nodes: p and
q through the same warp (denser toward AP1's faces, greys on a node), the luminance on a view
axis (:func:`generator.luts.aces_axes.view_axes`).

Luminance gets an axis of its own: above the tone scale's shoulder the rendering changes
little with it, and the chromaticity axes keep their nodes at every level. A per-channel
lattice of AP1 spends its nodes on both at once.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from generator.colorimetry.gamuts import gamuts
from generator.colorimetry.matrices import settled
from generator.luts import numbers
from generator.luts.aces_axes import ACES_BEND_ENTRIES, view_axes
from generator.luts.axes import LogAxis
from generator.luts.lattice import SHAPER_DECIMALS

#: The warp of each chromaticity axis, (share, offset): a blend of the uniform axis (``share``)
#: and a logit, ``log(t + offset) - log(1 - t + offset)``, whose nodes crowd toward AP1's faces,
#: where the cone compression's power makes the rendering bend. SDR views keep more nodes in the
#: middle for in-gamut colours; HDR views need them nearer the faces for saturated camera colours
#: (bench/aces_views.py, docs/aces-views.md).
SDR_WARP, HDR_WARP = (0.0, 0.1), (0.42, 0.01)

#: The Log operator on p and q is ``log2(x + CHROMA_LOG_OFFSET)``, scaled to [0, 1]. OCIO's fast
#: log2 (its default flags) errs by 1.4e-5 in log2, whatever the input: over the 4.1 bits this
#: spans, a quarter of what ``log2(x + 1)``'s one bit left (that put the file 1.7e-4 from its
#: float64 evaluation near AP1's faces, where the warp is steep).
CHROMA_LOG_OFFSET = 1.0 / 16.0

#: Bits of ``x + CHROMA_LOG_OFFSET`` from x = 0 to 1: the Log operator divides by them.
CHROMA_LOG_SPAN = float(np.log2(1.0 / CHROMA_LOG_OFFSET + 1.0))


def chroma_log(p) -> np.ndarray:
    """The Log operator's value in [0, 1] of p or q in [0, 1]."""
    return np.log2(np.asarray(p, dtype=np.float64) / CHROMA_LOG_OFFSET + 1.0) / CHROMA_LOG_SPAN


def chroma_unlog(v) -> np.ndarray:
    """:func:`chroma_log`'s inverse."""
    return (np.exp2(np.asarray(v, dtype=np.float64) * CHROMA_LOG_SPAN) - 1.0) * CHROMA_LOG_OFFSET


#: Added to (R, L, B) before XYZ_TO_xyY, and taken from L after it: black then has the greys'
#: chromaticity (not the (0, 0) of OCIO's division guard, past AP1's blue corner), and a float32
#: departure of its luminance coordinate reads the darkest grey, not a saturated blue (GPU log2:
#: up to 2e-3 on a pure-power display). Colours darker than a millionth of the toe move toward grey.
BLACK_OFFSET = 1e-9


def _ryb() -> np.ndarray:
    """AP1 to (R, L, B): red, luminance (AP1's Y, summing to 1: a grey's L is its value), blue."""
    luminance = gamuts()["AP1"].rgb_to_xyz[1]
    return settled(np.array([[1.0, 0.0, 0.0], luminance / luminance.sum(), [0.0, 0.0, 1.0]]))


def _xy(ryb: np.ndarray) -> np.ndarray:
    """XYZ_TO_xyY's chromaticity of (R, L, B) (m, 3); 0 where the sum is 0, as OCIO."""
    total = ryb.sum(axis=1)
    with np.errstate(all="ignore"):
        scale = np.where(total == 0.0, 0.0, 1.0 / total)
    return ryb[:, :2] * scale[:, None]


def _affine() -> tuple[np.ndarray, np.ndarray]:
    """The matrix (2, 2) and offset (2,) taking AP1's primaries' chromaticities to (1, 0), (1, 1), (0, 0)."""
    corners = _xy(np.eye(3) @ _ryb().T)
    solved = np.linalg.solve(np.c_[corners, np.ones(3)], np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 0.0]]))
    return settled(solved[:2].T), settled(solved[2])


def warp(t, share: float, offset: float) -> np.ndarray:
    """A chromaticity axis's coordinate in [0, 1] of ``t`` in [0, 1] (:data:`SDR_WARP`)."""
    t = np.clip(np.asarray(t, dtype=np.float64), 0.0, 1.0)
    end = np.log((1.0 + offset) / offset)
    logit = (np.log((t + offset) / offset) - np.log((1.0 - t + offset) / (1.0 + offset))) / (2.0 * end)
    return share * t + (1.0 - share) * logit


@dataclass(frozen=True, eq=False)
class ChromaAxes:
    """The operators before the table: (R, L, B) of AP1 (``ryb``), the chromaticity's matrix and
    ``offset`` to (p, q), the Log operator (:func:`chroma_log` on p and q, ``log`` on L), and the 1D
    table (entries uniform over [0, 1]; ``chroma`` for p and q alike, ``bend`` for L)."""

    ryb: np.ndarray
    matrix: np.ndarray
    offset: np.ndarray
    log: LogAxis
    chroma: np.ndarray
    bend: np.ndarray

    def coordinate(self, ap1) -> np.ndarray:
        """Lattice coordinates (m, 3) in [0, 1] of AP1 colours (m, 3, clamped as the config clamps
        them), as OCIO runs the operators."""
        return self.placed(*self.chromaticity(ap1))

    def chromaticity(self, ap1) -> tuple[np.ndarray, np.ndarray]:
        """(p, q) (m, 2) and luminance L (m,) of AP1 colours (m, 3), as the operators before the
        Log give them."""
        ryb = np.asarray(ap1, dtype=np.float64) @ self.ryb.T
        return _xy(ryb + BLACK_OFFSET) @ self.matrix.T + self.offset, ryb[:, 1]

    def placed(self, pq, luminance) -> np.ndarray:
        """Lattice coordinates (m, 3) of (p, q) (m, 2) and luminance (m,): the Log and the 1D table."""
        entries = np.linspace(0.0, 1.0, self.chroma.size)
        out = np.empty((len(luminance), 3))
        for channel in range(2):
            out[:, channel] = np.interp(chroma_log(pq[:, channel]), entries, self.chroma)
        out[:, 2] = np.interp(self.log.coordinate(luminance), entries, self.bend)
        return out

    def values(self, u) -> np.ndarray:
        """AP1 at lattice coordinates ``u`` (m, 3): :meth:`coordinate`'s inverse where p >= q (in
        the table's other half, chromaticities past AP1's R = 0 face, clamped to 0)."""
        u = np.asarray(u, dtype=np.float64)
        return self.node_values(u[:, :2], u[:, 2], paired=True)

    def node_values(self, chroma, luminance, paired: bool = False) -> np.ndarray:
        """:meth:`values` of every (p, q) coordinate pair of ``chroma`` (m, 2) with every luminance
        coordinate of ``luminance`` (k,), pairs outer (m·k, 3), each pair's chromaticity and each
        luminance computed once (a table's nodes); ``paired``: row i's pair with ``luminance[i]``
        alone (m, 3). Elementwise the same operations, so the same values."""
        chroma, luminance = np.asarray(chroma, dtype=np.float64), np.asarray(luminance, dtype=np.float64)
        entries = np.linspace(0.0, 1.0, self.chroma.size)
        pq = chroma_unlog(np.stack([np.interp(chroma[:, c], self.chroma, entries) for c in range(2)], axis=1))
        xy = (pq - self.offset) @ np.linalg.inv(self.matrix).T
        level = self.grey(luminance) + BLACK_OFFSET
        x, y = (xy[:, 0], xy[:, 1]) if paired else (xy[:, :1], xy[:, 1:])
        z = 1.0 - x - y
        with np.errstate(all="ignore"):
            total = np.where(y > 0.0, level / y, 0.0)
        level = np.broadcast_to(level, total.shape)
        ryb = np.stack([(x * total).ravel(), level.ravel(), (z * total).ravel()], axis=1) - BLACK_OFFSET
        return np.maximum(ryb @ np.linalg.inv(self.ryb).T, 0.0)

    def grey(self, u) -> np.ndarray:
        """The AP1 grey at luminance coordinate ``u`` (its L is its value)."""
        entries = np.linspace(0.0, 1.0, self.bend.size)
        return self.log.position(np.interp(np.asarray(u, dtype=np.float64), self.bend, entries))

    def grey_nodes(self, size: int) -> tuple[int, int]:
        """The (p, q) node indices of greys in a ``size``³ table."""
        u = self.coordinate(np.ones((1, 3)))[0, :2] * (size - 1)
        return int(np.rint(u[0])), int(np.rint(u[1]))


def chroma_axes(view, size: int, toe: float, shape: tuple[float, float]) -> ChromaAxes:
    """The axes of ``view``'s ``size``³ table: luminance on the view's axis of ``toe``, p and q
    through :func:`warp` of ``shape``, moved by less than half a node so that greys land on one."""
    log, _, bend = view_axes(view, toe)
    matrix, offset = _affine()
    ryb = _ryb()
    entries = np.linspace(0.0, 1.0, ACES_BEND_ENTRIES)
    table = warp(chroma_unlog(entries), *shape)
    grey = chroma_log(_xy(np.ones((1, 3)) @ ryb.T + BLACK_OFFSET)[0] @ matrix.T + offset)
    n, last = size - 1, entries.size - 1.0
    # piecewise linear in the entry, constant across each grey's two entries: the grey's coordinate
    # moves by exactly its node's remainder, and the table still rises
    knots, moves = [0.0], [0.0]
    for v in sorted(grey):
        k = np.floor(v * last)
        at = float(np.interp(v, entries, table))
        knots += [k, k + 1.0]
        moves += [round(at * n) / n - at] * 2
    table = table + np.interp(np.arange(entries.size), [*knots, last], [*moves, 0.0])
    table = numbers.rounded(table, SHAPER_DECIMALS)
    if np.any(np.diff(table) <= 0.0):
        raise ValueError(f"the chromaticity warp {shape} does not rise over {entries.size} entries")
    return ChromaAxes(ryb, matrix, offset, log, table, bend)
