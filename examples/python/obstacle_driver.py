#!/usr/bin/env python3
"""A driver that moves the obstacle in a loop: the section 7.2 case with the disk's
centre y0 lowered step by step, the beam's contact force (the contact pressure's
resultant) and its largest displacement against the position, plotted with
Matplotlib. Each run starts from nothing: no state is kept between calls.

    python3 examples/python/obstacle_driver.py [--quick] [--out DIR]"""
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
    p.add_argument("--out", default="out/obstacle-driver")
    a = p.parse_args()
    positions = np.linspace(-0.065, -0.09, 3 if a.quick else 8)
    sizes = {"fluid.h": 0.02, "structure.h": 0.03} if a.quick else {}
    forces, displacements = [], []
    for y0 in positions:
        r = fsicontact.run(set={"obstacle.y0": float(y0), "coupling.scheme": "aitken", "output.png": False,
                                "output.vtu": False, **sizes}, out=os.path.join(a.out, f"y0{y0:.4f}"))
        forces.append(r.summary["contact"]["pressure_resultant"])
        displacements.append(1e3 * r.summary["max_displacement"])
        print(f"y0 = {y0:.4f} m: contact force {forces[-1]:.4g} N/m on {r.summary['contact']['active_nodes']} "
              f"node(s), max |u| {displacements[-1]:.3f} mm ({r.status})")
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(positions, forces, "o-", color="C3")
    ax.set(xlabel="obstacle centre y0 (m)", ylabel="contact force (N/m)", title="the beam against a lowered disk")
    ax2 = ax.twinx()
    ax2.plot(positions, displacements, "s--", color="C0")
    ax2.set_ylabel("max |u| (mm)")
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    fig.savefig(os.path.join(a.out, "obstacle_driver.png"), dpi=100)
    print("plot:", os.path.join(a.out, "obstacle_driver.png"))


if __name__ == "__main__":
    main()
