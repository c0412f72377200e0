#!/usr/bin/env python3
"""Predicted against measured drape coefficients of published fabrics: docs/validation.md's tables.

Reads configs/fabrics/published.csv (each fabric's mechanics in SI and its measured Cusick drape
coefficient, with the source of every number in the file's comments), solves each fabric on the
standard drape tester (configs/fv/drape_tester_cotton_30.yaml: the 30 cm specimen on the 18 cm
disc, its material replaced by the row's) at each lattice spacing asked for, in each variant:

  no twist   D_66 = 0: the bending of the grid lines alone (Hu/Teng's assumption 2, drape before
             the twist term);
  twist      D_66 by the default rule (docs/reference.md, "Twist"), the model as it is;
  + friction the same with the row's bending friction (only where the row gives one).

Each solve is `drape solve` with the drape test's two levels (the spacing and twice it), so every
prediction carries drape's error bar. Then writes, between the markers in docs/validation.md, one
table per spacing (measured, each variant's DC ± error bar and folds, and the difference) and the
summary statistics (mean |Δ|, mean Δ, RMS, and how many measured values lie within prediction ±
error bar).

Run from the repository root after building drape (Release):
    python3 tools/validation.py [--drape build/drape] [--spacings 0.005,0.0026] [--out DIR]
                                [--only M1,M6] [--dry-run] [--reuse]
--dry-run prints the commands and writes nothing; --reuse takes a solve whose summary.json is
already in the output folder (a run that was stopped) instead of solving it again. About 15 minutes on the 2-core development
machine at the default spacings.
"""
import argparse
import csv
import io
import json
import math
import os
import subprocess
import sys
import time

BASE_SCENE = "configs/fv/drape_tester_cotton_30.yaml"
TABLE = "configs/fabrics/published.csv"
DOC = "docs/validation.md"
BEGIN, END = "<!-- validation:begin -->", "<!-- validation:end -->"


def read_fabrics(path):
    with open(path, encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(io.StringIO("".join(lines))))


def material(row, twist, friction):
    fv = (f"E_warp: {row['E_warp']}, E_weft: {row['E_weft']}, G: {row['G']}, "
          f"D_warp: {row['D_warp']}, D_weft: {row['D_weft']}")
    if not twist:
        fv += ", D_66: 0"
    if friction:
        fv += (f", bending_friction_warp: {row['bending_friction']}, "
               f"bending_friction_weft: {row['bending_friction']}")
    return (f"material={{model: finite_volume, density: {row['density']}, "
            f"finite_volume: {{{fv}}}}}")


def variants(row):
    found = [("no twist", False, False), ("twist", True, False)]
    if row["bending_friction"]:
        found.append(("twist + friction", True, True))
    return found


