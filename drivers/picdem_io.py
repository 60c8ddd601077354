"""Reads the output of a picdem run into numpy arrays (numpy and h5py only).

doc/output.md lists every file, column and array with its unit. Example:

    import sys; sys.path.insert(0, "drivers")
    import picdem_io
    run = picdem_io.Run("output/dam_break")
    ts = run.timeseries()                      # column name -> array, one value per step
    print(ts["t"][-1], ts["front_x"][-1])      # s, m
    for frame in run.frames():                 # every frame file, in step order
        p = frame.particles                    # x, z, u, w, speed [m, m/s], id
        print(frame.time, len(p["x"]), frame.cells["pressure"].max())
    ck = run.checkpoint()                      # the newest checkpoint, pressure as (nz, nx)
"""
import csv
import glob
import os

import h5py
import numpy as np

# CSV columns that hold whole numbers.
INTEGER_COLUMNS = {"step", "ppe_iterations", "particles", "solids_in_box", "id"}


def read_csv(path):
    """A picdem CSV file as {column: array} (float64, int64 for the integer columns)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    values = np.array(body, dtype=float).reshape(len(body), len(header))
    return {name: values[:, n].astype(np.int64) if name in INTEGER_COLUMNS else values[:, n]
            for n, name in enumerate(header)}


def _string(value):
    return value.decode("utf-8").rstrip("\0") if isinstance(value, bytes) else str(value)


def _outlines(group):
    """Outlines of a Mixed polyline set as a list of (body_id, (n, 2) array of x, z)."""
    xyz, conn, body = group["xyz"][()], group["connectivity"][()], group["body_id"][()]
    lines, r = [], 0
    while r < len(conn):
        n = int(conn[r + 1])
        lines.append((int(body[len(lines)]), xyz[conn[r + 2:r + 2 + n], :2]))
        r += 2 + n
    return lines


class Frame:
    """One frame file frames/frame_NNNNNN.h5.

    time [s], step, code_version, ranks; cells: {name: (nz, nx) array}, row k = z index;
    particles: {"x", "z", "u", "w", "speed", "id", ...} one value per particle; solids and
    obstacles: lists of (body_id, (n, 2) outline vertices x, z); units: {dataset: unit}.
    """

    def __init__(self, path):
        self.path = path
        with h5py.File(path, "r") as f:
            self.time = float(f.attrs["time"])
            self.step = int(f.attrs["step"])
            self.code_version = _string(f.attrs["code_version"])
            self.ranks = int(f.attrs["ranks"])
            self.units = {}
            f.visititems(lambda name, obj: self.units.__setitem__(name, _string(obj.attrs["units"]))
                         if isinstance(obj, h5py.Dataset) and "units" in obj.attrs else None)
            self.cells = {name: d[0] for name, d in f["cells"].items()}
            self.particles = self._particles(f["particles"])
            self.solids = _outlines(f["solids"])
            self.obstacles = _outlines(f["obstacles"])

    @staticmethod
    def _particles(g):
        out = {"x": g["xyz"][:, 0], "z": g["xyz"][:, 1]}
        for name, d in g.items():
            if name in ("xyz", "connectivity"):
                continue
            if d.ndim == 2 and d.shape[1] == 3:  # in-plane vectors (x, z, 0)
                prefix = {"velocity": ("u", "w")}.get(name, (name + "_x", name + "_z"))
                out[prefix[0]], out[prefix[1]] = d[:, 0], d[:, 1]
            else:
                out[name] = d[()]
        return out


class Checkpoint:
    """A checkpoint file (doc/restart.md, "File layout") with its grids put together.

    t [s], step, ranks, case_yaml; particles: {"x", "z", "u", "w", "id", ...} over all ranks;
    solids: {"id", "x", "z", "theta", "u", "w", "omega"}; pressure (nz, nx) [Pa] and
    cell_state (nz, nx) from every rank's owned cells.
    """

    def __init__(self, path):
        self.path = path
        with h5py.File(path, "r") as f:
            self.t = float(f.attrs["t"])
            self.step = int(f.attrs["step"])
            self.ranks = int(f.attrs["ranks"])
            self.case_yaml = _string(f.attrs["case_yaml"])
            self.particles = {n: d[()] for n, d in f["particles"].items()} if "particles" in f else {}
            self.solids = {n: d[()] for n, d in f["dem"].items()
                           if not n.startswith("spring")} if "dem" in f else {}
            boxes = f["grid/boxes"][()].reshape(-1, 24)
            self.pressure = self._owned(f["grid/p"], boxes, float)
            self.cell_state = self._owned(f["grid/cells"], boxes, np.int32)

    @staticmethod
    def _owned(dataset, boxes, dtype):
        """The global (nz, nx) array of a cell field stored per rank on its storage box."""
        data, lengths = dataset[()], dataset.attrs["slice_lengths"]
        nx, nz = boxes[:, 21].max(), boxes[:, 23].max()
        out = np.zeros((nz, nx), dtype=dtype)
        offsets = np.concatenate([[0], np.cumsum(lengths)])
        for r, box in enumerate(boxes):
            si0, si1, sk0, sk1 = box[16:20]
            oi0, oi1, ok0, ok1 = box[20:24]
            local = data[offsets[r]:offsets[r + 1]].reshape(sk1 - sk0, si1 - si0)
            out[ok0:ok1, oi0:oi1] = local[ok0 - sk0:ok1 - sk0, oi0 - si0:oi1 - si0]
        return out


class Run:
    """The output folder of one run."""

    def __init__(self, directory):
        self.directory = directory

    def path(self, name):
        return os.path.join(self.directory, name)

    def timeseries(self):
        """timeseries.csv: {column: array}, one row per step."""
        return read_csv(self.path("timeseries.csv"))

    def solids(self):
        """solids.csv: {column: array}, one row per solid per frame."""
        return read_csv(self.path("solids.csv"))

    def frame_steps(self):
        """The steps of the frame files on disk, ascending."""
        files = glob.glob(self.path(os.path.join("frames", "frame_*.h5")))
        return sorted(int(os.path.basename(p)[6:-3]) for p in files)

    def frame(self, step):
        return Frame(self.path(os.path.join("frames", "frame_%06d.h5" % step)))

    def frames(self):
        """Every frame, in step order (read one at a time)."""
        for step in self.frame_steps():
            yield self.frame(step)

    def checkpoints(self, directory=None):
        """Paths of the checkpoints (default folder: checkpoints/), oldest first."""
        folder = directory or self.path("checkpoints")
        return sorted(glob.glob(os.path.join(folder, "checkpoint_*.h5")))

    def checkpoint(self, path=None):
        """A checkpoint file (default: the newest one)."""
        if path is None:
            found = self.checkpoints()
            if not found:
                raise FileNotFoundError("no checkpoint in " + self.path("checkpoints"))
            path = found[-1]
        return Checkpoint(path)
