"""One writer per LUT format: a :class:`~generator.luts.lattice.Lattice` to bytes.

* ``resolve_cube``: DaVinci Resolve .cube (Blackmagic Design, "Resolve cube LUT
  specification"): an optional 1D shaper (``LUT_1D_SIZE``,
  ``LUT_1D_INPUT_RANGE``) then the 3D table (``LUT_3D_SIZE``,
  ``LUT_3D_INPUT_RANGE``), red index fastest.
* ``iridas_cube``: Iridas/Adobe .cube ("Cube LUT Specification" 1.0): 3D only,
  input domain in ``DOMAIN_MIN`` / ``DOMAIN_MAX``, red fastest.
* ``spi3d``: Sony Pictures Imageworks 3D (``SPILUT 1.0``, explicit node indices,
  input [0, 1]); the shaper, where there is one, is a separate .spi1d.
* ``clf``: Academy/ASC Common LUT Format v3 (S-2014-006, 2020 revision), all
  32-bit float: source decoding, Matrix, pre-shaper (Exponent, or Log for a
  logarithmic lattice), Range, LUT1D, LUT3D and, after a logarithmic lattice,
  the LUT1D to code values (or, in a config view ending in display light, the
  Exponent or Log operator undoing the lattice's curve), in one ProcessList;
  the 3D array has blue fastest.

Every writer returns text as bytes; the same lattice always gives the same bytes.
"""

from __future__ import annotations

import numpy as np

from generator.colorimetry.matrices import settled
from generator.colorimetry.transfer import Linear, LogCamera, PiecewisePower, Power
from generator.luts import numbers
from generator.luts.axes import LogAxis
from generator.luts.lattice import CUBE_DECIMALS, SHAPER_DECIMALS, Lattice
from generator.luts.names import ascii_text
from generator.luts.spi1d import format_spi1d

#: The XML namespace of CLF v3 (S-2014-006), which its version attribute "3.0" goes with.
CLF_NAMESPACE = "urn:AMPAS:CLF:v3.0"

#: Interpolation CLF's LUT3D asks for (and what the config's FileTransform uses).
INTERPOLATION = "tetrahedral"


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


def table_array(rows: np.ndarray, dim: str, decimals: int) -> str:
    """A CLF Array of ``rows`` (values within (-10, 10)) with fixed ``decimals``."""
    return f'<Array dim="{dim}">\n' + numbers.table(rows, decimals).decode("ascii") + "</Array>\n"


def op(tag: str, body: str, in_depth: str = "32f", out_depth: str = "32f", **attributes) -> str:
    """A CLF process node, 32-bit float in and out unless told (a half-domain LUT1D reads 16f)."""
    attrs = "".join(f' {key}="{value}"' for key, value in attributes.items())
    return f'<{tag} inBitDepth="{in_depth}" outBitDepth="{out_depth}"{attrs}>\n{body}</{tag}>\n'


def _exponent(style: str, gamma: float, offset: float | None = None) -> str:
    extra = f' offset="{_n(offset)}"' if offset is not None else ""
    return op("Exponent", f'<ExponentParams exponent="{_n(gamma)}"{extra}/>\n', style=style)


def _range(lo: float, hi: float) -> str:
    body = "".join(
        f"<{tag}>{_n(v)}</{tag}>\n"
        for tag, v in (("minInValue", lo), ("maxInValue", hi), ("minOutValue", 0.0), ("maxOutValue", 1.0))
    )
    return op("Range", body)


def _lut1d(values: np.ndarray, decimals: int) -> str:
    return op("LUT1D", table_array(values[:, None], f"{values.size} 1", decimals))


def _log_axis(axis: LogAxis, style: str = "linToLog") -> str:
    """The Log operator taking normalised display-linear x to the coordinate of ``axis``:
    ``log2(x + toe) / span - log2(toe) / span`` (``logToLin``: back)."""
    params = dict(
        base=2.0,
        logSideSlope=1.0 / axis.span,
        logSideOffset=-np.log2(axis.toe) / axis.span,
        linSideSlope=1.0,
        linSideOffset=axis.toe,
    )
    attrs = " ".join(f'{key}="{_n(value)}"' for key, value in params.items())
    return op("Log", f"<LogParams {attrs}/>\n", style=style)


def _pre_shaper(pre, forward: bool = True) -> str:
    """A :class:`~generator.luts.lattice.PreShaper` as an Exponent operator (its inverse
    with ``forward`` False)."""
    direction = "Rev" if forward else "Fwd"
    if pre.offset:
        return _exponent(f"monCurveMirror{direction}", pre.gamma, pre.offset)
    return _exponent(f"basicMirror{direction}", pre.gamma)


