#!/usr/bin/env python3
"""fsicontact.run from Python against the command line on Table 1 row 2 (the default
case), interleaved, 7 times each (issue 31's target: at most 5 % over the command line):
    PYTHONPATH=build/python python3 bench/python_vs_cli.py [BUILD_DIR]"""
import subprocess, sys, time, statistics
import fsicontact

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
cli, py = [], []
for i in range(7):
    t = time.perf_counter(); subprocess.run([BUILD + "/app/fsicontact", "run", "--out", "/tmp/bcli", "-q"], check=True, capture_output=True); cli.append(time.perf_counter() - t)
    t = time.perf_counter(); fsicontact.run(out="/tmp/bpy"); py.append(time.perf_counter() - t)
print("cli median %.3f s, python median %.3f s, ratio %.3f" % (statistics.median(cli), statistics.median(py), statistics.median(py) / statistics.median(cli)))
print("cli", ["%.3f" % x for x in cli]); print("py ", ["%.3f" % x for x in py])
