#!/usr/bin/env python3
"""The frozen 3D model's 1 mm specimens of 1# and 3#, pooled (issue 44;
docs/validation.md, "The frozen 3D model").

The folders of the specimens run before 2026-12-06's new machine are gone,
so every specimen is kept here as its row of validation.md (the rut to
0.01 mm, each DS window as 630 passes over its DS); a folder found in DIR
replaces its seed's row with its summary.json and deformation.csv at full
precision. vrut-pool's formulas: the Student-t
interval of the mean rut, the DS's median, the mean curve's DS and its
interval from the window's mean (analysis/standard_ds.hpp).

  benchmarks/pool_frozen3d_rows.py [-v] [DIR]
  DIR holds the folders d3-1mm-m1-model-sN and d3-1mm-m3-model-sN
  (default: the current folder); -v prints each folder's row."""
import json, csv, math, sys, glob, os

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from screening_table import t95  # the Student t quantiles the screening table uses

PASSES = 15 * 42  # the DS window's passes
# mix -> seed -> (deformation at 5, 15, 30, 45, 60 min in mm, DS as reported)
rows = {
  1: {1: (8.53, 11.38, 13.20, 14.15, 14.99, 744), 2: (8.48, 11.46, 13.48, 14.82, 16.00, 531),
      3: (8.53, 11.21, 12.79, 14.23, 15.27, 602), 4: (8.44, 11.24, 13.27, 14.68, 15.65, 652),
      5: (8.66, 11.25, 13.52, 15.32, 16.49, 538), 6: (8.80, 11.19, 13.30, 14.41, 15.29, 719),
      7: (8.72, 11.44, 13.36, 14.62, 15.62, 629), 8: (8.39, 10.94, 12.91, 14.25, 15.15, 702)},
  3: {1: (2.58, 4.14, 5.13, 6.24, 7.30, 595), 2: (2.66, 4.24, 5.38, 6.25, 7.11, 738),
      3: (2.62, 3.61, 4.28, 4.75, 5.17, 1492), 4: (2.50, 3.86, 4.34, 4.64, 5.16, 1215),
      5: (2.51, 4.11, 5.27, 6.12, 6.55, 1447), 6: (2.55, 3.86, 4.84, 5.60, 6.31, 893),
      7: (2.46, 3.96, 4.74, 5.30, 5.89, 1069), 8: (2.90, 4.40, 5.22, 5.80, 6.35, 1149)},
}

def at(curve, minute):
    # linear interpolation in the (minute, mm) samples
    for (m0, d0), (m1, d1) in zip(curve, curve[1:]):
        if m0 <= minute <= m1:
            return d0 + (d1 - d0) * (minute - m0) / (m1 - m0) if m1 > m0 else d1
    raise ValueError(minute)

def folder_row(d):
    j = json.load(open(os.path.join(d, "summary.json")))
    curve = []
    with open(os.path.join(d, "deformation.csv")) as f:
        r = csv.reader(l for l in f if not l.startswith("#"))
        head = next(r)
        im = [i for i, h in enumerate(head) if h.strip().startswith("minute")][0]
        idf = [i for i, h in enumerate(head) if "deformation" in h][0]
        for line in r:
            curve.append((float(line[im]), float(line[idf])))
    sk = j["skeleton"]["per_specimen"][0] if "per_specimen" in j.get("skeleton", {}) else None
    ds = j["dynamic_stability_passes_per_mm"]
    vals = [at(curve, m) for m in (5, 15, 30, 45)] + [j["rut_depth_mm"]]
    extra = dict(ds_exact=ds, ds_std=j["dynamic_stability_standard"], wall=j["wall_seconds"], steps=j.get("steps"),
                 speed=j.get("particle_steps_per_second"), safety=j.get("timestep_safety"), skeleton=sk,
                 d45=j["deformation_45min_mm"], d60=j["deformation_60min_mm"])
    return vals, extra

def pool(mix, folders, verbose):
    data = {s: (list(v[:5]), PASSES / v[5]) for s, v in rows.get(mix, {}).items()}
    for d in folders:
        s = int(d.rsplit("-s", 1)[1])
        vals, extra = folder_row(d)
        data[s] = (vals, extra["d60"] - extra["d45"])
        if verbose:
            print(f"{mix}# seed {s}: " + " ".join(f"{v:.4f}" for v in vals), json.dumps(extra))
    n = len(data)
    seeds = sorted(data)
    ruts = [data[s][0][4] for s in seeds]
    win = [data[s][1] for s in seeds]
    mean = sum(ruts) / n
    sd = math.sqrt(sum((r - mean) ** 2 for r in ruts) / (n - 1))
    t = t95(n - 1)
    h = t * sd / math.sqrt(n)
    means = [sum(data[s][0][k] for s in seeds) / n for k in range(5)]
    wm = sum(win) / n
    wsd = math.sqrt(sum((w - wm) ** 2 for w in win) / (n - 1))
    wh = t * wsd / math.sqrt(n)
    ds = sorted(PASSES / w for w in win)
    med = (ds[(n - 1) // 2] + ds[n // 2]) / 2
    print(f"{mix}#: n={n} seeds {seeds}; curve " + " ".join(f"{m:.2f}" for m in means) +
          f"; rut {mean:.2f} ({mean - h:.2f} to {mean + h:.2f}) sd {sd:.2f}; DS median {med:.0f};"
          f" mean curve {PASSES / wm:.0f} ({PASSES / (wm + wh):.0f} to {PASSES / (wm - wh) if wm > wh else float('inf'):.0f});"
          f" late creep of mean curve {(means[4] - means[3]) / means[4]:.3f}")
    return mean

if __name__ == "__main__":
    v = "-v" in sys.argv
    where = ([a for a in sys.argv[1:] if a != "-v"] or ["."])[0]

    def folders(mix):
        found = glob.glob(os.path.join(where, f"d3-1mm-m{mix}-model-s*[0-9]"))
        return sorted(d for d in found if os.path.exists(os.path.join(d, "summary.json")))

    m1 = pool(1, folders(1), v)
    m3 = pool(3, folders(3), v)
    print(f"1#/3# = {m1 / m3:.2f}")
