# Headless Blender check of a character export's surface (run by
# check-blender-skin.sh, next to blender-check.py for the skeleton and weights):
# imports a .glb and an .fbx of the same bound character and checks, for every
# mesh, a UV layer, a material with the expected name, and for a textured
# material an image with pixels (the texture travelled inside the file); then
# that both files give the same UV at the same place (a V flipped in one
# format would not match). --textures embedded (the default) wants the FBX's
# images packed from inside the file; --textures relative wants them read from
# files beside the FBX (written by `rigsmith-cli build --textures relative`),
# with the FBX holding no image bytes.
# usage: blender -b --factory-startup --python check-blender-skin.py -- FILE.glb FILE.fbx [--textures embedded|relative]
import sys

import numpy
numpy.bool = bool  # Debian 12's numpy 1.24 removed the alias Blender 3.4's importer uses

import bpy

import os

args = sys.argv[sys.argv.index('--') + 1:]
textures = 'embedded'
if '--textures' in args:
    at = args.index('--textures')
    textures = args[at + 1]
    del args[at:at + 2]
failures = []


def surface(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if path.lower().endswith('.fbx'):
        bpy.ops.import_scene.fbx(filepath=path)
    else:
        bpy.ops.import_scene.gltf(filepath=path)
    out = {}
    for obj in (o for o in bpy.data.objects if o.type == 'MESH'):
        mesh = obj.data
        if not mesh.uv_layers:
            failures.append(f'{path}: mesh {obj.name} has no UVs')
            continue
        materials = [m.name for m in mesh.materials if m]
        images = []
        for material in mesh.materials:
            for node in (material.node_tree.nodes if material and material.use_nodes else []):
                if node.type == 'TEX_IMAGE' and node.image:
                    images.append((node.image.name, tuple(node.image.size)))
                    if path.lower().endswith('.fbx'):
                        where = bpy.path.abspath(node.image.filepath)
                        beside = os.path.dirname(os.path.abspath(where)) == os.path.dirname(os.path.abspath(path))
                        print(f'CHECK {path}: image {node.image.name} packed {node.image.packed_file is not None}, file {where}')
                        if textures == 'embedded' and node.image.packed_file is None:
                            failures.append(f'{path}: image {node.image.name} is not embedded')
                        if textures == 'relative' and (node.image.packed_file is not None or not beside or
                                                       not os.path.isfile(where)):
                            failures.append(f'{path}: image {node.image.name} is not read from a file beside the FBX ({where})')
        uv = mesh.uv_layers.active.data
        pairs = set()
        for loop in mesh.loops:
            p = obj.matrix_world @ mesh.vertices[loop.vertex_index].co
            u, v = uv[loop.index].uv
            pairs.add((round(p.x, 4), round(p.y, 4), round(p.z, 4), round(u, 4), round(v, 4)))
        out[obj.name] = (materials, images, pairs)
        print(f'CHECK {path}: mesh {obj.name}: materials {materials}, images {images}, {len(pairs)} (place, UV) pairs')
    return out


glb, fbx = surface(args[0]), surface(args[1])
if sorted(glb) != sorted(fbx):
    failures.append(f'meshes differ: {sorted(glb)} / {sorted(fbx)}')
for name in sorted(set(glb) & set(fbx)):
    materials_a, images_a, pairs_a = glb[name]
    materials_b, images_b, pairs_b = fbx[name]
    if [m.split('.')[0] for m in materials_a] != [m.split('.')[0] for m in materials_b]:
        failures.append(f'{name}: materials {materials_a} / {materials_b}')
    for images, path in ((images_a, args[0]), (images_b, args[1])):
        if any(size[0] == 0 for _, size in images):
            failures.append(f'{path}: {name}: an image without pixels {images}')
    if bool(images_a) != bool(images_b):
        failures.append(f'{name}: textured in one file only ({images_a} / {images_b})')
    # Rounding can split a pair across a boundary: compare with a small allowance.
    missing = len(pairs_a ^ pairs_b)
    share = missing / max(1, len(pairs_a | pairs_b))
    print(f'CHECK {name}: {len(pairs_a)} / {len(pairs_b)} (place, UV) pairs, {share:.4%} differ')
    if share > 0.001:
        failures.append(f'{name}: the files disagree on {missing} (place, UV) pairs')
if not any(glb[name][1] for name in glb):
    failures.append(f'no texture in {args[0]}: the check needs a textured character')
for f in failures:
    print('ERROR', f)
sys.exit(1 if failures else 0)
