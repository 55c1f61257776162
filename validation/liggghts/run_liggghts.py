#!/usr/bin/env python3
"""LIGGGHTS side of the DEM cross-check: runs the scenes of scenes.py
(serial, one rank) with the linear spring-dashpot model (hooke/stiffness,
tangential history, absolute damping) and writes

    ../results/liggghts_restitution.csv   scene, e_requested, e_measured,
                                          contact_time_s, wall_time_s, dt_s
                                          (at scenes.DT and at DT/10)
    ../results/liggghts_silo.csv          time_s, discharged_mass_kg
    ../results/liggghts_silo_summary.csv  rate (fit over SILO["fit_window"]
                                          of the charge, and over 20-80 % of
                                          the final discharged mass), Beverloo,
                                          bulk density, wall times, steps
    silo_packing.dat                      settled packing, "x y z radius"

Restitution: e = -(relative normal velocity after)/(before); contact time
from the first to the last step with overlap. Silo: spheres settle on a
closed floor (plane z = 0) until their kinetic energy is below
SILO["settle_ke"]; the plane is then replaced by the STL plate with the
orifice (floor_stl.py); a sphere counts as discharged once its centre is
below z = 0 (it leaves the domain at z = -5 d and is deleted).

Usage (from the project root; needs `liggghts`, see install.sh):

    .venv/bin/python validation/liggghts/run_liggghts.py [restitution] [silo]

Runs go to validation/liggghts/runs/ (git-ignored). Wall times are the
LIGGGHTS loop times ("Loop time" in the log), without start-up.
"""

import csv
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

from floor_stl import plate_with_hole, write_stl
from scenes import (DENSITY, DIAMETER, DT, EFFECTIVE_MASS, GAP, GRAVITY, HEAD_ON,
                    LIMIT_FORCE, MASS, RADIUS, RESTITUTIONS, SILO, WALL, beverloo,
                    contact, contact_time, damping)

HERE = Path(__file__).resolve().parent
RUNS = HERE / "runs"
RESULTS = HERE.parent / "results"

MODEL = "model hooke/stiffness tangential history"
OPTIONS = (f"absolute_damping on tangential_damping on "
           f"limitForce {'on' if LIMIT_FORCE else 'off'}")


def header(lo, hi, c, gravity, dt=DT, skin=0.2*DIAMETER):
    """Common set-up; atom type 1 = spheres, 2 = walls."""
    pp, pw = c["particleParticle"], c["particleWall"]

    def matrix(key):     # peratomtypepair 2: 11 12 21 22
        return f"{pp[key]!r} {pw[key]!r} {pw[key]!r} {pw[key]!r}"

    lines = f"""\
units           si
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
region          domain block {lo[0]} {hi[0]} {lo[1]} {hi[1]} {lo[2]} {hi[2]} units box
create_box      2 domain
neighbor        {skin!r} bin
neigh_modify    delay 0
fix             kn all property/global kn peratomtypepair 2 {matrix('kn')}
fix             kt all property/global kt peratomtypepair 2 {matrix('kt')}
fix             gn all property/global gamman_abs peratomtypepair 2 {matrix('gamma_n')}
fix             gt all property/global gammat_abs peratomtypepair 2 {matrix('gamma_t')}
fix             mu all property/global coefficientFriction peratomtypepair 2 {matrix('mu')}
pair_style      gran {MODEL} {OPTIONS}
pair_coeff      * *
timestep        {dt!r}
"""
    if gravity:
        lines += f"fix             gravity all gravity {GRAVITY!r} vector 0 0 -1\n"
    return lines


def wall(name, plane, pos):
    return (f"fix             {name} all wall/gran {MODEL} primitive type 2 "
            f"{plane} {pos!r} {OPTIONS}\n")


def liggghts(case, script):
    """Run LIGGGHTS in `case`; return the log text."""
    case.mkdir(parents=True, exist_ok=True)
    (case / "in.liggghts").write_text(script)
    # screen output to a file: -screen none crashes once an STL is read
    with open(case / "screen.txt", "w") as out:
        subprocess.run(["liggghts", "-in", "in.liggghts", "-log", "log.liggghts",
                        "-echo", "none"], cwd=case, stdout=out,
                       stderr=subprocess.STDOUT, check=True)
    return (case / "log.liggghts").read_text()


