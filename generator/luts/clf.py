"""CLF files written by OpenColorIO from the transforms of :mod:`generator.luts.transforms`.

OCIO's GroupTransform.write writes the document: its header, every operator, style
and parameter, as the config's transforms hold them, each table a two-entry stand-in
of its kind, flags and channel count (writing the tables themselves took most of a
pack's CLF time, to be replaced). Their arrays are then written in an ElementTree
document of that output: the writer pads every table value to
eleven characters and eight significant digits of float32 (0.3 becomes 0.30000001),
which doubled the files (the LUT pack 28 to 36 MB, past LUT_PACK_BYTES), and eight
digits do not always read back to the same float32. Each table is written instead
with the fewest fixed decimals that read back to exactly the float32 values the
transform holds (the lattice's own decimals), else nine significant digits; and the
document flat, an element a line, as the verifier's tests edit it.
"""

from __future__ import annotations

from xml.etree import ElementTree

import numpy as np
import PyOpenColorIO as ocio

from generator.luts import numbers

#: OCIO's name of the format.
CLF_FORMAT = "Academy/ASC Common LUT Format"

#: Fixed decimals tried for a table, at most (float32 values of magnitude 1e-3 and more).
MAX_DECIMALS = 9


def clf_file(steps: list, identifier: str, description: str, descriptors: tuple[str, str] = ("", "")) -> bytes:
    """The CLF ProcessList of the transforms ``steps``, written by OCIO (module docstring), with
    its id, Description and, where given, Input and Output descriptors."""
    group = ocio.GroupTransform([_stand_in(t) for t in steps])
    meta = group.getFormatMetadata()
    meta.setID(identifier)
    meta.addChildElement("Description", description)
    for tag, text in zip(("InputDescriptor", "OutputDescriptor"), descriptors):
        if text:
            meta.addChildElement(tag, text)
    written = group.write(CLF_FORMAT, ocio.Config.CreateRaw())
    tables = [t for t in steps if isinstance(t, (ocio.Lut1DTransform, ocio.Lut3DTransform))]
    return _retexted(written, tables)


def _stand_in(step):
    """A LUT1D or LUT3D transform's two-entry stand-in: its kind, direction, interpolation, file
    bit depth, flags and channel count (OCIO writes one column for a table whose channels are
    equal); any other transform (and a half-domain LUT1D, whose length is fixed) as it is."""
    if isinstance(step, ocio.Lut3DTransform):
        out = ocio.Lut3DTransform(gridSize=2)
    elif isinstance(step, ocio.Lut1DTransform) and not step.getInputHalfDomain():
        rows = np.asarray(step.getData()).reshape(-1, 3)
        mono = bool(np.all(rows == rows[:, :1]))
        out = ocio.Lut1DTransform(length=2)
        out.setData(np.array([0, 0, 0, 1, 1, 1 if mono else 0.5], dtype=np.float32))
        out.setHueAdjust(step.getHueAdjust())
        out.setOutputRawHalfs(step.getOutputRawHalfs())
    else:
        return step
    out.setDirection(step.getDirection())
    out.setInterpolation(step.getInterpolation())
    out.setFileOutputBitDepth(step.getFileOutputBitDepth())
    return out


def _retexted(written: str, tables: list) -> bytes:
    """OCIO's document ``written``, flat, each LUT1D or LUT3D array holding :func:`table_text`
    of the transform in ``tables`` it was written from (or stands in for), with its dimensions."""
    root = ElementTree.fromstring(written)
    namespace = root.tag[1:].split("}")[0]
    for element in root.iter():  # local names, the namespace an attribute (ElementTree's
        element.tag = element.tag.split("}")[1]  # default_namespace refuses plain attributes)
    root.attrib = {"xmlns": namespace, **root.attrib}
    arrays = [_child(op, "Array") for op in root if op.tag in ("LUT1D", "LUT3D")]
    if len(arrays) != len(tables):
        raise ValueError(f"OCIO wrote {len(arrays)} tables of {len(tables)}")
    for array, table in zip(arrays, tables):
        columns = int(array.attrib["dim"].split()[-1])
        rows = np.asarray(table.getData()).reshape(-1, 3)
        grid = [table.getGridSize()] * 3 if isinstance(table, ocio.Lut3DTransform) else [len(rows)]
        array.attrib["dim"] = " ".join(str(n) for n in (*grid, columns))
        array.text = "\n" + table_text(rows[:, :columns])
    for element in root.iter():
        if len(element):
            element.text = "\n"
        elif element.tag == "Array" and element not in arrays:  # a Matrix's: OCIO's numbers, unpadded
            lines = (element.text or "").strip().splitlines()
            element.text = "".join(f"\n{' '.join(line.split())}" for line in lines) + "\n"
        elif element.text and element.tag != "Array":
            element.text = element.text.strip()
        element.tail = "\n"
    text = ElementTree.tostring(root, encoding="unicode")
    return ('<?xml version="1.0" encoding="UTF-8"?>\n' + text).encode("utf-8")


def _child(element: ElementTree.Element, tag: str) -> ElementTree.Element:
    """``element``'s first child ``tag``; ValueError when OCIO wrote none."""
    found = element.find(tag)
    if found is None:
        raise ValueError(f"OCIO wrote a {element.tag} without an {tag}")
    return found


def table_text(values: np.ndarray) -> str:
    """Rows of float32 ``values`` (rows, columns) as text reading back to exactly them: the
    fewest fixed decimals that do (trailing zeros dropped), else nine significant digits."""
    values = np.asarray(values, dtype=np.float32)
    wide = values.astype(np.float64)
    if np.all(np.abs(wide) < 9.0):
        for decimals in range(MAX_DECIMALS + 1):
            if np.array_equal(numbers.rounded(wide, decimals).astype(np.float32), values):
                return numbers.table(wide, decimals).decode("ascii")
    return "".join(" ".join(f"{v:.9g}" for v in row) + "\n" for row in wide.tolist())
