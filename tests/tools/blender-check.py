# Headless Blender check of an exported rig (run by check-export.sh): imports
# FILE (.glb/.gltf with Blender's glTF importer, .fbx with its FBX importer) and
# compares it with the export reference JSON written by rigsmith-cli --reference:
# exactly one armature with one root bone, the same joint names and parents,
# bone heads within 1e-4 m, and for every bound mesh each vertex's position and
# weights (by joint name) within 1e-4 of the reference vertex at that place.
# Options: --unit-scale S: the armature object's scale must be S (1 for a file in
# metres, 0.01 for centimetres); --animated: an action for each of the
# reference's clips, on the armature, whose bone scale curves move exactly for
# the joints the reference lists as scaled (constant ones may exist: Blender
# keys location, rotation and scale of every animated bone).
# usage: blender -b --factory-startup --python blender-check.py -- FILE REFERENCE.json [--unit-scale S] [--animated]
import json
import sys

import numpy
numpy.bool = bool  # Debian 12's numpy 1.24 removed the alias Blender 3.4's importer uses

import bpy
from mathutils import Vector
from mathutils.kdtree import KDTree

TOLERANCE = 1e-4
args = sys.argv[sys.argv.index('--') + 1:]
path, reference_path = args[0], args[1]
unit_scale = float(args[args.index('--unit-scale') + 1]) if '--unit-scale' in args else None
animated = '--animated' in args
reference = json.load(open(reference_path))
failures = []


def blender_space(p):
    x, y, z = p
    return Vector((x, -z, y))  # the rig's Y-up -> Blender's Z-up (both importers convert to this)


def check_armature(arm):
    bones = arm.data.bones
    roots = [b.name for b in bones if b.parent is None]
    if len(roots) != 1:
        failures.append(f'expected 1 root bone, found {roots}')
    if len(bones) != len(reference['joints']):
        failures.append(f"expected {len(reference['joints'])} bones, found {len(bones)}")
    worst = 0.0
    for joint in reference['joints']:
        bone = bones.get(joint['name'])
        if bone is None:
            failures.append(f"missing bone {joint['name']}")
            continue
        parent = bone.parent.name if bone.parent else None
        if parent != joint['parent']:
            failures.append(f"{joint['name']}: parent {parent}, expected {joint['parent']}")
        error = ((arm.matrix_world @ bone.head_local) - blender_space(joint['head'])).length
        worst = max(worst, error)
        if error > TOLERANCE:
            failures.append(f"{joint['name']}: head off by {error:.6f} m")
    print(f'CHECK {path}: {len(bones)} bones, root {roots}, worst head error {worst:.2e} m')
    if unit_scale is not None:
        scale = arm.matrix_world.to_scale()
        print(f'CHECK {path}: armature scale {tuple(round(c, 6) for c in scale)}')
        if max(abs(c - unit_scale) for c in scale) > 1e-6:
            failures.append(f'armature scale {tuple(scale)}, expected {unit_scale}')


def clip_action(name):
    """The armature's action Blender made for the clip `name` (named after the
    clip, not followed by another digit: range_of_motion_1 is not _10; the one
    with bone curves, not a controller object's)."""
    for action in bpy.data.actions:
        at = action.name.find(name)
        after = action.name[at + len(name):at + len(name) + 1] if at >= 0 else ''
        if at >= 0 and not after.isdigit() and any(fc.data_path.startswith('pose.bones[') for fc in action.fcurves):
            return action
    return None


def scale_moving(action):
    # The reference's rule (io/ExportScene.cpp, the "scaled" list): a bone whose
    # scale at some key is more than 1e-5 (the length of the difference) from
    # its first key's. A spine's volume, barely stretched, scales by as little.
    keys = {}
    for fc in action.fcurves:
        if fc.data_path.endswith('.scale') and fc.data_path.startswith('pose.bones["'):
            bone = fc.data_path[len('pose.bones["'):-len('"].scale')]
            keys.setdefault(bone, {})[fc.array_index] = [k.co[1] for k in fc.keyframe_points]
    moving = set()
    for bone, curves in keys.items():
        count = max(len(values) for values in curves.values())
        def at(axis, k):
            values = curves.get(axis, [])
            return values[min(k, len(values) - 1)] if values else 1.0
        first = [at(axis, 0) for axis in range(3)]
        for k in range(count):
            if sum((at(axis, k) - first[axis]) ** 2 for axis in range(3)) ** 0.5 > 1e-5:
                moving.add(bone)
                break
    return moving


