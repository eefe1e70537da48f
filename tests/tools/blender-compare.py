# The same rig and clip as .glb and .fbx, played by Blender (issue 21 item 2):
# both files are imported into one scene (Blender's glTF and FBX importers),
# each armature plays its file's action, and every bone head's world position
# is sampled with scene.frame_set at sub-frames: each interval between two of
# the action's keys cut in four (4x the key rate). The two armatures must
# agree within TOLERANCE metres at every sample. Both importers bring the
# files to Blender's Z-up metres (the FBX through its unit scale), so the
# positions compare as they are.
# The FBX is imported first (its importer sets the scene's frame rate to the
# file's), the glTF then converts seconds at that rate; each glTF action is
# moved to start where the FBX importer starts (frame 1, the glTF importer's is
# frame 0), so one frame_set plays both files at one time. Every clip (glTF
# animation, FBX take) is compared, one pair of actions playing at a time.
# --part K/N: only the K-th of N equal runs of samples (a long clip is checked
# by several processes, each under a minute).
# usage: blender -b --factory-startup --python blender-compare.py -- FILE.glb FILE.fbx [TOLERANCE=1e-4] [--part K/N]
import sys

import numpy
numpy.bool = bool  # Debian 12's numpy 1.24 removed the alias Blender 3.4's importer uses

import bpy

args = sys.argv[sys.argv.index('--') + 1:]
part, parts = 1, 1
if '--part' in args:
    at = args.index('--part')
    part, parts = (int(v) for v in args[at + 1].split('/'))
    del args[at:at + 2]
glb_path, fbx_path = args[0], args[1]
tolerance = float(args[2]) if len(args) > 2 else 1e-4
failures = []
scene = bpy.context.scene


def import_armature(path):
    before = set(bpy.data.objects)
    actions_before = set(bpy.data.actions)
    if path.endswith('.fbx'):
        bpy.ops.import_scene.fbx(filepath=path)
    else:
        bpy.ops.import_scene.gltf(filepath=path)
    fps = scene.render.fps / scene.render.fps_base
    arms = [o for o in set(bpy.data.objects) - before if o.type == 'ARMATURE']
    if len(arms) != 1:
        raise SystemExit(f'ERROR {path}: expected one armature, found {len(arms)}')
    arm = arms[0]
    if arm.animation_data is None or arm.animation_data.action is None:
        raise SystemExit(f'ERROR {path}: the armature plays no action')
    # Only the action under test plays: the glTF importer puts every clip on an NLA track.
    for track in arm.animation_data.nla_tracks:
        track.mute = True
    # The armature's actions (bone curves): a camera's (util.camera) or its lens's are not compared here.
    actions = [a for a in set(bpy.data.actions) - actions_before
               if any(fc.data_path.startswith('pose.bones[') for fc in a.fcurves)]
    return arm, sorted(actions, key=lambda a: a.name), fps


fbx_arm, fbx_actions, fps = import_armature(fbx_path)
gltf_arm, gltf_actions, gltf_fps = import_armature(glb_path)
if abs(gltf_fps - fps) > 1e-9:
    raise SystemExit(f'ERROR the glTF importer changed the frame rate ({fps} -> {gltf_fps})')

# Every clip as a pair of actions: the FBX importer names a take's action
# ARMATURE|TAKE|LAYER, the glTF importer CLIP_ARMATURE.
pairs = []
for fbx_action in fbx_actions:
    clip = fbx_action.name.split('|')[1] if fbx_action.name.count('|') >= 2 else fbx_action.name
    matches = [a for a in gltf_actions if a.name in (clip, clip + '_' + gltf_arm.name)]
    if len(matches) != 1:
        raise SystemExit(f'ERROR no glTF action for the FBX take {clip} (glTF actions: {[a.name for a in gltf_actions]})')
    pairs.append((clip, matches[0], fbx_action))
if len(pairs) != len(gltf_actions):
    raise SystemExit(f'ERROR {len(gltf_actions)} glTF clips but {len(pairs)} FBX takes')

