#!/usr/bin/env pvpython
"""Open a coaxfit result in ParaView: the assembled shaft and hub.

    pvpython tools/paraview/view.py OUTPUT_DIR [--scale S] [--png-dir DIR]
                                              [--no-png] [--angle DEG]

OUTPUT_DIR is a run's result directory (the one holding solution.pvd; for a
run with Fit/Case = all, its mean/ case is taken unless a case directory is
given). The script builds one pipeline:

  * the full longitudinal section: the computed quarter (r >= 0, z >= 0)
    mirrored about the mid-plane and about the axis, each body warped by
    displacement_mm (so the shaft and the hub meet at the joint and open only
    where they separate), coloured by von Mises;
  * the revolved 3D part, cut open (a sector of 360 - ANGLE degrees removed),
    coloured the same way.

The colour range leaves out the stress peak at the ends of the contact
(the edge singularity, within Output/Edge distance of the edge as in
summary.json, else 5 % of the contact length); the peak is printed and drawn
in the above-range colour. Stresses are cylindrical components (r, z, theta):
mirrored about the mid-plane sigma_rz changes sign and the copy says so; the
half of the section at r < 0 is the same meridian turned by 180 degrees, where
cylindrical components are unchanged.

Without --no-png it saves section.png and part_3d.png into
OUTPUT_DIR_views/ (beside the result directory, which coaxfit replaces as a
whole) or --png-dir. Without a display (no DISPLAY) it restarts itself under
xvfb-run when that is installed.

From the ParaView GUI: set COAXFIT_OUTPUT=OUTPUT_DIR in the environment and
start `paraview --script=tools/paraview/view.py`, or run the file from
View > Python Shell > Run Script; the pipeline appears in the Pipeline
Browser under the names used below, ready to be changed.
"""

import json
import os
import shutil
import sys


def parse_arguments(argv):
    """The options (a dict); argv without the program name."""
    options = {"dir": os.environ.get("COAXFIT_OUTPUT", ""), "scale": None,
               "png_dir": None, "png": True, "angle": 270.0}
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("-h", "--help"):
            print(__doc__)
            sys.exit(0)
        elif a in ("--scale", "--png-dir", "--angle"):
            if i + 1 >= len(argv):
                sys.exit("view.py: %s needs a value" % a)
            value = argv[i + 1]
            if a == "--png-dir":
                options["png_dir"] = value
            else:
                try:
                    number = float(value)
                except ValueError:
                    sys.exit("view.py: %s must be a number, not '%s'" % (a, value))
                if a == "--scale" and not number > 0:
                    sys.exit("view.py: --scale must be > 0, not %s" % value)
                if a == "--angle" and not 0 < number <= 360:
                    sys.exit("view.py: --angle must be in (0, 360], not %s" % value)
                options["scale" if a == "--scale" else "angle"] = number
            i += 1
        elif a == "--no-png":
            options["png"] = False
        elif a.startswith("-"):
            sys.exit("view.py: unknown option %s (see --help)" % a)
        else:
            options["dir"] = a
        i += 1
    if not options["dir"]:
        sys.exit("view.py: give the result directory (or set COAXFIT_OUTPUT)")
    return options


def result_directory(path):
    """The directory holding solution.pvd: PATH itself or PATH/mean."""
    for candidate in (path, os.path.join(path, "mean")):
        if os.path.isfile(os.path.join(candidate, "solution.pvd")):
            return os.path.abspath(candidate)
    sys.exit("view.py: no solution.pvd in %s (was it written with Output/Write vtu "
             "= true?)" % path)


def restart_under_xvfb():
    """Without a display pvpython cannot render: run this script again under
    xvfb-run and exit with its exit code. A virtual X server that is not
    ready when the first window opens aborts pvpython (SIGABRT, "bad X
    server connection", seen when several start at once and on a busy
    machine): up to 3 tries, each on a display of its own."""
    if os.environ.get("DISPLAY") or os.environ.get("COAXFIT_VIEW_XVFB"):
        return
    xvfb = shutil.which("xvfb-run")
    if xvfb is None:
        sys.exit("view.py: no display (DISPLAY unset) and no xvfb-run; install "
                 "Debian's xvfb or run with a display")
    import subprocess
    os.environ["COAXFIT_VIEW_XVFB"] = "1"
    # sys.executable names VTK's interpreter, not pvpython: take pvpython.
    interpreter = shutil.which("pvpython") or sys.executable
    for attempt in range(3):
        server = 100 + (os.getpid() * 3 + attempt * 97) % 800
        code = subprocess.call([xvfb, "-a", "-n", str(server), interpreter] + sys.argv)
        # 0 done, 1 this script's own error message; anything else is
        # pvpython aborted by the display (134, -6, or xvfb-run's own code,
        # e.g. 5 when it could not clean up after the abort).
        if code in (0, 1):
            break
        print("view.py: the virtual display failed (exit %d), trying again" % code,
              file=sys.stderr)
    sys.exit(code)


