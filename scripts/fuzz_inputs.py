#!/usr/bin/env python3
"""Mutation fuzzing of coinspect's file inputs through the command line (a developer tool).

    scripts/fuzz_inputs.py BUILD_DIR OUT [--cases N] [--seed S] [--timeout S] [TARGET ...]

Makes its seed files with BUILD_DIR/bin/coinspect (a short recorded run, a feature run, a
generated scenario and its mesh as PLY, OBJ and ASCII STL, a mission config, score captures,
and the CARIC MBS folder from ../shared when present), then for each target runs N cases: copy
the seed files, mutate one (bit flips, random runs, cuts, inserted or deleted chunks, boundary
integers, NaN floats; for text files also replaced values and deleted or repeated lines; a
rawlog is mutated decompressed and compressed again, so that MRPT's deserialisation sees the
damage), run the command, classify the outcome:

    ok               exit 0
    input-error      exit 2 with a message naming the mutated file (or a key)
    damage-reported  exit 1 with the rawlog reader's damage message (eval, plot-timeline)
    differs          exit 3 from eval (the mutation changed recorded values, not the layout)
    UNNAMED          exit 2 whose message does not name the mutated file
    OTHER            exit 1 without a damage message (an exception that is not InputError)
    CRASH            anything else: a signal, a sanitizer report (exit 98/99)
    TIMEOUT          still running after --timeout seconds

Cases of the last four kinds are kept in OUT/found-TARGET-N with OUT/TARGET.log; the exit
status is 1 when there is any but TIMEOUT (a mutated [mission] budget of 1e308 s is a long
mission, not a bug: look at those cases). With a sanitizer build (scripts/setup --sanitize, BUILD_DIR
build-sanitize) ASan and UBSan reports count as crashes. Deterministic for a given --seed.
"""
import argparse
import gzip
import os
import random
import re
import shutil
import struct
import subprocess
import sys

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEXT_SUFFIXES = (".ini", ".yaml", ".txt", ".csv", ".json", ".jsonl", ".launch", ".obj")
TOKENS = ["nan", "inf", "-inf", "-1", "0", "1e308", "-1e308", "1e-320", "4294967296",
          "99999999999999999999", "", "x", "1,2", "1 2 3", "[", "]", "=", "#", "\"", "-0"]


