#!/usr/bin/env python3
"""The SLEI3D tables of doc/strategies.md ("Table I, our runs") and doc/slei3d-runs.md: feature
missions of several methods on one generated scene for several scene seeds, then one markdown
row per method.

usage: bench/slei_table.py BUILD_DIR OUT_DIR [--scene slei-a] [--methods "slei3d slei-fix ..."]
                           [--seeds "1 2 3"] [--run-seed 1] [--jobs 2] [--set KEY=VALUE ...]
                           [--print]

Each run is `coinspect run` of a feature mission (links within 5 m, the station at 1 m/s, the
scene's own budget) with `[mission] scenario_seed` = the scene seed, into
OUT_DIR/<scene>/<method>/seed<N>; runs already there (report.json present) are kept, and
`--print` only prints the rows of those. The rawlogs are deleted (the tables need report.json
and events.csv). Columns: collected per scene seed, mean finish rate, time to 50 % collected per
seed ('-': never), the same to 75 % and 94 %, the time 94 % had been discovered (no feature is
collected before it is discovered: a bound on the 94 % time), finish time (all collected),
discovered per seed, the means of station-explorer and explorer-inspector meetings, of the
UAVs' summed idle time and of the real-time factor, and collisions over all runs.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

MISSION = """[mission]
scenario = {scene}
scenario_seed = {seed}
objective = features
links = range
link_range = 5
gcs_speed = 1

[strategy]
name = {method}
"""


def run_folder(out, scene, method, seed):
    return os.path.join(out, scene, method, f"seed{seed}")


def fly(coinspect, out, scene, method, seed, run_seed, sets):
    folder = run_folder(out, scene, method, seed)
    if os.path.exists(os.path.join(folder, "report.json")):
        return
    os.makedirs(os.path.dirname(folder), exist_ok=True)
    with tempfile.NamedTemporaryFile("w", suffix=".ini", delete=False) as config:
        config.write(MISSION.format(scene=scene, seed=seed, method=method))
    command = [coinspect, "run", config.name, "--seed", str(run_seed), "--quiet", "--out", folder]
    for s in sets:
        command += ["--set", s]
    with open(folder + ".log", "w") as log:
        subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, check=True)
    os.unlink(config.name)
    rawlog = os.path.join(folder, "run.rawlog")
    if os.path.exists(rawlog):
        os.unlink(rawlog)


def rtf(folder):
    with open(folder + ".log") as log:
        for line in log:
            if line.startswith("real-time factor"):
                return float(line.split()[2].rstrip("x"))
    return float("nan")


def collisions(folder):
    with open(folder + ".log") as log:
        for line in log:
            if line.startswith("collisions"):
                return int(line.split()[1])
    return 0


def row(out, scene, method, seeds):
    reports = []
    for seed in seeds:
        folder = run_folder(out, scene, method, seed)
        path = os.path.join(folder, "report.json")
        if not os.path.exists(path):
            return None
        with open(path) as f:
            reports.append((folder, json.load(f)["features"]))
    collected = [f["collected"] for _, f in reports]
    def reached(share, what="collected"):
        out = []
        for _, f in reports:
            times, n = f["timeline"][what], round(share * f["total"])
            out.append(f"{times[n - 1]:.0f}" if len(times) >= n else "-")
        return ", ".join(out)
    finish = ", ".join("-" if f["finish_time"] is None else f"{f['finish_time']:.0f}"
                       for _, f in reports)
    idle = [sum(u["idle_seconds"] for u in f["units"]) for _, f in reports]
    mean = statistics.mean
    cells = [
        f"`{method}`",
        ", ".join(map(str, collected)),
        f"{100.0 * mean(f['finish_rate'] for _, f in reports):.1f} %",
        reached(0.5),
        reached(0.75),
        reached(0.94),
        reached(0.94, "discovered"),
        finish,
        ", ".join(str(f["discovered"]) for _, f in reports),
        f"{mean(f['meetings']['gcs_explorer'] for _, f in reports):.1f}",
        f"{mean(f['meetings']['explorer_inspector'] for _, f in reports):.1f}",
        f"{mean(idle):.0f}",
        f"{mean(rtf(folder) for folder, _ in reports):.1f}x",
        str(sum(collisions(folder) for folder, _ in reports)),
    ]
    return "| " + " | ".join(cells) + " |"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build")
    parser.add_argument("out")
    parser.add_argument("--scene", default="slei-a")
    parser.add_argument("--methods", default="slei3d slei-pre slei-fix caric-team explore-then-inspect")
    parser.add_argument("--seeds", default="1 2 3")
    parser.add_argument("--run-seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--set", action="append", default=[], dest="sets")
    parser.add_argument("--print", action="store_true", dest="print_only")
    args = parser.parse_args()
    methods, seeds = args.methods.split(), [int(s) for s in args.seeds.split()]
    if not args.print_only:
        coinspect = os.path.join(args.build, "bin", "coinspect")
        with ThreadPoolExecutor(max_workers=args.jobs) as pool:
            jobs = [pool.submit(fly, coinspect, args.out, args.scene, m, s, args.run_seed, args.sets)
                    for m in methods for s in seeds]
            for job in jobs:
                job.result()
    print("| method | collected per seed | mean finish rate | time to 50 % collected (per seed) "
          "| to 75 % | to 94 % (the paper's SLEI3D rate on A) | 94 % discovered at (per seed) "
          "| finish time (all) | discovered per seed | station-explorer meetings (mean) "
          "| explorer-inspector meetings (mean) | total UAV idle s (mean) | rtf (mean) "
          "| collisions |")
    print("| --- " * 14 + "|")
    for method in methods:
        line = row(args.out, args.scene, method, seeds)
        print(line if line else f"| `{method}` | (not run) |")


if __name__ == "__main__":
    sys.exit(main())
