#!/usr/bin/env python3
"""Compares what Godot played (godot-sample.gd's JSON) with the glb's own
animation evaluated here (glTF semantics: LINEAR translation/scale, slerp
rotation, a channel's value held before its first and after its last key).
usage: compare-godot-rom.py FILE.glb GODOT.json STEP TOLERANCE_METRES
(STEP: the seconds between Godot's samples, as given to godot-sample.gd)"""
import json, math, struct, sys

def read_glb(path):
    data = open(path, 'rb').read()
    length = struct.unpack_from('<I', data, 12)[0]
    gltf = json.loads(data[20:20 + length])
    binary = data[20 + length + 8:]
    return gltf, binary

def accessor(gltf, binary, index):
    a = gltf['accessors'][index]
    view = gltf['bufferViews'][a['bufferView']]
    width = {'SCALAR': 1, 'VEC3': 3, 'VEC4': 4, 'MAT4': 16}[a['type']]
    offset = view.get('byteOffset', 0) + a.get('byteOffset', 0)
    values = struct.unpack_from('<%df' % (a['count'] * width), binary, offset)
    return [values[k * width:(k + 1) * width] for k in range(a['count'])]

def slerp(a, b, f):
    dot = sum(x * y for x, y in zip(a, b))
    if dot < 0:
        b, dot = [-x for x in b], -dot
    if dot > 0.9995:
        q = [x + f * (y - x) for x, y in zip(a, b)]
    else:
        th = math.acos(dot)
        s = math.sin(th)
        q = [(math.sin((1 - f) * th) * x + math.sin(f * th) * y) / s for x, y in zip(a, b)]
    n = math.sqrt(sum(x * x for x in q))
    return [x / n for x in q]

def sample(times, values, t, rotation):
    if t <= times[0]:
        return list(values[0])
    if t >= times[-1]:
        return list(values[-1])
    lo, hi = 0, len(times) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        (lo, hi) = (mid, hi) if times[mid] <= t else (lo, mid)
    f = (t - times[lo]) / (times[hi] - times[lo])
    if rotation:
        return slerp(values[lo], values[hi], f)
    return [x + f * (y - x) for x, y in zip(values[lo], values[hi])]

def matrix(t, r, s):
    x, y, z, w = r
    rot = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
           [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
           [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[rot[i][j] * s[j] for j in range(3)] + [t[i]] for i in range(3)] + [[0, 0, 0, 1]]

def multiply(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]

def main():
    glb, played, step, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    gltf, binary = read_glb(glb)
    godot = json.load(open(played))
    nodes = gltf['nodes']
    parent = {}
    for i, n in enumerate(nodes):
        for c in n.get('children', []):
            parent[c] = i
    # Godot's importer makes bone names unique its own way ("sk_antenna1" becomes
    # "sk_antenna_1", "sk_arm1_L" "sk_arm_1_l"): names are matched without
    # underscores and case when not exact.
    def key(name):
        return name.replace('_', '').lower()
    played_by_name = {a['name']: a['frames'] for a in godot['animations']}
    bodies = [n for n in nodes if 'mesh' not in n]
    worst, where, compared = 0.0, None, 0
    for animation in gltf.get('animations', []):
        frames = played_by_name.get(animation['name'])
        if not frames:
            sys.exit('Godot did not import the animation %s' % animation['name'])
        channels = {}
        for c in animation['channels']:
            s = animation['samplers'][c['sampler']]
            times = [x[0] for x in accessor(gltf, binary, s['input'])]
            channels[(c['target']['node'], c['target']['path'])] = (times, accessor(gltf, binary, s['output']))
        before = compared
        # Nodes neither animated nor under an animated node: their world is computed once per clip.
        moving = set()
        for i in range(len(nodes)):
            j = i
            while j is not None:
                if any((j, path) in channels for path in ('translation', 'rotation', 'scale')):
                    moving.add(i)
                    break
                j = parent.get(j)
        still = {}
        for k, frame in enumerate(frames):
            t = k * step
            world = dict(still)
            def world_of(i):
                if i in world:
                    return world[i]
                n = nodes[i]
                trs = []
                for path, default, rotation in (('translation', [0, 0, 0], False), ('rotation', [0, 0, 0, 1], True),
                                                ('scale', [1, 1, 1], False)):
                    if (i, path) in channels:
                        times, values = channels[(i, path)]
                        trs.append(sample(times, values, t, rotation))
                    else:
                        trs.append(n.get(path, default))
                local = matrix(*trs)
                world[i] = multiply(world_of(parent[i]), local) if i in parent else local
                if i not in moving:
                    still[i] = world[i]
                return world[i]
            loose = {key(name): p for name, p in frame.items()}
            for i, n in enumerate(nodes):
                name = n.get('name', '')
                p = frame.get(name, loose.get(key(name)))
                if p is None or 'mesh' in n:
                    continue
                m = world_of(i)
                d = math.dist([m[0][3], m[1][3], m[2][3]], p)
                compared += 1
                if d > 0.005 and '--verbose' in sys.argv:
                    print(animation['name'], name, round(t, 3), round(d, 4))
                if d > worst:
                    worst, where = d, (animation['name'], name, round(t, 4))
        if compared - before < len(frames) * len(bodies):
            sys.exit('Godot has not every node of the glTF in %s' % animation['name'])
    print('CHECK godot: %d animations, %d positions compared, worst %.5f m at %s' %
          (len(gltf.get('animations', [])), compared, worst, where))
    if compared == 0 or worst > tolerance:
        sys.exit('Godot plays the range of motion %.4f m away from the glTF (tolerance %g m)' % (worst, tolerance))

main()