def solve(drape, row, spacing, twist, friction, out, dry_run, reuse):
    folder = os.path.join(out, f"{row['name'].replace(' ', '_')}-{spacing}-"
                               f"{'twist' if twist else 'flat'}{'-friction' if friction else ''}")
    command = [drape, "solve", BASE_SCENE, "--set", material(row, twist, friction),
               "--set", f"mesh.spacing={spacing}", "--set", "output.write=[summary]",
               "--out", folder]
    if dry_run:
        print(" ".join(f"'{c}'" if " " in c else c for c in command))
        return None
    start = time.time()
    summary_path = os.path.join(folder, "summary.json")
    if not (reuse and os.path.exists(summary_path)):
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode not in (0, 1):
            sys.exit(f"validation: {' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    with open(summary_path, encoding="utf-8") as f:
        summary = json.load(f)
    error = summary.get("drape_coefficient_error", {}).get("estimate")
    result = {
        "dc": summary["drape_coefficient"],
        "error": error,
        "folds": summary["drape"]["folds"],
        "converged": summary.get("converged", False) and summary.get("stable", True),
        "seconds": time.time() - start,
    }
    print(f"{row['name']:>13} {spacing} {'twist' if twist else 'flat ':5} "
          f"{'friction' if friction else '':8} DC {result['dc']:.3f} ± {error:.3f} "
          f"({result['folds']} folds, {result['seconds']:.0f} s)", file=sys.stderr)
    return result


def statistics(rows, results, name):
    deltas, covered = [], 0
    for row in rows:
        r = results.get((row["name"], name))
        if r is None:
            continue
        delta = r["dc"] - float(row["measured_dc"])
        deltas.append(delta)
        covered += abs(delta) <= r["error"]
    if not deltas:
        return None
    n = len(deltas)
    return {"n": n, "mean_abs": sum(map(abs, deltas)) / n, "mean": sum(deltas) / n,
            "rms": math.sqrt(sum(d * d for d in deltas) / n), "covered": covered}


def tables(rows, spacing, results):
    names = ["no twist", "twist", "twist + friction"]
    text = [f"**Spacing {spacing * 1000:g} mm** (the drape test's error bar from the {spacing * 2000:g}"
            " mm level and the mesh rule; Δ = predicted − measured):", "",
            "| fabric | source | weave | measured | no twist: DC (folds), Δ | twist: DC (folds), Δ"
            " | twist + friction: DC (folds), Δ |", "|---|---|---|---|---|---|---|"]
    for row in rows:
        cells = [row["name"], row["source"], row["weave"], f"{float(row['measured_dc']):.3f}"]
        for name in names:
            r = results.get((row["name"], name))
            if r is None:
                cells.append("")
                continue
            delta = r["dc"] - float(row["measured_dc"])
            mark = "" if r["converged"] else " (not converged)"
            cells.append(f"{r['dc']:.3f} ± {r['error']:.3f} ({r['folds']}), {delta:+.3f}{mark}")
        text.append("| " + " | ".join(cells) + " |")
    text += ["", "| variant | fabrics | mean \\|Δ\\| | mean Δ | RMS | measured within the error bar |",
             "|---|---|---|---|---|---|"]
    for name in names:
        s = statistics(rows, results, name)
        if s:
            text.append(f"| {name} | {s['n']} | {s['mean_abs']:.3f} | {s['mean']:+.3f} | "
                        f"{s['rms']:.3f} | {s['covered']} of {s['n']} |")
    return "\n".join(text) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--drape", default="build/drape")
    parser.add_argument("--spacings", default="0.005,0.0026")
    parser.add_argument("--out", default="out/validation")
    parser.add_argument("--only", default="")
    parser.add_argument("--dry-run", action="store_true")
    parser.add_argument("--reuse", action="store_true",
                        help="read the summary.json of a solve already in --out instead of solving")
    args = parser.parse_args()
    rows = read_fabrics(TABLE)
    if args.only:
        rows = [r for r in rows if r["name"] in args.only.split(",")]
    blocks = []
    for spacing in (float(s) for s in args.spacings.split(",")):
        results = {}
        for row in rows:
            for name, twist, friction in variants(row):
                r = solve(args.drape, row, spacing, twist, friction, args.out, args.dry_run,
                          args.reuse)
                if r is not None:
                    results[(row["name"], name)] = r
        blocks.append(tables(rows, spacing, results))
    if args.dry_run:
        return
    command = "python3 tools/validation.py" + (f" --spacings {args.spacings}"
                                                if args.spacings != "0.005,0.0026" else "")
    body = f"`{command}`, with {describe(args.drape)}:\n\n" + "\n".join(blocks)
    with open(DOC, encoding="utf-8") as f:
        doc = f.read()
    head, rest = doc.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    with open(DOC, "w", encoding="utf-8") as f:
        f.write(head + BEGIN + "\n" + body + END + tail)


def describe(drape):
    done = subprocess.run([drape, "--version"], capture_output=True, text=True)
    return done.stdout.strip().split("\n")[0] if done.returncode == 0 else "(unknown version)"


if __name__ == "__main__":
    main()
