#!/usr/bin/env python3
"""Summary of a volume_budget CSV (volume_budget.cpp): at the step of the worst change of the
fluid volume against the water at t = 0 (V0), and at the end, each term's change since the first
step, in % of V0:
  volume = particle_area + (occupancy_area - particle_area) - crowded + thinned - dry
           + (volume - wet_cells)
the cells' part (thinned - crowded - dry) split into the bulk (cells with S > 1/2 all around:
below 0 where the particles are compressed) and the surface band; the interpolation (volume - wet_cells) split into the cells next to solids and the rest; and
volume_after - volume: the volume with the solids where the step leaves them against the step's
diagnostic, which weights the cells with the solids where the step started.
With EVERY (s), also the terms at every EVERY seconds, in % of V0 (not since step 1).
  usage: volume_budget.py BUDGET.csv V0 [T_MAX [EVERY]]"""
import csv
import sys


def terms_of(f):
    near = lambda r: f(r, "near_volume") - f(r, "near_wet")
    return {
        "particles (N h^2/ppc)": lambda r: f(r, "particle_area"),
        "occupancy - particles": lambda r: f(r, "occupancy_area") - f(r, "particle_area"),
        "- crowded (S > 1)": lambda r: -f(r, "crowded"),
        "+ thinned (1/2 < S < 1)": lambda r: f(r, "thinned"),
        "- dry (S <= 1/2)": lambda r: -f(r, "dry"),
        "   of it isolated": lambda r: -f(r, "dry_isolated"),
        "bulk (1 - S, S > 1/2 all around)": lambda r: f(r, "bulk"),
        "surface band (the rest of them)": lambda r: f(r, "thinned") - f(r, "crowded") - f(r, "dry")
        - f(r, "bulk"),
        "interpolation (volume - wet cells)": lambda r: f(r, "volume") - f(r, "wet_cells"),
        "   of it next to solids": near,
        "   of it elsewhere": lambda r: f(r, "volume") - f(r, "wet_cells") - near(r),
        "near solids ([S>1/2] - S)": lambda r: f(r, "near_solid"),
        "solids at X^n+1 (after - volume)": lambda r: f(r, "volume_after") - f(r, "volume"),
    }


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    v0 = float(sys.argv[2])
    t_max = float(sys.argv[3]) if len(sys.argv) > 3 else 1e300
    every = float(sys.argv[4]) if len(sys.argv) > 4 else 0.0
    rows = [r for r in rows if float(r["t"]) <= t_max + 1e-12]
    f = lambda r, k: float(r[k])
    terms = terms_of(f)
    first = rows[0]
    worst = max(rows, key=lambda r: abs(f(r, "volume") / v0 - 1))
    added = sum(int(r["added"]) for r in rows)
    print(f"{sys.argv[1]}: V0 = {v0:.6e}, first step {100 * (f(first, 'volume') / v0 - 1):+.3f}%,"
          f" particles {first['particles']}")
    for label, r in (("worst", worst), ("last", rows[-1])):
        upto = [q for q in rows if f(q, "t") <= f(r, "t")]
        rem = sum(int(q["removed"]) for q in upto)
        add = sum(int(q["added"]) for q in upto)
        print(f"  {label}: t = {f(r, 't'):.4f} s, volume {100 * (f(r, 'volume') / v0 - 1):+.3f}% of V0"
              f" ({100 * (f(r, 'volume') - f(first, 'volume')) / v0:+.3f}% since step 1);"
              f" particles {r['particles']} (added {add}, removed {rem}),"
              f" full cells {f(r, 'full_cells'):.0f} ({f(r, 'full_cut_cells'):.0f} cut)")
        for name, g in terms.items():
            print(f"    {name:36s} {100 * (g(r) - g(first)) / v0:+.3f}%")
    print(f"  added over the run {added}")
    if every > 0:
        names = ["volume", "bulk", "surface", "isolated", "interp near", "interp else",
                 "after - vol"]
        keys = ["bulk (1 - S, S > 1/2 all around)", "surface band (the rest of them)",
                "   of it isolated", "   of it next to solids", "   of it elsewhere",
                "solids at X^n+1 (after - volume)"]
        print("  t [s]  " + " ".join(f"{n:>11s}" for n in names) + "   (% of V0)")
        due = 0.0
        for r in rows:
            if f(r, "t") < due - 1e-9 and r is not rows[-1]:
                continue
            due = f(r, "t") + every - 1e-9 if due == 0.0 else due + every
            vals = [100 * (f(r, "volume") / v0 - 1)] + [100 * terms[k](r) / v0 for k in keys]
            print(f"  {f(r, 't'):.3f}  " + " ".join(f"{x:+11.3f}" for x in vals))


main()
