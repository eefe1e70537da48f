# Headless Blender check of an exported rig (run by check-export.sh):
# imports FILE with Blender's glTF importer and compares the armature with the
# skeleton JSON written by rigsmith-cli: exactly one armature, one root bone,
# same joint names and parents, bone heads within 1e-4 m.
# usage: blender -b --factory-startup --python blender-check.py -- FILE SKELETON.json
import json
import sys

import numpy
numpy.bool = bool  # Debian 12's numpy 1.24 removed the alias Blender 3.4's importer uses

import bpy
from mathutils import Vector

args = sys.argv[sys.argv.index('--') + 1:]
path, reference_path = args[0], args[1]
reference = json.load(open(reference_path))
failures = []

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=path)

armatures = [o for o in bpy.data.objects if o.type == 'ARMATURE']
if len(armatures) != 1:
    failures.append(f'expected 1 armature, found {len(armatures)}')
else:
    arm = armatures[0]
    bones = arm.data.bones
    roots = [b.name for b in bones if b.parent is None]
    if len(roots) != 1:
        failures.append(f'expected 1 root bone, found {roots}')
    if len(bones) != len(reference):
        failures.append(f'expected {len(reference)} bones, found {len(bones)}')
    worst = 0.0
    for joint in reference:
        bone = bones.get(joint['name'])
        if bone is None:
            failures.append(f"missing bone {joint['name']}")
            continue
        parent = bone.parent.name if bone.parent else None
        if parent != joint['parent']:
            failures.append(f"{joint['name']}: parent {parent}, expected {joint['parent']}")
        x, y, z = joint['head']
        expected = Vector((x, -z, y))  # glTF Y-up -> Blender Z-up
        error = ((arm.matrix_world @ bone.head_local) - expected).length
        worst = max(worst, error)
        if error > 1e-4:
            failures.append(f"{joint['name']}: head off by {error:.6f} m")
    print(f'CHECK {path}: {len(bones)} bones, root {roots}, worst head error {worst:.2e} m')

for f in failures:
    print('ERROR', f)
sys.exit(1 if failures else 0)
