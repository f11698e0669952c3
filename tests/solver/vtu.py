"""A reader for the .vtu pieces and .pvtu records deal.II writes (VTK XML,
binary, zlib-compressed, UInt32 block headers), for the tests that read the
output back. Only the standard library: no VTK on the test machines."""
import base64
import math
import os
import re
import struct
import zlib

_TYPES = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt32": "I",
          "Int64": "q", "UInt64": "Q", "UInt8": "B", "Int8": "b"}


def _decode(text, kind):
    """The values of one binary DataArray: base64 of the header
    [blocks, block size, last block size, compressed sizes...], then base64
    of the compressed blocks."""
    text = text.strip()
    first = base64.b64decode(text[:24])
    blocks = struct.unpack("<I", first[:4])[0]
    header_bytes = 4 * (3 + blocks)
    header_chars = 4 * ((header_bytes + 2) // 3)
    header = struct.unpack("<%dI" % (3 + blocks), base64.b64decode(text[:header_chars]))
    data = base64.b64decode(text[header_chars:])
    raw, offset = b"", 0
    for size in header[3:]:
        raw += zlib.decompress(data[offset:offset + size])
        offset += size
    code = _TYPES[kind]
    return list(struct.unpack("<%d%s" % (len(raw) // struct.calcsize(code), code), raw))


class Piece:
    """One .vtu piece: the PointData tag (header), points (x, y, z), cells
    (lists of point indices) and point data by name (lists of tuples of
    NumberOfComponents values)."""

    def __init__(self, path):
        with open(path, "rb") as f:
            text = f.read().decode("latin1")
        tag = re.search(r"<PointData[^>]*>", text)
        self.header = tag.group(0) if tag else ""
        self.arrays = {}
        for m in re.finditer(r'<DataArray type="(\w+)"([^>]*)>([^<]*)</DataArray>', text):
            kind, attributes, body = m.groups()
            name = re.search(r'Name="([^"]*)"', attributes)
            components = re.search(r'NumberOfComponents="(\d+)"', attributes)
            n = int(components.group(1)) if components else 1
            if 'format="ascii"' in attributes:
                values = [float(v) for v in body.split()]
            else:
                values = _decode(body, kind)
            key = name.group(1) if name else "Points"
            if key in self.arrays:  # the cells' arrays come after the points
                key = key + "_" + str(len(self.arrays))
            self.arrays[key] = [tuple(values[i:i + n]) for i in range(0, len(values), n)]
        self.points = self.arrays.pop("Points")
        connectivity = [v[0] for v in self.arrays.pop("connectivity")]
        offsets = [v[0] for v in self.arrays.pop("offsets")]
        self.arrays.pop("types", None)
        self.cells, start = [], 0
        for end in offsets:
            self.cells.append(connectivity[start:end])
            start = end

    def __getitem__(self, name):
        return self.arrays[name]


def read_record(path):
    """A .pvtu record: its header text (up to the first piece) and the
    pieces it lists, read."""
    with open(path) as f:
        text = f.read()
    directory = os.path.dirname(path)
    pieces = [Piece(os.path.join(directory, p))
              for p in re.findall(r'<Piece Source="([^"]*)"', text)]
    return text, pieces


def norm(v):
    return math.sqrt(sum(x * x for x in v))
