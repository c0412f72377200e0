#!/usr/bin/env python3
"""Predicted against measured drape coefficients of published fabrics: docs/validation.md's tables.

Runs `drape fabrics` on configs/fabrics/published.csv (each fabric's mechanics and its measured
Cusick drape coefficient, with the source of every number in the file's comments) at each lattice
spacing asked for, in each variant, and writes the tables between the markers of
docs/validation.md from the fabrics.csv files it writes:

  no twist   --set material.finite_volume.D_66=0, no friction, and the shear at the corners
             (--set material.finite_volume.cell_shear=false): the bending of the grid lines alone
             (Hu/Teng's assumption 2, drape before the twist term);
  twist      no friction, the shear at the corners: D_66 by the default rule (docs/reference.md,
             "Twist"), the model of sessions 29-37;
  cell shear no friction, the twist, and the in-plane shear at the lattice cells' centres
             (docs/reference.md, "Shear at the cells' centres"): the model as it is;
  + friction the table as it is: the model as it is with the row's bending friction (shown only
             where it gives one).

`drape fabrics` solves each fabric with the drape test's two levels (the spacing and twice it), so
every prediction carries drape's error bar, and keeps what it solved: a run that was stopped goes
on where it stopped, and a folder deleted is solved again (the tables' heading names the drape that
solved each variant's rows, from fabrics.csv's drape_version column).

Run from the repository root after building drape (Release):
    python3 tools/validation.py [--drape build/drape] [--spacings 0.005,0.0026] [--out DIR]
                                [--dry-run]
--dry-run prints the commands and writes nothing. About 35 minutes on the 2-core development
machine at the default spacings (session 38, sharing it with other runs).
"""
import argparse
import csv
import subprocess
import sys

TABLE = "configs/fabrics/published.csv"
DOC = "docs/validation.md"
BEGIN, END = "<!-- validation:begin -->", "<!-- validation:end -->"
NO_FRICTION = ["material.finite_volume.bending_friction_warp=0",
               "material.finite_volume.bending_friction_weft=0"]
CORNERS = ["material.finite_volume.cell_shear=false"]
WITH_FRICTION = "cell shear + friction"
VARIANTS = [("no twist", ["material.finite_volume.D_66=0"] + NO_FRICTION + CORNERS),
            ("twist", NO_FRICTION + CORNERS),
            ("cell shear", NO_FRICTION),
            (WITH_FRICTION, [])]


def run_fabrics(drape, spacing, name, overrides, out, dry_run):
    folder = f"{out}/{spacing}-{name.replace(' ', '').replace('+', '-')}"
    command = [drape, "fabrics", TABLE, "--set", f"mesh.spacing={spacing}", "-o", folder]
    for override in overrides:
        command += ["--set", override]
    print(" ".join(command), file=sys.stderr)
    if dry_run:
        return None
    done = subprocess.run(command, text=True, stdout=subprocess.PIPE)
    if done.returncode not in (0, 1):
        sys.exit(f"validation: {' '.join(command)} failed ({done.returncode})")
    with open(f"{folder}/fabrics.csv", encoding="utf-8") as f:
        return {row["name"]: row for row in csv.DictReader(f)}


def has_friction(row):
    return bool(row.get("bending_friction_warp [N]"))


def statistics(rows):
    deltas = [float(r["difference"]) for r in rows if r["difference"]]
    if not deltas:
        return None
    n = len(deltas)
    within = sum(r["within_error_bar"] == "true" for r in rows if r["difference"])
    return (n, sum(map(abs, deltas)) / n, sum(deltas) / n, (sum(d * d for d in deltas) / n) ** 0.5,
            within)


def cell(row):
    if not row["predicted_dc"]:
        return f"({row['state']})"
    mark = "" if row["state"] == "stable minimum" else f" ({row['state']})"
    return (f"{float(row['predicted_dc']):.3f} ± {float(row['predicted_dc_error']):.3f} "
            f"({row['folds']}), {float(row['difference']):+.3f}{mark}")


def tables(spacing, results):
    text = [f"**Spacing {spacing * 1000:g} mm** (the drape test's error bar from the "
            f"{spacing * 2000:g} mm level and the mesh rule; Δ = predicted − measured):", "",
            "| fabric | source | description | measured | "
            + " | ".join(f"{variant}: DC (folds), Δ" for variant, _ in VARIANTS) + " |",
            "|---|---|---|---|" + "---|" * len(VARIANTS)]
    for name, row in results["twist"].items():
        cells = [name, row["source"], row["description"], f"{float(row['measured_dc']):.3f}"]
        for variant, _ in VARIANTS:
            shown = variant != WITH_FRICTION or has_friction(row)
            cells.append(cell(results[variant][name]) if shown else "")
        text.append("| " + " | ".join(cells) + " |")
    text += ["", "| variant | fabrics | mean \\|Δ\\| | mean Δ | RMS | measured within the error bar |",
             "|---|---|---|---|---|---|"]
    for variant, _ in VARIANTS:
        rows = [r for r in results[variant].values()
                if variant != WITH_FRICTION or has_friction(r)]
        s = statistics(rows)
        if s:
            text.append(f"| {variant} | {s[0]} | {s[1]:.3f} | {s[2]:+.3f} | {s[3]:.3f} | "
                        f"{s[4]} of {s[0]} |")
    return "\n".join(text) + "\n"


def solved_by(all_results):
    """Which drape solved the rows: `drape fabrics` keeps a re-run's finished rows, so a table may
    hold rows of an older drape (their drape_version column), named here with their variants."""
    variants = {}
    for results in all_results:
        for variant, rows in results.items():
            for row in rows.values():
                variants.setdefault(row["drape_version"].strip(), [])
                if variant not in variants[row["drape_version"].strip()]:
                    variants[row["drape_version"].strip()].append(variant)
    if len(variants) == 1:
        return f"drape {next(iter(variants))}"
    return "; ".join(f"drape {version} ({', '.join(names)})" for version, names in variants.items())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--drape", default="build/drape")
    parser.add_argument("--spacings", default="0.005,0.0026")
    parser.add_argument("--out", default="out/validation")
    parser.add_argument("--dry-run", action="store_true")
    args = parser.parse_args()
    blocks, all_results = [], []
    for spacing in (float(s) for s in args.spacings.split(",")):
        results = {name: run_fabrics(args.drape, spacing, name, overrides, args.out, args.dry_run)
                   for name, overrides in VARIANTS}
        if not args.dry_run:
            blocks.append(tables(spacing, results))
            all_results.append(results)
    if args.dry_run:
        return
    command = "python3 tools/validation.py" + (f" --spacings {args.spacings}"
                                                if args.spacings != "0.005,0.0026" else "")
    body = f"`{command}`, with {solved_by(all_results)}, one run:\n\n" + "\n".join(blocks)
    with open(DOC, encoding="utf-8") as f:
        doc = f.read()
    head, rest = doc.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    with open(DOC, "w", encoding="utf-8") as f:
        f.write(head + BEGIN + "\n" + body + END + tail)


if __name__ == "__main__":
    main()
