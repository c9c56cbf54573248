#!/usr/bin/env python3
"""A sweep over the mastic's Maxwell viscosity eta1 for mix 2#, three
specimens each (100 mm sections, about a minute in all on 2 cores), its rut
depths printed and, where matplotlib is installed, plotted to a PNG.

    PYTHONPATH=build/python python3 examples/python/eta1_sweep.py [out.png]
"""
import sys

import vrut

ETA1_MPA_S = (60.0, 83.34, 110.0)  # 83.34: the source's mastic, the default (docs/method.md)
SEEDS = [1, 2, 3]


def main():
    png = sys.argv[1] if len(sys.argv) > 1 else "eta1_sweep.png"
    rows = []
    for eta1 in ETA1_MPA_S:
        run = vrut.rutting(gradation=2, seeds=SEEDS, width_mm=100, eta1=eta1)
        depths = [s["rut_depth_mm"] for s in run.per_seed]
        rows.append((eta1, run, depths))
        print(f"eta1 {eta1:6.2f} MPa s: rut depth {run.rut_depth_mm:.2f} mm "
              f"({', '.join(f'{d:.2f}' for d in depths)}), DS of the mean curve {run.dynamic_stability:.0f} passes/mm")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: no plot (apt-get install python3-matplotlib)")
        return 0
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for eta1, run, depths in rows:
        left.plot(run.minutes, run.deformation_mm, label=f"eta1 {eta1:g} MPa s")
        right.plot([eta1] * len(depths), depths, "o", color="grey")
    right.plot([r[0] for r in rows], [r[1].rut_depth_mm for r in rows], "k-", label="mean of 3 specimens")
    left.set(xlabel="minutes", ylabel="deformation, mm", title="2#, mean of 3 specimens")
    right.set(xlabel="eta1, MPa s", ylabel="rut depth at 60 min, mm", title="the sweep")
    left.legend()
    right.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"plot in {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
