# Headless Blender check of an export's cameras (util.camera; run by
# check-camera.sh): imports FILE (.glb/.gltf with Blender's glTF importer, .fbx
# with its FBX importer) and compares its camera objects with the export
# reference JSON (rigsmith-cli --reference, "cameras"): as many camera objects
# as the reference has cameras, none of them a bone; each one's world position
# within 1e-3 m and its look direction (-Z) and up (+Y) within 1e-3 rad of the
# reference's at every sampled key time of every clip that moves it (the
# clip's action on the camera object, played alone); the lens: the glTF's
# vertical field of view, the FBX's focal length at each sample (the
# FocalLength curve, when the clip animates it).
# usage: blender -b --factory-startup --python blender-camera.py -- FILE REFERENCE.json
import json
import math
import sys

import numpy
numpy.bool = bool  # Debian 12's numpy 1.24 removed the alias Blender 3.4's importers use

import bpy
from mathutils import Vector

POSITION_TOLERANCE = 1e-3  # metres
ANGLE_TOLERANCE = 1e-3     # radians
args = sys.argv[sys.argv.index('--') + 1:]
path, reference_path = args[0], args[1]
reference = json.load(open(reference_path))
fbx = path.lower().endswith('.fbx')
failures = []


def blender_space(p):
    x, y, z = p
    return Vector((x, -z, y))  # the rig's Y-up -> Blender's Z-up (both importers convert to this)


def angle(a, b):
    return a.normalized().angle(b.normalized(), 0.0)


def clip_action(actions, clip, owner_name):
    """The action of `clip` for the camera object (or its data: owner_name)."""
    found = [a for a in actions if clip in a.name and owner_name in a.name]
    if not found:
        found = [a for a in actions if clip in a.name]
    return found[0] if found else None


def play(id_block, action):
    """`action` alone on `id_block` (NLA tracks muted)."""
    data = id_block.animation_data or id_block.animation_data_create()
    for track in data.nla_tracks:
        track.mute = True
    data.action = action


def check_camera(obj, expected):
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    object_actions = [a for a in bpy.data.actions
                      if any(not fc.data_path.startswith('pose.') and fc.data_path in
                             ('location', 'rotation_euler', 'rotation_quaternion') for fc in a.fcurves)]
    lens_actions = [a for a in bpy.data.actions if any(fc.data_path == 'lens' for fc in a.fcurves)]
    worst_position = worst_look = worst_up = worst_lens = 0.0
    imported_lens = obj.data.lens  # what a clip without a FocalLength curve plays
    clips = sorted(set(s['clip'] for s in expected['samples']))
    for clip in clips:
        action = clip_action(object_actions, clip, obj.name)
        if action is None:
            failures.append(f"{obj.name}: no action moves it in clip {clip} "
                            f"(actions: {[a.name for a in bpy.data.actions]})")
            continue
        play(obj, action)
        lens_action = clip_action(lens_actions, clip, obj.data.name) if fbx else None
        if lens_action:
            play(obj.data, lens_action)
        else:
            if obj.data.animation_data:
                obj.data.animation_data.action = None
            obj.data.lens = imported_lens
        start = action.frame_range[0]
        for sample in (s for s in expected['samples'] if s['clip'] == clip):
            frame = start + sample['time'] * fps
            whole = int(math.floor(frame))
            scene.frame_set(whole, subframe=frame - whole)
            world = obj.matrix_world
            position = world.to_translation()
            look = -Vector(world.col[2][:3])
            up = Vector(world.col[1][:3])
            where = f"{clip} at {sample['time']:.3f} s"
            errors = ((position - blender_space(sample['position'])).length,
                      angle(look, blender_space(sample['look'])), angle(up, blender_space(sample['up'])))
            worst_position, worst_look, worst_up = (max(worst_position, errors[0]), max(worst_look, errors[1]),
                                                    max(worst_up, errors[2]))
            if '--verbose' in args:
                print(f'  {where}: {tuple(round(c, 5) for c in position)} {errors}')
            if errors[0] > POSITION_TOLERANCE:
                failures.append(f'{obj.name}: {where}: position off by {errors[0]:.6f} m')
            if errors[1] > ANGLE_TOLERANCE or errors[2] > ANGLE_TOLERANCE:
                failures.append(f'{obj.name}: {where}: look off by {errors[1]:.6f} rad, up by {errors[2]:.6f} rad')
            if fbx:
                lens_error = abs(obj.data.lens - sample['focal_length'])
                worst_lens = max(worst_lens, lens_error)
                if lens_error > 1e-3:
                    failures.append(f"{obj.name}: {where}: focal length {obj.data.lens:.4f} mm, "
                                    f"expected {sample['focal_length']:.4f}")
    lens = f'worst focal length error {worst_lens:.2e} mm' if fbx else f'yfov {obj.data.angle_y:.6f} rad'
    print(f"CHECK {path}: camera {obj.name}: {len(expected['samples'])} samples in {len(clips)} clips, worst "
          f"position error {worst_position:.2e} m, look {worst_look:.2e} rad, up {worst_up:.2e} rad, {lens}")
    if not fbx and abs(obj.data.angle_y - expected['yfov']) > 1e-5:
        failures.append(f"{obj.name}: yfov {obj.data.angle_y:.6f} rad, expected {expected['yfov']:.6f}")
    if fbx and not any(s['focal_length'] != expected['focal_length'] for s in expected['samples']) \
            and abs(obj.data.lens - expected['focal_length']) > 1e-3:
        failures.append(f"{obj.name}: focal length {obj.data.lens:.4f} mm, expected {expected['focal_length']}")


bpy.ops.wm.read_factory_settings(use_empty=True)
if fbx:
    bpy.ops.import_scene.fbx(filepath=path)
else:
    bpy.ops.import_scene.gltf(filepath=path)

cameras = [o for o in bpy.data.objects if o.type == 'CAMERA']
if len(cameras) != len(reference['cameras']):
    failures.append(f"expected {len(reference['cameras'])} cameras, found {[o.name for o in cameras]}")
for arm in (o for o in bpy.data.objects if o.type == 'ARMATURE'):
    for expected in reference['cameras']:
        if expected['name'] in arm.data.bones:
            failures.append(f"camera {expected['name']} is a bone of {arm.name}")
for expected in reference['cameras']:
    obj = bpy.data.objects.get(expected['name'])
    if obj is None or obj.type != 'CAMERA':
        failures.append(f"no camera object {expected['name']}")
    elif not expected['samples']:
        failures.append(f"camera {expected['name']}: the reference has no samples (export with --rom or --clip)")
    else:
        check_camera(obj, expected)

for f in failures:
    print('ERROR', f)
sys.exit(1 if failures else 0)
