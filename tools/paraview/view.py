#!/usr/bin/env pvpython
"""Open a coaxfit result in ParaView: the assembled part and its contact.

    pvpython tools/paraview/view.py OUTPUT_DIR [--field NAME] [--scale S]
                                   [--png-dir DIR] [--no-png] [--angle DEG]
                                   [--state FILE.pvsm]

OUTPUT_DIR is a run's result directory (the one holding solution.pvd; for a
run with Fit/Case = all, its mean/ case is taken unless a case directory is
given). Every block of solution.pvd is followed: an unstructured grid is a
body (shaft and hub, or every body of an assembly: Assembly/Bodies), a
polydata block is a contact surface (contact_surface, or contact_<inner>_
<outer> for each joint of an assembly). A half model (every z >= 0, what coaxfit computes for
plain cylinders and symmetric sections; summary.json's
geometry.sections.model says which for sections) is mirrored about the
mid-plane z = 0; a whole model is drawn as it is.

The views, each titled with the case name (from summary.json, else the
directory name) and with a length scale:

  section          the full longitudinal section, axis horizontal, each
                   body warped by displacement_mm x S (the bodies meet at the
                   joint and open only where they separate) and coloured by
                   the field; the contact surface drawn over the joint as a
                   thick line coloured by the contact pressure, white where
                   separated;
  part_3d          the revolved part, cut open (360 - DEG degrees removed),
                   with an axes grid in mm;
  contact_chart    contact pressure (left axis) and gap (right axis) along
                   the joint, z in mm (z >= 0 for a half model); the seats
                   of a joint beside a relief groove each drawn apart;
  separation_zoom  each separated zone close up (separation_zoom_2, ... for
                   further zones, largest gap first, at most 4): the radial
                   displacement relative to a parabola fitted to the hub's
                   bore over the zone (the joint runs nearly straight),
                   magnified by a factor of its own that draws the zone's
                   largest gap as a tenth of the picture's height (axial
                   lengths true), shaft and hub in plain colours and both
                   sides of the joint as lines coloured by pressure.

Colours: the field NAME (default von_Mises_MPa; any scalar array of the
bodies, e.g. sigma_tt_MPa) with a colour range of each body's own (copied by
a Calculator into BODY_FIELD, e.g. shaft_von_Mises_MPa, so that each body
has its own lookup table and scalar bar). The range leaves out the peak at the
ends of the contact and of its pieces beside a groove (the edge singularity,
within Design/Edge distance of the edge as in summary.json, else 5 % of the
contact length); values above the range are drawn magenta, below it black,
and the peaks are printed.
Stresses are cylindrical components (r, z, theta): mirrored about the
mid-plane sigma_rz changes sign and the copy says so; the half of the section
at r < 0 is the same meridian turned by 180 degrees, where cylindrical
components are unchanged.

Without --no-png it saves section.png, part_3d.png, contact_chart.png and
separation_zoom*.png into OUTPUT_DIR_views/ (beside the result directory,
which coaxfit replaces as a whole) or --png-dir; each is written under a
temporary name and renamed, and refused when ParaView drew it in one colour
(a view not drawn). --state saves the pipeline as a ParaView state file
(File > Load State). Without a display (no DISPLAY) it restarts itself under
xvfb-run when that is installed. Exit code 1 with a message on bad input.

From the ParaView GUI: set COAXFIT_OUTPUT=OUTPUT_DIR in the environment and
start `paraview --script=tools/paraview/view.py`, or run the file from
View > Python Shell > Run Script. The views are placed in a layout
"coaxfit CASE" (section and 3D part above, chart and the largest separated
zone below; a tab for each further zone) and every step appears in the
Pipeline Browser under the names used above. The GUI writes nothing unless
asked: COAXFIT_PNG_DIR=DIR writes the PNGs there, COAXFIT_STATE=FILE.pvsm
the state; COAXFIT_VIEW_OPTIONS holds further options as on the command
line (e.g. "--field sigma_tt_MPa --scale 50"). Messages go to the GUI's
Output Messages. When COAXFIT_VIEW_READY names a file, it is created once
the views are in place (for scripts that wait for the GUI).
"""

import json
import math
import os
import shlex
import shutil
import sys

# The colours of the pictures (R, G, B in 0..1).
ABOVE_RANGE = [1.0, 0.0, 1.0]     # magenta: above a colour range
BELOW_RANGE = [0.0, 0.0, 0.0]     # black: below a body's colour range
SEPARATED = [1.0, 1.0, 1.0]       # white: the contact line where open
SHAFT_PLAIN = [0.25, 0.45, 0.75]  # the zoom's plain colours: shaft (body 0),
HUB_PLAIN = [0.55, 0.55, 0.50]    # hub (body 1; further bodies alternate)
# The chart's series (pressure, gap) for each contact surface in turn.
SERIES_COLOURS = [([0.0, 0.0, 0.6], [0.0, 0.67, 0.0]),
                  ([0.6, 0.3, 0.0], [0.0, 0.6, 0.6])]
PICTURE = [1400, 900]
MAX_ZOOMS = 4


class ViewError(Exception):
    """A message for the user: the command line exits with it (code 1),
    the GUI prints it."""


