#!/usr/bin/env python3
"""A parameter study from Python: the paper's Table 1 columns against the relaxation
factor omega and the penalty eps (paper section 7.2), plotted with Matplotlib.

    python3 examples/python/table1_study.py [--quick] [--out DIR]

For each (eps, omega) it runs the section 7.2 case and reads k (the coupling's passes,
as the paper counts them) and ||v||/eps (the fluid's velocity inside the structure over
eps) from the run's summary; the plot is DIR/table1_study.png. --quick: a coarser mesh
and fewer points (a few seconds)."""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import fsicontact


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true")
    p.add_argument("--out", default="out/table1-study")
    a = p.parse_args()
    omegas = [0.2, 0.5, 1.0] if a.quick else [0.1, 0.2, 0.3, 0.5, 0.7, 1.0]
    epsilons = [1e-3, 1e-4] if a.quick else [1e-2, 1e-3, 1e-4, 1e-5]
    sizes = {"fluid.h": 0.02, "structure.h": 0.03} if a.quick else {}
    fig, (ax_k, ax_v) = plt.subplots(1, 2, figsize=(10, 4))
    for eps in epsilons:
        ks, vs = [], []
        for omega in omegas:
            r = fsicontact.run(set={"coupling.eps": eps, "coupling.omega": omega, "output.png": False,
                                    "output.vtu": False, **sizes},
                               out=os.path.join(a.out, f"eps{eps:g}-omega{omega:g}"))
            ks.append(r.summary["paper_k"] if r.converged else float("nan"))
            vs.append(r.summary["fluid_velocity_l2_in_structure_over_eps"])
            print(f"eps {eps:g}  omega {omega:g}: k = {ks[-1]}, ||v||/eps = {vs[-1]:.4g} ({r.status})")
        ax_k.plot(omegas, ks, "o-", label=f"eps = {eps:g}")
        ax_v.plot(omegas, vs, "o-", label=f"eps = {eps:g}")
    ax_k.set(xlabel="omega", ylabel="k (passes)", title="Table 1: k against omega")
    ax_v.set(xlabel="omega", ylabel="||v|| / eps", yscale="log", title="the penalty's velocity")
    ax_k.legend(), ax_v.legend()
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    fig.savefig(os.path.join(a.out, "table1_study.png"), dpi=100)
    print("plot:", os.path.join(a.out, "table1_study.png"))


if __name__ == "__main__":
    main()
