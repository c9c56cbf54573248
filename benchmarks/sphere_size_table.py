#!/usr/bin/env python3
"""The table of benchmarks/sphere_size_study.sh: one row a run (mix, seed,
sphere radius), from each run's summary.json, then per mix and radius the
mean over the seeds that finished at every radius (paired), and 1#/3#.

Per run: the spheres and the stones that hold one (the rigid bodies), the
rut and its late-creep share (d60 - d45) / d60, the load path across the
cut at 5 minutes (the shares on the stones' spring, on their films alone,
on the mastic), the stones touching per stone at the end, the stone pairs'
films at the start (how many, their mean thickness in mm, the share that
bear at once), and the wall time.

  benchmarks/sphere_size_table.py OUTDIR
"""
import glob
import json
import os
import re
import sys


def runs(directory):
    for path in sorted(glob.glob(os.path.join(directory, "m*-s*-r*/summary.json"))):
        m = re.search(r"m(\w+)-s(\d+)-r([0-9.]+)/summary.json$", path)
        with open(path) as f:
            j = json.load(f)
        if j.get("interrupted"):
            continue
        yield m.group(1), int(m.group(2)), float(m.group(3)), j


def row(mix, seed, r, j):
    sk = j["skeleton"]["per_specimen"][0]
    five = sk["load_path_5min"]["share"]
    films = sk["stone_films_start"]
    count = films["contacts"]
    thickness = sum(b["contacts"] * b["film_diameters"] for b in films["by_film"]) / count * 2.0 * r if count else 0.0
    return {
        "mix": mix, "seed": seed, "r": r, "spheres": j["particles"], "stones": j["stones"],
        "rut": j["rut_depth_mm"], "late": sk["late_creep_share"], "spring5": five["stone_spring"],
        "film5": five["stone_film"], "mastic5": five["mastic"], "touching": sk["stones_touching_per_stone"],
        "pairs": count, "film_mm": thickness, "bare": films["bearing_on_stone_spring"] / count if count else 0.0,
        "wall": j["wall_seconds"],
    }


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    rows = [row(*run) for run in runs(sys.argv[1])]
    print("| mix | seed | sphere radius mm | spheres | stones holding a sphere | rut mm | late creep | "
          "load at 5 min: spring / film / mastic | stones touching per stone | stone-pair films at start | "
          "their mean mm | bare at start | wall s |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for x in sorted(rows, key=lambda x: (x["mix"], x["seed"], -x["r"])):
        print(f"| {x['mix']}# | {x['seed']} | {x['r']:g} | {x['spheres']:,} | {x['stones']:,} | {x['rut']:.2f} | "
              f"{x['late']:.3f} | {x['spring5']:.2f} / {x['film5']:.2f} / {x['mastic5']:.2f} | "
              f"{x['touching']:.2f} | {x['pairs']:,} | {x['film_mm']:.3f} | {x['bare']:.2f} | {x['wall']:.0f} |")
    radii = sorted({x["r"] for x in rows}, reverse=True)
    mixes = sorted({x["mix"] for x in rows})
    # Paired: only the seeds a mix finished at every radius.
    complete = {}
    for mix in mixes:
        seeds = None
        for r in radii:
            s = {x["seed"] for x in rows if x["mix"] == mix and x["r"] == r}
            seeds = s if seeds is None else seeds & s
        complete[mix] = sorted(seeds or [])
    print()
    print("| mix | seeds | " + " | ".join(f"rut at {r:g} mm" for r in radii) + " | " +
          " | ".join(f"spring share 5 min at {r:g} mm" for r in radii) + " |")
    print("| --- | --- | " + " | ".join(["---"] * (2 * len(radii))) + " |")
    mean = {}
    for mix in mixes:
        seeds = complete[mix]
        if not seeds:
            continue
        cells, springs = [], []
        for r in radii:
            chosen = [x for x in rows if x["mix"] == mix and x["r"] == r and x["seed"] in seeds]
            mean[mix, r] = sum(x["rut"] for x in chosen) / len(chosen)
            cells.append(f"{mean[mix, r]:.2f}")
            springs.append(f"{sum(x['spring5'] for x in chosen) / len(chosen):.2f}")
        print(f"| {mix}# | {','.join(map(str, seeds))} | " + " | ".join(cells) + " | " + " | ".join(springs) + " |")
    if all(("1", r) in mean and ("3", r) in mean for r in radii):
        print("\n1#/3# (on each mix's paired seeds): " +
              ", ".join(f"{mean['1', r] / mean['3', r]:.2f} at {r:g} mm" for r in radii))


if __name__ == "__main__":
    main()
