"""One tube in CalculiX: inflate, place the probe and the plate, indent; the force curve, the
turgid diameter and k over the instrument's window, read as the shell model reads them."""
import filecmp
import os
import subprocess
import time
from dataclasses import dataclass

import numpy as np

from deck import Wall, element_ids, read_dat, write
from far_field import stvk_stretches
from geometry import Tube, plate, probe, wall
from mesh import Mesh
from results import inflated_position, node_count, probe_forces, read_run
from window import fit_force_window


@dataclass
class Case:
    p: float          # turgor [MPa]
    E: float          # [MPa]
    h0: float         # unstressed wall thickness [um]
    d0: float         # unstressed mid-surface diameter [um]
    rho: float        # probe radius [um]
    nu: float = 0.2
    length: float = 100.0
    behind_apex: float = 10.0
    end: str = "pinned"  # the distal end: "pinned" (the mid-surface ring, as the shell's edge) or "zsym" (README.md)


class SolidTimeout(RuntimeError):
    """A ccx run stopped after its allotted wall time (a wall that collapses under the probe can
    cut its increments for hours, README.md); `seconds`: that time, `deck`: the run's base path."""

    def __init__(self, message, seconds, deck):
        super().__init__(message)
        self.seconds, self.deck = seconds, deck


STOPPED = "stopped by tools/solid/solid.py: the probe's force passed"
TIMED_OUT = "stopped by tools/solid/solid.py after its timeout of"


def run_ccx(deck_base, threads=1, timeout=None, niceness=15, stop_force=None):
    """Runs ccx on deck_base.inp in its directory, under `nice -n niceness`; returns the wall
    time in s. Stops it and raises SolidTimeout after `timeout` s. With `stop_force` [uN, whole
    tube], ccx is also stopped, as a finished run, once the probe's force in its .dat passes it
    (`run_until_force`)."""
    if stop_force is not None:
        return run_until_force(deck_base, stop_force, threads, timeout, niceness)
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), CCX_NPROC_STIFFNESS=str(threads))
    start = time.monotonic()
    folder, name = os.path.split(deck_base)
    try:
        result = subprocess.run(["nice", "-n", str(niceness), "ccx", "-i", name], cwd=folder or ".", env=env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout)
    except subprocess.TimeoutExpired as expired:
        with open(deck_base + ".log", "w") as f:  # what ccx said, and that it was stopped (`solve`)
            f.write((expired.stdout or b"").decode(errors="replace") + f"\n{TIMED_OUT} {timeout:.0f} s\n")
        raise SolidTimeout(f"ccx stopped after {timeout:.0f} s on {deck_base}.inp", timeout, deck_base) from None
    with open(deck_base + ".log", "w") as f:
        f.write(result.stdout)
    if result.returncode != 0 or "*ERROR" in result.stdout:
        lines = [l for l in result.stdout.splitlines() if "ERROR" in l]
        raise RuntimeError(f"ccx failed on {deck_base}.inp: {lines[:3]} (log {deck_base}.log)")
    return time.monotonic() - start


def probe_force(dat):
    """The largest force on the probe [uN, whole tube] in a ccx .dat so far (0 before any)."""
    forces = [f for _, f in probe_forces(read_dat(dat))] if os.path.exists(dat) else []
    return max(forces, default=0.0)


