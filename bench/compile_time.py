#!/usr/bin/env python3
"""Where the compile time goes (docs/performance.md, "Build and test budgets").

Reads the -ftime-trace JSON files clang writes beside each object file of a build and
prints the phases summed over all files, the slowest files, the headers by the time
spent parsing them (inclusive: a header's includes count in it too) and the templates
by the time spent instantiating them (nested instantiations count in their parents).

    cmake -S . -B build-trace -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++ \\
          -DCMAKE_UNITY_BUILD=OFF -DFSICONTACT_PCH=OFF \\
          -DCMAKE_CXX_FLAGS="-ftime-trace -ftime-trace-granularity=200"
    cmake --build build-trace -j 2
    bench/compile_time.py build-trace [--top N]
"""
import argparse
import collections
import glob
import json
import os

PHASES = ["Total ExecuteCompiler", "Total Frontend", "Total Source", "Total InstantiateClass",
          "Total InstantiateFunction", "Total Backend", "Total OptModule"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build", help="a build directory compiled with -ftime-trace")
    ap.add_argument("--top", type=int, default=15)
    args = ap.parse_args()
    traces = glob.glob(os.path.join(args.build, "**", "CMakeFiles", "**", "*.json"), recursive=True)
    phase, parse, parse_n = collections.Counter(), collections.Counter(), collections.Counter()
    inst, inst_n = collections.Counter(), collections.Counter()
    files = []
    for path in traces:
        try:
            events = json.load(open(path)).get("traceEvents", [])
        except (ValueError, OSError):
            continue  # not a trace (CMake writes other JSON files too)
        totals = {}
        for e in events:
            name, seconds = e.get("name", ""), e.get("dur", 0) / 1e6
            if name.startswith("Total "):
                totals[name] = seconds
            elif name == "Source":
                parse[e["args"]["detail"]] += seconds
                parse_n[e["args"]["detail"]] += 1
            elif name in ("InstantiateClass", "InstantiateFunction"):
                template = e["args"]["detail"].split("<")[0]
                inst[template] += seconds
                inst_n[template] += 1
        if "Total ExecuteCompiler" not in totals:
            continue
        for p in PHASES:
            phase[p] += totals.get(p, 0)
        files.append((totals["Total ExecuteCompiler"], totals.get("Total Frontend", 0),
                      totals.get("Total Backend", 0), path.split("CMakeFiles/")[-1][:-len(".json")]))
    if not files:
        raise SystemExit(f"compile_time.py: no -ftime-trace files under {args.build}")
    print(f"{len(files)} files, one core's seconds")
    for p in PHASES:
        print(f"  {phase[p]:8.1f}  {p[len('Total '):]}")
    print(f"\nslowest files: total, frontend, backend")
    for total, front, back, name in sorted(files, reverse=True)[:args.top]:
        print(f"  {total:6.1f} {front:6.1f} {back:6.1f}  {name}")
    print(f"\nheaders: seconds parsing (inclusive), files that parse them")
    for h, s in parse.most_common(args.top):
        print(f"  {s:7.1f} {parse_n[h]:4d}  {h}")
    print(f"\ntemplates: seconds instantiating (nested included), instantiations")
    for t, s in inst.most_common(args.top):
        print(f"  {s:7.1f} {inst_n[t]:6d}  {t[:110]}")


if __name__ == "__main__":
    main()
