"""Render the girder stresses of a run with solids to a PNG with ParaView.

The picture of doc/user_guide.md 3.6: the stress envelope of the girders
(stress_envelope.vtu: the largest von Mises stress of each cell over the
run, MPa) with the frame's members (solution.pvd, last step) drawn as lines
around it, seen from above and from the side of girder 1.

Usage (Debian's python3-paraview; no display needed):
  pvpython --force-offscreen-rendering scripts/render_girder_stresses.py \
      <output directory> <picture.png> [warp factor, default 0: undeformed]
"""
import os
import sys

from paraview.simple import (Calculator, ExtractSurface, ColorBy, CreateView, GetColorTransferFunction,
                             GetScalarBar, PVDReader, SaveScreenshot, Show, Tube,
                             XMLUnstructuredGridReader)

if len(sys.argv) < 3:
    sys.exit("usage: pvpython scripts/render_girder_stresses.py <output directory> "
             "<picture.png> [warp factor]")
directory, picture = sys.argv[1], sys.argv[2]
envelope_file = os.path.join(directory, "stress_envelope.vtu")
frame_file = os.path.join(directory, "solution.pvd")
if not os.path.isfile(envelope_file):
    sys.exit("%s: no stress_envelope.vtu (a transient run with Model/Frame/Solids "
             "writes it)" % directory)

view = CreateView("RenderView")
view.ViewSize = [1600, 900]
view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 1
view.OrientationAxesLabelColor = [0, 0, 0]

# the envelope in MPa (largest von Mises stress of each cell over the run,
# written per cell patch as point data)
envelope = XMLUnstructuredGridReader(FileName=[envelope_file])
mpa = Calculator(Input=envelope, AttributeType="Point Data", ResultArrayName="max_von_mises_MPa",
                 Function="max_von_mises/1e6")
shown = Show(mpa, view)
ColorBy(shown, ("POINTS", "max_von_mises_MPa"))
lut = GetColorTransferFunction("max_von_mises_MPa")
lut.ApplyPreset("Jet", True)
bar = GetScalarBar(lut, view)
bar.Title = "largest von Mises stress over the run (MPa)"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
bar.WindowLocation = "Upper Right Corner"
shown.SetScalarBarVisibility(view, True)
mpa.UpdatePipeline()
lut.RescaleTransferFunction(*mpa.PointData["max_von_mises_MPa"].GetRange())

# the members (end carriages, trolley, hoist, rails) as grey tubes
if os.path.isfile(frame_file):
    frame = PVDReader(FileName=frame_file)
    times = frame.TimestepValues
    view.ViewTime = max(times) if isinstance(times, list) and times else 0.
    tubes = Tube(Input=ExtractSurface(Input=frame), Radius=0.05)
    frame_shown = Show(tubes, view)
    frame_shown.ColorArrayName = ["POINTS", ""]
    frame_shown.DiffuseColor = [0.35, 0.35, 0.35]

view.ResetCamera()
camera = view.GetActiveCamera()
camera.SetViewUp(0, 0, 1)
focal = camera.GetFocalPoint()
camera.SetPosition(focal[0] - 14., focal[1] - 22., focal[2] + 12.)
view.ResetCamera()
camera.Dolly(1.55)
SaveScreenshot(picture, view, ImageResolution=[1600, 900])
print("wrote", picture)
