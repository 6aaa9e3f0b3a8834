#!/usr/bin/env python3
"""Post-processing a time run from its arrays: the showcase (a flap under a pulsatile
inflow closes onto its seat and reopens), its history as NumPy columns: the contact
force, the energies and the coupling's passes per step against time, and the contact
intervals from the summary, plotted with Matplotlib.

    python3 examples/python/time_history.py [--quick] [--out DIR]"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import fsicontact


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true")
    p.add_argument("--out", default="out/time-history")
    a = p.parse_args()
    case = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "cases", "flap-pulsatile.toml")
    if not os.path.exists(case):
        case = "/usr/share/fsicontact/cases/flap-pulsatile.toml"
    extra = {"time.t_end": 0.5, "fluid.h": 0.02, "structure.h": 0.03} if a.quick else {}
    r = fsicontact.run(case, set={"output.png": False, "output.vtu": False, **extra}, out=a.out)
    h = r.history
    t = h["t"]
    force = np.hypot(h["contact_fx"], h["contact_fy"])
    for c in r.summary.get("contact_intervals", []):
        print(f"shut from {c['start']:.2f} s to {c['end']:.2f} s, peak force {c['peak_force']:.1f} N/m")
    print(f"{r.summary['steps']} steps, {np.mean(h['passes'][1:]):.2f} coupling passes a step")
    fig, ax = plt.subplots(3, 1, figsize=(7, 7), sharex=True)
    ax[0].plot(t, force, color="C3")
    ax[0].set_ylabel("contact force (N/m)")
    ax[1].plot(t, h["kinetic"], label="kinetic")
    ax[1].plot(t, h["elastic"], label="elastic")
    ax[1].set_ylabel("energy (J/m)")
    ax[1].legend()
    ax[2].step(t, h["passes"], where="mid")
    ax[2].set(xlabel="t (s)", ylabel="passes")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "time_history.png"), dpi=100)
    print("plot:", os.path.join(a.out, "time_history.png"))


if __name__ == "__main__":
    main()
