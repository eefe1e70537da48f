# Compares Rigsmith's automatic weights with Blender's (issue 19): imports the
# character (Collada .dae; Blender cannot read a zipped .zae), builds an
# armature with one bone per Rigsmith skin joint, parents every mesh to it with
# automatic weights (Blender's bone heat), and reports, per vertex, whether
# Blender's and Rigsmith's dominant joints agree. Vertices are matched by
# position (Blender welds the file's vertices; Rigsmith keeps them split at
# seams, each copy with its welded vertex's weights).
#
# WEIGHTS.json is written by `rigsmith-cli skin bind GUIDE --json WEIGHTS.json`:
# the bones (name, parent, head, segment ends) and each mesh's vertices
# (metres, Y-up) with their weights. A Blender bone has one segment: a joint
# with several skin children (the hips, the chest, the wrist) points at the
# child that continues its parent's direction best (spine, neck, middle finger),
# as a rigger would draw it; its other segments are not heat sources in Blender.
#
# usage: blender -b --factory-startup --python compare-blender-weights.py -- MODEL.dae WEIGHTS.json [REPORT.json]
import json
import sys
from collections import Counter

import bpy
from mathutils import Vector
from mathutils.kdtree import KDTree

args = sys.argv[sys.argv.index('--') + 1:]
model_path, weights_path = args[0], args[1]
report_path = args[2] if len(args) > 2 else None
ours = json.load(open(weights_path))
bones = ours['bones']


def blender_space(p):
    x, y, z = p
    return Vector((x, -z, y))  # Rigsmith's Y-up -> Blender's Z-up


def tail_of(index):
    bone = bones[index]
    head = Vector(bone['head'])
    tails = [Vector(t) for t in bone['tails'] if (Vector(t) - head).length > 1e-6]
    if not tails:
        return head + Vector((0, 0.01, 0))
    if bone['parent'] < 0 or len(tails) == 1:
        return tails[0]
    direction = head - Vector(bones[bone['parent']]['head'])
    if direction.length < 1e-6:
        return tails[0]
    direction.normalize()
    cosines = [(t - head).normalized().dot(direction) for t in tails]
    best = max(cosines)
    # Collinear segments (a twist joint's on the same line): the longest.
    return max((t for t, c in zip(tails, cosines) if c > best - 1e-3), key=lambda t: (t - head).length)


for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)
bpy.ops.wm.collada_import(filepath=model_path)
meshes = [o for o in bpy.data.objects if o.type == 'MESH']
if not meshes:
    sys.exit('no mesh imported from ' + model_path)

armature_data = bpy.data.armatures.new('rig')
armature = bpy.data.objects.new('rig', armature_data)
bpy.context.scene.collection.objects.link(armature)
bpy.context.view_layer.objects.active = armature
bpy.ops.object.mode_set(mode='EDIT')
edit_bones = []
for i, bone in enumerate(bones):
    b = armature_data.edit_bones.new(bone['name'])
    b.head = blender_space(bone['head'])
    b.tail = blender_space(tail_of(i))
    b.use_deform = True
    edit_bones.append(b)
for i, bone in enumerate(bones):
    if bone['parent'] >= 0:
        edit_bones[i].parent = edit_bones[bone['parent']]
bpy.ops.object.mode_set(mode='OBJECT')

bpy.ops.object.select_all(action='DESELECT')
for obj in meshes:
    obj.select_set(True)
armature.select_set(True)
bpy.context.view_layer.objects.active = armature
bpy.ops.object.parent_set(type='ARMATURE_AUTO')

# Rigsmith's vertices, all meshes, with their dominant joint.
points = []
for mesh in ours['meshes']:
    for p, w in zip(mesh['positions'], mesh['weights']):
        dominant = bones[max(w, key=lambda x: x[1])[0]]['name'] if w else None
        points.append((blender_space(p), dominant))
tree = KDTree(len(points))
for i, (p, _) in enumerate(points):
    tree.insert(p, i)
tree.balance()


def region(name):
    if name is None:
        return 'none'
    for part in ('thumb', 'index', 'middle', 'ring', 'pinky'):
        if part in name:
            return 'fingers'
    for part, label in (('arm', 'arms'), ('leg', 'legs'), ('neck', 'neck/head'), ('spine', 'trunk')):
        if part in name:
            return label
    return 'root'


report = {'meshes': {}}
confusions = Counter()
total = agree_total = 0
worst_match = 0.0
for obj in meshes:
    groups = {g.index: g.name for g in obj.vertex_groups}
    agree = unweighted = 0
    by_region = Counter()
    agree_region = Counter()
    for vertex in obj.data.vertices:
        position = obj.matrix_world @ vertex.co
        _, index, distance = tree.find(position)
        worst_match = max(worst_match, distance)
        ours_dominant = points[index][1]
        weights = [(g.weight, groups[g.group]) for g in vertex.groups if g.weight > 0.0]
        theirs = max(weights)[1] if weights else None
        unweighted += theirs is None
        by_region[region(ours_dominant)] += 1
        if theirs == ours_dominant:
            agree += 1
            agree_region[region(ours_dominant)] += 1
        else:
            confusions[(ours_dominant, theirs)] += 1
    n = len(obj.data.vertices)
    total += n
    agree_total += agree
    report['meshes'][obj.name] = {
        'vertices': n, 'agree': agree, 'percent': 100.0 * agree / n, 'unweighted_in_blender': unweighted,
        'by_region': {r: {'vertices': by_region[r], 'percent': 100.0 * agree_region[r] / by_region[r]} for r in sorted(by_region)}}
    print(f'COMPARE {obj.name}: {n} vertices, dominant joint agrees on {agree} ({100.0 * agree / n:.1f}%), '
          f'{unweighted} left unweighted by Blender')
    for r in sorted(by_region):
        print(f'COMPARE   {r}: {by_region[r]} vertices, {100.0 * agree_region[r] / by_region[r]:.1f}% agree')
report['all'] = {'vertices': total, 'agree': agree_total, 'percent': 100.0 * agree_total / total}
report['worst_position_match_m'] = worst_match
report['top_disagreements'] = [{'rigsmith': a, 'blender': b, 'vertices': c} for (a, b), c in confusions.most_common(15)]
print(f'COMPARE all meshes: {total} vertices, {100.0 * agree_total / total:.1f}% agree '
      f'(worst position match {worst_match:.2e} m)')
for (a, b), c in confusions.most_common(15):
    print(f'COMPARE   rigsmith {a} / blender {b}: {c}')
if report_path:
    json.dump(report, open(report_path, 'w'), indent=1)
