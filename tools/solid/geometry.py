"""The experiment's bodies as quadratic bricks: the half tube (wall), the probe and the plate.

The tube's grid is graded towards the line under the probe (theta = 0, z = z_probe); the finest
in-plane cell is `finest` um there, growing by `ratio` per cell. The probe and the plate are
rigid bodies in the deck (ccx_input.py); only their contact faces matter.
"""
from dataclasses import dataclass

import numpy as np

from mesh import block, graded, with_midpoints


@dataclass
class Tube:
    d0: float          # unstressed mid-surface diameter [um]
    h0: float          # unstressed wall thickness [um]
    length: float      # mid-surface length, tip included [um]
    z_probe: float     # height of the probe's axis, reference configuration [um]


@dataclass
class Resolution:
    layers: int        # bricks through the wall
    finest: float      # in-plane cell under the probe [um]
    ratio: float = 1.4
    coarsest_angle: float = np.pi / 6
    coarsest_length: float = 8.0
    probe_cells: int = 24      # cells over the probe's half circle at its finest: finer than the wall's (slave side)
    element: str = "C3D20"     # or C3D20R
    # Fewer bricks through the wall away from the probe, as the study's driver meshed: half of
    # `layers` farther than `band_um` along the tube from the probe's line (0: `layers` everywhere).
    far_layers: int = 0
    band_um: float = 0.0


def wall_position(tube):
    """xyz of the point at (theta, s, t) of the tube's wall."""
    r0 = tube.d0 / 2
    cylinder = tube.length - r0

    def position(theta, s, t):
        if s <= cylinder:
            radius, z = r0 + t, s
        else:
            phi = (s - cylinder) / r0
            radius, z = (r0 + t) * np.cos(phi), cylinder + (r0 + t) * np.sin(phi)
        return np.array([radius * np.cos(theta), radius * np.sin(theta), z])
    return position


def wall(mesh, tube, res):
    """The tube's bricks (set WALL) and the apex's wedges (set APEX). Returns the grids theta,
    s, t (corners), the WALL element of the outer face per (theta cell, s cell), for the contact
    surfaces, the WALL and APEX elements whose face 1 is the inner wall, for the turgor, and the
    equations that tie the band's bricks to the far ones (`transition`; none without
    res.far_layers). A node's key is ("wall", i, j, k), its indices along theta, s and t counting
    midpoints, k counted over the band's `layers` bricks: a far brick's node has the key of the
    band's node at its place."""
    r0 = tube.d0 / 2
    apex = tube.length - r0 + np.pi * r0 / 2
    theta = graded(0.0, np.pi, 0.0, res.finest / r0, res.ratio, res.coarsest_angle)
    s = graded(0.0, apex, tube.z_probe, res.finest, res.ratio, res.coarsest_length)
    t = np.linspace(-tube.h0 / 2, tube.h0 / 2, res.layers + 1)
    position = wall_position(tube)
    far = res.far_layers or res.layers
    equations = []
    if far == res.layers:
        outer, inner = block(mesh, "WALL", "wall", theta, s[:-1], t, position)
    else:
        if res.layers != 2 * far:
            raise ValueError(f"far_layers {far}: expected half of layers ({res.layers})")
        # The band: the s cells within band_um of the probe's line, all around the tube.
        j_lo = int(np.searchsorted(s, tube.z_probe - res.band_um, side="right")) - 1
        j_hi = int(np.searchsorted(s, tube.z_probe + res.band_um, side="left"))
        if j_lo < 1 or j_hi > len(s) - 3:
            raise ValueError(f"band_um {res.band_um}: the band reaches the tube's end or its apex")
        outer, inner = {}, {}
        for j0, j1, n in ((0, j_lo, far), (j_lo, j_hi, res.layers), (j_hi, len(s) - 2, far)):
            scale = res.layers // n
            o, i_ = block(mesh, "WALL", "wall", theta, s[j0:j1 + 1], np.linspace(-tube.h0 / 2, tube.h0 / 2, n + 1),
                          position, index=lambda i, j, k, j0=j0, scale=scale: (i, j + 2 * j0, k * scale))
            outer.update({(a, b + j0): e for (a, b), e in o.items()})
            inner.update({(a, b + j0): e for (a, b), e in i_.items()})
        equations = transition(len(theta), far, (2 * j_lo, 2 * j_hi))
    # The last ring: wedges with the apex as their third corner (the theta lines meet there).
    scale = res.layers // far
    tt, th = with_midpoints(np.linspace(-tube.h0 / 2, tube.h0 / 2, far + 1)), with_midpoints(theta)
    j = 2 * (len(s) - 2)
    s_mid = 0.5 * (s[-2] + s[-1])
    key = lambda i, jj, k: ("wall", i, jj, k)
    for a in range(len(theta) - 1):
        for c in range(far):
            def n(i, jj, k):
                return mesh.node(key(2 * a + i, j + jj, scale * (2 * c + k)),
                                 position(th[2 * a + i], s[-2] if jj == 0 else s_mid, tt[2 * c + k]))
            def pole(k):
                return mesh.node(("apex", scale * (2 * c + k)), position(0.0, apex, tt[2 * c + k]))
            nodes = [n(0, 0, 0), n(2, 0, 0), pole(0), n(0, 0, 2), n(2, 0, 2), pole(2),
                     n(1, 0, 0), n(2, 1, 0), n(0, 1, 0), n(1, 0, 2), n(2, 1, 2), n(0, 1, 2),
                     n(0, 0, 1), n(2, 0, 1), pole(1)]
            mesh.add("APEX", "C3D15", nodes)
    apex_inner = [e for e in range(len(mesh.elements["APEX"])) if e % far == 0]
    return theta, s, t, outer, sorted(inner.values()), apex_inner, equations


