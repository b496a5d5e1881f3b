"""Open the result of an assembly of several bodies (Assembly/Bodies) with
ParaView's own reader (pvpython) and print what a ParaView user relies on:
a block per body and per joint, the arrays with their units, and for every
joint whether its two sides meet where in contact and stand apart by the
gap where open: in the joint's interface_<joint>.vtp (the outer side's
displacement_mm against the inner side's <inner>_displacement_mm) and in
the bodies' VTU files warped by displacement_mm (the inner body's outer
surface against the outer body's bore); the gap against summary.json's
diametral gap and the pressure against contact_pressure_<joint>.csv.

    pvpython tests/stack_paraview_check.py OUTPUT_DIR

Used by tests/stack_views.cc, whose output numdiff compares.
"""

import csv
import json
import os
import re
import sys

from paraview.simple import ExtractBlock, MergeBlocks, PVDReader
from paraview import servermanager
from paraview.vtk.util.numpy_support import vtk_to_numpy
import numpy

directory = sys.argv[1]
summary = json.load(open(os.path.join(directory, "summary.json")))
reader = PVDReader(FileName=os.path.join(directory, "solution.pvd"))
reader.UpdatePipeline()
collection = servermanager.Fetch(reader)
names = [collection.GetMetaData(i).Get(collection.NAME())
         for i in range(collection.GetNumberOfBlocks())]
print("blocks: " + ", ".join(names))


def block(name):
    """Points (r, z) and point arrays of the block NAME."""
    data = servermanager.Fetch(MergeBlocks(
        Input=ExtractBlock(Input=reader, Selectors=["/Root/" + name])))
    arrays = {}
    pd = data.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        arrays[pd.GetArrayName(i)] = vtk_to_numpy(pd.GetArray(i)).astype(float)
    return vtk_to_numpy(data.GetPoints().GetData()).astype(float)[:, :2], arrays


def units(file):
    """Array name -> units attribute, from the XML as written."""
    text = open(os.path.join(directory, file), errors="replace").read()
    found = {}
    for tag in re.findall(r"<DataArray[^>]*>", text):
        name = re.search(r'Name="([^"]*)"', tag)
        if name and name.group(1) not in ("connectivity", "offsets", "types"):
            unit = re.search(r'units="([^"]*)"', tag)
            found[name.group(1)] = unit.group(1) if unit else "-"
    return found


def yes(condition):
    return "yes" if condition else "NO"


bodies = summary["assembly"]["bodies"]
keys = [b.lower() for b in bodies]
for joint_number, joint in enumerate(summary["joints"]):
    inner, outer = keys[joint_number], keys[joint_number + 1]
    block_name = "contact_%s_%s" % (inner, outer)
    file = "interface_%s.vtp" % joint["name"]
    points, arrays = block(block_name)
    status = arrays["contact_status"] > 0.5
    print("%s (%s): %d points, %d in contact, body_id %s"
          % (block_name, file, len(points), int(status.sum()),
             sorted(set(arrays["body_id"].astype(int).tolist()))))
    for name, unit in sorted(units(file).items()):
        print("  %-24s units %s" % (name, unit))
    d = joint["diametral_interference"] / 2.0
    r_joint = joint["diameter"] / 2.0
    if abs(points[:, 0] - r_joint).max() > 1e-12 * r_joint:
        print("  POINTS NOT AT THE JOINT RADIUS %g" % r_joint)
    # The radial positions of the two sides (the inner side's array holds
    # its oversize d: it is drawn at the joint radius plus d).
    outer_r = arrays["displacement_mm"][:, 0]
    inner_r = arrays["%s_displacement_mm" % inner][:, 0]
    apart = outer_r - inner_r
    if status.any():
        print("  sides meet where in contact: %s (largest |u_out - u_in| %s of d)"
              % (yes(numpy.abs(apart[status]).max() <= 1e-9 * abs(d)),
                 "below 1e-9" if numpy.abs(apart[status]).max() <= 1e-9 * abs(d)
                 else "%.3g" % (numpy.abs(apart[status]).max() / abs(d))))
    if (~status).any():
        print("  open: gap_mm = u_out - u_in: %s; 2 max gap_mm = summary gap_max "
              "%.6g mm: %s"
              % (yes(numpy.abs(apart[~status] - arrays["gap_mm"][~status]).max()
                     <= 1e-12),
                 joint["contact"]["gap_max"],
                 yes(abs(2.0 * arrays["gap_mm"][~status].max()
                         - joint["contact"]["gap_max"]) <= 1e-9 * abs(d))))
    # The pressure as in the CSV (17 digits in the VTP, 6 in the CSV).
    rows = list(csv.DictReader(open(os.path.join(
        directory, "contact_pressure_%s.csv" % joint["name"]))))
    csv_p = numpy.array([float(r["pressure_MPa"]) for r in rows])
    csv_z = numpy.array([float(r["z_mm"]) for r in rows])
    order = numpy.argsort(points[:, 1])
    same = (len(rows) == len(points)
            and numpy.abs(points[order, 1] - csv_z).max() <= 1e-4
            and numpy.abs(arrays["contact_pressure_MPa"][order] - csv_p).max()
            <= 1e-5 * max(1.0, float(numpy.abs(csv_p).max())))
    print("  pressure = contact_pressure_%s.csv: %s, max %.4f MPa (summary max %.4f)"
          % (joint["name"], yes(same), float(arrays["contact_pressure_MPa"].max()),
             joint["pressure"]["max"]))

    # The bodies warped by displacement_mm: the inner body's nodes at the
    # joint radius against the outer body's, node by node (shared z).
    sides = []
    for key in (inner, outer):
        body_points, body_arrays = block(key)
        at = numpy.abs(body_points[:, 0] - r_joint) <= 1e-9 * r_joint
        z = body_points[at, 1]
        r = body_points[at, 0] + body_arrays["displacement_mm"][at, 0]
        unique_z, first = numpy.unique(numpy.round(z, 9), return_index=True)
        sides.append(dict(zip(unique_z.tolist(), r[first].tolist())))
    shared = sorted(set(sides[0]) & set(sides[1]))
    difference = numpy.array([sides[1][z] - sides[0][z] for z in shared])
    # A node touches where the contact point at its z (float32 in the VTU)
    # is in contact.
    touching = numpy.array([bool(status[numpy.argmin(numpy.abs(points[:, 1] - z))])
                            for z in shared])
    # The VTU holds float32 points: the warped radii meet within float32's
    # resolution of the radius.
    tolerance = 8 * numpy.finfo(numpy.float32).eps * r_joint
    line = "  %s.vtu, %s.vtu warped: %d shared joint nodes" % (inner, outer, len(shared))
    if touching.any():
        line += ", meet where in contact: %s" % yes(
            numpy.abs(difference[touching]).max() <= tolerance)
    if (~touching).any():
        gap_open = 2.0 * difference[~touching].max()
        line += ", open by the diametral gap %.5g mm (summary %.5g): %s" % (
            gap_open, joint["contact"]["gap_max"],
            yes(abs(gap_open - joint["contact"]["gap_max"]) <= tolerance * 2))
    print(line)
