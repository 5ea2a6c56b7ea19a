"""One writer per LUT format: a :class:`~generator.luts.lattice.Lattice` to bytes.

* ``resolve_cube``: DaVinci Resolve .cube (Blackmagic Design, "Resolve cube LUT
  specification"): an optional 1D shaper (``LUT_1D_SIZE``,
  ``LUT_1D_INPUT_RANGE``) then the 3D table (``LUT_3D_SIZE``,
  ``LUT_3D_INPUT_RANGE``), red index fastest.
* ``iridas_cube``: Iridas/Adobe .cube ("Cube LUT Specification" 1.0): 3D only,
  input domain in ``DOMAIN_MIN`` / ``DOMAIN_MAX``, red fastest.
* ``spi3d``: Sony Pictures Imageworks 3D (``SPILUT 1.0``, explicit node indices,
  input [0, 1]); the shaper, where there is one, is a separate .spi1d.
* ``clf``: Academy/ASC Common LUT Format, written by OCIO from the same transforms
  a config uses (:mod:`generator.luts.transforms`, :mod:`generator.luts.clf`):
  source decoding, Matrix, pre-shaper (Exponent, or Log for a logarithmic
  lattice), Range, LUT1D, LUT3D and, after a logarithmic lattice, the LUT1D to
  code values (or, in a config view ending in display light, the Exponent or Log
  operator undoing the lattice's curve), in one ProcessList.

The .cube and .spi writers are ours: colour-science's write a TITLE line OCIO's
Resolve reader refuses, a .cube's domain with the table's fixed decimals (a shaper's
-0.0078125 becomes -0.00781) and a .spi1d's values with fixed decimals (a curve's toe
loses float32 digits); its .spi3d writer gives the same numbers, 60 times slower (6.3 s
for a 65³ table against 0.1 s), with trailing zeros.

Every writer returns text as bytes; the same lattice always gives the same bytes.
"""

from __future__ import annotations

import numpy as np
import PyOpenColorIO as ocio

from generator.luts import numbers, transforms
from generator.luts.axes import LogAxis
from generator.luts.clf import clf_file
from generator.luts.lattice import SHAPER_DECIMALS, Lattice
from generator.luts.names import ascii_text
from generator.luts.spi1d import format_spi1d


def red_fastest(cube: np.ndarray) -> np.ndarray:
    """``cube[r, g, b]`` as rows with the red index changing fastest."""
    return cube.transpose(2, 1, 0, 3).reshape(-1, 3)


def blue_fastest(cube: np.ndarray) -> np.ndarray:
    """``cube[r, g, b]`` as rows with the blue index changing fastest."""
    return cube.reshape(-1, 3)


#: Longest line a .cube may hold (Adobe's Cube specification 1.0: 250 bytes, its end
#: included); comment lines are wrapped, a title cut, to fit.
LINE_MAX = 250


def _comments(lines) -> str:
    """``# `` comment lines, ASCII, each wrapped to fit :data:`LINE_MAX`."""
    import textwrap

    wrapped = (part for line in lines for part in textwrap.wrap(ascii_text(line), LINE_MAX - 3) or [""])
    return "".join(f"# {part}\n" for part in wrapped)


def _title(title: str) -> str:
    """An Iridas ``TITLE`` line: ASCII, in double quotes, which the format cannot escape (one
    in the text becomes a single quote), cut to fit :data:`LINE_MAX`."""
    text = ascii_text(title).replace('"', "'")
    room = LINE_MAX - len('TITLE ""\n')
    return f'TITLE "{text if len(text) <= room else text[: room - 3] + "..."}"\n'


def _n(value) -> str:
    return numbers.number(value)


def resolve_cube(lattice: Lattice, title: str, notes=()) -> bytes:
    """``lattice`` as a Resolve .cube (a 1D shaper table before the 3D table, when it has one)."""
    lo, hi = lattice.domain
    head = [_comments([title, *notes])]  # OCIO's Resolve reader takes no TITLE line
    body = []
    if lattice.shaper is not None:
        head += [
            f"LUT_1D_SIZE {lattice.shaper.size}\n",
            f"LUT_1D_INPUT_RANGE {_n(lo)} {_n(hi)}\n",
            f"LUT_3D_SIZE {lattice.size}\n",
            "LUT_3D_INPUT_RANGE 0 1\n",
        ]
        body.append(numbers.table(np.repeat(lattice.shaper[:, None], 3, axis=1), SHAPER_DECIMALS))
    else:
        head += [f"LUT_3D_SIZE {lattice.size}\n", f"LUT_3D_INPUT_RANGE {_n(lo)} {_n(hi)}\n"]
    body.append(numbers.table(red_fastest(lattice.cube), lattice.decimals))
    return ascii_text("".join(head)).encode("ascii") + b"".join(body)


def iridas_cube(lattice: Lattice, title: str, notes=()) -> bytes:
    """``lattice`` as an Iridas .cube (3D table only; ValueError for a lattice with a shaper)."""
    if lattice.shaper is not None:
        raise ValueError("an Iridas .cube holds no shaper")
    lo, hi = lattice.domain
    head = (
        f"{_title(title)}{_comments(notes)}LUT_3D_SIZE {lattice.size}\n"
        f"DOMAIN_MIN {_n(lo)} {_n(lo)} {_n(lo)}\nDOMAIN_MAX {_n(hi)} {_n(hi)} {_n(hi)}\n"
    )
    return ascii_text(head).encode("ascii") + numbers.table(red_fastest(lattice.cube), lattice.decimals)


