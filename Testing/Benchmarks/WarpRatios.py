#!/usr/bin/env python3
"""The warp's figures over the thin-plate spline's, per warp and landmark count: median and worst
draw of RMS and drift ratios (below 1: the warp closer), from LandmarkWarpBenchmark's JSON lines.

    build/vtk/bin/LandmarkWarpBenchmark ../shared/data --landmarks 100 --draws 12 --drags 0 \\
        | Testing/Benchmarks/WarpRatios.py [--tps tps-r2logr] [--method arap]
"""
import argparse
import json
import statistics
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tps", default="tps-r2logr", help="the spline's method name")
    parser.add_argument("--method", default="arap", help="the warp's method name")
    parser.add_argument("files", nargs="*", help="JSON lines (standard input if none)")
    arguments = parser.parse_args()
    lines = []
    for name in arguments.files or ["-"]:
        stream = sys.stdin if name == "-" else open(name)
        lines += [json.loads(line) for line in stream if line.startswith("{")]
    runs = {}
    for line in lines:
        key = (line["warp"], line["landmarks"], line.get("draw", 0))
        runs.setdefault(key, {})[line["method"]] = line
    ratios = {}
    for (warp, landmarks, _), methods in runs.items():
        if arguments.tps in methods and arguments.method in methods:
            spline, warped = methods[arguments.tps], methods[arguments.method]
            ratios.setdefault((warp, landmarks), []).append(
                (warped["rms"] / spline["rms"], warped["stay_drift"] / spline["stay_drift"]))
    print("| warp | landmarks | draws | RMS median | RMS worst | drift median | drift worst |")
    print("|---|---|---|---|---|---|---|")
    for (warp, landmarks), pairs in sorted(ratios.items()):
        rms, drift = zip(*pairs)
        print(f"| {warp} | {landmarks:,} | {len(pairs)} | {statistics.median(rms):.2f} | {max(rms):.2f} "
              f"| {statistics.median(drift):.2f} | {max(drift):.2f} |")
    return 0 if ratios else 1


if __name__ == "__main__":
    sys.exit(main())