samples = []  # (pair index, seconds from the clip's start)
key_times = 0
for index, (clip, gltf_action, fbx_action) in enumerate(pairs):
    shift = fbx_action.frame_range[0] - gltf_action.frame_range[0]
    for fc in gltf_action.fcurves:
        for k in fc.keyframe_points:
            k.co.x += shift
            k.handle_left.x += shift
            k.handle_right.x += shift
        fc.update()
    start = fbx_action.frame_range[0]
    if abs(gltf_action.frame_range[0] - start) > 1e-6:
        raise SystemExit(f'ERROR {clip}: the actions start at frames {gltf_action.frame_range[0]} and {start}')
    # The key times of the glTF action, in seconds from its start.
    frames = set()
    for fc in gltf_action.fcurves:
        for k in fc.keyframe_points:
            frames.add(round(k.co[0], 4))
    times = sorted((f - start) / fps for f in frames)
    key_times += len(times)
    for a, b in zip(times, times[1:]):
        samples += [(index, a + (b - a) * q / 4) for q in range(4)]
    samples.append((index, times[-1]))
count = len(samples)
samples = samples[(part - 1) * count // parts:part * count // parts]

names = [b.name for b in gltf_arm.pose.bones]
missing = [n for n in names if n not in fbx_arm.pose.bones]
if missing:
    raise SystemExit(f'ERROR bones missing from the FBX armature: {missing[:10]}')


def moving_locations(action):
    moving = set()
    for fc in action.fcurves:
        if fc.data_path.endswith('.location') and fc.keyframe_points:
            values = [k.co[1] for k in fc.keyframe_points]
            if max(values) - min(values) > 1e-6:
                moving.add(fc.data_path.split('"')[1])
    return moving


# Blender's FBX importer connects a bone whose head is its parent's tail (it
# infers the tail along the parent's +Y), and Blender ignores the location of
# a connected bone, whatever the file says. A Y-up export's root is turned so
# that its +Y does not point at the hips (io/ExportScene.h): no bone whose
# location moves may be connected after a plain import.
gltf_moving = set().union(*(moving_locations(g) for _, g, _ in pairs))
fbx_moving = set().union(*(moving_locations(f) for _, _, f in pairs))
connected_moving = sorted(n for n in gltf_moving if fbx_arm.data.bones[n].use_connect)
if connected_moving:
    raise SystemExit(f'ERROR Blender connects {connected_moving} on FBX import, so their location curves are ignored')
not_in_fbx = sorted(n for n in gltf_moving if n not in fbx_moving)
if not_in_fbx:
    raise SystemExit(f'ERROR the FBX action does not move the location of {not_in_fbx}')


def frame_set(frame):
    whole = int(frame // 1)
    scene.frame_set(whole, subframe=frame - whole)


def heads(arm):
    evaluated = arm.evaluated_get(bpy.context.evaluated_depsgraph_get())
    return [evaluated.matrix_world @ evaluated.pose.bones[n].head for n in names]


worst, where, travel = 0.0, '', 0.0
rest = None
playing = None
for index, time in samples:
    clip, gltf_action, fbx_action = pairs[index]
    if playing != index:
        # A bone the next action does not key keeps its last pose in Blender: back to rest, as on import.
        for arm in (gltf_arm, fbx_arm):
            for bone in arm.pose.bones:
                bone.matrix_basis.identity()
        gltf_arm.animation_data.action, fbx_arm.animation_data.action, playing = gltf_action, fbx_action, index
    frame_set(fbx_action.frame_range[0] + time * fps)
    gltf_heads = heads(gltf_arm)
    rest = rest or gltf_heads
    travel = max(travel, max((h - r).length for h, r in zip(gltf_heads, rest)))
    for n, head, fbx_head in zip(names, gltf_heads, heads(fbx_arm)):
        d = (fbx_head - head).length
        if d > worst:
            worst, where = d, f'{n} at {time:.4f} s of {clip}'
print(f'CHECK blender {len(pairs)} clips ({pairs[0][1].name} / {pairs[0][2].name}...): {key_times} key times, part {part}/{parts}: '
      f'{len(samples)} of {count} samples, {len(names)} bones travelling up to {travel:.3f} m, fps {fps:g}, worst {worst:.2e} m ({where})')
if travel < 1e-3:
    print('ERROR the glTF armature does not move')
    sys.exit(1)
if worst > tolerance:
    print(f'ERROR glTF and FBX differ by {worst:.3e} m at {where} (tolerance {tolerance})')
    sys.exit(1)