def run_until_force(deck_base, stop_force, threads=1, timeout=None, niceness=15, poll=2.0):
    """run_ccx that stops ccx once the probe's force passes `stop_force`: past the window's top
    the curve is not read, and a St-VK wall can collapse under the probe there and cut its
    increments for as long as it is let (README.md, "Results"). The log ends with a line that
    says so, which `solve` takes as a finished run."""
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), CCX_NPROC_STIFFNESS=str(threads))
    start = time.monotonic()
    folder, name = os.path.split(deck_base)
    with open(deck_base + ".log", "w") as log:
        ccx = subprocess.Popen(["nice", "-n", str(niceness), "ccx", "-i", name], cwd=folder or ".", env=env,
                               stdout=log, stderr=subprocess.STDOUT)
        while ccx.poll() is None:
            time.sleep(poll)
            if timeout is not None and time.monotonic() - start > timeout:
                ccx.kill()
                ccx.wait()
                log.write(f"\n{TIMED_OUT} {timeout:.0f} s\n")
                raise SolidTimeout(f"ccx stopped after {timeout:.0f} s on {deck_base}.inp", timeout, deck_base)
            force = probe_force(deck_base + ".dat")
            if force >= stop_force:
                ccx.kill()
                ccx.wait()
                seconds = time.monotonic() - start
                log.write(f"\n{STOPPED} {stop_force:g} uN ({force:.4g} uN) after {seconds:.1f} s\n")
                return seconds
    text = open(deck_base + ".log").read()
    if ccx.returncode != 0 or "*ERROR" in text:
        lines = [l for l in text.splitlines() if "ERROR" in l]
        raise RuntimeError(f"ccx failed on {deck_base}.inp: {lines[:3]} (log {deck_base}.log)")
    return time.monotonic() - start


def solve(base, reuse=False, timeout=None, niceness=15, stop_force=None):
    """ccx on the deck just written to base.new.inp, which becomes base.inp (run_ccx); returns
    the wall time in s. With `reuse`, when base.inp is that same deck and base.log ends a
    finished run (or one stopped at the force, `run_until_force`), the run is read, not
    repeated, and the time is the one its log gives (ccx's own total, or the stop's); one its
    timeout stopped raises SolidTimeout again, its files left to be read as far as it went."""
    fresh = base + ".new.inp"
    if reuse and os.path.exists(base + ".inp") and filecmp.cmp(fresh, base + ".inp", shallow=False):
        logged = open(base + ".log").read().splitlines() if os.path.exists(base + ".log") else []
        total = [l for l in logged if "Total CalculiX Time" in l]
        stopped = [l for l in logged if l.startswith(STOPPED)]
        timed_out = [l for l in logged if l.startswith(TIMED_OUT)]
        if timed_out and not (total or stopped):
            os.remove(fresh)
            seconds = float(timed_out[-1].split()[-2])
            raise SolidTimeout(f"ccx stopped after {seconds:.0f} s on {base}.inp (read from its log)", seconds, base)
        if total or stopped:
            os.remove(fresh)
            return float(total[-1].split(":")[1]) if total else float(stopped[-1].split()[-2])
    os.replace(fresh, base + ".inp")
    return run_ccx(base, timeout=timeout, niceness=niceness, stop_force=stop_force)