def parse_arguments(argv, directory=""):
    """The options (a dict); argv without the program name."""
    options = {"dir": directory, "scale": None, "png_dir": None, "png": True,
               "angle": 270.0, "field": "von_Mises_MPa", "state": None}
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("-h", "--help"):
            print(__doc__)
            sys.exit(0)
        elif a in ("--scale", "--png-dir", "--angle", "--field", "--state"):
            if i + 1 >= len(argv):
                raise ViewError("%s needs a value" % a)
            value = argv[i + 1]
            if a in ("--png-dir", "--field", "--state"):
                options[a[2:].replace("-", "_")] = value
            else:
                try:
                    number = float(value)
                except ValueError:
                    raise ViewError("%s must be a number, not '%s'" % (a, value))
                if a == "--scale" and not number > 0:
                    raise ViewError("--scale must be > 0, not %s" % value)
                if a == "--angle" and not 0 < number <= 360:
                    raise ViewError("--angle must be in (0, 360], not %s" % value)
                options[a[2:]] = number
            i += 1
        elif a == "--no-png":
            options["png"] = False
        elif a.startswith("-"):
            raise ViewError("unknown option %s (see --help)" % a)
        else:
            options["dir"] = a
        i += 1
    if not options["dir"]:
        raise ViewError("give the result directory (or set COAXFIT_OUTPUT)")
    return options


def in_gui():
    """Whether this runs inside the ParaView GUI (paraview --script, or its
    Python shell) rather than pvpython, which passes the script's name."""
    try:
        executable = os.path.basename(os.path.realpath("/proc/self/exe"))
    except OSError:
        executable = ""
    if executable.startswith("paraview"):
        return True
    return not (sys.argv and sys.argv[0].endswith(".py"))


def gui_options():
    """The options in the GUI: COAXFIT_OUTPUT and COAXFIT_VIEW_OPTIONS; PNGs
    only into COAXFIT_PNG_DIR, the state only into COAXFIT_STATE."""
    options = parse_arguments(shlex.split(os.environ.get("COAXFIT_VIEW_OPTIONS", "")),
                              os.environ.get("COAXFIT_OUTPUT", ""))
    options["png_dir"] = os.environ.get("COAXFIT_PNG_DIR") or None
    options["png"] = options["png_dir"] is not None
    options["state"] = os.environ.get("COAXFIT_STATE") or options["state"]
    return options


