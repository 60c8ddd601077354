#!/usr/bin/env python3
"""Compares two picdem checkpoints (layout in doc/restart.md).

usage: compare_checkpoints.py A.h5 B.h5 bitwise
       compare_checkpoints.py A.h5 B.h5 close RTOL ATOL_POSITION [ATOL_VELOCITY]

bitwise: both files were written on the same number of ranks; every dataset and every attribute
must be identical bit for bit.
close:   the files may come from different rank counts; particles are matched by id (the same set
of ids is required), grid fields are put together from every rank's owned box, solids by id.
Positions and velocities must agree within ATOL_POSITION (m, m/s; velocities within ATOL_VELOCITY
when given), pressure within RTOL relative to its largest magnitude. Prints the largest differences; exit code 1 on failure.
"""
import sys

import h5py
import numpy as np

def datasets(f):
    out = {}
    f.visititems(lambda name, obj: out.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset)
                 else None)
    return out


def bitwise(a, b):
    ok = True
    if sorted(a.attrs) != sorted(b.attrs):
        print("the attributes differ:", sorted(set(a.attrs) ^ set(b.attrs)))
        return False
    for key in sorted(a.attrs):
        x, y = a.attrs[key], b.attrs[key]
        if not np.array_equal(np.asarray(x), np.asarray(y)):
            print(f"attribute {key} differs: {x!r} vs {y!r}"[:400])
            ok = False
    da, db = datasets(a), datasets(b)
    if sorted(da) != sorted(db):
        print("the datasets differ:", sorted(set(da) ^ set(db)))
        return False
    for name in sorted(da):
        x, y = da[name], db[name]
        if x.shape != y.shape or x.tobytes() != y.tobytes():
            diff = "shape" if x.shape != y.shape else f"max |diff| {np.max(np.abs(x - y))}"
            print(f"dataset {name} differs ({diff})")
            ok = False
    print(f"compared {len(da)} datasets and {len(a.attrs)} attributes bitwise: "
          f"{'identical' if ok else 'DIFFERENT'}")
    return ok


def global_field(f, name, which):
    boxes = f["grid/boxes"][()].reshape(-1, 24)
    lengths = f[name].attrs["slice_lengths"]
    data = f[name][()]
    nx = max(b[8 * which + 5] for b in boxes)
    nz = max(b[8 * which + 7] for b in boxes)
    out = np.full((nz, nx), np.nan)
    offset = 0
    for b, n in zip(boxes, lengths):
        s = b[8 * which: 8 * which + 4]
        o = b[8 * which + 4: 8 * which + 8]
        block = data[offset: offset + n].reshape(s[3] - s[2], s[1] - s[0])
        out[o[2]:o[3], o[0]:o[1]] = block[o[2] - s[2]:o[3] - s[2], o[0] - s[0]:o[1] - s[0]]
        offset += n
    return out


def close(a, b, rtol, atol, atol_v=None):
    atol_v = atol if atol_v is None else atol_v
    ok = True
    for key in ["t", "step", "format_version"]:
        if a.attrs[key] != b.attrs[key]:
            print(f"attribute {key} differs: {a.attrs[key]} vs {b.attrs[key]}")
            ok = False
    ia, ib = a["particles/id"][()], b["particles/id"][()]
    oa, ob = np.argsort(ia), np.argsort(ib)
    if not np.array_equal(ia[oa], ib[ob]):
        print(f"the particle ids differ ({len(ia)} vs {len(ib)} particles)")
        return False
    for q in ["x", "z", "u", "w"]:
        tol = atol if q in "xz" else atol_v
        d = np.max(np.abs(a["particles/" + q][()][oa] - b["particles/" + q][()][ob]), initial=0)
        print(f"particles/{q}: max |diff| = {d:.3e} (allowed {tol:.1e})")
        ok = ok and d <= tol
    if a.attrs["has_fluid"]:
        pa, pb = global_field(a, "grid/p", 2), global_field(b, "grid/p", 2)
        scale = max(np.nanmax(np.abs(pa)), 1e-300)
        d = np.nanmax(np.abs(pa - pb)) / scale
        print(f"grid/p: max |diff| / max |p| = {d:.3e} (allowed {rtol:.1e})")
        ok = ok and d <= rtol
        for q, which in [("u", 0), ("w", 1)]:
            d = np.nanmax(np.abs(global_field(a, "grid/" + q, which) -
                                 global_field(b, "grid/" + q, which)))
            print(f"grid/{q}: max |diff| = {d:.3e} (allowed {atol_v:.1e})")
            ok = ok and d <= atol_v
    sa, sb = a["dem/id"][()], b["dem/id"][()]
    if not np.array_equal(sa, sb):
        print("the solid ids differ")
        return False
    for q in ["x", "z", "theta", "u", "w", "omega"]:
        tol = atol if q in ["x", "z", "theta"] else atol_v
        d = np.max(np.abs(a["dem/" + q][()] - b["dem/" + q][()]), initial=0)
        print(f"dem/{q}: max |diff| = {d:.3e} (allowed {tol:.1e})")
        ok = ok and d <= tol
    print("close" if ok else "NOT CLOSE")
    return ok


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
        if sys.argv[3] == "bitwise":
            return 0 if bitwise(a, b) else 1
        atol_v = float(sys.argv[6]) if len(sys.argv) > 6 else None
        return 0 if close(a, b, float(sys.argv[4]), float(sys.argv[5]), atol_v) else 1


if __name__ == "__main__":
    sys.exit(main())
