#!/usr/bin/env python3
"""Post-processing from the arrays, without a file: the section 7.2 case's fluid speed
with the deformed beam coloured by its von Mises stress over it, and the contact
pressure (the contact multipliers) along the contact zone of a block pressed
onto a wedge (cases/block-on-a-wedge.toml), both from Result.fluid and Result.structure.

    python3 examples/python/postprocess.py [--quick] [--out DIR]"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np

import fsicontact

CASES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "cases")


def corners(triangles):
    """The P1 triangles of a structure (P2's six nodes: its first three are the vertices)."""
    return triangles[:, :3]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true")
    p.add_argument("--out", default="out/postprocess")
    a = p.parse_args()
    quiet = {"output.png": False, "output.vtu": False}
    sizes = {"fluid.h": 0.02, "structure.h": 0.03} if a.quick else {}
    fsi = fsicontact.run(set={**quiet, **sizes}, out=os.path.join(a.out, "paper-7.2"))
    contact = fsicontact.run(os.path.join(CASES, "block-on-a-wedge.toml"), set=quiet,
                             out=os.path.join(a.out, "block-on-a-wedge"))

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7))
    f, s = fsi.fluid, fsi.structure
    speed = top.tripcolor(mtri.Triangulation(*f.vertices.T, f.triangles), f.velocity_magnitude, shading="gouraud",
                          cmap="Blues")
    beam = top.tripcolor(mtri.Triangulation(*s.deformed.T, corners(s.triangles)), facecolors=s.von_mises, cmap="magma")
    top.triplot(mtri.Triangulation(*s.vertices.T, corners(s.triangles)), color="0.6", lw=0.3)
    fig.colorbar(speed, ax=top, label="|v| (m/s)")
    fig.colorbar(beam, ax=top, label="von Mises (Pa)")
    top.set(aspect="equal", xlim=(0, 0.45), ylim=(-0.15, 0.08), title=f"section 7.2: max |u| = {1e3 * fsi.summary['max_displacement']:.2f} mm")

    c = contact.structure
    active = c.contact_status > 0
    x = c.deformed[active, 0]
    order = np.argsort(x)
    bottom.plot(1e3 * x[order], c.contact_multiplier[active][order], "o-", color="C3")
    bottom.set(xlabel="x (mm)", ylabel="contact pressure: the multiplier (Pa)",
               title=f"block on a wedge: {int(active.sum())} active nodes, "
                     f"resultant {contact.summary['contact']['pressure_resultant']:.4g} N/m")
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    fig.savefig(os.path.join(a.out, "postprocess.png"), dpi=100)
    print("plot:", os.path.join(a.out, "postprocess.png"))


if __name__ == "__main__":
    main()