def loop_times(log):
    """[(phase, seconds, steps)] of each run, phases from 'PHASE x' prints."""
    phase, runs = None, []
    for line in log.splitlines():
        if line.startswith("PHASE "):
            phase = line.split()[1]
        m = re.match(r"Loop time of (\S+) on \d+ procs for (\d+) steps", line)
        if m:
            runs.append((phase, float(m.group(1)), int(m.group(2))))
    return runs


def read_dump(path):
    """Steps (n,) and per-atom columns (n, atoms, cols), sorted by id."""
    steps, frames = [], []
    for block in path.read_text().split("ITEM: TIMESTEP\n")[1:]:
        lines = block.splitlines()
        n = int(lines[2])
        steps.append(int(lines[0]))
        frames.append(np.array([l.split() for l in lines[8:8 + n]], float))
    return np.array(steps), np.array(frames)


# --------------------------------------------------------------- collisions
def collision(scene, e, dt):
    c = contact(e)
    if scene == "headOn":
        v, x0 = HEAD_ON["speed"], RADIUS + GAP/2
        setup = header((-0.01, -0.01, -0.01), (0.01, 0.01, 0.01), c, HEAD_ON["gravity"], dt)
        setup += f"""\
create_atoms    1 single {-x0!r} 0 0 units box
create_atoms    1 single {x0!r} 0 0 units box
set             atom * diameter {DIAMETER!r} density {DENSITY!r}
group           a id 1
group           b id 2
velocity        a set {v!r} 0 0 units box
velocity        b set {-v!r} 0 0 units box
"""
        duration = HEAD_ON["duration"]
    else:
        setup = header((-0.01, -0.01, -0.001), (0.01, 0.01, 0.01), c, WALL["gravity"], dt)
        setup += wall("floor", "zplane", 0.0) + f"""\
create_atoms    1 single 0 0 {RADIUS + GAP!r} units box
set             atom * diameter {DIAMETER!r} density {DENSITY!r}
velocity        all set 0 0 {-WALL['speed']!r} units box
"""
        duration = WALL["duration"]
    script = setup + f"""\
fix             integr all nve/sphere
dump            traj all custom 1 traj.dump id x y z vx vy vz
dump_modify     traj sort id format "%d %.17e %.17e %.17e %.17e %.17e %.17e"
run             {round(duration/dt)}
"""
    case = RUNS / f"{scene}_e{e}_dt{dt:g}"
    log = liggghts(case, script)
    steps, f = read_dump(case / "traj.dump")
    if scene == "headOn":
        overlap = 2*RADIUS - (f[:, 1, 1] - f[:, 0, 1])
        vn = f[:, 1, 4] - f[:, 0, 4]                    # > 0 separating
    else:
        overlap = RADIUS - f[:, 0, 3]
        vn = f[:, 0, 6]
    touching = np.flatnonzero(overlap > 0)
    assert touching[-1] < len(steps) - 1, "contact not over at the end"
    e_measured = -vn[-1]/vn[0]
    t_contact = (steps[touching[-1]] - steps[touching[0]])*dt
    return e_measured, t_contact, sum(t for _, t, _ in loop_times(log))


def restitution():
    """Both scenes at the scenes' time step DT and at DT/10 (convergence)."""
    rows = []
    print(f"{'scene':7s} {'dt [s]':>7s} {'e':>5s} {'measured':>9s} {'error':>8s}"
          f" {'t_c [s]':>10s} {'theory':>10s} {'wall [s]':>8s}")
    for scene in ("headOn", "wall"):
        m_eff = EFFECTIVE_MASS["particleParticle" if scene == "headOn" else "particleWall"]
        for dt in (DT, DT/10):
            for e in RESTITUTIONS:
                em, tc, wt = collision(scene, e, dt)
                rows.append([scene, e, f"{em:.6f}", f"{tc:.6g}", f"{wt:.4g}", f"{dt:g}"])
                print(f"{scene:7s} {dt:7.1e} {e:5.2f} {em:9.5f} {100*(em/e - 1):+7.3f}%"
                      f" {tc:10.4e} {contact_time(e, m_eff):10.4e} {wt:8.3f}", flush=True)
    write_csv(RESULTS / "liggghts_restitution.csv",
              ["scene", "e_requested", "e_measured", "contact_time_s", "wall_time_s",
               "dt_s"], rows)