def result_directory(path):
    """The directory holding solution.pvd: PATH itself or PATH/mean."""
    for candidate in (path, os.path.join(path, "mean")):
        if os.path.isfile(os.path.join(candidate, "solution.pvd")):
            return os.path.abspath(candidate)
    raise ViewError("no solution.pvd in %s (was it written with Output/Write vtu "
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
        raise ViewError("no display (DISPLAY unset) and no xvfb-run; install "
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

from paraview.simple import (AppendDatasets, AssignViewToLayout, Calculator,  # noqa: E402
                             ColorBy, CreateLayout, CreateView, Delete, ExtractBlock,
                             ExtractSelection, ExtractSurface, GetColorTransferFunction,
                             GetLayout, GetLayouts, GetScalarBar, GetViewsInLayout,
                             IDSelectionSource, MergeBlocks, PVDReader, Reflect,
                             RemoveLayout, Render, RenameSource, RenameView,
                             RotationalExtrusion, Ruler, SaveScreenshot, SaveState,
                             SetActiveSource, SetActiveView, Show, Text, Transform,
                             WarpByVector)
from paraview import servermanager  # noqa: E402
from paraview.vtk.util.numpy_support import vtk_to_numpy  # noqa: E402
import numpy  # noqa: E402


# ---------------------------------------------------------------------------
# The data

def read_summary(directory):
    """summary.json of the run, or {} if absent."""
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def first_leaf(data):
    """The first dataset inside DATA that is not a collection (or None)."""
    if data is None or not data.IsA("vtkCompositeDataSet"):
        return data
    iterator = data.NewIterator()
    iterator.InitTraversal()
    return None if iterator.IsDoneWithTraversal() else iterator.GetCurrentDataObject()


def blocks_of(reader):
    """(name, kind) of each top-level block of the collection, in order;
    kind is "body" for an unstructured grid and "contact" for polydata."""
    collection = servermanager.Fetch(reader)
    found = []
    for i in range(collection.GetNumberOfBlocks()):
        name = collection.GetMetaData(i).Get(collection.NAME())
        leaf = first_leaf(collection.GetBlock(i))
        if leaf is None or not name:
            continue
        if leaf.IsA("vtkUnstructuredGrid"):
            found.append((name, "body"))
        elif leaf.IsA("vtkPolyData"):
            found.append((name, "contact"))
    return found


def fetch_points(source):
    """Points (r, z) and point arrays of a merged source as numpy arrays."""
    data = servermanager.Fetch(source)
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    arrays = {}
    pd = data.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        arrays[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i)).astype(float)
    return points[:, :2], arrays


def contact_pieces(source):
    """The point indices of each cell (polyline) of a merged contact
    surface, or of all its points if it has no cells."""
    data = servermanager.Fetch(source)
    pieces = []
    for cell in range(data.GetNumberOfCells()):
        ids = data.GetCell(cell).GetPointIds()
        pieces.append(numpy.array([ids.GetId(k) for k in range(ids.GetNumberOfIds())],
                                  dtype=int))
    return pieces or [numpy.arange(data.GetNumberOfPoints())]


class Part:
    """One block of solution.pvd: its pipeline item (merged into one
    dataset), its points and point arrays."""

    def __init__(self, reader, name, kind):
        self.name, self.kind = name, kind
        block = named("%s: block" % name, ExtractBlock(Input=reader,
                                                        Selectors=["/Root/" + name]))
        self.source = named(name, MergeBlocks(Input=block))
        self.points, self.arrays = fetch_points(self.source)
        # A contact surface's pieces: the point indices of each polyline
        # (several for a joint beside a relief groove).
        self.pieces = contact_pieces(self.source) if kind == "contact" else []


def contact_zones(surface):
    """The separated zones of a contact surface, in z order: dicts with
    z_from, z_to (the contact points around the zone), z_bore and u_bore
    (the zone's points with these two, and the hub's radial displacement
    there), z_gap, r, gap and u_hub (where the gap is largest) and the
    surface."""
    z = surface.points[:, 1]
    order = numpy.argsort(z, kind="stable")
    separated = surface.arrays["contact_status"][order] < 0.5
    zones = []
    i = 0
    while i < len(order):
        if not separated[i]:
            i += 1
            continue
        j = i
        while j + 1 < len(order) and separated[j + 1]:
            j += 1
        members = order[i:j + 1]
        widest = members[numpy.argmax(surface.arrays["gap_mm"][members])]
        before, after = order[max(i - 1, 0)], order[min(j + 1, len(order) - 1)]
        u_hub = surface.arrays["displacement_mm"][:, 0]
        around = order[max(i - 1, 0):min(j + 2, len(order))]
        zones.append({"surface": surface,
                      "z_from": float(z[before]), "z_to": float(z[after]),
                      "z_bore": z[around], "u_bore": u_hub[around],
                      "z_gap": float(z[widest]),
                      "r": float(surface.points[widest, 0]),
                      "gap": float(surface.arrays["gap_mm"][widest]),
                      "u_hub": float(u_hub[widest])})
        i = j + 1
    return zones


# ---------------------------------------------------------------------------
# Pipeline pieces

def named(name, source):
    """SOURCE, named NAME in the Pipeline Browser."""
    RenameSource(name, source)
    return source


def mirrored(source, plane, negate, name):
    """SOURCE and its mirror image about PLANE ('X' or 'Y' through 0), with
    the arrays in NEGATE sign-flipped in the image."""
    image = named("%s: mirror image" % name,
                  Reflect(Input=source, Plane=plane, CopyInput=0, FlipAllInputArrays=1))
    for array in negate:
        image = named("%s: -%s" % (name, array),
                      Calculator(Input=image, ResultArrayName=array, Function="-" + array))
    both = named("%s: both" % name, AppendDatasets(Input=[source, image]))
    return named(name, MergeBlocks(Input=both))


def mirrored_line(source, plane, name):
    """A polyline SOURCE and its mirror image about PLANE ('X' or 'Y'
    through 0), for colouring by scalars. (Reflect turns a polyline's
    points 0, 1, ..., n-1 into 0, n-1, ..., 1: a segment from the first
    point to the last would cross the line. A Transform keeps the order.)"""
    image = named("%s: mirror image" % name, Transform(Input=source))
    image.Transform.Scale = [-1.0, 1.0, 1.0] if plane == "X" else [1.0, -1.0, 1.0]
    both = named("%s: both" % name, AppendDatasets(Input=[source, image]))
    return named(name, MergeBlocks(Input=both))


def radial_warp(source, vector, factor, trend, name):
    """SOURCE warped by FACTOR times the radial component of its point
    vector VECTOR less TREND = (z0, a, b, c), the parabola
    a + b (z - z0) + c (z - z0)^2 (axial positions kept: lengths along z
    stay true)."""
    z0, a, b, c = trend
    radial = named("%s: radial part of %s" % (name, vector), Calculator(
        Input=source, ResultArrayName="radial_" + vector,
        Function="(%s_X - (%.17g + %.17g*(coordsY - %.17g) + %.17g*(coordsY - %.17g)^2))*iHat"
                 % (vector, a, b, z0, c, z0)))
    return named(name, WarpByVector(Input=radial, Vectors=["POINTS", "radial_" + vector],
                                    ScaleFactor=factor))


def towards_camera(source, distance, name):
    """SOURCE moved by DISTANCE towards the camera of a section view (which
    looks along +z): a line drawn over the bodies it lies between."""
    moved = Transform(Input=source)
    moved.Transform.Translate = [0.0, 0.0, -distance]
    return named(name, moved)


def colour_range(low, high):
    """The colour range for values LOW..HIGH: 0.1 % of their magnitude
    wider on each side (values that differ by round-off only are not drawn
    above or below it), at least 1 % of their magnitude wide (round-off is
    not spread over the colours), and not below 0 for values that are not."""
    magnitude = max(abs(low), abs(high), 1e-30)
    pad = 1e-3 * magnitude
    if high - low < 1e-2 * magnitude:
        pad = 0.5e-2 * magnitude
        low = high = 0.5 * (low + high)
    start = low - pad
    if low >= 0.0 > start:
        start = 0.0
    return [start, high + pad]


def nice_length(length):
    """The largest 1, 2 or 5 times a power of ten not above LENGTH."""
    power = 10.0 ** math.floor(math.log10(length))
    for step in (5.0, 2.0, 1.0):
        if step * power <= length:
            return step * power
    return power


def add_ruler(view, start, end, name):
    """A length scale from START to END (points of a section view),
    labelled in mm."""
    ruler = named(name, Ruler(Point1=list(start), Point2=list(end)))
    display = Show(ruler, view)
    display.LabelFormat = "%-.3g mm"
    display.Color = [1.0, 1.0, 1.0]
    display.AxisColor = [1.0, 1.0, 1.0]
    display.FontSize = 14
    display.AxisLineWidth = 2.0
    return ruler


def add_title(view, lines, name):
    """The title LINES (the case and the view, then notes on the colours)
    as one block at the top left of VIEW (one block: no overlap however
    small the view)."""
    source = named(name, Text(Text="\n".join(lines)))
    display = Show(source, view)
    display.WindowLocation = "Upper Left Corner"
    display.Justification = "Left"
    display.FontSize = 14
    return source


def colour_bar(lut, view, title, position, length, horizontal=False):
    """LUT's scalar bar in VIEW at POSITION (fractions of the view)."""
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.HorizontalTitle = 1
    bar.AddRangeLabels = 1
    bar.RangeLabelFormat = "%-#.4g"
    bar.TitleFontSize = 14
    bar.LabelFontSize = 13
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Horizontal" if horizontal else "Vertical"
    bar.Position = list(position)
    bar.ScalarBarLength = length
    bar.Visibility = 1
    return bar


def save_png(view, path, resolution=PICTURE):
    """VIEW saved as PATH: written beside and renamed, so a killed or failed
    view leaves the earlier picture, never half of one; refused when
    ParaView drew one colour only (a view that was not drawn)."""
    directory = os.path.dirname(path)
    base = os.path.basename(path)[:-4]
    partial = os.path.join(directory, ".%s.partial-%d.png" % (base, os.getpid()))
    try:
        # Fonts at their size, also for a smaller view of the GUI's layout.
        if not SaveScreenshot(partial, view, ImageResolution=list(resolution),
                              FontScaling="Do not scale fonts"):
            raise ViewError("ParaView could not save %s" % path)
        if not drawn(partial):
            raise ViewError("ParaView drew %s in one colour (the view was not "
                            "drawn); the earlier file is kept" % path)
        os.replace(partial, path)
    finally:
        if os.path.exists(partial):
            os.remove(partial)
    print("  wrote %s" % path)


def drawn(png):
    """Whether the picture PNG holds more than one colour."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    if scalars is None:
        return False
    pixels = vtk_to_numpy(scalars)
    return bool((pixels != pixels[0]).any())


# ---------------------------------------------------------------------------
# The views

class Viewer:
    """The pipeline, the views and the pictures of one result."""

    def __init__(self, options, gui):
        self.options, self.gui = options, gui
        self.directory = result_directory(options["dir"])
        self.run = read_summary(self.directory)
        case = self.run.get("case")
        if not isinstance(case, str) or not case:
            case = os.path.basename(self.directory)
            if case in ("min", "mean", "max"):
                case = os.path.basename(os.path.dirname(self.directory)) + "/" + case
        self.case = case
        self.field = options["field"]
        self.views = {}
        self.zoom_views = []

    # -- the data -----------------------------------------------------------

    def read(self):
        """Open solution.pvd, split it into bodies and contact surfaces,
        check the field."""
        self.reader = named("solution.pvd", PVDReader(
            FileName=os.path.join(self.directory, "solution.pvd")))
        self.reader.UpdatePipeline()
        kinds = blocks_of(self.reader)
        self.bodies = [Part(self.reader, n, k) for n, k in kinds if k == "body"]
        self.contacts = [Part(self.reader, n, k) for n, k in kinds if k == "contact"]
        if not self.bodies:
            raise ViewError("%s/solution.pvd has no body (no unstructured grid block)"
                            % self.directory)
        allowed = sorted(set.intersection(*[
            set(a for a, v in b.arrays.items() if v.ndim == 1 and a != "body_id")
            for b in self.bodies]))
        if self.field not in allowed:
            raise ViewError("no field '%s' in the bodies; --field takes one of: %s"
                            % (self.field, ", ".join(allowed)))
        every_z = numpy.concatenate([p.points[:, 1] for p in self.bodies + self.contacts])
        extent = float(numpy.abs(every_z).max()) or 1.0
        # A half model has z >= 0 only, but so may a whole one drawn from
        # z = 0 (a pulley flush with the shaft end): summary.json says.
        model = self.run.get("geometry", {}).get("sections", {}).get("model")
        self.half = (model == "half") if model else \
            bool(every_z.min() >= -1e-9 * extent)
        self.r_outer = float(numpy.concatenate([b.points[:, 0] for b in self.bodies]).max())
        self.z_low = -extent if self.half else float(every_z.min())
        self.z_high = float(every_z.max())

    def analyse(self):
        """Scales, colour ranges and separated zones; print them."""
        # The scale of the drawing: the given one, or the one that draws the
        # largest displacement as 3 % of the part's outer radius (the warped
        # bodies meet at the joint at any scale: both move by the scaled
        # displacement).
        u_max = max(float(numpy.abs(b.arrays["displacement_mm"][:, :2]).max())
                    for b in self.bodies)
        self.scale = self.options["scale"] or (0.03 * self.r_outer / u_max
                                               if u_max > 0 else 1.0)

        # The ends of the contact's pieces (not the mid-plane of a half
        # model): the colour ranges leave out the edge singularity around
        # them, also beside a relief groove.
        self.ends = []
        length = 0.0
        for c in self.contacts:
            z = c.points[:, 1]
            for piece in c.pieces:
                for i in (piece[numpy.argmin(z[piece])], piece[numpy.argmax(z[piece])]):
                    if not (self.half and abs(z[i]) <= 1e-9 * (abs(self.z_high) or 1.0)):
                        self.ends.append(c.points[i])
            length = max(length, (2.0 if self.half else 1.0) * float(z.max() - z.min()))
        edge = (self.run.get("design", {}) or {}).get("edge_distance")
        self.edge = edge if isinstance(edge, (int, float)) and edge > 0 else 0.05 * length

        print("coaxfit view: %s (case %s, %s model)"
              % (self.directory, self.case, "half" if self.half else "whole"))
        print("  displacement drawn x %.4g (largest %.4g mm)" % (self.scale, u_max))
        self.ranges = {}
        for body in self.bodies:
            values = body.arrays[self.field]
            away = self.away_from_edges(body.points)
            kept = values[away] if away.any() else values
            low, high = float(kept.min()), float(kept.max())
            self.ranges[body.name] = colour_range(low, high)
            print("  %s %s: %.4g - %.4g farther than %.4g mm from the edges of the "
                  "contact (colour range %.4g - %.4g), %.4g - %.4g with them"
                  % (body.name, self.field, low, high, self.edge, self.ranges[body.name][0],
                     self.ranges[body.name][1], values.min(), values.max()))

        # Contact pressure away from the edges; the separated zones.
        self.zones = []
        p_high, self.p_peak = 0.0, 0.0
        for c in self.contacts:
            p = c.arrays["contact_pressure_MPa"]
            away = self.away_from_edges(c.points)
            high = float((p[away] if away.any() else p).max())
            p_high, self.p_peak = max(p_high, high), max(self.p_peak, float(p.max()))
            zones = contact_zones(c)
            self.zones += zones
            largest = max(zones, key=lambda zone: zone["gap"]) if zones else None
            print("  %s: %d points, %d in contact, %d separated zone%s%s; pressure "
                  "up to %.4g MPa away from the edges, %.4g MPa with them"
                  % (c.name, len(p), int((c.arrays["contact_status"] > 0.5).sum()),
                     len(zones), "" if len(zones) == 1 else "s",
                     ", largest gap %.4g mm at z = %.6g mm" % (largest["gap"], largest["z_gap"])
                     if largest else "", high, float(p.max())))
        self.p_high = colour_range(0.0, p_high)[1] if p_high > 0 else 1.0
        self.zones.sort(key=lambda zone: -zone["gap"])
        if len(self.zones) > MAX_ZOOMS:
            print("  %d separated zones: the %d with the largest gaps are drawn"
                  % (len(self.zones), MAX_ZOOMS))
        self.zones = self.zones[:MAX_ZOOMS]

    def away_from_edges(self, points):
        """Which of POINTS (r, z) lie farther than the edge distance from
        every end of the contact."""
        away = numpy.ones(len(points), dtype=bool)
        for end in self.ends:
            away &= numpy.hypot(points[:, 0] - end[0], points[:, 1] - end[1]) >= self.edge
        return away

    # -- colours ------------------------------------------------------------

    def body_array(self, body):
        """The name of BODY's copy of the field."""
        return "%s_%s" % (body.name, self.field)

    @staticmethod
    def colour(display, view, array, preset, low, high, below):
        """Colour DISPLAY by the point ARRAY over LOW..HIGH (after ColorBy,
        which rescales to the data), magenta above, BELOW below."""
        ColorBy(display, ("POINTS", array))
        lut = GetColorTransferFunction(array)
        if not lut.ApplyPreset(preset, True):
            lut.ApplyPreset("Jet", True)
        lut.AutomaticRescaleRangeMode = "Never"
        lut.RescaleTransferFunction(low, high)
        lut.UseAboveRangeColor = 1
        lut.AboveRangeColor = ABOVE_RANGE
        lut.UseBelowRangeColor = 1
        lut.BelowRangeColor = below
        display.SetScalarBarVisibility(view, False)
        return lut

    def show_bodies(self, view, sources):
        """The bodies (SOURCES: name -> item) coloured in VIEW, with a
        scalar bar each on the right."""
        n = len(self.bodies)
        for k, body in enumerate(self.bodies):
            display = Show(sources[body.name], view)
            lut = self.colour(display, view, self.body_array(body), "Turbo",
                              *self.ranges[body.name], BELOW_RANGE)
            colour_bar(lut, view, "%s: %s" % (body.name, self.field),
                       [0.89, 0.86 - (k + 1) * 0.78 / n], 0.78 / n - 0.1)

    def show_lines(self, view, sources, width):
        """The contact lines (SOURCES) in VIEW, coloured by the pressure
        (white where separated), with their scalar bar."""
        for source in sources:
            display = Show(source, view)
            lut = self.colour(display, view, "contact_line_MPa", "Inferno (matplotlib)",
                              0.0, self.p_high, SEPARATED)
            display.LineWidth = width
            display.Ambient, display.Diffuse = 1.0, 0.0
        if sources:
            colour_bar(lut, view, "contact pressure (MPa); white: separated, "
                       "magenta: above", [0.33, 0.02], 0.33, horizontal=True)

    # -- the pipeline ---------------------------------------------------------

    def build(self):
        """The pipeline items that the views share."""
        self.copies, self.halves, self.sections = {}, {}, {}
        for body in self.bodies:
            array = self.body_array(body)
            copy = named("%s: %s" % (body.name, array),
                         Calculator(Input=body.source, ResultArrayName=array,
                                    Function=self.field))
            self.copies[body.name] = copy
            warped = named("%s: warped x%.3g" % (body.name, self.scale),
                           WarpByVector(Input=copy, Vectors=["POINTS", "displacement_mm"],
                                        ScaleFactor=self.scale))
            # sigma_rz is odd in z: it changes sign in the mirror image about
            # z = 0; the displacement vectors are flipped by the filter.
            flip = [a for a in ("sigma_rz_MPa",) if a in body.arrays]
            flip += [array] if self.field == "sigma_rz_MPa" else []
            half = (mirrored(warped, "Y", flip, "%s: mirrored about the mid-plane"
                             % body.name) if self.half else warped)
            self.halves[body.name] = half
            self.sections[body.name] = mirrored(half, "X", [], "%s: full section"
                                                % body.name)
        self.lines = {}
        for c in self.contacts:
            # The pressure where in contact, -1 where separated (drawn white).
            c.line = named("%s: contact_line_MPa" % c.name, Calculator(
                Input=c.source, ResultArrayName="contact_line_MPa",
                Function="contact_pressure_MPa*contact_status - (1 - contact_status)"))
            warped = named("%s: warped x%.3g" % (c.name, self.scale),
                           WarpByVector(Input=c.line, Vectors=["POINTS", "displacement_mm"],
                                        ScaleFactor=self.scale))
            half = (mirrored_line(warped, "Y", "%s: mirrored about the mid-plane" % c.name)
                    if self.half else warped)
            full = mirrored_line(half, "X", "%s: full section" % c.name)
            self.lines[c.name] = towards_camera(full, 0.01 * self.r_outer,
                                                "%s: line over the section" % c.name)

    def new_render_view(self, key):
        """A render view for one picture (no orientation axes)."""
        view = CreateView("RenderView")
        view.ViewSize = list(PICTURE)
        view.OrientationAxesVisibility = 0
        self.views[key] = view
        RenameView(key, view)
        return view

    def section_camera(self, view, centre, half_height):
        """A 2D camera on a section: z to the right, r up."""
        view.InteractionMode = "2D"
        view.CameraParallelProjection = 1
        view.CameraFocalPoint = [centre[0], centre[1], 0.0]
        view.CameraPosition = [centre[0], centre[1], -10.0 * self.r_outer]
        view.CameraViewUp = [1.0, 0.0, 0.0]
        view.CameraParallelScale = half_height

    def render(self, view):
        """Draw VIEW now (pvpython; the GUI draws the views in its layout)."""
        if not self.gui:
            Render(view)

    def section_view(self):
        """The full longitudinal section with the contact lines."""
        view = self.new_render_view("section")
        self.show_bodies(view, self.sections)
        self.show_lines(view, [self.lines[c.name] for c in self.contacts], 6.0)
        add_title(view, ["coaxfit %s: longitudinal section, displacement x %.3g"
                         % (self.case, self.scale),
                         "%s, each body its own colour range: magenta above it, "
                         "black below" % self.field,
                         "contact line: contact pressure, white where separated"],
                  "section: title")
        # Room for the title above, the pressure bar below and the bodies'
        # bars on the right (the part left of the middle).
        z_span = self.z_high - self.z_low
        half_height = max(1.3 * self.r_outer, 0.5 * z_span / 0.72 * PICTURE[1] / PICTURE[0])
        width = 2.0 * half_height * PICTURE[0] / PICTURE[1]
        z_centre = 0.5 * (self.z_low + self.z_high) + 0.05 * width
        self.section_camera(view, [0.0, z_centre], half_height)
        # At the bottom left of the view (the pressure's bar is in the middle).
        ruler = nice_length(0.25 * z_span)
        r, z = -0.86 * half_height, z_centre - 0.45 * width
        add_ruler(view, [r, z, 0.0], [r, z + ruler, 0.0], "section: length scale")
        self.render(view)

    def part_view(self):
        """The 3D part, revolved, cut open; the axes grid in mm."""
        view = self.new_render_view("part_3d")
        parts = {}
        angle = self.options["angle"]
        for body in self.bodies:
            # The half section (r >= 0) turned so that the axis is z, and
            # revolved by ANGLE degrees (the rest stays open).
            surface = named("%s: outline" % body.name,
                            ExtractSurface(Input=self.halves[body.name]))
            turned = named("%s: axis along z" % body.name, Transform(Input=surface))
            turned.Transform.Rotate = [90.0, 0.0, 0.0]
            parts[body.name] = named("%s: 3D" % body.name, RotationalExtrusion(
                Input=turned, Angle=angle, Resolution=max(12, int(angle / 5)), Capping=1))
        self.show_bodies(view, parts)
        add_title(view, ["coaxfit %s: assembled part, cut open, displacement x %.3g"
                         % (self.case, self.scale),
                         "%s, each body its own colour range: magenta above it, "
                         "black below" % self.field], "part_3d: title")
        grid = view.AxesGrid
        grid.Visibility = 1
        grid.XTitle, grid.YTitle, grid.ZTitle = "x (mm)", "y (mm)", "z, the axis (mm)"
        for axis in "XYZ":
            setattr(grid, axis + "TitleFontSize", 14)
            setattr(grid, axis + "LabelFontSize", 12)
        r = self.r_outer
        view.CameraPosition = [2.2 * r, -3.0 * r, 2.0 * r]
        view.CameraFocalPoint = [0.0, 0.0, 0.5 * (self.z_low + self.z_high)]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        view.ResetCamera()
        self.render(view)

    def chart_view(self):
        """Contact pressure (left axis) and gap (right axis) along the
        joint (the computed half of a half model)."""
        view = CreateView("XYChartView")
        view.ViewSize = list(PICTURE)
        self.views["contact_chart"] = view
        RenameView("contact_chart", view)
        gap_high = 0.0
        for k, c in enumerate(self.contacts):
            pressure, gap = SERIES_COLOURS[k % len(SERIES_COLOURS)]
            prefix = "%s: " % c.name if len(self.contacts) > 1 else ""
            for piece, source in enumerate(self.chart_pieces(c)):
                display = Show(source, view)
                display.UseIndexForXAxis = 0
                display.XArrayName = "Points_Y"
                display.SeriesVisibility = ["contact_pressure_MPa", "gap_mm"]
                # One legend entry per joint: its further pieces unlabelled.
                display.SeriesLabel = (["contact_pressure_MPa", "", "gap_mm", ""] if piece else
                                       ["contact_pressure_MPa", prefix + "contact pressure (MPa)",
                                        "gap_mm", prefix + "gap (mm, right axis)"])
                display.SeriesColor = (["contact_pressure_MPa"] + [str(v) for v in pressure]
                                       + ["gap_mm"] + [str(v) for v in gap])
                display.SeriesLineThickness = ["contact_pressure_MPa", "3", "gap_mm", "3"]
                display.SeriesPlotCorner = ["contact_pressure_MPa", "0", "gap_mm", "1"]
            gap_high = max(gap_high, float(c.arrays["gap_mm"].max()))
        view.SortByXAxis = 1
        view.BottomAxisTitle = "z (mm)" + (", from the mid-plane" if self.half else "")
        view.LeftAxisTitle = "contact pressure (MPa)"
        view.RightAxisTitle = "gap (mm)"
        view.ShowLegend = 1
        view.LegendLocation = "TopLeft"
        # The edge peak would flatten the rest: the axis stops above the
        # pressure away from the edges and the title gives the peak.
        clipped = self.p_peak > 1.3 * self.p_high
        view.LeftAxisUseCustomRange = 1
        view.LeftAxisRangeMinimum = 0.0
        view.LeftAxisRangeMaximum = 1.3 * self.p_high
        view.RightAxisUseCustomRange = 1
        view.RightAxisRangeMinimum = 0.0
        # Round-off gaps (1e-16 mm) stay at the bottom: the axis reaches at
        # least 1e-3 of the radial interference d (or 1e-6 of the radius).
        d = ((self.run.get("geometry") or {}).get("d"))
        floor = 1e-3 * abs(d) if isinstance(d, (int, float)) and d else 1e-6 * self.r_outer
        view.RightAxisRangeMaximum = max(2.0 * gap_high, floor)
        view.ChartTitle = ("coaxfit %s: contact pressure and gap along the joint%s"
                           % (self.case, "; edge peak %.4g MPa off the scale" % self.p_peak
                              if clipped else ""))
        view.ChartTitleFontSize = 16
        for axis in ("Left", "Right", "Bottom"):
            setattr(view, axis + "AxisTitleFontSize", 15)
            setattr(view, axis + "AxisLabelFontSize", 13)
        self.render(view)

    def chart_pieces(self, contact):
        """The sources the chart draws for a contact surface: the surface,
        or each of its polylines apart (the pieces of a joint beside a relief
        groove: a line joining them would cross the groove)."""
        if len(contact.pieces) <= 1:
            return [contact.source]
        pieces = [named("%s: piece %d" % (contact.name, cell + 1), ExtractSelection(
            Input=contact.source, Selection=IDSelectionSource(IDs=[0, cell], FieldType="CELL")))
            for cell in range(len(contact.pieces))]
        ranges = []
        for piece in pieces:
            z = fetch_points(piece)[0][:, 1]
            ranges.append("z %.6g to %.6g" % (z.min(), z.max()))
        print("  %s: %d pieces, drawn apart in the chart (%s mm)"
              % (contact.name, len(pieces), ", ".join(ranges)))
        return pieces

    def zoom_view(self, number, zone):
        """A separated zone close up. The radial displacement is drawn
        relative to a parabola fitted to the hub's bore over the zone (the
        joint runs nearly straight however its displacement varies along z;
        both bodies are shifted alike, so the gap drawn is the gap times the
        magnification), magnified so that the zone's largest gap is a tenth
        of the picture's height."""
        key = "separation_zoom" if number == 1 else "separation_zoom_%d" % number
        view = self.new_render_view(key)
        z_from, z_to = zone["z_from"], zone["z_to"]
        width = 2.0 * max(z_to - z_from, 1e-9)
        height = width * PICTURE[1] / PICTURE[0]
        factor = max(1.0, 0.1 * height / max(zone["gap"], 1e-300))
        z_mid = 0.5 * (z_from + z_to)
        degree = min(2, len(zone["z_bore"]) - 1)
        fit = numpy.polyfit(zone["z_bore"] - z_mid, zone["u_bore"], degree)[::-1]
        trend = (z_mid,) + tuple(float(v) for v in fit) + (0.0,) * (2 - degree)
        crosses = self.half and z_mid - 0.5 * width < 0.0
        label = "zone %d" % number
        for k, body in enumerate(self.bodies):
            warped = radial_warp(body.source, "displacement_mm", factor, trend,
                                 "%s: %s, radial displacement x%.3g" % (label, body.name, factor))
            if crosses:
                warped = mirrored(warped, "Y", [], "%s: %s, both halves" % (label, body.name))
            display = Show(warped, view)
            display.ColorArrayName = ["POINTS", ""]
            display.AmbientColor = display.DiffuseColor = (SHAFT_PLAIN, HUB_PLAIN)[k % 2]
        lines = []
        for c in self.contacts:
            # The outer side's displacement_mm, the inner side's
            # <inner body>_displacement_mm (shaft_ in a run of two bodies).
            inner = [a for a in c.arrays
                     if a.endswith("_displacement_mm") and a != "displacement_mm"]
            for vector, side in (("displacement_mm", "outer side"),
                                 (inner[0] if inner else "displacement_mm",
                                  "inner side")):
                warped = radial_warp(c.line, vector, factor, trend,
                                     "%s: %s, %s" % (label, c.name, side))
                if crosses:
                    warped = mirrored_line(warped, "Y", "%s: %s, %s, both halves"
                                           % (label, c.name, side))
                lines.append(towards_camera(warped, 0.01 * self.r_outer, "%s: %s, %s line"
                                            % (label, c.name, side)))
        self.show_lines(view, lines, 4.0)
        plain = ", ".join("%s %s" % (b.name, ("blue", "grey")[k % 2])
                          for k, b in enumerate(self.bodies))
        add_title(view, ["coaxfit %s: separated zone %d, z = %.4g to %.4g mm"
                         % (self.case, number, z_from, z_to),
                         "radial displacement x %.3g relative to a parabola fitted to the "
                         "joint's outer side: largest gap %.3g mm drawn %.3g mm"
                         % (factor, zone["gap"], factor * zone["gap"]),
                         plain + "; lines: the two sides of the joint, coloured by the "
                         "contact pressure, white where separated"], "%s: title" % label)
        # The joint a little above the middle (the notes at the top left).
        dz = zone["z_gap"] - z_mid
        r_joint = zone["r"] + factor * (zone["u_hub"] - trend[1] - trend[2] * dz
                                        - trend[3] * dz * dz - 0.5 * zone["gap"])
        self.section_camera(view, [r_joint - 0.1 * height, z_mid], 0.5 * height)
        ruler = nice_length(0.25 * width)
        r = r_joint - 0.48 * height
        add_ruler(view, [r, z_mid - 0.45 * width, 0.0],
                  [r, z_mid - 0.45 * width + ruler, 0.0], "%s: length scale" % label)
        print("  separated zone %d (%s): z = %.6g to %.6g mm, largest gap %.4g mm at "
              "z = %.6g mm, radial displacement drawn x %.3g"
              % (number, zone["surface"].name, z_from, z_to, zone["gap"], zone["z_gap"],
                 factor))
        self.render(view)
        self.zoom_views.append((key, view))

    # -- layouts and files ----------------------------------------------------

    def layout(self):
        """The views in layouts: section and 3D part above, chart and the
        largest separated zone below; a tab for each further zone. In the
        GUI the empty layout it starts with is closed."""
        main = CreateLayout("coaxfit %s" % self.case)
        if self.gui:
            for layout in list(GetLayouts().values()):
                views = GetViewsInLayout(layout)
                if layout != main and all(v not in self.views.values() and not any(
                        r.Visibility for r in v.Representations) for v in views):
                    for v in views:
                        Delete(v)
                    RemoveLayout(layout)
        main.SplitVertical(0, 0.55)
        above = main.SplitHorizontal(1, 0.5)
        main.AssignView(above, self.views["section"])
        main.AssignView(above + 1, self.views["part_3d"])
        if self.zoom_views:
            below = main.SplitHorizontal(2, 0.5)
            main.AssignView(below, self.views["contact_chart"])
            main.AssignView(below + 1, self.zoom_views[0][1])
        else:
            main.AssignView(2, self.views["contact_chart"])
        for number, (key, view) in enumerate(self.zoom_views[1:], start=2):
            AssignViewToLayout(view=view, layout=CreateLayout(
                "coaxfit %s: separated zone %d" % (self.case, number)))
        SetActiveView(self.views["section"])
        SetActiveSource(self.reader)

    def save_pictures(self, keys):
        """The PNGs of the views KEYS, where asked."""
        if not self.options["png"]:
            return
        # Beside the directory given (for a Case = all run not inside it).
        png_dir = self.options["png_dir"] or (os.path.abspath(self.options["dir"]).rstrip("/")
                                              + "_views")
        os.makedirs(png_dir, exist_ok=True)
        for key in keys:
            view = self.views[key]
            layout = self.gui and GetLayout(view)
            if layout:
                # The view alone in its layout while it is saved (the
                # picture is drawn larger than the view, less so alone).
                layout.MaximizeCell(layout.GetViewLocation(view))
                Render(view)
            try:
                save_png(view, os.path.join(png_dir, key + ".png"))
            finally:
                if layout:
                    layout.RestoreMaximizedState()

    def show(self):
        """Everything, in order."""
        self.read()
        self.analyse()
        self.build()
        self.chart_view()
        if not self.gui:
            # Before any text of a render view is drawn: VTK 9.2 draws the
            # chart's labels garbled once a text actor has been drawn in the
            # same process.
            self.save_pictures(["contact_chart"])
        self.section_view()
        self.part_view()
        for number, zone in enumerate(self.zones, start=1):
            self.zoom_view(number, zone)
        pictures = [key for key in self.views if self.gui or key != "contact_chart"]
        if not self.gui:
            # Each at its own size, before the views share a layout.
            self.save_pictures(pictures)
        self.layout()
        if self.gui:
            for view in self.views.values():
                Render(view)
            self.save_pictures(pictures)
        if self.options["state"]:
            SaveState(self.options["state"])
            print("  wrote %s" % self.options["state"])


def main():
    """Run from pvpython (exit code 1 with a message on bad input) or from
    the GUI (the message printed, the GUI kept)."""
    gui = in_gui()
    try:
        if gui:
            options = gui_options()
        else:
            options = parse_arguments(sys.argv[1:], os.environ.get("COAXFIT_OUTPUT", ""))
            result_directory(options["dir"])
            restart_under_xvfb()
        Viewer(options, gui).show()
    except ViewError as error:
        if not gui:
            sys.exit("view.py: %s" % error)
        print("view.py: %s" % error, file=sys.stderr)
    ready = os.environ.get("COAXFIT_VIEW_READY")
    if ready:
        with open(ready, "w") as f:
            f.write("ready\n")


main()