def mutate_bytes(rng, data):
    data = bytearray(data)
    if not data:
        return bytes(data)
    kind = rng.randrange(7)
    if kind == 0:
        for _ in range(rng.randint(1, 8)):
            data[rng.randrange(len(data))] ^= 1 << rng.randrange(8)
    elif kind == 1:
        at = rng.randrange(len(data))
        for i in range(at, min(len(data), at + rng.randint(1, 32))):
            data[i] = rng.randrange(256)
    elif kind == 2:
        del data[rng.randrange(len(data)):]
    elif kind == 3:
        at = rng.randrange(max(1, len(data) - 8))
        width = rng.choice([1, 2, 4, 8])
        value = rng.choice([0, 0x7F, 0x80, 0xFF, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 2**64 - 1])
        data[at:at + width] = (value & (2**(8 * width) - 1)).to_bytes(width, "little")
    elif kind == 4:
        at = rng.randrange(len(data))
        data[at:at] = data[at:at + rng.randint(1, 256)]
    elif kind == 5:
        at = rng.randrange(len(data))
        del data[at:at + rng.randint(1, 256)]
    else:
        at = rng.randrange(max(1, len(data) // 4)) * 4
        data[at:at + 4] = rng.choice([b"\x00\x00\xc0\x7f", b"\x00\x00\x80\x7f", b"\xff\xff\x7f\x7f"])
    return bytes(data)


def mutate_text(rng, text):
    lines = text.split("\n")
    at = rng.randrange(len(lines))
    kind = rng.randrange(6)
    if kind == 0:
        if "=" in lines[at]:
            lines[at] = lines[at].split("=", 1)[0] + "= " + rng.choice(TOKENS)
        else:
            words = lines[at].replace(",", " ").split()
            if words:
                words[rng.randrange(len(words))] = rng.choice(TOKENS)
                lines[at] = " ".join(words)
    elif kind == 1:
        del lines[at]
    elif kind == 2:
        lines.insert(at, lines[rng.randrange(len(lines))])
    elif kind == 3:
        return mutate_bytes(rng, text.encode("latin-1")).decode("latin-1")
    elif kind == 4:
        numbers = list(re.finditer(r"-?\d+(\.\d+)?", text))
        if numbers:
            m = rng.choice(numbers)
            return text[:m.start()] + rng.choice(TOKENS) + text[m.end():]
    else:
        lines[at] = lines[at][:rng.randrange(len(lines[at]) + 1)]
    return "\n".join(lines)


def mutate_file(rng, path):
    raw = open(path, "rb").read()
    if path.endswith(".rawlog") and rng.random() < 0.7:
        data = mutate_bytes(rng, gzip.decompress(raw))
        open(path, "wb").write(gzip.compress(data, mtime=0))
    elif path.endswith(TEXT_SUFFIXES) or (path.endswith(".stl") and raw.startswith(b"solid")):
        text = mutate_text(rng, raw.decode("latin-1"))
        open(path, "wb").write(text.encode("latin-1"))
    else:
        open(path, "wb").write(mutate_bytes(rng, raw))


def check(cmd, **kwargs):
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, **kwargs)


def stl_triangles(path):
    data = open(path, "rb").read()
    count = struct.unpack("<I", data[80:84])[0]
    return [struct.unpack("<12f", data[84 + 50 * i:84 + 50 * i + 48])[3:]
            for i in range(count)]


def make_seeds(coinspect, seeds):
    """Each target: a folder of seed files and a command line (@CASE is the case folder)."""
    shutil.rmtree(seeds, ignore_errors=True)
    targets = {}

    def target(name, command, files):
        folder = os.path.join(seeds, name)
        os.makedirs(folder)
        for source, dest in files:
            shutil.copyfile(source, os.path.join(folder, dest))
        targets[name] = command

    runs = os.path.join(seeds, "_runs")
    check([coinspect, "run", os.path.join(SOURCE, "config/quick.ini"), "--set",
           "mission.budget=4", "--out", os.path.join(runs, "quick"), "--quiet"])
    short = os.path.join(SOURCE, "tests/strategies/slei-b-short.ini")
    check([coinspect, "run", short, "--set", "mission.budget=60", "--out",
           os.path.join(runs, "slei3d"), "--quiet"])
    scene = os.path.join(runs, "scene")
    check([coinspect, "scenario", "generate", "slei-b", "--out", scene])

    target("eval", "eval @CASE/run.rawlog --out @CASE/_out",
           [(os.path.join(runs, "quick/run.rawlog"), "run.rawlog")])
    target("timeline", "plot-timeline --out @CASE/_t.png @CASE/run.rawlog",
           [(os.path.join(runs, "slei3d/run.rawlog"), "run.rawlog")])
    target("features", "plot-features --out @CASE/_f.png @CASE/report.json",
           [(os.path.join(runs, "slei3d/report.json"), "report.json")])
    scene_files = [(os.path.join(scene, f), f) for f in os.listdir(scene)]
    target("scenario", "scenario info @CASE/scenario.ini", scene_files)

    # The scene's mesh as PLY (written by coinspect), OBJ and ASCII STL (written here).
    ini = open(os.path.join(scene, "scenario.ini")).read()
    points = (os.path.join(scene, "interest_points.pcd"), "interest_points.pcd")
    triangles = stl_triangles(os.path.join(scene, "building.stl"))
    made = os.path.join(runs, "meshes")
    os.makedirs(made)
    check([coinspect, "scenario", "export", os.path.join(scene, "scenario.ini"), "--mesh",
           os.path.join(made, "building.ply")])
    index, vertices, faces = {}, [], []
    for t in triangles:
        face = []
        for corner in (t[0:3], t[3:6], t[6:9]):
            if corner not in index:
                index[corner] = len(vertices) + 1
                vertices.append(corner)
            face.append(index[corner])
        faces.append(face)
    with open(os.path.join(made, "building.obj"), "w") as obj:
        obj.writelines("v %r %r %r\n" % v for v in vertices)
        obj.writelines("f %d %d %d\n" % tuple(f) for f in faces)
    with open(os.path.join(made, "building_ascii.stl"), "w") as stl:
        stl.write("solid building\n")
        for t in triangles:
            stl.write(" facet normal 0 0 0\n  outer loop\n")
            for corner in (t[0:3], t[3:6], t[6:9]):
                stl.write("   vertex %r %r %r\n" % corner)
            stl.write("  endloop\n endfacet\n")
        stl.write("endsolid building\n")
    for name, mesh in (("mesh-ply", "building.ply"), ("mesh-obj", "building.obj"),
                       ("mesh-stl-ascii", "building_ascii.stl")):
        folder_ini = os.path.join(made, name + ".ini")
        open(folder_ini, "w").write(ini.replace("file = building.stl", "file = " + mesh))
        target(name, "scenario info @CASE/scenario.ini",
               [(os.path.join(made, mesh), mesh), points, (folder_ini, "scenario.ini")])

    config = os.path.join(runs, "config.ini")
    open(config, "w").write(open(short).read().replace("budget = 120", "budget = 3"))
    target("config", "run @CASE/config.ini --out @CASE/_out --quiet", [(config, "config.ini")])
    target("score", "score --scenario hangar --input @CASE/captures.jsonl",
           [(os.path.join(SOURCE, "tests/score/frontal_hangar.jsonl"), "captures.jsonl")])
    caric = os.path.join(os.path.dirname(SOURCE), "shared/data/caric-mbs")
    if os.path.isdir(caric):
        target("caric", "scenario info @CASE",
               [(os.path.join(caric, f), f) for f in os.listdir(caric)])
    return targets


def classify(target, victim, status, output):
    if status == "timeout":
        return "TIMEOUT"
    if status == 0:
        return "ok"
    if status == 2:
        return "input-error" if victim in output or "key" in output else "UNNAMED"
    if status == 1:
        damage = "damage at byte offset" in output or "DAMAGED" in output
        return "damage-reported" if damage else "OTHER"
    if status == 3 and target == "eval":
        return "differs"
    return "CRASH"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("build")
    parser.add_argument("out")
    parser.add_argument("--cases", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=60.0)
    parser.add_argument("targets", nargs="*")
    args = parser.parse_args()
    coinspect = os.path.join(os.path.abspath(args.build), "bin", "coinspect")
    os.makedirs(args.out, exist_ok=True)
    seeds = os.path.join(args.out, "seeds")
    targets = make_seeds(coinspect, seeds)
    env = dict(os.environ, ASAN_OPTIONS="exitcode=99:detect_leaks=0",
               UBSAN_OPTIONS="halt_on_error=1:exitcode=98:print_stacktrace=1")
    bad = 0
    for name in args.targets or sorted(targets):
        rng = random.Random("%d-%s" % (args.seed, name))
        case = os.path.join(args.out, "case-" + name)
        counts = {}
        with open(os.path.join(args.out, name + ".log"), "w") as log:
            for n in range(args.cases):
                shutil.rmtree(case, ignore_errors=True)
                shutil.copytree(os.path.join(seeds, name), case)
                victim = rng.choice(sorted(os.listdir(case)))
                mutate_file(rng, os.path.join(case, victim))
                command = [coinspect] + targets[name].replace("@CASE", case).split()
                try:
                    run = subprocess.run(command, capture_output=True, timeout=args.timeout,
                                         env=env)
                    status, output = run.returncode, (run.stdout + run.stderr).decode("latin-1")
                except subprocess.TimeoutExpired:
                    status, output = "timeout", ""
                kind = classify(name, victim, status, output)
                counts[kind] = counts.get(kind, 0) + 1
                if kind in ("UNNAMED", "OTHER", "CRASH", "TIMEOUT"):
                    bad += kind != "TIMEOUT"
                    kept = os.path.join(args.out, "found-%s-%d" % (name, n))
                    shutil.rmtree(kept, ignore_errors=True)
                    shutil.copytree(case, kept)
                    log.write("case %d: %s (exit %s), %s mutated\n%s\n" %
                              (n, kind, status, victim, output[-4000:]))
        print("%-15s %s" % (name, ", ".join("%s %d" % kv for kv in sorted(counts.items()))))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