# --------------------------------------------------------------------- silo
# Seeds of the insertion (LIGGGHTS wants primes above 10000): the committed
# packing's, then those of the ensemble's other fills
SILO_SEEDS = (15485863, 32452843, 32452867)


def prime_seeds(member):
    """Three primes above 10000 for ensemble member > 0."""
    primes, candidate = [], 100003 + 2*7919*member
    while len(primes) < 3:
        if all(candidate % q for q in range(2, int(candidate**0.5) + 1)):
            primes.append(candidate)
        candidate += 2
    return tuple(primes)


def silo_script(seeds=SILO_SEEDS, discharge_time=SILO["discharge_time"]):
    s = SILO
    w, n = s["width"]/2, s["n_particles"]
    z0, z1 = s["insert_zone"]
    margin = RADIUS + 0.2*DIAMETER       # insertion away from the walls
    chunk = round(0.02/DT)               # fill checked every 0.02 s
    every = round(s["sample_every"]/DT)
    script = header((-w - 0.005, -w - 0.005, -5*DIAMETER), (w + 0.005, w + 0.005, z1 + 0.02),
                    contact(s["e"]), gravity=True)
    for name, plane, pos in (("x0", "xplane", -w), ("x1", "xplane", w),
                             ("y0", "yplane", -w), ("y1", "yplane", w),
                             ("closed", "zplane", 0.0)):
        script += wall(name, plane, pos)
    return script + f"""\
region          insert block {-w + margin!r} {w - margin!r} {-w + margin!r} {w - margin!r} {z0!r} {z1!r} units box
fix             pts all particletemplate/sphere {seeds[0]} atom_type 1 density constant {DENSITY!r} radius constant {RADIUS!r}
fix             pdd all particledistribution/discrete {seeds[1]} 1 pts 1.0
fix             ins all insert/pack seed {seeds[2]} distributiontemplate pdd maxattempt 1000 insert_every once overlapcheck yes all_in yes vel constant 0 0 0 particles_in_region {n} region insert
fix             integr all nve/sphere
compute         rke all erotate/sphere
thermo_style    custom step atoms ke c_rke
thermo_modify   lost ignore norm no
thermo          {chunk}
print           "PHASE fill"
run             1
unfix           ins
label           fill
run             {chunk}
if              "$(ke) < {s['settle_ke']!r} && $(step*dt) > {s['settle_time'][0]!r}" then "jump SELF settled"
if              "$(step*dt) < {s['settle_time'][1]!r}" then "jump SELF fill"
label           settled
print           "SETTLED $(step) $(atoms) $(ke)"
dump            packing all custom 1 packing.dump id x y z radius
dump_modify     packing sort id format "%d %.17e %.17e %.17e %.17e"
run             0
undump          packing

print           "PHASE discharge"
unfix           closed
fix             floormesh all mesh/surface file floor.stl type 2
fix             floor all wall/gran {MODEL} mesh n_meshes 1 meshes floormesh {OPTIONS}
reset_timestep  0
region          above block INF INF INF INF 0 INF units box
variable        inside equal count(all,above)
variable        st equal step
fix             out all print {every} "${{st}} ${{inside}}" file discharge.dat screen no title "# step particles_above_floor"
run             {round(discharge_time/DT)}
"""


def bulk_density(xyz):
    """Density of the core of the packing: centres at least 2 d from the side
    walls and the floor and 2 d below the top (98th percentile height)."""
    w, d = SILO["width"]/2, DIAMETER
    top = np.percentile(xyz[:, 2], 98)
    core = ((np.abs(xyz[:, :2]) < w - 2*d).all(axis=1)
            & (xyz[:, 2] > 2*d) & (xyz[:, 2] < top - 2*d))
    volume = (2*(w - 2*d))**2*(top - 4*d)
    return core.sum()*MASS/volume


