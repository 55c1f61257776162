"""ten Cate et al. (2002) settling sphere: case data and a plot of the sphere's
velocity against the experiment (reference README section 1)."""

import numpy as np

from common import read_csv

CASES = {
    # case: (rho_f, nu, u_max [m/s], reference file tag, time to bottom [s])
    "E1": (970, 3.8454e-4, 0.035986, "Re1p5", 4.12),
    "E2": (965, 2.1969e-4, 0.05718, "Re4p1", 2.49),
    "E3": (962, 1.1746e-4, 0.087269, "Re11p6", 1.63),
    "E4": (960, 6.0417e-5, 0.12224, "Re31p9", 1.20),
}


def reference_velocity(case):
    _, data = read_csv(f"tenCate2002_fig5b_velocity_{CASES[case][3]}.csv")
    return data[:, 0], data[:, 1]


def reference_gap(case):
    _, data = read_csv(f"tenCate2002_fig5a_gap_{CASES[case][3]}.csv")
    return data[:, 0], data[:, 1]


def summary(case, history):
    """u_max of the run and its relative error against the experiment."""
    u_max = -history[:, 6].min()
    return u_max, u_max/CASES[case][2] - 1


def plot(case, histories, path):
    """histories: label -> particle history array."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    t, u = reference_velocity(case)
    ax1.plot(t, u, "k.", label="ten Cate et al. (2002)")
    tg, gap = reference_gap(case)
    for label, h in histories.items():
        ax1.plot(h[:, 0], h[:, 6], label=label)
        ax2.plot(h[:, 0], (h[:, 3] - 0.0075)/0.015, label=label)
    # The experiment's curve starts at gap/d = 8.15, the runs at 8: shift the
    # experiment's time so that its gap/d = 8 falls on t = 0
    start = (0.1275 - 0.0075)/0.015
    shift = np.interp(start, gap[::-1], tg[::-1])
    ax2.plot(tg - shift, gap, "k.", label="ten Cate et al. (2002)")
    ax1.set_xlabel("t [s]")
    ax1.set_ylabel("u_z [m/s]")
    ax1.set_title(f"ten Cate {case}: sphere velocity")
    ax1.legend(fontsize=8)
    ax2.set_xlabel("t [s] (experiment aligned at gap/d = 8)")
    ax2.set_ylabel("gap/d")
    ax2.set_title(f"ten Cate {case}: gap to the bottom")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