def _experiment(case, res, contact, depth, z_ref, centre, plate_x, with_probe):
    """The mesh, node sets, contact surfaces and pressed elements of one deck: the wall graded
    towards the line theta = 0, s = z_ref; the probe's cap centred at `centre`, the plate's
    top at x = plate_x. Without `with_probe` the probe's contact pair is left out (the
    inflation pass that finds where the graded line lies once inflated)."""
    r0 = case.d0 / 2
    mesh = Mesh()
    theta, s, t, outer_faces, inner_wall, inner_apex, transition = wall(mesh, Tube(case.d0, case.h0, case.length, z_ref),
                                                                        res)
    probe_faces = probe(mesh, centre, case.rho, cells=res.probe_cells)
    reach = 2 * case.rho + 2 * case.h0 + depth + 0.5  # the patch the probe can touch
    # The plate stays where it is put while the tube stretches along its axis (by up to 11 % on
    # the tubes of tubes.csv), so it is centred on the probe's axis as placed on the inflated
    # tube, not on the wall's reference line z_ref, and runs past the apex if need be: the
    # tube's bottom presses on it up to about 5 um beyond the probe (the shell's contact on
    # study_stretch at 0.79 um). Centred on z_ref and cut at the reference length, it ended
    # behind the probe on the stretched tubes, whose tips then tipped over its edge (README.md).
    plate_faces = plate(mesh, plate_x, (-0.5, 0.5 * r0), (centre[2] - 4 * case.d0, centre[2] + 4 * case.d0), (2, 24))
    j_mid = 2 * int(np.argmin(np.abs(s - case.length / 2)))
    j_probe = 2 * int(np.argmin(np.abs(s - z_ref)))
    th = np.repeat(theta, 2)[1:]
    key_of = {n: key for key, n in mesh.ids.items()}
    sets = {"MIRROR": [], "END": [], "MIDRING": [], "UNDER": [], "AXIS": []}
    last_i = len(th) - 1
    for n, key in key_of.items():
        if key[0] == "apex":
            sets["MIRROR"].append(n)
        if key[0] != "wall":
            continue
        _, i, j, k = key
        if i in (0, len(th) - 1):
            sets["MIRROR"].append(n)
        if j == 0 and (k == res.layers if case.end == "pinned" else True):
            # pinned: the mid-surface ring, the shell's pinned edge; zsym: the whole end face
            sets["END"].append(n)
        if j == j_mid and k == res.layers:
            sets["MIDRING"].append(n)
        if i == 0 and j == j_probe:
            sets["AXIS"].append(n)  # through the wall under the probe: its thickness (results.py)
        if k == 2 * res.layers and r0 * th[i] < reach and abs(mesh.coordinates[n - 1][2] - z_ref) < reach:
            sets["UNDER"].append(n)
    sets["REPORT"] = sorted(sets["MIDRING"] + sets["UNDER"])
    sets["PROBEN"] = [n for k, n in mesh.ids.items() if k[0] == "probe"]
    sets["PLATEN"] = [n for k, n in mesh.ids.items() if k[0] == "plate"]
    numbers = element_ids(mesh)
    centre_of = lambda a, b: (r0 * 0.5 * (theta[a] + theta[a + 1]), 0.5 * (s[b] + s[b + 1]))
    top = [(numbers["WALL"][e], 2) for (a, b), e in outer_faces.items()
           if centre_of(a, b)[0] < reach and abs(centre_of(a, b)[1] - z_ref) < reach]
    bottom = [(numbers["WALL"][e], 2) for (a, b), e in outer_faces.items()
              if theta[a] > 0.75 * np.pi and abs(centre_of(a, b)[1] - z_ref) < 4 * case.d0]
    probe_surface = ("PROBESURF", [(numbers["PROBE"][e], 2) for e in probe_faces.values()])
    # Which side is slave: README.md, "Contact" (the wall's faces as slaves of the small cap
    # paired far faces with it under surface to surface).
    top_pair = (probe_surface, ("TUBETOP", top)) if contact.probe_slave else (("TUBETOP", top), probe_surface)
    surfaces = [(("TUBEBOTTOM", bottom), ("PLATESURF", [(numbers["PLATE"][e], 2) for e in plate_faces.values()]))]
    if with_probe:
        surfaces.insert(0, top_pair)
    pressed = [numbers["WALL"][e] for e in inner_wall] + [numbers["APEX"][e] for e in inner_apex]
    axis_outer = mesh.ids[("wall", 0, j_probe, 2 * res.layers)]
    # zsym: the end face's two inner nodes on the mirror plane (theta 0 and pi), whose mean x
    # the deck holds (deck.py, `end_pair`).
    end_pair = (mesh.ids[("wall", 0, 0, 0)], mesh.ids[("wall", last_i, 0, 0)]) if case.end == "zsym" else None
    # The band's nodes tied to the far bricks (geometry.transition), each component; u_y of a
    # node on the mirror plane is held there already.
    mirror = set(sets["MIRROR"])
    equations = [(mesh.ids[node], dof, [(mesh.ids[n], c) for n, c in terms]) for node, terms in transition
                 for dof in (1, 2, 3) if not (dof == 2 and mesh.ids[node] in mirror)]
    return mesh, sets, surfaces, pressed, axis_outer, end_pair, equations


