#!/usr/bin/env python3
"""Render a point-cloud frame, its reconstruction and the aligned template (coloured by error),
side by side.

usage: PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 scripts/render_point_cloud.py \
           OUT.png CLOUD RECONSTRUCTED ALIGNED.vtp [ERROR_RANGE_M]

CLOUD is a .pcd, .ply or .xyz frame; RECONSTRUCTED its mesh (OUT/reconstructed/frames/frame_NNNN.obj of
`clothtrack align CLOUDS`); ALIGNED.vtp the aligned template of that frame (OUT/aligned/aligned_NNNN.vtp).
"""
import sys

from clothtrack.report import _save_panels, error_actor
from clothtrack.rendering import colour_actor
from clothtrack.sequence import read_sequence
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

out, cloud_path, mesh_path, aligned_path = sys.argv[1:5]
error_range = float(sys.argv[5]) if len(sys.argv) > 5 else 0.1

cloud = read_sequence(cloud_path)[0]
cloud_actor = colour_actor(cloud, (0.25, 0.4, 0.7))
cloud_actor.GetProperty().SetPointSize(1.5)
mesh = read_sequence(mesh_path)[0]
reader = vtkXMLPolyDataReader()
reader.SetFileName(aligned_path)
reader.Update()
aligned_actor, bar, _ = error_actor(reader.GetOutput(), error_range)
panels = [("point cloud, %d points" % cloud.GetNumberOfPoints(), cloud_actor),
          ("reconstruction, %d vertices" % mesh.GetNumberOfPoints(),
           colour_actor(mesh, (0.85, 0.85, 0.85), smooth_normals=True)),
          ("aligned template", aligned_actor)]
_save_panels(panels, out, bar)
print("wrote", out)
