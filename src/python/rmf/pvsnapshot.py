# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""A case opened as a ParaView user opens it: the OpenFOAM reader on a
.foam file (made if the case has none), every cell and cloud array, the
last written time; prints what it read as one JSON line and saves a
picture: the internal mesh coloured by a cell field, the cloud's parcels
as points on top.  Runs under ParaView's pvbatch (Debian's needs a
display: xvfb-run -a), not /usr/bin/python3:

    xvfb-run -a pvbatch src/python/rmf/pvsnapshot.py CASE \\
        [--field alpha.grains] [--cloud grains] [--output CASE/snapshot.png]

JSON: {"time", "cells", "cellArrays", "clouds": {name: {"parcels",
"arrays"}}, "field": [min, max] of the colouring field}."""

import argparse
import glob
import json
import os

from paraview import servermanager
from paraview.simple import (ColorBy, CreateRenderView, ExtractBlock,
                             GetColorTransferFunction, GetScalarBar,
                             OpenFOAMReader, ResetCamera, SaveScreenshot, Show)


def look(view, reader):
    """Camera across a thin case (a 2-D slab or a wedge) along its thinnest
    axis, the later of the other two up (y for an x-y slab); from the side
    of a 3-D box (along y, z up)."""
    b = reader.GetDataInformation().GetBounds()
    extent = [b[2*i + 1] - b[2*i] for i in range(3)]
    centre = [(b[2*i + 1] + b[2*i])/2 for i in range(3)]
    thin = min(range(3), key=lambda i: extent[i])
    if extent[thin] < 0.5*sorted(extent)[1]:
        along, up = thin, [i for i in range(3) if i != thin][1]
    else:
        along, up = 1, 2
    position = list(centre)
    position[along] -= 10*max(extent)
    view.CameraPosition = position
    view.CameraFocalPoint = centre
    view.CameraViewUp = [1.0 if i == up else 0.0 for i in range(3)]
    ResetCamera(view)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("case")
    parser.add_argument("--field", default="alpha.grains")
    parser.add_argument("--cloud", default="grains")
    parser.add_argument("--output")
    args = parser.parse_args()
    case = os.path.abspath(args.case)
    output = args.output or os.path.join(case, "snapshot.png")

    foams = glob.glob(os.path.join(case, "*.foam"))
    foam = foams[0] if foams else os.path.join(case, os.path.basename(case) + ".foam")
    open(foam, "a").close()

    reader = OpenFOAMReader(FileName=foam)
    clouds = [r for r in reader.GetProperty("MeshRegions").Available
              if r.startswith("lagrangian/")]
    reader.MeshRegions = ["internalMesh"] + clouds
    reader.CellArrays = reader.GetProperty("CellArrayInfo")[::2]
    reader.LagrangianArrays = reader.GetProperty("LagrangianArrayInfo")[::2]
    time = reader.TimestepValues[-1] if reader.TimestepValues else 0.0
    reader.UpdatePipeline(time)

    # What was read, block by block
    data = servermanager.Fetch(reader)
    found = {"time": time, "clouds": {}}
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        block = it.GetCurrentDataObject()
        name = it.GetCurrentMetaData().Get(data.NAME())
        if name == "internalMesh":
            cd = block.GetCellData()
            found["cells"] = block.GetNumberOfCells()
            found["cellArrays"] = [cd.GetArrayName(i) for i in range(cd.GetNumberOfArrays())]
            array = cd.GetArray(args.field)
            found["field"] = list(array.GetRange()) if array else None
        elif block.GetNumberOfPoints() or block.IsA("vtkPolyData"):
            pd = block.GetPointData()
            found["clouds"][name] = {
                "parcels": block.GetNumberOfPoints(),
                "arrays": [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]}
        it.GoToNextItem()
    print(json.dumps(found))

    # The picture
    view = CreateRenderView()
    view.ViewSize = [800, 600]
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    mesh = Show(ExtractBlock(Input=reader, Selectors=["/Root/internalMesh"]), view)
    if found.get("field"):
        ColorBy(mesh, ("CELLS", args.field))
        mesh.RescaleTransferFunctionToDataRange(True)
        mesh.SetScalarBarVisibility(view, True)
        bar = GetScalarBar(GetColorTransferFunction(args.field), view)
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
    mesh.Opacity = 0.5      # the parcels inside stay visible
    cloud = "lagrangian/" + args.cloud
    if cloud in clouds:
        parcels = Show(ExtractBlock(Input=reader, Selectors=["/Root/" + cloud]), view)
        parcels.SetRepresentationType("Points")
        parcels.PointSize = 2
        parcels.ColorArrayName = [None, ""]
        parcels.AmbientColor = parcels.DiffuseColor = [0.1, 0.1, 0.1]
    look(view, reader)
    SaveScreenshot(output, view, ImageResolution=[800, 600])


if __name__ == "__main__":
    main()
