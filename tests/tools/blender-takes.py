# The range of motion as one clip per controller (--rom-clips per-control,
# issue 21 item 3), imported by Blender: the FBX importer makes one action per
# take (AnimationStack, "<armature>|<take>|<layer>") and the glTF importer one
# per animation ("<animation>_<armature>"); each clip of the export's
# reference JSON must come in from both files under its name and last as
# long as the reference says (its frame range at the scene's frame rate).
# FBX markers are not read by Blender (nor by three.js or Assimp), which is
# why the per-controller ranges are clips of their own, not markers.
# usage: blender -b --factory-startup --python blender-takes.py -- FILE.fbx FILE.glb REFERENCE.json
import json
import sys

import numpy
numpy.bool = bool  # Debian 12's numpy 1.24 removed the alias Blender 3.4's importer uses

import bpy

args = sys.argv[sys.argv.index('--') + 1:]
fbx_path, glb_path, reference_path = args[:3]
clips = json.load(open(reference_path))['clips']
scene = bpy.context.scene
failures = []


def imported(path):
    before = set(bpy.data.actions)
    if path.endswith('.fbx'):
        bpy.ops.import_scene.fbx(filepath=path)
    else:
        bpy.ops.import_scene.gltf(filepath=path)
    return [a for a in bpy.data.actions if a not in before]


fbx_actions = imported(fbx_path)  # first: sets the scene's frame rate to the file's
fps = scene.render.fps / scene.render.fps_base
gltf_actions = imported(glb_path)
for kind, actions, named in (('FBX', fbx_actions, lambda a, n: a.name.split('|')[1:2] == [n]),
                             ('glTF', gltf_actions, lambda a, n: a.name.rsplit('_', 1)[0] == n)):
    if len(actions) != len(clips):
        failures.append(f'{kind}: {len(actions)} actions for {len(clips)} clips: {[a.name for a in actions][:12]}')
    for clip in clips:
        found = [a for a in actions if named(a, clip['name'])]
        if len(found) != 1:
            failures.append(f'{kind}: clip {clip["name"]} comes in as {len(found)} actions')
            continue
        first, last = found[0].frame_range
        seconds = (last - first) / fps
        if abs(seconds - clip['seconds']) > 1e-3:
            failures.append(f'{kind}: {found[0].name} lasts {seconds:.4f} s, the clip {clip["seconds"]:.4f} s')
print(f'CHECK blender takes: {len(clips)} clips, FBX actions {len(fbx_actions)}, glTF actions {len(gltf_actions)}, '
      f'fps {fps:g}, e.g. {fbx_actions[0].name if fbx_actions else "-"} frames {tuple(fbx_actions[0].frame_range) if fbx_actions else "-"}')
for f in failures:
    print('ERROR ' + f)
sys.exit(1 if failures else 0)
