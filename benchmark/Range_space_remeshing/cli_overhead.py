#!/usr/bin/env python3
"""Where the command-line program's wall time goes: reading, repair, remeshing,
writing, against the whole run, on the meshes given.

    cli_overhead.py PROGRAM [--baseline OLD_PROGRAM] [--runs N] MESH...

Runs PROGRAM (and OLD_PROGRAM, alternated with it run by run: same machine state)
N times on each mesh with --stats, output to a temporary .off file, and prints a
Markdown table of medians: wall time, the stages --stats reports, and the ratio of
the wall time to the remeshing time (`time_ms.total`)."""

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time


def run(program, mesh, output):
    start = time.perf_counter()
    result = subprocess.run([program, "--stats", mesh, output], capture_output=True, text=True)
    wall = (time.perf_counter() - start) * 1000
    if result.returncode != 0:
        sys.exit(f"{program} {mesh}: exit {result.returncode}: {result.stderr.strip()}")
    return wall, json.loads(result.stdout)["time_ms"]


def main():
    args = sys.argv[1:]
    baseline, runs = None, 7
    if "--baseline" in args:
        i = args.index("--baseline")
        baseline = args[i + 1]
        del args[i:i + 2]
    if "--runs" in args:
        i = args.index("--runs")
        runs = int(args[i + 1])
        del args[i:i + 2]
    program, meshes = args[0], args[1:]
    print("| mesh | program | wall ms | read | repair | remesh (`total`) | write | wall / remesh |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        output = os.path.join(work, "out.off")
        for mesh in meshes:
            samples = {program: [], baseline: []}
            for _ in range(runs):
                for p in [program] + ([baseline] if baseline else []):
                    samples[p].append(run(p, mesh, output))
            for p in [program] + ([baseline] if baseline else []):
                wall = statistics.median(s[0] for s in samples[p])
                stage = lambda key: statistics.median(s[1].get(key, float("nan")) for s in samples[p])
                total = stage("total")
                label = "this" if p == program else "baseline"
                print(f"| {os.path.basename(mesh)} | {label} | {wall:.0f} | {stage('read'):.0f} | "
                      f"{stage('repair'):.0f} | {total:.0f} | {stage('write'):.0f} | {wall / total:.2f} |")


if __name__ == "__main__":
    main()
