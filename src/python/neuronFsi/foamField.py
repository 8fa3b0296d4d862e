"""OpenFOAM field files of our runs: the internal field of a volField
written in ascii (a nonuniform List<scalar> or List<vector>), and a
pointField (constant/polyMesh/points, <time>/polyMesh/points) in ascii or
binary."""

import re

import numpy as np

from . import options


class FieldError(Exception):
    """A field file that is not what is asked; the message names it."""


def _readable(path):
    """A FieldError naming path when it is no regular file (a FIFO, a
    device: read without end) or beyond a field file's sane size
    (options.readRefusal, TABLE_LIMIT)."""
    refusal = options.readRefusal(path, options.TABLE_LIMIT, "field file")
    if refusal:
        raise FieldError(refusal)


def internalField(path):
    """The internal field of a volField file, ascii or binary: an array
    of n values (scalar) or n x 3 (vector)."""
    _readable(path)
    with open(path, "rb") as f:
        raw = f.read()
    head = raw[:raw.index(b"}") + 1].decode(errors="replace")
    if re.search(r"format\s+binary", head):
        m = re.search(rb"internalField\s+nonuniform\s+List<(\w+)>\s*"
                      rb"(\d+)\s*\(", raw)
        if m is None:
            raise FieldError(f"{path}: no nonuniform internalField")
        kind, n = m.group(1).decode(), int(m.group(2))
        width = {"scalar": 1, "vector": 3}.get(kind)
        if width is None:
            raise FieldError(f"{path}: internalField of {kind}: scalar or "
                             "vector wanted")
        data = raw[m.end():m.end() + 8*width*n]
        if len(data) != 8*width*n:
            raise FieldError(f"{path}: internalField cut short ({len(data)} "
                             f"of {8*width*n} bytes)")
        v = np.frombuffer(data, dtype="<f8")
        return v.copy() if width == 1 else v.reshape(n, 3).copy()
    s = raw.decode()
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*\n?(\d+)\s*"
                  r"\n?\(\n(.*?)\n\)", s, re.S)
    if m is None:
        raise FieldError(f"{path}: no ascii nonuniform internalField")
    kind, body = m.group(1), m.group(3)
    if kind == "scalar":
        return np.array(body.split(), float)
    if kind == "vector":
        return np.array([line.strip("()").split()
                         for line in body.split("\n")], float)
    raise FieldError(f"{path}: internalField of {kind}: scalar or vector "
                     "wanted")


def points(path):
    """The points of a pointField file, n x 3, ascii or binary."""
    _readable(path)
    with open(path, "rb") as f:
        raw = f.read()
    head = raw[:raw.index(b"}") + 1].decode()
    m = re.search(rb"\n(\d+)\s*\(", raw[len(head):])
    n = int(m.group(1))
    start = len(head) + m.end()
    if re.search(r"format\s+binary", head):
        return np.frombuffer(raw[start:start + 24*n],
                             dtype="<f8").reshape(n, 3)
    body = raw[start:].decode()
    pts = re.findall(r"\(([^()]*)\)", body)[:n]
    return np.array([[float(v) for v in q.split()] for q in pts])
