"""Renders one frame of a picdem run with ParaView (doc/output.md, "ParaView").

usage: xvfb-run -a pvpython drivers/plot/paraview_frame.py OUTPUT_DIR [--time T] [--out PNG]
                                                          [--width PIXELS] [--colour-max V]
Reads OUTPUT_DIR/picdem.xdmf with ParaView's "XDMF Reader" (it names the blocks: cells, solids,
obstacles, particles) and draws the frame at time T (default: the last one): particles as points
coloured by speed with a labelled colour bar (0 to --colour-max, default the frame's largest
speed), solid and obstacle outlines in dark grey, the tank outline, the time and the case name.
Without a display, ParaView needs xvfb-run (pvpython crashes in XSync otherwise).
"""
import argparse
import os

from paraview.simple import (ColorBy, CreateView, ExtractBlock, GetColorTransferFunction,
                             GetScalarBar, Outline, Render, SaveScreenshot, Show, Text,
                             XDMFReader)


def block(reader, name):
    e = ExtractBlock(Input=reader)
    e.Selectors = ["/Root/" + name]
    return e


def case_name(directory):
    """The case/name of case_resolved.yaml (the run folder's name if it cannot be read)."""
    try:
        with open(os.path.join(directory, "case_resolved.yaml")) as f:
            lines = [line.strip() for line in f]
        at = lines.index("case:", lines.index("case:") + 1)  # the top list, then the case section
        return lines[at + 1].split(":", 1)[1].strip().strip('"')
    except (OSError, ValueError, IndexError):
        return os.path.basename(os.path.abspath(directory))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("directory")
    p.add_argument("--time", type=float)
    p.add_argument("--out")
    p.add_argument("--width", type=int, default=1200)
    p.add_argument("--colour-max", type=float)
    a = p.parse_args()
    reader = XDMFReader(FileNames=[os.path.join(a.directory, "picdem.xdmf")])
    times = list(reader.TimestepValues)
    t = times[-1] if a.time is None else min(times, key=lambda v: abs(v - a.time))
    view = CreateView("RenderView")
    view.ViewTime = t
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    view.UseColorPaletteForBackground = 0
    names = reader.GetProperty("GridInfo")[::2] if reader.GetProperty("GridInfo") else []

    cells = block(reader, "cells")
    tank = Show(Outline(Input=cells), view)
    tank.AmbientColor = tank.DiffuseColor = [0.25, 0.25, 0.25]
    tank.LineWidth = 2.0
    for name in ("solids", "obstacles"):
        if not names or name in names:
            d = Show(block(reader, name), view)
            ColorBy(d, None)
            d.AmbientColor = d.DiffuseColor = [0.25, 0.25, 0.25]
            d.LineWidth = 2.0
    particles = block(reader, "particles")
    particles.UpdatePipeline(t)
    d = Show(particles, view)
    d.SetRepresentationType("Points")
    # Points as wide as the particle spacing h / 2 (2 x 2 per cell; the slab's thickness is h).
    b = reader.GetDataInformation().GetBounds()
    d.PointSize = max(1.0, 0.5 * (b[5] - b[4]) * 0.75 * a.width / max(b[1] - b[0], 1e-30))
    ColorBy(d, ("POINTS", "speed"))
    lut = GetColorTransferFunction("speed")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    top = a.colour_max
    if top is None:
        top = particles.PointData["speed"].GetRange()[1] or 1.0
    lut.RescaleTransferFunction(0.0, top)
    bar = GetScalarBar(lut, view)
    bar.Title = "speed (m/s)"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    bar.TitleFontSize, bar.LabelFontSize = 16, 14
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = [0.80, 0.12]
    bar.ScalarBarLength = 0.7
    bar.Visibility = 1
    d.SetScalarBarVisibility(view, True)
    label = Show(Text(Text="%s   t = %.3f s" % (case_name(a.directory), t)), view)
    label.Color = [0.1, 0.1, 0.1]
    label.FontSize = 16
    label.WindowLocation = "Upper Left Corner"

    # The tank in the left 75 % of the picture, the colour bar right of it.
    bounds = cells.GetDataInformation().GetBounds()
    length, height_m = bounds[1] - bounds[0], bounds[3] - bounds[2]
    height = max(200, int(0.75 * a.width * height_m / max(length, 1e-30) * 1.15))
    view.ViewSize = [a.width, height]
    view.InteractionMode = "2D"
    view.CameraParallelProjection = 1
    Render(view)
    centre = [bounds[0] - 0.02 * length + 0.5 * length / 0.75, 0.5 * (bounds[2] + bounds[3]), 0.0]
    camera = view.GetActiveCamera()
    camera.SetFocalPoint(centre)
    camera.SetPosition(centre[0], centre[1], 1.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetParallelScale(0.5 * height_m * 1.15)
    Render(view)
    out = a.out or os.path.join(a.directory, "pictures", "paraview_%09.4f.png" % t)
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    SaveScreenshot(out, view, ImageResolution=[a.width, height])
    print("wrote %s (t = %.6g s, %d particles)" %
          (out, t, particles.GetDataInformation().GetNumberOfPoints()))


if __name__ == "__main__":
    main()
