# Run by Blender (blender -b --factory-startup --python-exit-code 1 --python
# THIS -- FILE.glb TIMELINE.csv FPS PICK ...): imports the glTF export with
# Blender's own importer and checks, at each pick SECONDS:ROW[:SURFACE] of
# the animation "roll", that the ball's world rotation and centre are the
# solver's (row ROW of the timeline), that the ball carries extras.rollspin,
# and, where SURFACE is given, that only that surface's node is shown
# (several surfaces take turns by a STEP scale of 0 or 1). Blender's world
# is z-up, as the scene is: its importer undoes the root node's z-up → y-up
# rotation.
import csv
import math
import sys

import addon_utils
import bpy
from mathutils import Quaternion, Vector

args = sys.argv[sys.argv.index("--") + 1:]
glb, timeline, fps = args[0], args[1], int(args[2])
picks = [[float(field) for field in pick.split(":")] for pick in args[3:]]

# The importer is a bundled add-on; enable it where it is not (a factory
# start-up enables it in Debian's 3.4, but say so if that changes).
if not addon_utils.check("io_scene_gltf2")[1]:
    print("blender_check: enabling the io_scene_gltf2 add-on")
    addon_utils.enable("io_scene_gltf2", default_set=True)

# Debian 12's Blender 3.4.1 imports meshes with `np.bool`, an alias numpy
# 1.24 removed (io_scene_gltf2/blender/imp/gltf2_blender_mesh.py:612): put it
# back for the importer (docs/interactive.md gives users the same line).
import numpy

if "bool" not in numpy.__dict__:
    numpy.bool = bool

rows = [r for r in csv.DictReader(line for line in open(timeline) if not line.startswith("#"))]
bpy.context.scene.render.fps = fps  # the importer keys frame = seconds × fps
bpy.ops.import_scene.gltf(filepath=glb)
ball = bpy.data.objects["ball"]
failures = []
if "rollspin" not in ball.keys() or "version" not in ball["rollspin"].keys():
    failures.append("the ball has no extras.rollspin.version: " + str(ball.keys()))
surfaces = sorted(name for name in bpy.data.objects.keys() if name.startswith("surface"))
for pick in picks:
    seconds, row = pick[0], rows[int(pick[1])]
    # The importer keys frame = seconds × fps, not rounded: a key between
    # frames is reached with a subframe.
    frame = seconds * fps
    bpy.context.scene.frame_set(math.floor(frame), subframe=frame - math.floor(frame))
    solver = Quaternion((float(row["qw"]), float(row["qx"]), float(row["qy"]), float(row["qz"])))
    centre = Vector((float(row["cx"]), float(row["cy"]), float(row["cz"])))
    world = ball.matrix_world
    # The importer turns each node's own axes too (glTF's y-up mesh data to
    # Blender's z-up: a quarter turn about x), so a body direction d of the
    # scene is yUpToZUp · d in the ball's Blender-local frame: the ball's
    # orientation in scene terms is its world rotation times that turn.
    q = world.to_quaternion() @ Quaternion((1.0, 0.0, 0.0), math.pi / 2)
    angle = solver.rotation_difference(q).angle
    angle = abs(min(angle, 2 * math.pi - angle))  # q and -q are one rotation
    offset = (world.translation - centre).length
    print(f"blender_check: {seconds:.4f} s: s = {row['s']}, rotation off by {angle:.3g} rad, centre by {offset:.3g}")
    if angle > 1e-5 or offset > 1e-5 * (1 + centre.length):
        failures.append(f"{seconds:.4f} s: rotation {angle:.3g} rad, centre {offset:.3g}")
    if len(pick) > 2:
        shown = [name for name in surfaces if bpy.data.objects[name].matrix_world.to_scale().length > 0.5]
        expected = "surface" if pick[2] == 0 else f"surface.{int(pick[2])}"
        print(f"blender_check: {seconds:.4f} s: shown {shown}, the timeline's surface {row.get('surface', '-')}")
        if shown != [expected] or ("surface" in row and int(row["surface"]) != int(pick[2])):
            failures.append(f"{seconds:.4f} s: shown {shown}, expected {expected} (timeline: {row.get('surface')})")
if failures:
    print("blender_check: FAILED: " + "; ".join(failures))
    sys.exit(1)
print("blender_check: passed")
