"""CalculiX input decks of the experiment (ccx 2.20 keywords; units um, uN, MPa).

Two decks per tube: the inflation alone (to place the probe and the plate on the inflated
wall, as the shell model does, src/fe/forward.cpp), then inflation and indentation. *ELASTIC
under NLGEOM is Saint Venant-Kirchhoff (Hooke's law of the Green-Lagrange strain for the second
Piola-Kirchhoff stress), the law of `growthuq indent --law stvk`. Pressure under NLGEOM follows
the deformed face (a follower load). The probe and the plate are held rigid by prescribing
every one of their nodes; the probe's force is the total reaction of its nodes.
"""
from dataclasses import dataclass

import numpy as np


@dataclass
class Wall:
    E: float          # Young's modulus [MPa]
    nu: float
    p: float          # turgor [MPa]


@dataclass
class Contact:
    method: str = "SURFACE TO SURFACE"   # or "NODE TO SURFACE"
    stiffness: float = 100.0             # penalty slope K in units of E / h0 (pressure per overclosure)
    probe_slave: bool = True             # the probe's faces slave to the wall's (solid.py)
    tension: float = 2.5e-3              # node to surface: sigma_inf in units of E


def _lines(ids, per_line=12):
    ids = list(ids)
    return "\n".join(", ".join(str(i) for i in ids[k:k + per_line]) for k in range(0, len(ids), per_line))


def element_ids(mesh):
    """Global element numbers per set, in the order the deck writes them."""
    numbers, next_id = {}, 1
    for name, elements in mesh.elements.items():
        numbers[name] = list(range(next_id, next_id + len(elements)))
        next_id += len(elements)
    return numbers


