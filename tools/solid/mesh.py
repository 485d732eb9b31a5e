"""Quadratic brick meshes of the indentation experiment: the half tube, the probe and the plate.

Lengths in um. The tube is the shell model's (src/fe/README.md, section 1): a cylinder of
unstressed mid-surface radius R0 closed by a hemispherical tip, total length L at the
mid-surface, axis z, distal end in z = 0, mirror plane y = 0 (the model keeps y >= 0), probe on
the meridian x > 0. The wall is a structured grid over (theta, s, t): theta the angle from +x,
s the mid-surface meridian's arc length from the end, t the offset from the mid-surface along
its normal; so a brick's faces follow the mid-surface and its thickness is exact. The ring at
the apex, where the theta lines meet, is made of 15-node wedges.

Element node orders and face numbers are CalculiX's (ccx 2.20 manual, C3D20, C3D15, C3D8).
"""
from dataclasses import dataclass, field

import numpy as np


def graded(start, end, focus, finest, ratio, coarsest):
    """Corner coordinates from start to end with a corner at `focus`: cells of size `finest`
    there, growing by `ratio` away from it up to `coarsest`, each side scaled to fit exactly."""
    def side(length):
        sizes, total = [], 0.0
        while total < length * (1 - 1e-9):
            sizes.append(min(finest * ratio ** len(sizes), coarsest))
            total += sizes[-1]
        return np.cumsum(sizes) * (length / total) if sizes else np.zeros(0)
    return np.concatenate([focus - side(focus - start)[::-1], [focus], focus + side(end - focus)])


def with_midpoints(corners):
    """Corner coordinates interleaved with the middle of each cell (the quadratic nodes)."""
    out = np.empty(2 * len(corners) - 1)
    out[0::2] = corners
    out[1::2] = 0.5 * (corners[:-1] + corners[1:])
    return out


@dataclass
class Mesh:
    """Nodes (1-based ids in insertion order) and elements grouped by set name."""
    coordinates: list = field(default_factory=list)
    ids: dict = field(default_factory=dict)
    elements: dict = field(default_factory=dict)   # set name -> list of (type, node ids)
    first_element: dict = field(default_factory=dict)

    def node(self, key, position):
        if key not in self.ids:
            self.coordinates.append(np.asarray(position, dtype=float))
            self.ids[key] = len(self.coordinates)
        return self.ids[key]

    def add(self, name, kind, nodes):
        self.elements.setdefault(name, []).append((kind, list(nodes)))


# Local offsets (in half cells along xi, eta, zeta) of a 20-node brick's nodes, CalculiX's order.
BRICK20 = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2),
           (1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0), (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
           (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1)]
BRICK8 = BRICK20[:8]


def block(mesh, name, tag, u, v, w, position, kind="C3D20", index=None):
    """A structured block over corner coordinates u, v, w (zeta = w: face 1 at w[0], face 2 at
    w[-1]); position(u, v, w) -> xyz must be right-handed in (u, v, w).
    Returns the element grid's (iu, iv) -> element index within the set, for the faces at
    w[-1] (outer) and at w[0] (inner). A node's key is (tag, i, j, k), its indices along u, v, w
    counting midpoints, or (tag,) + index(i, j, k): blocks that share a face share its nodes
    when their indices map to the same keys there."""
    quadratic = kind == "C3D20"
    uu, vv, ww = (with_midpoints(a) for a in (u, v, w)) if quadratic else (u, v, w)
    step = 2 if quadratic else 1
    pattern = BRICK20 if quadratic else BRICK8
    outer, inner = {}, {}
    for a in range(len(u) - 1):
        for b in range(len(v) - 1):
            for c in range(len(w) - 1):
                nodes = []
                for (di, dj, dk) in pattern:
                    i, j, k = (step * a + di // (3 - step), step * b + dj // (3 - step),
                               step * c + dk // (3 - step))
                    key = (tag, i, j, k) if index is None else (tag,) + index(i, j, k)
                    nodes.append(mesh.node(key, position(uu[i], vv[j], ww[k])))
                mesh.add(name, kind, nodes)
                if c == len(w) - 2:
                    outer[(a, b)] = len(mesh.elements[name]) - 1
                if c == 0:
                    inner[(a, b)] = len(mesh.elements[name]) - 1
    return outer, inner
