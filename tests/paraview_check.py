"""Open a coaxfit result with ParaView's own reader (pvpython) and print what
a ParaView user relies on: the named blocks, the arrays with their units,
the ranges that physics fixes, and whether the bodies warped by
displacement_mm meet at the joint.

    pvpython tests/paraview_check.py OUTPUT_DIR LAME|SEPARATING

LAME: the equal-length Lame case (p = 187.5 MPa, hub hoop stress at the bore
p (R2^2 + R1^2)/(R2^2 - R1^2) = 312.5 MPa, solid shaft sigma_rr = sigma_tt =
-p). SEPARATING: a case whose contact opens at its ends.

Used by tests/paraview_view.cc, whose output numdiff compares.
"""

import os
import re
import sys

from paraview.simple import MergeBlocks, ExtractBlock, PVDReader, WarpByVector
from paraview import servermanager
from paraview.vtk.util.numpy_support import vtk_to_numpy
import numpy

directory, case = sys.argv[1], sys.argv[2]
reader = PVDReader(FileName=os.path.join(directory, "solution.pvd"))
reader.UpdatePipeline()
collection = servermanager.Fetch(reader)
names = [collection.GetMetaData(i).Get(collection.NAME())
         for i in range(collection.GetNumberOfBlocks())]
print("blocks: " + ", ".join(names))


def block(name, warp=False):
    source = MergeBlocks(Input=ExtractBlock(Input=reader, Selectors=["/Root/" + name]))
    if warp:
        source = WarpByVector(Input=source, Vectors=["POINTS", "displacement_mm"])
    data = servermanager.Fetch(source)
    arrays = {}
    pd = data.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        arrays[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i)).astype(float)
    return vtk_to_numpy(data.GetPoints().GetData()).astype(float), arrays, data


def units(file):
    """Array name -> units attribute, from the XML as written."""
    text = open(os.path.join(directory, file), errors="replace").read()
    found = {}
    for tag in re.findall(r"<DataArray[^>]*>", text):
        name = re.search(r'Name="([^"]*)"', tag)
        unit = re.search(r'units="([^"]*)"', tag)
        if name:
            found[name.group(1)] = unit.group(1) if unit else "-"
    return found


bodies = {}
for name, file in (("shaft", "shaft.vtu"), ("hub", "hub.vtu"),
                   ("contact_surface", "interface.vtp")):
    points, arrays, data = block(name)
    bodies[name] = (points, arrays)
    unit = units(file)
    print("%s: %d points, %s, body_id %s" % (
        name, data.GetNumberOfPoints(), data.GetClassName(),
        sorted(set(int(v) for v in arrays["body_id"]))))
    for array in sorted(arrays):
        if array == "body_id":
            continue
        a = arrays[array]
        print("  %-24s units %-4s components %d" % (
            array, unit.get(array, "?"), 1 if a.ndim == 1 else a.shape[1]))

shaft_points, shaft = bodies["shaft"]
hub_points, hub = bodies["hub"]
surface_points, surface = bodies["contact_surface"]
R1 = surface_points[0, 0]
p = surface["contact_pressure_MPa"]
contact = surface["contact_status"] > 0.5
d = surface["shaft_displacement_mm"][0, 0] - shaft["elastic_displacement_mm"][
    numpy.argmin(numpy.hypot(shaft_points[:, 0] - R1, shaft_points[:, 1] - surface_points[0, 1])), 0]
print("joint radius %.6g mm, %d contact points, %d in contact" % (R1, len(p), contact.sum()))


def fmt(x):
    return "%.5g" % x


if case == "LAME":
    R2 = hub_points[:, 0].max()
    exact_p = 187.5
    exact_tt = exact_p * (R2 ** 2 + R1 ** 2) / (R2 ** 2 - R1 ** 2)
    print("contact_pressure_MPa min %s max %s (Lame %s)" % (fmt(p.min()), fmt(p.max()), fmt(exact_p)))
    at_bore = numpy.abs(hub_points[:, 0] - R1) < 1e-9 * R1
    tt = hub["sigma_tt_MPa"][at_bore]
    print("hub sigma_tt_MPa at the bore min %s max %s (Lame %s)" % (fmt(tt.min()), fmt(tt.max()), fmt(exact_tt)))
    for array in ("sigma_rr_MPa", "sigma_tt_MPa"):
        s = shaft[array]
        print("shaft %s min %s max %s (Lame %s)" % (array, fmt(s.min()), fmt(s.max()), fmt(-exact_p)))