def check_animation(arm):
    actions = [a.name for a in bpy.data.actions]
    action = arm.animation_data.action if arm.animation_data else None
    if action is None or not action.fcurves:
        failures.append(f'the armature has no action with curves (actions: {actions})')
        return
    first, last = action.frame_range
    print(f'CHECK {path}: action {action.name}: {len(action.fcurves)} curves, frames {first:g}-{last:g}')
    # Each clip's action scales exactly the bones the reference says that clip scales.
    for clip in reference.get('clips', []):
        clip_act = clip_action(clip['name'])
        if clip_act is None:
            failures.append(f"no action for clip {clip['name']} (actions: {actions})")
            continue
        scaled, moving = set(clip['scaled']), scale_moving(clip_act)
        print(f"CHECK {path}: clip {clip['name']} (action {clip_act.name}): scale moves on {len(moving)} bones "
              f'(reference: {len(scaled)})')
        if moving != scaled:
            failures.append(f"clip {clip['name']}: scale moves on {sorted(moving - scaled)} but should not; "
                            f'does not move on {sorted(scaled - moving)}')

def check_mesh(obj, expected):
    tree = KDTree(len(expected['vertices']))
    for i, v in enumerate(expected['vertices']):
        tree.insert(blender_space(v[:3]), i)
    tree.balance()
    groups = {g.index: g.name for g in obj.vertex_groups}
    worst_position = worst_weight = 0.0
    for vertex in obj.data.vertices:
        position = obj.matrix_world @ vertex.co
        co, index, distance = tree.find(position)
        worst_position = max(worst_position, distance)
        have = {groups[g.group]: g.weight for g in vertex.groups if g.weight > 0.0}
        # Reference vertices at the same place are told apart by their weights.
        candidates = [i for _, i, _ in tree.find_range(position, distance + 1e-6)] or [index]
        errors = []
        for i in candidates:
            want = expected['vertices'][i][3]
            errors.append(max(abs(want.get(n, 0.0) - have.get(n, 0.0)) for n in set(want) | set(have)))
        worst_weight = max(worst_weight, min(errors))
    print(f"CHECK {path}: mesh {obj.name}: {len(obj.data.vertices)} vertices, worst position error "
          f"{worst_position:.2e} m, worst weight error {worst_weight:.2e}")
    if worst_position > TOLERANCE:
        failures.append(f'mesh {obj.name}: a vertex is {worst_position:.6f} m from its reference')
    if worst_weight > TOLERANCE:
        failures.append(f'mesh {obj.name}: a weight is off by {worst_weight:.6f}')


bpy.ops.wm.read_factory_settings(use_empty=True)
if path.lower().endswith('.fbx'):
    bpy.ops.import_scene.fbx(filepath=path)
else:
    bpy.ops.import_scene.gltf(filepath=path)

armatures = [o for o in bpy.data.objects if o.type == 'ARMATURE']
if len(armatures) != 1:
    failures.append(f'expected 1 armature, found {len(armatures)}')
else:
    check_armature(armatures[0])
    if animated:
        check_animation(armatures[0])
meshes = [o for o in bpy.data.objects if o.type == 'MESH']
if len(meshes) != len(reference['meshes']):
    failures.append(f"expected {len(reference['meshes'])} meshes, found {len(meshes)}")
for expected in reference['meshes']:
    obj = bpy.data.objects.get(expected['name'])
    if obj is None or obj.type != 'MESH':
        failures.append(f"missing mesh {expected['name']}")
    else:
        check_mesh(obj, expected)

for f in failures:
    print('ERROR', f)
sys.exit(1 if failures else 0)