def silo_run(case, seeds=SILO_SEEDS, discharge_time=SILO["discharge_time"]):
    """Fill and discharge in `case`: the settled packing (x y z radius), the
    discharged mass against time, the log's loop times."""
    case.mkdir(parents=True, exist_ok=True)
    write_stl(case / "floor.stl",
              plate_with_hole(SILO["width"], SILO["orifice"], SILO["orifice_segments"]))
    log = liggghts(case, silo_script(seeds, discharge_time))
    _, packing = read_dump(case / "packing.dump")
    xyzr = packing[0][:, 1:5]
    step, inside = np.loadtxt(case / "discharge.dat", unpack=True)
    t = np.concatenate([[0.0], step*DT])
    mass = np.concatenate([[0.0], (len(xyzr) - inside)*MASS])
    return xyzr, t, mass, loop_times(log)


def silo_rate(t, mass, n):
    """Discharge rate fitted over SILO["fit_window"] of the charge of n."""
    lo, hi = SILO["fit_window"]
    return fit_rate(t, mass, lo*n*MASS, hi*n*MASS)


def silo():
    xyzr, t, mass, runs = silo_run(RUNS / "silo")
    np.savetxt(HERE / "silo_packing.dat", xyzr, fmt="%.9e",
               header=f"settled silo packing (LIGGGHTS, scenes.SILO): {len(xyzr)} spheres\n"
                      "x y z radius [m]")
    rho_bulk = bulk_density(xyzr[:, :3])

    charge, final = len(xyzr)*MASS, mass[-1]
    lo, hi = SILO["fit_window"]
    rate = silo_rate(t, mass, len(xyzr))
    rate_20_80 = fit_rate(t, mass, 0.2*final, 0.8*final)
    predicted = beverloo(rho_bulk, **SILO["beverloo"])

    fill = [r for r in runs if r[0] == "fill"]
    discharge = [r for r in runs if r[0] == "discharge"]
    fill_wall, fill_steps = sum(r[1] for r in fill), sum(r[2] for r in fill)
    dis_wall, dis_steps = sum(r[1] for r in discharge), sum(r[2] for r in discharge)

    write_csv(RESULTS / "liggghts_silo.csv", ["time_s", "discharged_mass_kg"],
              [[f"{a:.6g}", f"{b:.6e}"] for a, b in zip(t, mass)])
    summary = {
        "n_particles": len(xyzr),
        "rho_bulk_kg_m3": rho_bulk,
        "packing_fraction": rho_bulk/DENSITY,
        "discharge_rate_kg_s": rate,
        "beverloo_kg_s": predicted,
        "rate_over_beverloo": rate/predicted,
        "rate_20_80_final_kg_s": rate_20_80,
        "discharged_mass_kg": final,
        "charge_kg": charge,
        "fill_time_s": fill_steps*DT,
        "discharge_time_s": dis_steps*DT,
        "fill_wall_s": fill_wall,
        "discharge_wall_s": dis_wall,
        "fill_steps": fill_steps,
        "discharge_steps": dis_steps,
        "dt_s": DT,
    }
    write_csv(RESULTS / "liggghts_silo_summary.csv", list(summary),
              [[f"{v:.6g}" for v in summary.values()]])
    print(f"silo: rate fitted between {lo:.0%} and {hi:.0%} of the charge")
    for name, value in summary.items():
        print(f"  {name:22s} {value:.6g}")


# ------------------------------------------------------------------ pebbles
def frustum(z0, r0, z1, r1, segments=128):
    """Triangles (n, 3, 3) of the side of a cone frustum (or a cylinder)
    about the z axis, from radius r0 at z0 to r1 at z1; polygons of the
    circles' area."""
    scale = np.sqrt(2*np.pi/(segments*np.sin(2*np.pi/segments)))
    theta = 2*np.pi*np.arange(segments + 1)/segments
    ring = np.stack([np.cos(theta), np.sin(theta), np.zeros_like(theta)], axis=1)
    low = ring*[r0*scale, r0*scale, 1] + [0, 0, z0]
    high = ring*[r1*scale, r1*scale, 1] + [0, 0, z1]
    tris = []
    for i in range(segments):
        tris.append([low[i], low[i + 1], high[i + 1]])
        tris.append([low[i], high[i + 1], high[i]])
    return np.array(tris)


