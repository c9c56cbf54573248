#!/usr/bin/env python3
"""The fidelity study's screening table (docs/studies/2026-12-04-fidelity-round-four.md).

Reads the seeds.csv of runs named PREFIX-mM-ROW (a folder ROW/seeds.csv, or a
file PREFIX-mM-ROW.seeds.csv as the device script leaves them) and prints,
per mix and row, the mean rut, its change paired with the row `base` on the
same seeds (mean and 95 % Student t interval), the same for the late-creep
share and the load path's shares (stones on their spring at 5 min and at the
end), the stones touching per stone, and whether the rut's change lies
within the chaos control (the row `ratio101`: the stones' contact ratio 101
against 100, a change with no physical meaning).

  benchmarks/screening_table.py DIR PREFIX "MIXES" "ROWS"
  e.g. benchmarks/screening_table.py out/gpu d3 "1 2 3" "base ratio101 leastfilm friction03"
"""
import csv
import math
import os
import sys

T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145, 2.131]


def t95(dof):
    return T95[dof - 1] if dof <= len(T95) else 1.96 + 2.5 / dof


def rows_of(directory, prefix, mix, row):
    for path in (os.path.join(directory, f"{prefix}-m{mix}-{row}.seeds.csv"),
                 os.path.join(directory, f"{prefix}-m{mix}-{row}", "seeds.csv")):
        if os.path.exists(path):
            with open(path) as f:
                return {int(r["seed"]): r for r in csv.DictReader(f)}
    return None


def mean_ci(values):
    n = len(values)
    m = sum(values) / n
    if n < 2:
        return m, float("nan"), float("nan")
    sd = math.sqrt(sum((v - m) ** 2 for v in values) / (n - 1))
    half = t95(n - 1) * sd / math.sqrt(n)
    return m, m - half, m + half


def paired(base, run, column):
    seeds = sorted(set(base) & set(run))
    diffs = [float(run[s][column]) - float(base[s][column]) for s in seeds]
    return mean_ci(diffs) if diffs else (float("nan"),) * 3


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    directory, prefix, mixes, rows = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4].split()
    print("| mix | row | n | rut mm | rut change (95 % CI) | within chaos control | late creep | its change | "
          "spring share 5 min | at end | its change | stones touching per stone |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for mix in mixes:
        base = rows_of(directory, prefix, mix, "base")
        chaos = rows_of(directory, prefix, mix, "ratio101")
        band = paired(base, chaos, "rut_depth_mm") if base and chaos else None
        for row in rows:
            run = rows_of(directory, prefix, mix, row)
            if run is None:
                continue
            n = len(run)
            rut = sum(float(r["rut_depth_mm"]) for r in run.values()) / n
            late = sum(float(r["late_creep_share"]) for r in run.values()) / n
            spring5 = sum(float(r["load_5min_stone_spring_share"]) for r in run.values()) / n
            spring_end = sum(float(r["load_end_stone_spring_share"]) for r in run.values()) / n
            per_stone = sum(float(r["stones_touching_per_stone"]) for r in run.values()) / n
            if base and row != "base":
                d, lo, hi = paired(base, run, "rut_depth_mm")
                change = f"{d:+.2f} ({lo:+.2f} to {hi:+.2f})"
                # Within the chaos control: the change's interval overlaps the control's.
                within = "-" if not band or row == "ratio101" else ("yes" if lo <= band[2] and hi >= band[1] else "no")
                dl = paired(base, run, "late_creep_share")[0]
                ds = paired(base, run, "load_end_stone_spring_share")[0]
                late_change, spring_change = f"{dl:+.3f}", f"{ds:+.3f}"
            else:
                change, within, late_change, spring_change = "", "", "", ""
            print(f"| {mix}# | {row} | {n} | {rut:.2f} | {change} | {within} | {late:.3f} | {late_change} | "
                  f"{spring5:.3f} | {spring_end:.3f} | {spring_change} | {per_stone:.2f} |")


if __name__ == "__main__":
    main()