def simulate(case, res, contact, depth, folder, increments=32, clearance=0.01, probe_clearance=0.02, timeout=None,
             niceness=15, reuse=False, stop_force=None):
    """Inflation, then the probe moved `depth` [um] past first touch in -x. Two ccx runs: the
    inflation alone, which gives where the wall's finest line (under the probe) lies once
    inflated, then inflation and indentation with the probe's axis on that point,
    `probe_clearance` um clear of it. The plate is placed `clearance` um clear of the far
    field's inflated wall (far_field.py), so that nothing touches during the inflation; the
    shell's plane touches its lowest node, and the wall reaches the plate within the
    indentation's first hundredth of a um, at a force of order 1e-5 uN (k without the
    substrate, src/fe/README.md), so k does not see the difference. The depth is counted from first touch, measured on the inflated wall. Returns a
    dict: turgid diameter d [um], depth and force curves [um, uN, whole tube], the window fit
    (k [N/m] over 0.4-4 uN), the node count and the run time [s] of both runs. Each ccx run is
    stopped after `timeout` s (SolidTimeout) and runs under `nice -n niceness`; with `reuse`, a
    run already finished in `folder` on the same deck is read instead (`solve`); with
    `stop_force` [uN], the indentation's ccx run is stopped once the probe's force passes it."""
    os.makedirs(folder, exist_ok=True)
    r0 = case.d0 / 2
    hoop, axial, thickness = stvk_stretches(case.p / case.E, case.h0 / case.d0, case.nu)
    outer_radius = hoop * r0 + thickness * case.h0 / 2
    # The inflated apex, estimated with the cap stretched as the hoop, 10 um behind it; the
    # wall's grid is graded towards the point that the far field's axial stretch would carry
    # there. The pinned end's boundary layer stretches the tube less (by 0.25 um over 90 um on
    # the wild-type-like tube, as much as the probe's radius), so the probe goes where that
    # point actually lies after the inflation, found by running the inflation alone first.
    z_axis = axial * (case.length - r0) + hoop * r0 - case.behind_apex
    z_ref = z_axis / axial
    wall_law = Wall(case.E, case.nu, case.p)
    plate_x = -outer_radius - clearance

    far = np.array([outer_radius + 1.0 + case.rho, 0.0, z_axis])  # 1 um clear: no contact
    mesh, sets, surfaces, pressed, axis_outer, end_pair, equations = _experiment(case, res, contact, depth, z_ref, far,
                                                                                 plate_x, False)
    base = os.path.join(folder, "inflate")
    write(base + ".new.inp", mesh, sets, wall_law, case.h0, pressed, surfaces, contact, probe_move=0.0,
          wall_element=res.element, indent=False, end_pair=end_pair, equations=equations)
    seconds = solve(base, reuse, timeout, niceness)
    x = inflated_position(base, axis_outer)

    centre = np.array([x[0] + probe_clearance + case.rho, 0.0, x[2]])
    mesh, sets, surfaces, pressed, _, end_pair, equations = _experiment(case, res, contact, depth, z_ref, centre, plate_x,
                                                                        True)
    base = os.path.join(folder, "indent")
    write(base + ".new.inp", mesh, sets, wall_law, case.h0, pressed, surfaces, contact,
          probe_move=depth + probe_clearance, increments=increments, wall_element=res.element, end_pair=end_pair,
          equations=equations)
    seconds += solve(base, reuse, timeout, niceness, stop_force)

    return indentation_run(base, case.rho, seconds)


def indentation_run(base, rho, seconds):
    """The indentation run `base`.inp/.dat as `simulate` returns it, read as far as it went."""
    d, depths, forces = read_run(base, rho)
    return {"d": d, "depth": depths, "force": forces, "fit": fit_force_window(depths, forces, 0.4, 4.0),
            "nodes": node_count(base), "seconds": seconds}