def pebble_script(g, bed, density, c, gravity, dt, end_time, sample_every):
    """The pebble discharge without water (validate_pebbleDischarge.py
    --liggghts): the bed, upward buoyancy-reduced gravity, the reservoir
    (cylinder), floor, cone and chute of the case's constant/geometry; a
    pebble leaves when its centre passes the outlet (the top of the box)."""
    R, d = g["R"], g["d"]
    script = header((-R - d, -R - d, -d), (R + d, R + d, g["outletZ"]), c, gravity=False,
                    dt=dt, skin=0.2*d)
    script += f"fix             gravity all gravity {float(gravity)!r} vector 0 0 1\n"
    script += wall("reservoir", f"zcylinder {R!r} 0", 0)
    script += wall("floor", "zplane", 0.0)
    script += f"""\
fix             conemesh all mesh/surface file cone.stl type 2
fix             chutemesh all mesh/surface file chute.stl type 2
fix             funnel all wall/gran {MODEL} mesh n_meshes 2 meshes conemesh chutemesh {OPTIONS}
"""
    for x, y, z, _ in bed:
        script += f"create_atoms    1 single {float(x)!r} {float(y)!r} {float(z)!r} units box\n"
    every = round(sample_every/dt)
    return script + f"""\
set             atom * diameter {d!r} density {float(density)!r}
fix             integr all nve/sphere
thermo_style    custom step atoms ke
thermo_modify   lost ignore norm no
thermo          {every*10}
dump            traj all custom {every} traj.dump id x y z vx vy vz
dump_modify     traj sort id format "%d %.9e %.9e %.9e %.9e %.9e %.9e"
print           "PHASE discharge"
run             {round(end_time/dt)}
"""


def pebble_run(case, g, bed, density, kn, restitution, friction, gravity, end_time,
               sample_every=0.01):
    """LIGGGHTS on a pebble bed (x y z radius rows; density [kg/m3]) in `case`, with the
    linear spring-dashpot (kn [N/m] per pair, particleParticle and
    particleWall; kt = 2/7 kn, the damping of the given restitution for
    each pair's effective mass): history times, ids and
    rows (x y z u v w) of the pebbles present, and the loop time [s]."""
    mass = density*np.pi/6*g["d"]**3
    c = {}
    for pair, m_eff in (("particleParticle", mass/2), ("particleWall", mass)):
        gamma_n = damping(restitution, m_eff, kn[pair])
        c[pair] = dict(kn=kn[pair], kt=2/7*kn[pair], gamma_n=gamma_n, gamma_t=gamma_n,
                       mu=friction)
    # 50 steps a collision, of the shorter of the two pairs
    dt = min(contact_time(restitution, mass/2, kn["particleParticle"]),
             contact_time(restitution, mass, kn["particleWall"]))/50
    case.mkdir(parents=True, exist_ok=True)
    write_stl(case / "cone.stl", frustum(g["coneBase"], g["R"], g["coneTop"], g["r"]), "cone")
    write_stl(case / "chute.stl", frustum(g["coneTop"], g["r"], g["lidZ"], g["r"]), "chute")
    log = liggghts(case, pebble_script(g, bed, density, c, gravity, dt, end_time,
                                       sample_every))
    # Not read_dump: the number of pebbles falls as they leave
    times, ids, rows = [], [], []
    for block in (case / "traj.dump").read_text().split("ITEM: TIMESTEP\n")[1:]:
        lines = block.splitlines()
        n = int(lines[2])
        frame = np.array([line.split() for line in lines[8:8 + n]], float).reshape(n, 7)
        times.append(np.full(n, int(lines[0])*dt))
        ids.append(frame[:, 0].astype(int))
        rows.append(frame[:, 1:])
    return (np.concatenate(times), np.concatenate(ids), np.concatenate(rows),
            sum(t for _, t, _ in loop_times(log)))


def fit_rate(t, mass, m0, m1):
    """Slope [kg/s] of the discharged mass between masses m0 and m1."""
    sel = (mass >= m0) & (mass <= m1)
    return np.polyfit(t[sel], mass[sel], 1)[0]


def write_csv(path, names, rows):
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        csv.writer(f).writerows([names] + rows)


if __name__ == "__main__":
    todo = sys.argv[1:] or ["restitution", "silo"]
    if "restitution" in todo:
        restitution()
    if "silo" in todo:
        silo()