try:
    import paraview  # noqa: F401
except ImportError:
    sys.exit("view.py: run it with pvpython (Debian: apt-get install paraview)")

# In the GUI (paraview --script, or the Python shell) argv is not this
# script's command line: the directory comes from COAXFIT_OUTPUT.
from_command_line = bool(sys.argv) and sys.argv[0].endswith(".py")
options = parse_arguments(sys.argv[1:] if from_command_line else [])
directory = result_directory(options["dir"])
restart_under_xvfb()

from paraview.simple import (AppendDatasets, Calculator, ColorBy, CreateView,  # noqa: E402
                             ExtractBlock, ExtractSurface, GetColorTransferFunction,
                             GetScalarBar, MergeBlocks, PVDReader, Reflect, Render,
                             RenameSource, RotationalExtrusion, SaveScreenshot, SetActiveView,
                             Show, Text, Transform, WarpByVector)
from paraview import servermanager  # noqa: E402
from paraview.vtk.util.numpy_support import vtk_to_numpy  # noqa: E402
import numpy  # noqa: E402


def summary(directory):
    """summary.json of the run, or {} if absent."""
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def block(reader, name):
    """One named block of the collection, as its own pipeline item."""
    extract = ExtractBlock(Input=reader, Selectors=["/Root/" + name])
    merged = MergeBlocks(Input=extract)
    RenameSource(name, merged)
    return merged


def fetch_points(source):
    """Points and point arrays of a (merged) source as numpy arrays."""
    data = servermanager.Fetch(source)
    points = vtk_to_numpy(data.GetPoints().GetData())
    arrays = {}
    pd = data.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        arrays[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i))
    return points, arrays


def mirrored(source, plane, negate, name):
    """SOURCE and its mirror image about PLANE ('X' or 'Y' through 0), with
    the arrays in NEGATE sign-flipped in the image."""
    image = Reflect(Input=source, Plane=plane, CopyInput=0, FlipAllInputArrays=1)
    for array in negate:
        image = Calculator(Input=image, ResultArrayName=array, Function="-" + array)
    both = MergeBlocks(Input=AppendDatasets(Input=[source, image]))
    RenameSource(name, both)
    return both


run = summary(directory)
reader = PVDReader(FileName=os.path.join(directory, "solution.pvd"))
RenameSource("solution.pvd", reader)
reader.UpdatePipeline()
bodies = MergeBlocks(Input=ExtractBlock(Input=reader, Selectors=["/Root/shaft", "/Root/hub"]))
RenameSource("shaft and hub", bodies)
surface = block(reader, "contact_surface")

# The scale of the drawing: the given one, or the one that draws the largest
# displacement as 3 % of the part's outer radius (the warped bodies meet at
# the joint at any scale: both move by the scaled displacement).
points, arrays = fetch_points(bodies)
r_outer = float(points[:, 0].max())
u = arrays["displacement_mm"]
u_max = float(numpy.abs(u[:, :2]).max())
scale = options["scale"] or (0.03 * r_outer / u_max if u_max > 0 else 1.0)

# The colour range away from the ends of the contact (edge singularity).
contact_points, _ = fetch_points(surface)
joint_radius = float(contact_points[:, 0].mean())
contact_end = float(contact_points[:, 1].max())
edge = (run.get("design", {}) or {}).get("edge_distance")
if not isinstance(edge, (int, float)) or edge <= 0:
    edge = 0.05 * 2 * contact_end