def write(path, mesh, node_sets, wall, h0, pressed, surfaces, contact, probe_move, increments=50, wall_element="C3D20",
          indent=True, end_pair=None, equations=()):
    """A deck: the mesh, `node_sets` (name -> node ids), the wall's law, the mirror and end
    conditions (without `end_pair`, the set END pinned; with it, END held in z only, the
    study's driver's z-symmetry end face, and the mean x of the two nodes of `end_pair`, on the
    mirror plane at opposite sides of the tube, held); `equations`: (node, component, [(node,
    coefficient)]), the node's displacement component the sum of the others' (geometry.transition); step 1 inflates (turgor on face 1 of the `pressed` elements, the inner wall's), step 2
    moves the probe's nodes by `probe_move` in -x (left out without `indent`). `surfaces`: (slave, master) pairs of
    (name, [(element id, face)])."""
    numbers = element_ids(mesh)
    out = ["*HEADING", "growthuq tools/solid: pollen tube indentation, half model", "*NODE, NSET=NALL"]
    out += [f"{n + 1}, {x[0]:.10g}, {x[1]:.10g}, {x[2]:.10g}" for n, x in enumerate(mesh.coordinates)]
    for name, elements in mesh.elements.items():
        kind = wall_element if name == "WALL" else elements[0][0]
        out.append(f"*ELEMENT, TYPE={kind}, ELSET={name}")
        for number, (_, nodes) in zip(numbers[name], elements):
            # ccx reads at most 16 entries per line: the 20-node brick continues on a second line.
            out.append(", ".join(str(v) for v in [number] + nodes[:15]) + ("," if len(nodes) > 15 else ""))
            if len(nodes) > 15:
                out.append(", ".join(str(v) for v in nodes[15:]))
    for name, ids in node_sets.items():
        out += [f"*NSET, NSET={name}", _lines(ids)]
    out += ["*MATERIAL, NAME=WALLMAT", "*ELASTIC", f"{wall.E:.10g}, {wall.nu:.10g}",
            # The rigid bodies' elements carry no free degree of freedom; any stiffness will do.
            "*MATERIAL, NAME=RIGIDMAT", "*ELASTIC", f"{1000 * wall.E:.10g}, 0.3"]
    for name in mesh.elements:
        out += [f"*SOLID SECTION, ELSET={name}, MATERIAL={'WALLMAT' if name in ('WALL', 'APEX') else 'RIGIDMAT'}"]
    for slave, master in surfaces:
        for surface_name, faces in (slave, master):
            out += [f"*SURFACE, NAME={surface_name}, TYPE=ELEMENT"]
            out += [f"{e}, S{f}" for e, f in faces]
    for slave, master in surfaces:
        out += [f"*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE={contact.method}", f"{slave[0]}, {master[0]}"]
    slope = contact.stiffness * wall.E / h0
    out += ["*SURFACE INTERACTION, NAME=FRICTIONLESS", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
                # K; the tension at large clearance (node to surface only), a small fraction of the
                # contact pressure under the probe (of order E); 1e-6 E was tried first (README).
            f"{slope:.6g}, {contact.tension * wall.E:.6g}"]
    out += ["*BOUNDARY", "MIRROR, 2, 2", "END, 1, 3" if end_pair is None else "END, 3, 3", "PROBEN, 1, 3", "PLATEN, 1, 3"]
    if end_pair is not None:
        # The z-symmetry end face and the mirror plane leave the tube free to slide in x (the
        # plate is clear of it during the inflation): u_x of the end face's two mirror nodes
        # sum to zero, which a uniform inflation satisfies and a translation does not.
        out += ["*EQUATION", "2", f"{end_pair[0]}, 1, 1., {end_pair[1]}, 1, 1."]
    for node, dof, terms in equations:
        entries = [(node, 1.0)] + [(n, -c) for n, c in terms]
        # ccx reads at most 12 entries, 4 terms, per line.
        out += ["*EQUATION", str(len(entries))]
        out += [", ".join(f"{n}, {dof}, {c:.10g}" for n, c in entries[k:k + 4]) for k in range(0, len(entries), 4)]
    out += ["*STEP, NLGEOM, INC=1000", "*STATIC", "0.25, 1.0, 1e-4, 0.5", "*DLOAD"]
    out += [f"{e}, P1, {wall.p:.10g}" for e in pressed]
    out += ["*NODE PRINT, NSET=REPORT", "U", "*END STEP"]
    if not indent:
        with open(path, "w") as f:
            f.write("\n".join(out) + "\n")
        return numbers
    first = 1.0 / increments
    out += ["*STEP, NLGEOM, INC=2000", "*STATIC", f"{first:.6g}, 1.0, {first * 1e-4:.6g}, {first:.6g}",
            # Converged on the force residual (0.5 % of the mean force, ccx's default) alone: in an
            # increment where the probe barely moves, one contact node switching makes the
            # correction a large fraction of a tiny increment, and the default 1 % test on it
            # cut the increment four times at a residual of 1e-5 of the mean force.
            "*CONTROLS, PARAMETERS=FIELD", "0.005, 1.0",
            # Contact iterations: more of them before an increment is judged divergent and cut
            # (ccx's defaults, 4 and 8, cut increments to 1/256 of the step).
            "*CONTROLS, PARAMETERS=TIME INCREMENTATION", "16, 24, 9, 200, 10, 4, , 20",
            "*BOUNDARY", f"PROBEN, 1, 1, {-probe_move:.10g}",
            "*NODE PRINT, NSET=PROBEN, TOTALS=ONLY", "RF",
            # The wall's nodes through its thickness under the probe: how much it is squeezed.
            "*NODE PRINT, NSET=AXIS", "U", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return numbers


def read_dat(path):
    """Blocks of a .dat file: list of (quantity, set, time, rows as float arrays)."""
    blocks, current = [], None
    with open(path) as f:
        for line in f:
            words = line.split()
            if " for set " in line and " and time " in line:
                quantity = line.split("(")[0].strip()
                name = line.split(" for set ")[1].split()[0]
                current = (quantity, name, float(words[-1]), [])
                blocks.append(current)
            elif current is not None and words:
                try:
                    current[3].append(np.array([float(w) for w in words]))
                except ValueError:
                    current = None
    return blocks
