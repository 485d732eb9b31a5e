"""A ccx run of the experiment read back from its files (deck.py's .inp and ccx's .dat), so a run
can be read while it goes on or after it: the turgid diameter at the end of the inflation, and
the force curve of the indentation from first touch (whole tube: the half model's doubled)."""
import numpy as np

from deck import read_dat


def _inp(path):
    """Node coordinates, node sets and the probe's prescribed move of a deck.py deck."""
    nodes, sets, move, section, name = {}, {}, None, None, None
    for line in open(path):
        if line.startswith("*"):
            words = [w.strip() for w in line.split(",")]
            section = words[0].upper()
            name = words[1].split("=")[1] if section == "*NSET" else None
            continue
        values = [v for v in line.replace(",", " ").split()]
        if section == "*NODE":
            nodes[int(values[0])] = np.array([float(v) for v in values[1:4]])
        elif section == "*NSET":
            sets.setdefault(name, []).extend(int(v) for v in values)
        elif section == "*BOUNDARY" and values[0] == "PROBEN" and len(values) == 4:
            move = -float(values[3])
    return nodes, sets, move


def node_count(base):
    """Nodes of the deck `base`.inp."""
    return len(_inp(base + ".inp")[0])


def inflated_position(base, node):
    """xyz [um] of `node` at the end of the inflation (step 1) of the run `base`.inp/.dat."""
    nodes, _, _ = _inp(base + ".inp")
    inflated = [b for b in read_dat(base + ".dat") if b[0] == "displacements" and b[2] <= 1.0 + 1e-9][-1]
    row = next(r for r in inflated[3] if int(r[0]) == node)
    return nodes[node] + row[1:4]


def probe_forces(blocks):
    """(total time, force on the probe [uN, whole tube: the half model's doubled]) at each
    increment that printed the probe's reaction, from read_dat's blocks."""
    return [(time, -2.0 * rows[0][0]) for _, name, time, rows in blocks if name == "PROBEN" and rows]


def read_run(base, rho):
    """d [um], depth [um] and force [uN] arrays (from first touch) of the run `base`.inp/.dat."""
    nodes, sets, move = _inp(base + ".inp")
    blocks = read_dat(base + ".dat")
    inflated = [b for b in blocks if b[0] == "displacements" and b[2] <= 1.0 + 1e-9][-1]
    x = {int(row[0]): nodes[int(row[0])] + row[1:4] for row in inflated[3]}
    d = 2 * float(np.mean([np.hypot(x[n][0], x[n][1]) for n in sets["MIDRING"]]))
    probe = np.array([nodes[n] for n in sets["PROBEN"]])
    # The probe's cap is centred on its frontmost node, which lies on the probe's axis.
    front = probe[np.argmin(probe[:, 0])]
    centre = front + np.array([rho, 0.0, 0.0])
    lateral = [(x[n], x[n][1] ** 2 + (x[n][2] - centre[2]) ** 2) for n in sets["UNDER"]]
    touch = max(v[0] + np.sqrt(rho ** 2 - l2) for v, l2 in lateral if l2 < rho ** 2)
    gap = centre[0] - touch
    curve = probe_forces(blocks)  # total time: step 2 runs from 1 to 2
    depth = (np.array([t for t, _ in curve]) - 1.0) * move - gap
    force = np.array([f for _, f in curve])
    keep = depth > 0  # the approach before first touch carries no force
    return d, np.concatenate([[0.0], depth[keep]]), np.concatenate([[0.0], force[keep]])


def thickness_under_probe(base):
    """The wall's current thickness under the probe's axis [um] at each increment of the
    indentation (time > 1): the spread in x of the nodes through the wall on the probe's line."""
    nodes, _, _ = _inp(base + ".inp")
    out = []
    for quantity, name, time, rows in read_dat(base + ".dat"):
        if quantity == "displacements" and name == "AXIS" and time > 1.0:
            x = [nodes[int(r[0])][0] + r[1] for r in rows]
            out.append((time, max(x) - min(x)))
    return out