def spi3d(lattice: Lattice, notes=()) -> bytes:
    """The .spi3d; ``notes`` go as ``#`` lines after the header's three lines, where OCIO's
    reader (which takes only lines of six numbers there) and colour-science's skip them."""
    n = lattice.size
    index = np.indices((n, n, n)).reshape(3, -1).T
    values = numbers.table(blue_fastest(lattice.cube), lattice.decimals).decode("ascii").splitlines()
    rows = "".join(f"{i} {j} {k} {v}\n" for (i, j, k), v in zip(index.tolist(), values))
    return f"SPILUT 1.0\n3 3\n{n} {n} {n}\n{_comments(notes)}{rows}".encode("ascii")


def spi1d_shaper(lattice: Lattice, notes=()) -> bytes:
    """The .spi1d taking the lattice's input to [0, 1] (a straight line without a shaper table);
    ``notes`` go as ``#`` lines after its first line, among the header's tags, where OCIO's
    reader skips lines it does not know."""
    values = lattice.shaper if lattice.shaper is not None else np.array([0.0, 1.0])
    version, rest = format_spi1d(values, lattice.domain).split("\n", 1)
    return f"{version}\n{_comments(notes)}{rest}".encode("ascii")


def needs_spi1d(lattice: Lattice) -> bool:
    """Whether an .spi3d of this lattice needs a shaper beside it (its input is not [0, 1])."""
    return lattice.shaper is not None or tuple(lattice.domain) != (0.0, 1.0)


def _pre_shaper(pre, forward: bool = True) -> ocio.Transform:
    """A :class:`~generator.luts.lattice.PreShaper`'s curve as an Exponent (CLF's basicMirrorRev,
    or monCurveMirrorRev with an offset); its inverse with ``forward`` False."""
    direction = transforms.INVERSE if forward else transforms.FORWARD
    if pre.offset:
        return transforms.mon_curve(pre.gamma, pre.offset, direction=direction)
    return transforms.power(pre.gamma, direction=direction)


def _axis_shaper(axis, forward: bool = True) -> list:
    """A lattice's curve of normalised display-linear light (``forward``; else back): the Log of a
    :class:`LogAxis`, or a :class:`~generator.luts.lattice.PreShaper`'s Exponent between the
    scalings keeping the peak at 1."""
    if isinstance(axis, LogAxis):
        return [transforms.log_shaper(axis.span, axis.toe, transforms.FORWARD if forward else transforms.INVERSE)]
    if axis.scale == 1.0:
        return [_pre_shaper(axis, forward)]
    if forward:
        return [transforms.scale_transform(axis.scale), _pre_shaper(axis), transforms.scale_transform(1.0 / axis.norm)]
    return [
        transforms.scale_transform(axis.norm),
        _pre_shaper(axis, False),
        transforms.scale_transform(1.0 / axis.scale),
    ]


def decode_steps(name: str, curve) -> list:
    """Transforms decoding ``curve``, as the config's (:func:`generator.ocio.curves.decode_transforms`)
    where OCIO has an exact operator in every version; else the baked curve of
    :mod:`generator.luts.curve1d`, whose 1D LUT the file holds (CLF has no builtins)."""
    analytic = transforms.analytic_decode(curve)
    if analytic is not None:
        return analytic
    from generator.luts.curve1d import bake_curve

    baked = bake_curve(name, curve, curve.domain)
    return transforms.baked_decode(baked.domain, baked.shaper, transforms.lut1d(baked.values))


def clf_steps(lattice: Lattice, include_matrix: bool = True) -> list:
    """The transforms of a lattice's CLF. Display layout: [decoding, Matrix,] pre-shaper, Range,
    [LUT1D,] LUT3D, [LUT1D,] [the pre-shaper undone]; without ``include_matrix`` they start at
    the pre-shaper and take normalised display-linear RGB (the config keeps the matrix as a
    MatrixTransform). Source layout: Range, [LUT1D,] LUT3D."""
    steps = []
    if lattice.pre is not None:
        if include_matrix:
            if lattice.source is not None and lattice.decode is not None:
                steps += decode_steps(lattice.source.name, lattice.decode)
            steps.append(transforms.matrix_transform(lattice.matrix))
        steps += _axis_shaper(lattice.pre)
    steps.append(transforms.range_transform(*lattice.domain))
    if lattice.shaper is not None:
        steps.append(transforms.lut1d(lattice.shaper))
    steps.append(transforms.lut3d(lattice.cube))
    if lattice.post is not None:
        steps.append(transforms.lut1d(lattice.post))
    if lattice.light is not None:
        steps += _axis_shaper(lattice.light, forward=False)
    return steps


def clf(
    lattice: Lattice,
    identifier: str,
    description: str,
    include_matrix: bool = True,
    descriptors: tuple[str, str] = ("", ""),
) -> bytes:
    """The CLF of ``lattice`` (:func:`clf_steps`), written by OCIO (:mod:`generator.luts.clf`)."""
    return clf_file(clf_steps(lattice, include_matrix), identifier, description, descriptors)
