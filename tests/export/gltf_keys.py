# Picks keys of a rollspin glTF export's "roll" animation for the Blender
# check (tests/export/blender_import_test.sh), read with the standard library
# only: the ball's keys whose arc length differs from both neighbours' (a
# hold's keys share one s, and `rollspin timeline --at-s` keeps one row per
# s), spread evenly over the clip, plus the last key before and the first
# after each change of surface.
#   python3 gltf_keys.py FILE.glb COUNT S_FILE  → prints "time index" lines;
#   S_FILE gets the picked keys' arc lengths, one a line, in the same order.
import json
import struct
import sys

glb_path, count, s_path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
data = open(glb_path, "rb").read()
json_length = struct.unpack_from("<I", data, 12)[0]
gltf = json.loads(data[20:20 + json_length])
binary_start = 20 + json_length + 8


def floats(accessor_index, width=1):
    accessor = gltf["accessors"][accessor_index]
    view = gltf["bufferViews"][accessor["bufferView"]]
    start = binary_start + view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
    values = struct.unpack_from(f"<{accessor['count'] * width}f", data, start)
    return [values[i * width:(i + 1) * width] for i in range(accessor["count"])]


ball = next(i for i, node in enumerate(gltf["nodes"]) if node.get("name") == "ball")
arc_length = [v[0] for v in floats(gltf["nodes"][ball]["extras"]["rollspin"]["arc_length"])]
roll = next(a for a in gltf["animations"] if a["name"] == "roll")
rotation = next(c for c in roll["channels"] if c["target"] == {"node": ball, "path": "rotation"})
times = [v[0] for v in floats(roll["samplers"][rotation["sampler"]]["input"])]
assert len(times) == len(arc_length), "one arc length per key"

# Which surface each key is on, from the surfaces' STEP scale channels.
surface_of_key = [0] * len(times)
for channel in roll["channels"]:
    node = gltf["nodes"][channel["target"]["node"]]
    if not node.get("name", "").startswith("surface") or channel["target"]["path"] != "scale":
        continue
    sampler = roll["samplers"][channel["sampler"]]
    step_times = [v[0] for v in floats(sampler["input"])]
    scales = [v[0] for v in floats(sampler["output"], 3)]
    index = 0 if node["name"] == "surface" else int(node["name"].split(".")[1])
    for k, t in enumerate(times):
        shown = [scale for step, scale in zip(step_times, scales) if step <= t]
        if shown and shown[-1] > 0.5:
            surface_of_key[k] = index

distinct = [k for k in range(len(times))
            if (k == 0 or arc_length[k] > arc_length[k - 1]) and (k + 1 == len(times) or arc_length[k + 1] > arc_length[k])]
picks = {distinct[round(i * (len(distinct) - 1) / (count - 1))] for i in range(count)}
for before, after in zip(distinct, distinct[1:]):
    if surface_of_key[before] != surface_of_key[after]:
        picks |= {before, after}
picks = sorted(picks)
with open(s_path, "w") as s_file:
    s_file.writelines(f"{arc_length[k]!r}\n" for k in picks)
for k in picks:
    print(f"{times[k]!r} {surface_of_key[k]}")