# The warped surfaces at the joint, radially (the contact is frictionless:
# the bodies slide axially against each other, so a point of the shaft and
# the hub's point at the same z move apart along the surface; the surfaces
# themselves coincide). interface.vtp (Float64): the shaft's and the hub's
# surface points, warped, must be at one radius where in contact (1e-9 of
# the radial interference d) and be apart by the gap where separated.
warped_shaft = surface_points[:, :2] + surface["shaft_displacement_mm"][:, :2]
warped_hub = surface_points[:, :2] + surface["displacement_mm"][:, :2]
distance = numpy.abs(warped_hub[:, 0] - warped_shaft[:, 0])
scale = abs(d)
print("interface.vtp: warped surfaces meet where in contact: %s"
      % ("yes, to 1e-9 of d" if distance[contact].max() <= 1e-9 * scale else
         "NO, %.3g mm apart" % distance[contact].max()))
if (~contact).any():
    opening = warped_hub[~contact, 0] - warped_shaft[~contact, 0]
    print("interface.vtp: separated points open by gap_mm: %s, largest gap %s mm"
          % ("yes" if numpy.abs(opening - surface["gap_mm"][~contact]).max() <= 1e-9 * scale
             else "NO", fmt(surface["gap_mm"].max())))

# The bodies' VTU (deal.II writes Float32): their nodes on S, warped, meet to
# the float32 rounding of the displacement (1e-6 of d) where in contact; a
# missing oversize would leave them d apart.
on_shaft = numpy.abs(shaft_points[:, 0] - R1) < 1e-6 * R1
on_hub = numpy.abs(hub_points[:, 0] - R1) < 1e-6 * R1
shaft_z = shaft_points[on_shaft, 1]
hub_z = hub_points[on_hub, 1]
in_contact_z = surface_points[contact, 1]
worst = 0.0
for z in in_contact_z:
    i = numpy.argmin(abs(shaft_z - z))
    j = numpy.argmin(abs(hub_z - z))
    if abs(shaft_z[i] - z) > 1e-6 * R1 or abs(hub_z[j] - z) > 1e-6 * R1:
        continue  # a hub edge node, not on the shaft
    us = shaft["displacement_mm"][on_shaft][i]
    uh = hub["displacement_mm"][on_hub][j]
    worst = max(worst, abs(uh[0] - us[0]))
print("shaft.vtu, hub.vtu: warped nodes meet where in contact: %s"
      % ("yes, to 1e-6 of d" if worst <= 1e-6 * scale else
         "NO, %.3g mm apart" % worst))

# ParaView's Warp By Vector, as a user applies it (points in float32: the
# bound is 4 units in the last place at the joint radius).
ws, _, _ = block("shaft", warp=True)
wh, _, _ = block("hub", warp=True)
ulp = 4 * numpy.spacing(numpy.float32(R1))
far = 0.0
for z in in_contact_z:
    i = numpy.argmin(abs(shaft_points[:, 0] - R1) + abs(shaft_points[:, 1] - z))
    j = numpy.argmin(abs(hub_points[:, 0] - R1) + abs(hub_points[:, 1] - z))
    if abs(shaft_points[i, 1] - z) > 1e-6 * R1 or abs(hub_points[j, 1] - z) > 1e-6 * R1:
        continue
    far = max(far, abs(wh[j, 0] - ws[i, 0]))
print("Warp By Vector: shaft and hub meet at the joint where in contact: %s"
      % ("yes, within 4 float32 ulp of the radius" if far <= ulp else "NO, %.3g mm apart" % far))
print("radial interference recovered from the arrays: %s mm" % fmt(d))
