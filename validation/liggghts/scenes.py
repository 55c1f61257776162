"""Scene parameters of the DEM cross-check, in one place for LIGGGHTS
(run_liggghts.py) and for our own code: identical physics in both.

    from scenes import *          # constants, SILO, HEAD_ON, WALL, contact(e)
    python3 scenes.py             # print the derived contact constants

Units SI, gravity along -z. Contact: linear spring-dashpot (LIGGGHTS
`model hooke/stiffness tangential history absolute_damping on`), per pair
(particle-particle, particle-wall):

    Fn = kn delta - gamma_n vn          (vn > 0 approaching; NOT clipped: may
                                         turn attractive at the end, LIMIT_FORCE)
    xi += vt dt, then projected onto the tangent plane (history spring)
    Ft = -kt xi - gamma_t vt            if kt |xi| <= mu |Fn|  (stick)
    Ft = -mu |Fn| xi/|xi|, xi = -Ft/kt  otherwise (slip: spring truncated,
                                         no damping in that step)

vt is the relative tangential velocity at the contact point, with lever arms
r_i - delta/2 (LIGGGHTS, also against walls); the Coulomb limit uses |Fn|,
so an attractive Fn at the end of a contact still allows friction. The
history is deleted when the contact ends. gamma_t is LIGGGHTS' gammat_abs,
which we set equal to gamma_n (tangential_damping on, its default; checked:
gammat_abs = 0 gives the same result as tangential_damping off). Time
integration: velocity Verlet (fix nve/sphere), so the damping forces use
the half-step velocity. With LIMIT_FORCE off the force jumps from -gamma_n
vn to 0 when the overlap ends, so the measured e depends on where the exit
falls between two steps, by up to about gamma_n dt/m* (9 % for e = 0.1
head on at DT, 0.9 % at DT/10): compare both codes with the same GAP.
"""

import numpy as np

DIAMETER = 4e-3                         # m
RADIUS = DIAMETER/2
DENSITY = 2500.0                        # kg/m3
MASS = DENSITY*np.pi/6*DIAMETER**3      # 8.3776e-5 kg
GRAVITY = 9.81                          # m/s2, along -z

KN = 1e4                                # N/m, normal stiffness
KT = 2/7*KN                             # N/m, tangential (history) spring
FRICTION = 0.5                          # Coulomb, particle-particle and -wall
TANGENTIAL_DAMPING_RATIO = 1.0          # gamma_t/gamma_n (LIGGGHTS gammat_abs)
LIMIT_FORCE = False                     # no clipping of an attractive Fn, so
                                        # the damping below gives e exactly
DT = 5e-6                               # s

PAIRS = ("particleParticle", "particleWall")
EFFECTIVE_MASS = {"particleParticle": MASS/2, "particleWall": MASS}


def damping(e, m_eff, kn=KN):
    """Normal damping gamma_n [kg/s] giving restitution e (unclipped LSD)."""
    le = np.log(e)
    return float(-2*le*np.sqrt(m_eff*kn)/np.sqrt(np.pi**2 + le**2))


def contact_time(e, m_eff, kn=KN):
    """Duration of an unclipped linear spring-dashpot collision [s]."""
    le = np.log(e)
    zeta = -le/np.sqrt(np.pi**2 + le**2)
    return float(np.pi/(np.sqrt(kn/m_eff)*np.sqrt(1 - zeta**2)))


def contact(e_pp, e_pw=None):
    """Per-pair constants {pair: dict(e, kn, kt, gamma_n, gamma_t, mu)}."""
    e_pw = e_pp if e_pw is None else e_pw
    out = {}
    for pair, e in zip(PAIRS, (e_pp, e_pw)):
        gn = damping(e, EFFECTIVE_MASS[pair])
        out[pair] = dict(e=e, kn=KN, kt=KT, gamma_n=gn,
                         gamma_t=TANGENTIAL_DAMPING_RATIO*gn, mu=FRICTION)
    return out


# Collisions: no gravity, no friction effect (head on), surfaces GAP apart at
# the start; run long enough for the contact and a few steps after it.
RESTITUTIONS = (0.1, 0.3, 0.5, 0.7, 0.9, 0.95)
# Initial surface gap: closed at 1 m/s after 20.25 DT (202.5 DT/10), so that
# contact does not start exactly on a step (round-off would decide it).
GAP = 1.0125e-4                         # m
HEAD_ON = dict(speed=0.5, gravity=False, duration=1e-3)   # each sphere, along x
WALL = dict(speed=1.0, gravity=False, duration=1e-3)      # down onto floor z = 0

# Silo: square box (4 planes), flat floor z = 0 with a centred circular orifice.
# Fill on a closed floor (the plane z = 0); at the opening the plane is
# replaced by the plate with the hole (contacts with the floor restart there,
# with no tangential history).
SILO = dict(
    e=0.5,                              # particle-particle and particle-wall
    width=0.06,                         # m, walls at x, y = +-width/2
    orifice=7*DIAMETER,                 # m, D0 = 28 mm
    orifice_segments=64,                # STL polygon, same area as the circle
    n_particles=2500,
    insert_zone=(0.005, 0.2),           # m, random insertion height range
    settle_ke=1e-8,                     # J, total translational KE: settled
    settle_time=(0.3, 1.5),             # s, min and max fill time
    discharge_time=2.0,                 # s, after the orifice opens
    sample_every=1e-3,                  # s, discharged-mass output
    # rate: linear fit of the discharged mass between these fractions of the
    # charge; the bed is short (about 40 mm), so the rate decays after about
    # half of the charge is out (and spheres keep rolling out slowly)
    fit_window=(0.2, 0.5),
    beverloo=dict(C=0.58, k=1.4),
)


def beverloo(rho_bulk, D0=SILO["orifice"], d=DIAMETER, C=0.58, k=1.4):
    """Beverloo discharge rate [kg/s]."""
    return C*rho_bulk*np.sqrt(GRAVITY)*(D0 - k*d)**2.5


if __name__ == "__main__":
    print(f"m = {MASS:.6e} kg, kn = {KN:g}, kt = {KT:.6g} N/m, dt = {DT:g} s")
    for pair, m in EFFECTIVE_MASS.items():
        print(f"{pair}: m* = {m:.6e} kg, undamped t_c = "
              f"{np.pi*np.sqrt(m/KN):.4e} s ({np.pi*np.sqrt(m/KN)/DT:.1f} steps)")
    for e in RESTITUTIONS:
        c = contact(e)
        print(f"e = {e:4.2f}: gamma_n pp {c['particleParticle']['gamma_n']:.6e}"
              f"  pw {c['particleWall']['gamma_n']:.6e} kg/s")