def _log_camera(curve: LogCamera) -> str:
    """A LogCamera curve's decoding: CLF's camera style with a break, its plain log style without."""
    params = dict(
        base=curve.base,
        logSideSlope=curve.log_side_slope,
        logSideOffset=curve.log_side_offset,
        linSideSlope=curve.lin_side_slope,
        linSideOffset=curve.lin_side_offset,
    )
    if curve.lin_side_break is not None:
        params["linSideBreak"] = curve.lin_side_break
    if curve.linear_slope is not None:
        params["linearSlope"] = curve.linear_slope
    attrs = " ".join(f'{key}="{_n(value)}"' for key, value in params.items())
    style = "cameraLogToLin" if curve.lin_side_break is not None else "logToLin"
    return op("Log", f"<LogParams {attrs}/>\n", style=style)


def decode_ops(name: str, curve) -> str:
    """CLF operators decoding ``curve``: analytic (Exponent, Log) where CLF has one,
    else the baked 1D LUT of :mod:`generator.luts.curve1d` behind a Range."""
    if isinstance(curve, Linear):
        return ""
    if isinstance(curve, Power):
        return _exponent("basicMirrorFwd", curve.exponent)
    if isinstance(curve, PiecewisePower):
        return _exponent("monCurveFwd", curve.gamma, curve.offset)
    if isinstance(curve, LogCamera):
        return _log_camera(curve)
    from generator.luts.curve1d import bake_curve

    baked = bake_curve(name, curve, curve.domain)
    ops = _range(*baked.domain)
    if baked.shaper != 1:
        ops += _exponent("basicFwd", 1.0 / baked.shaper)
    values = np.asarray(baked.values)
    return ops + op("LUT1D", f'<Array dim="{values.size} 1">\n' + "".join(f"{v:.9g}\n" for v in values) + "</Array>\n")


def _matrix(matrix: np.ndarray) -> str:
    rows = "".join(" ".join(_n(v) for v in row) + "\n" for row in settled(matrix))
    return op("Matrix", f'<Array dim="3 3">\n{rows}</Array>\n')


def _pre(lattice: Lattice, include_matrix: bool) -> list[str]:
    """Operators before the Range of a display layout: decoding and Matrix (with
    ``include_matrix``), then the Log or Exponent pre-shaper."""
    ops = []
    if include_matrix:
        if lattice.decode is not None:
            ops.append(decode_ops(lattice.source.name, lattice.decode))
        ops.append(_matrix(lattice.matrix))
    pre = lattice.pre
    if isinstance(pre, LogAxis):
        return [*ops, _log_axis(pre)]
    if pre.scale == 1.0:
        return [*ops, _pre_shaper(pre)]
    return [*ops, _matrix(np.eye(3) * pre.scale), _pre_shaper(pre), _matrix(np.eye(3) / pre.norm)]


def _light(lattice: Lattice) -> list[str]:
    """The exact operator after the lattice of a file ending in display light."""
    if lattice.light is None:
        return []
    if isinstance(lattice.light, LogAxis):
        return [_log_axis(lattice.light, "logToLin")]
    light = lattice.light
    if light.scale == 1.0:
        return [_pre_shaper(light, forward=False)]
    return [_matrix(np.eye(3) * light.norm), _pre_shaper(light, forward=False), _matrix(np.eye(3) / light.scale)]


def clf(
    lattice: Lattice,
    identifier: str,
    description: str,
    include_matrix: bool = True,
    descriptors: tuple[str, str] = ("", ""),
) -> bytes:
    """A CLF v3 ProcessList of ``lattice``. Display layout: [decoding, Matrix,] pre-shaper,
    Range, [LUT1D,] LUT3D, [LUT1D]; without ``include_matrix`` the file starts at the
    pre-shaper and its input is normalised display-linear RGB (the config keeps
    the matrix as a MatrixTransform). Source layout: Range, [LUT1D,] LUT3D."""
    ops = _pre(lattice, include_matrix) if lattice.pre is not None else []
    ops.append(_range(*lattice.domain))
    if lattice.shaper is not None:
        ops.append(_lut1d(lattice.shaper, SHAPER_DECIMALS))
    n = lattice.size
    ops.append(
        op(
            "LUT3D",
            table_array(blue_fastest(lattice.cube), f"{n} {n} {n} 3", lattice.decimals),
            interpolation=INTERPOLATION,
        )
    )
    if lattice.post is not None:
        ops.append(_lut1d(lattice.post, CUBE_DECIMALS))
    ops += _light(lattice)
    return clf_document(ops, identifier, description, descriptors)


def clf_document(ops: list[str], identifier: str, description: str, descriptors: tuple[str, str] = ("", "")) -> bytes:
    """A CLF v3 ProcessList of the process nodes ``ops`` (text from :func:`op`)."""
    head = (
        f'<?xml version="1.0" encoding="UTF-8"?>\n'
        f'<ProcessList xmlns="{CLF_NAMESPACE}" compCLFversion="3.0" id="{_xml(identifier)}">\n'
        f"<Description>{_xml(description)}</Description>\n"
    )
    if descriptors[0]:
        head += f"<InputDescriptor>{_xml(descriptors[0])}</InputDescriptor>\n"
    if descriptors[1]:
        head += f"<OutputDescriptor>{_xml(descriptors[1])}</OutputDescriptor>\n"
    return (head + "".join(ops) + "</ProcessList>\n").encode("utf-8")


def _xml(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")
