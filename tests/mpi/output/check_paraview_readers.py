"""What ParaView's XDMF readers make of a run's indexes, against the HDF5 frame files.
usage: pvpython check_paraview_readers.py OUTPUT_DIR   (run by ctest with pvpython when found)

Without ParaView's Python modules (no pvpython: Debian's paraview + python3-paraview) it prints
that it was skipped and exits 77, which ctest reports as skipped. Checked at the first, a middle
and the last frame time (doc/output.md, "Why this shape"):
- the older "XDMF Reader" on picdem.xdmf: four blocks named cells, solids, obstacles, particles,
  in this order at every time, with the frame's particle count (one vertex cell each), the grid's
  nx * nz cells and the outlines' line count;
- Xdmf3ReaderS (the default: OpenDataFile picks it for .xdmf) on picdem.xdmf: the same four
  grids, in the same order at every time, as pieces of one multipiece dataset;
- Xdmf3ReaderT on picdem.xdmf: the same four grids as blocks in the same order at every time;
- all three readers on each per-grid index GRID.xdmf: that grid alone as one dataset
  (not a composite) with the counts above (particles: with the velocity vector);
- the three readers on frames/frame_NNNNNN_particles.xdmf: that frame's particles.
"""
import os
import sys
import xml.etree.ElementTree as ET

try:
    from paraview import servermanager as sm
    from paraview import simple
except ImportError:
    print("SKIPPED: ParaView's Python modules are not available (no pvpython; Debian: paraview "
          "python3-paraview): the ParaView readers were not checked")
    sys.exit(77)
import h5py
import numpy as np
from check_support import GRIDS, check, finish


def expected(out, step):
    """{grid: (vtk class, points or None, cells)} of a frame file."""
    with h5py.File(os.path.join(out, "frames", "frame_%06d.h5" % step), "r") as f:
        nz, nx = f["cells/pressure"].shape[1:]
        want = {"cells": ("vtkUniformGrid", None, nx * nz),
                "particles": ("vtkUnstructuredGrid", f["particles/xyz"].shape[0],
                              f["particles/xyz"].shape[0])}
        for g in ("solids", "obstacles"):
            want[g] = ("vtkUnstructuredGrid", f[g + "/xyz"].shape[0], f[g + "/body_id"].shape[0])
    return want


def same(data, want, where):
    cls, points, cells = want
    check(data is not None and data.IsA(cls), f"{where}: {data.GetClassName() if data else None}, "
          f"expected {cls}")
    if data is None:
        return
    if points is not None:
        check(data.GetNumberOfPoints() == points, f"{where}: {data.GetNumberOfPoints()} points, "
              f"the frame file has {points}")
    check(data.GetNumberOfCells() == cells, f"{where}: {data.GetNumberOfCells()} cells, "
          f"the frame file has {cells}")


def blocks(data):
    """[(name or None, block)] of a multiblock or a multipiece dataset."""
    if data.IsA("vtkMultiPieceDataSet"):
        return [(None, data.GetPiece(i)) for i in range(data.GetNumberOfPieces())]
    out = []
    for i in range(data.GetNumberOfBlocks()):
        meta = data.GetMetaData(i) if data.HasMetaData(i) else None
        name = meta.Get(data.NAME()) if meta and meta.Has(data.NAME()) else None
        out.append((name, data.GetBlock(i)))
    return out


def main(out):
    index = ET.parse(os.path.join(out, "picdem.xdmf")).getroot()
    frames = {}
    for g in index.find("Domain").find("Grid").findall("Grid"):  # the first collection: cells
        step = [i for i in g.findall("Information") if i.get("Name") == "step"][0]
        frames[float(g.find("Time").get("Value"))] = int(step.get("Value"))
    times = sorted(frames)
    picked = [times[0], times[len(times) // 2], times[-1]]
    index_file = os.path.join(out, "picdem.xdmf")
    older = simple.XDMFReader(FileNames=[index_file])
    default = simple.OpenDataFile(index_file)
    check(default.GetXMLName() == "Xdmf3ReaderS", f"OpenDataFile picks {default.GetXMLName()}")
    temporal = simple.Xdmf3ReaderT(FileName=index_file)
    per_grid = {g: simple.OpenDataFile(os.path.join(out, g + ".xdmf")) for g in GRIDS}
    per_grid_t = {g: simple.Xdmf3ReaderT(FileName=os.path.join(out, g + ".xdmf")) for g in GRIDS}
    per_grid_old = {g: simple.XDMFReader(FileNames=[os.path.join(out, g + ".xdmf")]) for g in GRIDS}
    for t in picked:
        want = expected(out, frames[t])
        older.UpdatePipeline(time=t)
        got = blocks(sm.Fetch(older))
        check([n for n, _ in got] == GRIDS, f"XDMF Reader at t = {t}: blocks {[n for n, _ in got]}")
        for (name, data), g in zip(got, GRIDS):
            same(data, (("vtkImageData",) + want[g][1:]) if g == "cells" else want[g],
                 f"XDMF Reader, {g} at t = {t}")
        default.UpdatePipeline(time=t)
        top = blocks(sm.Fetch(default))
        pieces = blocks(top[0][1]) if len(top) == 1 and top[0][1] else []
        check(len(pieces) == 4, f"Xdmf3ReaderS at t = {t}: {len(pieces)} pieces, expected 4")
        for (_, data), g in zip(pieces, GRIDS):
            same(data, want[g], f"Xdmf3ReaderS, picdem.xdmf piece {g} at t = {t}")
        temporal.UpdatePipeline(time=t)
        got = blocks(sm.Fetch(temporal))
        check(len(got) == 4, f"Xdmf3ReaderT at t = {t}: {len(got)} blocks, expected 4")
        for (_, data), g in zip(got, GRIDS):
            same(data, want[g], f"Xdmf3ReaderT, picdem.xdmf block {g} at t = {t}")
        for g, source in per_grid.items():
            source.UpdatePipeline(time=t)
            data = sm.Fetch(source)
            same(data, want[g], f"Xdmf3ReaderS, {g}.xdmf at t = {t}")
            per_grid_t[g].UpdatePipeline(time=t)
            same(sm.Fetch(per_grid_t[g]), want[g], f"Xdmf3ReaderT, {g}.xdmf at t = {t}")
            per_grid_old[g].UpdatePipeline(time=t)
            same(sm.Fetch(per_grid_old[g]), (("vtkImageData",) + want[g][1:]) if g == "cells"
                 else want[g], f"XDMF Reader, {g}.xdmf at t = {t}")
            if g == "particles" and data is not None:
                v = data.GetPointData().GetArray("velocity")
                check(v is not None and v.GetNumberOfComponents() == 3,
                      f"particles.xdmf at t = {t}: no 3-component velocity")
        single = os.path.join(out, "frames", "frame_%06d_particles.xdmf" % frames[t])
        for make in (simple.Xdmf3ReaderS, simple.Xdmf3ReaderT, simple.XDMFReader):
            reader = make(FileNames=[single]) if make is simple.XDMFReader else make(FileName=single)
            reader.UpdatePipeline()
            same(sm.Fetch(reader), want["particles"],
                 f"{reader.GetXMLName()}, {os.path.basename(single)}")
            simple.Delete(reader)
    return len(picked)


if __name__ == "__main__":
    n = main(sys.argv[1])
    finish(f"ParaView's XDMF Reader, Xdmf3ReaderS and Xdmf3ReaderT checked at {n} frame times: "
           "named, stable blocks (older reader), stable pieces or blocks, one plain dataset per "
           "grid file and per frame's particle file")