vm = arrays["von_Mises_MPa"]
near_edge = numpy.hypot(points[:, 0] - joint_radius, points[:, 1] - contact_end) < edge
away = vm[~near_edge] if (~near_edge).any() else vm
colour_range = [float(away.min()), float(away.max())]
peak = float(vm.max())
print("coaxfit view: %s" % directory)
print("  displacement drawn x %.4g (largest %.4g mm)" % (scale, u_max))
print("  von Mises colour range %.4g - %.4g MPa (without %.4g mm around the edge of "
      "the contact at r = %.6g, z = %.6g; peak there %.4g MPa)"
      % (colour_range[0], colour_range[1], edge, joint_radius, contact_end, peak))

warped = WarpByVector(Input=bodies, Vectors=["POINTS", "displacement_mm"], ScaleFactor=scale)
RenameSource("warped x%.3g" % scale, warped)
# sigma_rz is odd in z: it changes sign in the mirror image about z = 0; the
# displacement vectors are flipped by the filter (FlipAllInputArrays).
half = mirrored(warped, "Y", ["sigma_rz_MPa"], "mirrored about the mid-plane")
section = mirrored(half, "X", [], "full section")

lut = GetColorTransferFunction("von_Mises_MPa")
if not lut.ApplyPreset("Turbo", True):
    lut.ApplyPreset("Jet", True)
lut.AutomaticRescaleRangeMode = "Never"
lut.UseAboveRangeColor = 1
lut.AboveRangeColor = [1.0, 1.0, 1.0]


def show_coloured(source, view, title):
    display = Show(source, view)
    ColorBy(display, ("POINTS", "von_Mises_MPa"))
    lut.RescaleTransferFunction(colour_range[0], colour_range[1])
    display.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)
    bar.Title = "von Mises (MPa)"
    bar.ComponentTitle = ""
    bar.AddRangeLabels = 1
    text = Text(Text=title)
    text_display = Show(text, view)
    text_display.WindowLocation = "Upper Center"
    text_display.FontSize = 14
    return display


size = [1400, 900]
section_view = CreateView("RenderView")
section_view.ViewSize = size
section_view.OrientationAxesVisibility = 0
show_coloured(section, section_view,
              "coaxfit: longitudinal section, displacement x %.3g; white: above %.4g MPa "
              "(edge peak %.4g MPa)" % (scale, colour_range[1], peak))
section_view.InteractionMode = "2D"
section_view.ResetCamera()
section_view.CameraPosition = [0, 0, 10 * r_outer]
section_view.CameraFocalPoint = [0, 0, 0]
section_view.CameraViewUp = [0, 1, 0]
section_view.ResetCamera()
Render(section_view)

# The 3D part: the half section (r >= 0) turned so that the axis is z, and
# revolved by ANGLE degrees (the rest stays open to show the section).
turned = Transform(Input=ExtractSurface(Input=half))
turned.Transform.Rotate = [90.0, 0.0, 0.0]
part = RotationalExtrusion(Input=turned, Angle=options["angle"],
                           Resolution=max(12, int(options["angle"] / 5)), Capping=1)
RenameSource("3D part", part)
part_view = CreateView("RenderView")
part_view.ViewSize = size
part_view.OrientationAxesVisibility = 0
show_coloured(part, part_view,
              "coaxfit: assembled part, cut open, displacement x %.3g" % scale)
part_view.CameraPosition = [2.2 * r_outer, -3.0 * r_outer, 2.0 * r_outer]
part_view.CameraFocalPoint = [0, 0, 0]
part_view.CameraViewUp = [0, 0, 1]
part_view.ResetCamera()
Render(part_view)
SetActiveView(part_view)

if options["png"]:
    # Beside the directory given (for a Case = all run not inside it).
    png_dir = options["png_dir"] or os.path.abspath(options["dir"]).rstrip("/") + "_views"
    os.makedirs(png_dir, exist_ok=True)
    for name, view in (("section.png", section_view), ("part_3d.png", part_view)):
        path = os.path.join(png_dir, name)
        # Written beside and renamed: a killed or failed view leaves the
        # earlier picture, never half of one.
        partial = os.path.join(png_dir, ".%s.partial-%d.png" % (name[:-4], os.getpid()))
        try:
            if not SaveScreenshot(partial, view, ImageResolution=size):
                sys.exit("view.py: ParaView could not save %s" % path)
            os.replace(partial, path)
        finally:
            if os.path.exists(partial):
                os.remove(partial)
        print("  wrote %s" % path)
