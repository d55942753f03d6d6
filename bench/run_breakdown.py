#!/usr/bin/env python3
"""Where a recorded CARIC run's score comes from and where its units' time goes.

usage: bench/run_breakdown.py RUN_DIR [CARIC_DIR]

RUN_DIR is a `coinspect run --out` folder (score.csv, one <unit>.tum per unit). With CARIC_DIR
(a CARIC scenario folder: *_interest_points.pcd, box_description.yaml) the interest points are
split by box (a point within 2 m of a box counts for it; boxes may overlap) and by height.
Per unit: distance flown and the share of time hovering (< 0.3 m/s), slow (< 1.5 m/s) and fast,
from the 20 Hz trajectory. Python 3 standard library only.
"""
import glob
import math
import os
import re
import struct
import sys


def read_scores(run):
    scores = {}
    with open(os.path.join(run, "score.csv")) as f:
        next(f)
        for line in f:
            fields = line.split(",")
            scores[int(fields[7])] = float(fields[6])
    return scores


def read_points(caric):
    path = glob.glob(os.path.join(caric, "*interest_points.pcd"))[0]
    raw = open(path, "rb").read()
    header = raw[: raw.index(b"DATA binary\n")].decode()
    fields = re.search(r"^FIELDS (.*)$", header, re.M).group(1).split()
    sizes = [int(v) for v in re.search(r"^SIZE (.*)$", header, re.M).group(1).split()]
    counts = [int(v) for v in re.search(r"^COUNT (.*)$", header, re.M).group(1).split()]
    n = int(re.search(r"^POINTS (\d+)$", header, re.M).group(1))
    stride = sum(s * c for s, c in zip(sizes, counts))
    offset = {}
    at = 0
    for name, size, count in zip(fields, sizes, counts):
        offset[name] = at
        at += size * count
    start = raw.index(b"DATA binary\n") + len(b"DATA binary\n")
    return [tuple(struct.unpack_from("<f", raw, start + i * stride + offset[k])[0]
                  for k in ("x", "y", "z")) for i in range(n)]


def read_boxes(caric):
    text = open(os.path.join(caric, "box_description.yaml")).read()
    pattern = (r"(?:#\s*([^\n]*)\n)?\s*(box\w*):\s*center:\s*\[([^\]]*)\]\s*size:\s*\[([^\]]*)\]"
               r"\s*orientation:\s*\[([^\]]*)\]")
    boxes = []
    for m in re.finditer(pattern, text):
        numbers = [[float(v) for v in m.group(k).split(",")] for k in (3, 4, 5)]
        boxes.append((m.group(2), (m.group(1) or "").strip(), *numbers))
    return boxes


def in_box(p, box, margin=2.0):
    _, _, centre, size, rotation = box
    d = [p[i] - centre[i] for i in range(3)]
    for k in range(3):  # the box's axes are the columns of the 4x4 row-major transform
        axis = (rotation[k], rotation[4 + k], rotation[8 + k])
        if abs(sum(d[i] * axis[i] for i in range(3))) > size[k] / 2 + margin:
            return False
    return True


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    run = sys.argv[1]
    scores = read_scores(run)
    print(f"{run}: Q {sum(scores.values()):.2f}, {len(scores)} points detected")
    histogram = [0] * 5
    for v in scores.values():
        histogram[min(4, int(v * 5))] += 1
    print("detected points by score 0-0.2, -0.4, -0.6, -0.8, -1:", histogram)
    if len(sys.argv) == 3:
        points = read_points(sys.argv[2])
        print(f"interest points: {len(points)}")
        for box in read_boxes(sys.argv[2]):
            inside = [i for i, p in enumerate(points) if in_box(p, box)]
            seen = [i for i in inside if i in scores]
            q = sum(scores[i] for i in seen)
            print(f"  {box[0]} ({box[1]}): {len(inside)} points, {len(seen)} detected "
                  f"({100 * len(seen) / max(1, len(inside)):.1f} %), Q {q:.1f}")
        bands = {}
        for i, p in enumerate(points):
            band = bands.setdefault(int(p[2] // 15) * 15, [0, 0, 0.0])
            band[0] += 1
            if i in scores:
                band[1] += 1
                band[2] += scores[i]
        for z in sorted(bands):
            total, seen, q = bands[z]
            print(f"  z {z}-{z + 15} m: {total} points, {seen} detected, Q {q:.1f}")
    for path in sorted(glob.glob(os.path.join(run, "*.tum"))):
        rows = [[float(v) for v in line.split()[:4]] for line in open(path)]
        time = [0.0, 0.0, 0.0]
        distance = 0.0
        for a, b in zip(rows, rows[1:]):
            dt = b[0] - a[0]
            step = math.dist(a[1:4], b[1:4])
            distance += step
            speed = step / dt if dt > 0 else 0.0
            time[0 if speed < 0.3 else 1 if speed < 1.5 else 2] += dt
        total = sum(time) or 1.0
        print(f"  {os.path.basename(path)[:-4]:10s} {distance:7.0f} m, hovering "
              f"{100 * time[0] / total:3.0f} %, slow {100 * time[1] / total:3.0f} %, "
              f"fast {100 * time[2] / total:3.0f} %")


if __name__ == "__main__":
    main()
