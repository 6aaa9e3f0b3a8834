#!/usr/bin/env python3
"""Markdown tables from the JSON of build/bench/structure_bench or coupling_bench
(run with --benchmark_repetitions=N --benchmark_report_aggregates_only=true
--benchmark_out=FILE --benchmark_out_format=json), as in docs/performance.md: the median
of each benchmark per mesh level, its coefficient of variation, and the least-squares
slope of log(time) against log(size) over the levels.

  bench/kernel_tables.py structure out/perf/structure.json
  bench/kernel_tables.py coupling out/perf/coupling.json
"""
import json
import math
import sys

SCALE = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}  # to microseconds


def load(path):
    """{(family, level, warm): {"median": us, "cv": fraction, "counters": {...}}}"""
    runs = {}
    for b in json.load(open(path))["benchmarks"]:
        agg = b.get("aggregate_name")
        if agg not in ("median", "cv"):
            continue
        parts = b["run_name"].split("/")
        family = parts[0].removeprefix("BM_")
        args = {}
        for i, p in enumerate(parts[1:]):
            name, _, value = p.rpartition(":")
            args[name or ("hS_level" if i == 0 else f"arg{i}")] = int(value)
        key = (family, args.get("hS_level", 0), args.get("warm", 0))
        r = runs.setdefault(key, {"counters": {}})
        if agg == "median":
            r["median"] = b["real_time"] * SCALE[b["time_unit"]]
            r["counters"] = {k: v for k, v in b.items() if k in COUNTERS}
        else:
            r["cv"] = b["real_time"]  # a fraction, whatever the time unit
    return runs


COUNTERS = {"triangles", "dofs", "contact_rows", "qp_iterations", "active", "structure_vertices",
            "fluid_triangles"}


def slope(points):
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)


def fmt(us):
    if us is None:
        return "-"
    if us >= 1e5:
        return f"{us / 1e3:.0f} ms"
    if us >= 1e3:
        return f"{us / 1e3:.2f} ms"
    if us >= 10:
        return f"{us:.0f} µs"
    return f"{us:.1f} µs"


def table(runs, columns, size_counter, size_name, levels, extra_rows):
    """columns: [(header, family, warm)]"""
    head = ["hS", *extra_rows.keys()] + [h for h, _, _ in columns]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for level in levels:
        cells = [f"{0.015 / 2 ** level:g}"]
        counters = {}  # the mesh counters, from whichever benchmark of this level has them
        for k in runs:
            if k[1] == level:
                counters.update(runs[k]["counters"])
        for counter in extra_rows.values():
            cells.append(f"{counters[counter]:.0f}" if counter in counters else "-")
        for _, family, warm in columns:
            r = runs.get((family, level, warm))
            if r is None:
                cells.append("-")
                continue
            text = fmt(r.get("median"))
            if "qp_iterations" in r["counters"]:
                text += f" ({r['counters']['qp_iterations']:.0f} it.)"
            cells.append(text)
        print("| " + " | ".join(cells) + " |")
    cells = [f"exponent vs {size_name}"] + [""] * len(extra_rows)
    for _, family, warm in columns:
        pts = [(runs[(family, lv, warm)]["counters"].get(size_counter, 0), runs[(family, lv, warm)]["median"])
               for lv in levels if (family, lv, warm) in runs]
        s = slope(pts)
        cells.append("-" if s is None else f"{s:.2f}")
    print("| " + " | ".join(cells) + " |")
    cvs = [r["cv"] for r in runs.values() if "cv" in r]
    if cvs:
        cvs.sort()
        print(f"\ncoefficient of variation of the repetitions: median {100 * cvs[len(cvs) // 2]:.0f} %, "
              f"max {100 * cvs[-1]:.0f} %")


def main():
    kind, path = sys.argv[1], sys.argv[2]
    runs = load(path)
    levels = sorted({k[1] for k in runs})
    if kind == "structure":
        columns = [("A_S assembly", "AssembleA_S", 0), ("C_S, c_lb assembly", "AssembleC_S", 0),
                   ("set-up (Cholesky of A_S, S = C A⁻¹Cᵀ)", "SolverSetup", 0),
                   ("QP active-set, cold", "QpActiveSet", 0), ("QP active-set, warm", "QpActiveSet", 1),
                   ("QP IPOPT", "QpIpopt", 0)]
        table(runs, columns, "dofs", "dofs", levels,
              {"triangles": "triangles", "dofs": "dofs", "contact rows": "contact_rows"})
        print("\n| hS | IPOPT / active-set cold | active-set warm / cold | active constraints |")
        print("|---|---|---|---|")
        for lv in levels:
            cold, warm, ip = runs.get(("QpActiveSet", lv, 0)), runs.get(("QpActiveSet", lv, 1)), \
                runs.get(("QpIpopt", lv, 0))
            if cold and warm and ip:
                print(f"| {0.015 / 2 ** lv:g} | {ip['median'] / cold['median']:.0f}× | "
                      f"{warm['median'] / cold['median']:.2f} | {cold['counters'].get('active', 0):.0f} |")
    elif kind == "coupling":
        columns = [("χ barycentre", "ChiBarycentre", 0), ("χ area-fraction", "ChiAreaFraction", 0),
                   ("v_h, p_h at the deformed vertices", "SampleAtDeformedVertices", 0),
                   ("force of eq. (33)", "FluidForce", 0), ("exact ‖v_h‖ over Ω_S^u", "VelocityL2OverStructure", 0)]
        table(runs, columns, "structure_vertices", "structure vertices", levels,
              {"structure vertices": "structure_vertices", "fluid triangles": "fluid_triangles"})
    else:
        sys.exit("usage: kernel_tables.py structure|coupling FILE.json")


if __name__ == "__main__":
    main()
