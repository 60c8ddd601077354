"""drivers/plot/paraview_frame.py renders the fixture run's last frame with ParaView.
usage: check_paraview.py OUTPUT_DIR SCRIPT XVFB_RUN PVPYTHON

Asserted: the script exits 0 and reports the last frame's time and particle count (the frame
file's); the PNG is 1200 pixels wide and as high as the tank's aspect ratio gives (0.75 x 1200 x
0.10 / 0.12 x 1.15 = 862); at least 5 % of its pixels have the colour of a particle (saturated:
max - min channel > 0.25) and some are the dark grey of the outlines.
"""
import os
import re
import subprocess
import sys
import time

import h5py
import matplotlib.image
import numpy as np

out, script, xvfb, pvpython = sys.argv[1:5]
png = out + "_paraview.png"
if os.path.exists(png):
    os.remove(png)
# The virtual X server is sometimes not there when pvpython opens its window ("bad X server
# connection", SIGABRT in vtkXOpenGLRenderWindow::WindowInitialize, before the script runs): seen
# under load, while the server of an earlier xvfb-run was still going away. That start-up race of
# the test's display, not the script, is retried after a pause, at most three times, and said so.
for attempt in range(4):
    if attempt:
        time.sleep(5.0)
    r = subprocess.run([xvfb, "-a", pvpython, script, out, "--out", png], capture_output=True,
                       text=True, timeout=300)
    if r.returncode == 0 or "WindowInitialize" not in r.stdout + r.stderr:
        break
    print(f"attempt {attempt + 1}: the X server was not ready for a window (exit {r.returncode});"
          " retried")
failures = []
m = re.search(r"wrote .* \(t = ([0-9.e+-]+) s, (\d+) particles\)", r.stdout)
steps = sorted(int(f[6:-3]) for f in os.listdir(os.path.join(out, "frames")) if f.endswith(".h5"))
with h5py.File(os.path.join(out, "frames", "frame_%06d.h5" % steps[-1]), "r") as f:
    t, n = float(f.attrs["time"]), f["particles/xyz"].shape[0]
if r.returncode != 0 or m is None:
    failures.append(f"exit {r.returncode}: {r.stdout[-500:]} {r.stderr[-500:]}")
else:
    if abs(float(m.group(1)) - t) > 1e-6 or int(m.group(2)) != n:
        failures.append(f"rendered t = {m.group(1)}, {m.group(2)} particles; last frame {t}, {n}")
    image = matplotlib.image.imread(png)[:, :, :3]
    if image.shape[:2] != (862, 1200):
        failures.append(f"picture {image.shape[1]} x {image.shape[0]}, expected 1200 x 862")
    saturated = (image.max(axis=2) - image.min(axis=2) > 0.25).mean()
    grey = (np.abs(image - 0.25).max(axis=2) < 0.05).mean()
    if saturated < 0.05 or grey <= 0.0:
        failures.append(f"{saturated:.3f} of the pixels particle-coloured, {grey:.4f} outline grey")
if failures:
    print("\n".join("FAIL: " + f for f in failures))
    sys.exit(1)
print(f"ParaView rendered t = {t} s with {n} particles: {saturated:.2f} of the picture particles")
