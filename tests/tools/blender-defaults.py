# Headless Blender check of cleanup's default values (run by check-defaults.sh):
# reads the expected defaults from GLB's own JSON chunk (each controller node's
# extras rig.defaults), then imports GLB with Blender's glTF importer and FBX
# with its FBX importer and finds them again as custom properties: the glTF
# node extras as the empty's "rig" property (its "defaults" group), the FBX
# user properties as "rig_default_<channel>"; and the controllers' attributes
# (extras rig.attributes; FBX user properties named like the attribute, an
# enum read as its label). Prints CHECK lines per file;
# any difference is an ERROR line and exit code 1.
# usage: blender -b --factory-startup --python blender-defaults.py -- FILE.glb FILE.fbx
import json
import struct
import sys

import numpy
numpy.bool = bool  # Debian 12's numpy 1.24 removed the alias Blender 3.4's importer uses

import bpy

TOLERANCE = 1e-6
args = sys.argv[sys.argv.index('--') + 1:]
glb_path, fbx_path = args[0], args[1]
failures = []


def glb_json(path):
    data = open(path, 'rb').read()
    magic, version, length = struct.unpack_from('<4sII', data, 0)
    assert magic == b'glTF' and version == 2, 'not a glb 2.0'
    chunk_length, chunk_type = struct.unpack_from('<I4s', data, 12)
    assert chunk_type == b'JSON'
    return json.loads(data[20:20 + chunk_length])


def expected_defaults(gltf):
    out = {}
    for node in gltf['nodes']:
        rig = node.get('extras', {}).get('rig', {})
        if rig.get('kind') == 'controller':
            out[node['name']] = rig.get('defaults')
    return out


def clear_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def compare(label, expected, read):
    """read(obj) -> {channel: value} of an object, or None when it has none."""
    objects = {o.name: o for o in bpy.data.objects}
    checked = values = 0
    for name, defaults in expected.items():
        if not defaults:
            failures.append(f'{label}: controller {name} has no defaults in the glb (was the rig cleaned up?)')
            continue
        obj = objects.get(name)
        if obj is None:
            failures.append(f'{label}: no object {name}')
            continue
        got = read(obj)
        if got is None:
            failures.append(f'{label}: {name} has no default values among its custom properties {list(obj.keys())}')
            continue
        for channel, value in defaults.items():
            if channel not in got:
                failures.append(f'{label}: {name} lacks the default of {channel}')
            elif abs(got[channel] - value) > TOLERANCE:
                failures.append(f'{label}: {name}.{channel} default {got[channel]} instead of {value}')
            values += 1
        extra = set(got) - set(defaults)
        if extra:
            failures.append(f'{label}: {name} has unexpected defaults {sorted(extra)}')
        checked += 1
    print(f'CHECK {label}: {checked} controllers, {values} default values read back (expected {len(expected)} controllers)')


def from_gltf(obj):
    rig = obj.get('rig')
    if rig is None or 'defaults' not in rig.keys():
        return None
    d = rig['defaults']
    return {k: float(d[k]) for k in d.keys()}


def from_fbx(obj):
    prefix = 'rig_default_'
    got = {k[len(prefix):]: float(obj[k]) for k in obj.keys() if k.startswith(prefix)}
    return got or None


def expected_attributes(gltf):
    """{controller: {attribute: value, or its label for an enum}} from the glb's extras."""
    out = {}
    for node in gltf['nodes']:
        rig = node.get('extras', {}).get('rig', {})
        if rig.get('kind') == 'controller' and rig.get('attributes'):
            out[node['name']] = {name: (a['labels'][int(round(a['value']))] if a.get('labels') else a['value'])
                                 for name, a in rig['attributes'].items()}
    return out


def compare_attributes(label, expected, read):
    objects = {o.name: o for o in bpy.data.objects}
    values = 0
    for name, attributes in expected.items():
        obj = objects.get(name)
        if obj is None:
            failures.append(f'{label}: no object {name}')
            continue
        for attribute, value in attributes.items():
            got = read(obj, attribute)
            if got is None:
                failures.append(f'{label}: {name} lacks its attribute {attribute} among {list(obj.keys())}')
            elif isinstance(value, str) != isinstance(got, str) or \
                    (got != value if isinstance(value, str) else abs(float(got) - value) > TOLERANCE):
                failures.append(f'{label}: {name}.{attribute} is {got!r} instead of {value!r}')
            values += 1
    print(f'CHECK {label}: {len(expected)} controllers with attributes, {values} attribute values read back')


def gltf_attribute(obj, attribute):
    rig = obj.get('rig')
    if rig is None or 'attributes' not in rig.keys() or attribute not in rig['attributes'].keys():
        return None
    a = rig['attributes'][attribute]
    labels = list(a['labels']) if 'labels' in a.keys() else None
    return labels[int(round(a['value']))] if labels else float(a['value'])


def fbx_attribute(obj, attribute):
    return obj.get(attribute)


gltf = glb_json(glb_path)
expected = expected_defaults(gltf)
attributes = expected_attributes(gltf)
if not attributes:
    print('NOTE the glb has no controller attributes')
if not expected:
    failures.append('the glb has no controller nodes (built without --controllers?)')

clear_scene()
bpy.ops.import_scene.gltf(filepath=glb_path)
compare('glTF ' + glb_path, expected, from_gltf)
compare_attributes('glTF ' + glb_path, attributes, gltf_attribute)

clear_scene()
bpy.ops.import_scene.fbx(filepath=fbx_path)
compare('FBX ' + fbx_path, expected, from_fbx)
compare_attributes('FBX ' + fbx_path, attributes, fbx_attribute)

for f in failures[:40]:
    print('ERROR ' + f)
sys.exit(1 if failures else 0)
