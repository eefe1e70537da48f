# An FBX clip played by Blender against joint positions sampled from the
# clip's own curves (issue 21 item 1, the keyed clip: tests/core/KeyedClipTest.cpp
# writes FILE-samples.json). Blender 3.4's glTF importer turns CUBICSPLINE keys
# into Bezier keys with AUTO handles and drops the file's tangents (its
# make_fcurve: "this may change when tangent will be managed"), so its glTF
# import does not play the glTF spec's curve; the samples are that curve.
# Blender's FBX importer keys every curve linearly (it ignores KeyAttrFlags):
# the FBX's frame keys must still give the curve within TOLERANCE metres.
# The samples are in the file's Y-up metres; Blender's are Z-up.
# usage: blender -b --factory-startup --python blender-play-samples.py -- FILE.fbx SAMPLES.json [TOLERANCE=1e-3]
import json
import sys

import bpy
from mathutils import Vector

args = sys.argv[sys.argv.index('--') + 1:]
fbx_path, samples_path = args[0], args[1]
tolerance = float(args[2]) if len(args) > 2 else 1e-3
reference = json.load(open(samples_path))
scene = bpy.context.scene

bpy.ops.import_scene.fbx(filepath=fbx_path)
arms = [o for o in bpy.data.objects if o.type == 'ARMATURE']
if len(arms) != 1:
    raise SystemExit(f'ERROR expected one armature, found {len(arms)}')
arm = arms[0]
action = arm.animation_data.action if arm.animation_data else None
if action is None or reference['clip'] not in action.name:
    raise SystemExit(f'ERROR the armature plays {action.name if action else "nothing"}, not {reference["clip"]}')
fps = scene.render.fps / scene.render.fps_base
start = action.frame_range[0]
missing = [n for n in reference['joints'] if n not in arm.pose.bones]
if missing:
    raise SystemExit(f'ERROR bones missing from the FBX armature: {missing[:10]}')

worst, where, travel = 0.0, '', 0.0
first = None
for sample in reference['samples']:
    frame = start + sample['time'] * fps
    whole = int(frame // 1)
    scene.frame_set(whole, subframe=frame - whole)
    evaluated = arm.evaluated_get(bpy.context.evaluated_depsgraph_get())
    heads = [Vector((x, -z, y)) for x, y, z in sample['heads']]  # Y-up to Blender's Z-up
    first = first or heads
    travel = max(travel, max((h - f).length for h, f in zip(heads, first)))
    for name, head in zip(reference['joints'], heads):
        d = (evaluated.matrix_world @ evaluated.pose.bones[name].head - head).length
        if d > worst:
            worst, where = d, f'{name} at {sample["time"]:.4f} s'
print(f'CHECK blender {action.name}: {len(reference["samples"])} samples of the clip\'s curves, '
      f'{len(reference["joints"])} bones travelling up to {travel:.3f} m, fps {fps:g}, worst {worst:.2e} m ({where})')
if travel < 1e-3:
    print('ERROR the samples do not move')
    sys.exit(1)
if worst > tolerance:
    print(f'ERROR the FBX and the clip\'s curves differ by {worst:.3e} m at {where} (tolerance {tolerance})')
    sys.exit(1)
