"""Closed forms of Stokes flow that the tests and the validation scripts
(validation/common.py puts tests/ on the path) both use."""

import numpy as np

# Hasimoto (1959), J. Fluid Mech. 5: 317: in a simple cubic lattice of side L
# of point forces F, the images and the mean pressure gradient that balances
# them move the fluid at each point force by -HASIMOTO F/(6 pi mu L) relative
# to the mean velocity (the sphere's 1.7601 phi^(1/3) with phi = 4/3 pi a^3/L^3)
HASIMOTO = 2.8373


def oberbeck_resistances(a, b, mu):
    """Stokes drag coefficients (force over velocity) of a prolate spheroid
    of semi-axes a > b translating along and across its axis (Oberbeck, as
    in Happel & Brenner 1965, eqs. 5-11.13 and 5-11.14)."""
    e = np.sqrt(1 - (b/a)**2)
    log = np.log((1 + e)/(1 - e))
    along = 16*np.pi*mu*a*e**3/((1 + e**2)*log - 2*e)
    across = 32*np.pi*mu*a*e**3/(2*e + (3*e**2 - 1)*log)
    return along, across


def unbounded_resistance(periodic, mu, L):
    """The resistance (force over superficial velocity, along a principal
    axis of the body) in unbounded fluid of a body whose resistance in a
    simple cubic array of side L is 'periodic', to the leading order of
    the array: the body sees the mean flow U plus the images' HASIMOTO
    F/(6 pi mu L), so that F = R (U + HASIMOTO F/(6 pi mu L)) and
    1/R = 1/R_periodic + HASIMOTO/(6 pi mu L); the remainder is O(L^-3)
    (for a sphere of radius a, 4/3 pi a^3/L^3 in 1/K: Zick & Homsy 1982)."""
    return 1/(1/periodic + HASIMOTO/(6*np.pi*mu*L))