def transition(corners, far, rings):
    """Where the band's 2 bricks per far brick meet the far brick (the rings at s indices
    `rings`), the band's nodes that the far brick lacks follow its quadratic field on their
    shared face, so the two meshes stay conforming: on a line through the wall at a corner of
    the theta grid (even i), the far brick's three nodes there give the band's at zeta = -1/2
    and 1/2; in the middle of a theta cell (odd i), the far face's eight nodes give its
    serendipity value at the centre. Returns (dependent key, [(key, coefficient)]) per node,
    for every displacement component (deck.py)."""
    out = []
    for j in rings:
        for c in range(far):
            k = 4 * c  # the far brick's nodes through the wall: k, k + 2, k + 4
            for i in range(2 * (corners - 1) + 1):
                def node(ii, kk):
                    return ("wall", ii, j, kk)
                if i % 2 == 0:
                    line = [node(i, k), node(i, k + 2), node(i, k + 4)]
                    out.append((node(i, k + 1), list(zip(line, (0.375, 0.75, -0.125)))))
                    out.append((node(i, k + 3), list(zip(line, (-0.125, 0.75, 0.375)))))
                else:
                    face_corners = [node(i - 1, k), node(i + 1, k), node(i - 1, k + 4), node(i + 1, k + 4)]
                    middles = [node(i, k), node(i, k + 4), node(i - 1, k + 2), node(i + 1, k + 2)]
                    out.append((node(i, k + 2), [(n, -0.25) for n in face_corners] + [(n, 0.5) for n in middles]))
    return out


def probe(mesh, centre, rho, cells):
    """The probe's cap facing -x, 69 degrees around the point it first touches, as one layer of
    bricks (set PROBE) from 0.8 rho to rho, graded towards that point; returns the outer face's
    element indices. The contact patch at the window's top stays well inside it (the shell's
    contact radius there is below 0.8 rho)."""
    psi = graded(np.pi / 2 - 1.2, np.pi / 2 + 1.2, np.pi / 2, np.pi / cells, 1.2, np.pi / 8)
    omega = graded(np.pi - 1.2, np.pi + 1.2, np.pi, np.pi / cells, 1.2, np.pi / 8)

    def position(a, b, r):  # (psi, omega, r) is right-handed: e_psi x e_omega = e_r
        return centre + r * np.array([np.sin(a) * np.cos(b), np.sin(a) * np.sin(b), np.cos(a)])
    return block(mesh, "PROBE", "probe", psi, omega, np.array([0.8 * rho, rho]), position)[0]


def plate(mesh, x_top, y_range, z_range, cells):
    """The substrate, a flat plate of linear bricks (set PLATE) whose top face is x = x_top."""
    y = np.linspace(*y_range, cells[0] + 1)
    z = np.linspace(*z_range, cells[1] + 1)
    x = np.array([x_top - 0.5, x_top])
    return block(mesh, "PLATE", "plate", y, z, x, lambda a, b, c: np.array([c, a, b]), kind="C3D8")[0]
