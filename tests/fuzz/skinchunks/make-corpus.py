#!/usr/bin/env python3
"""Writes the fuzz-skinchunks seed corpus: small skin chunk files, written
from the format described in core/io/SkinChunks.h alone (so it also checks
that a script in another language can write the format). Run from anywhere:
  tests/fuzz/skinchunks/make-corpus.py"""
import math, os, struct

def fnv1a(data):
    h = 1469598103934665603
    for b in data:
        h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h

def text(s):
    b = s.encode()
    return struct.pack('<I', len(b)) + b

def matrix(t):
    m = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, t[0], t[1], t[2], 1]  # column-major
    return struct.pack('<16d', *m)

def chunk(name, grid, posed, joints, neighbours):
    n = grid * grid
    out = text(name) + text('models/' + name + '.obj') + text('rigsmith 0.1.0') + text('fuzz')
    out += struct.pack('<qIQBBH', 1714571112000000, n, 0x1234 + n, 1 if posed else 0, 0 if posed else 1, 0)
    out += struct.pack('<I', len(joints))
    for j, (tag, parent) in enumerate(joints):
        out += struct.pack('<I', 1) + text('L' if j % 2 else '') + text(tag) + text(tag + '_jnt') + struct.pack('<i', parent)
        out += matrix((0, j * 0.1, 0)) + matrix((0, 0.1 if parent >= 0 else 0, 0)) + matrix((0, j * 0.1, 0))
    out += struct.pack('<I', n) + struct.pack('<%dI' % n, *range(n))
    points = [(x * 0.1, y * 0.1, 0.0) for y in range(grid) for x in range(grid)]
    normal = [(0.0, 0.0, 1.0)] * n
    lists = [points, normal] + ([[(x + 0.5, y, z) for x, y, z in points], normal] if posed else [])
    for values in lists:
        out += b''.join(struct.pack('<3f', *p) for p in values)
    weights, offsets = [], [0]
    for v in range(n):
        t = (v % grid) / max(grid - 1, 1)
        ws = [(0, 1.0)] if len(joints) == 1 else [(0, 1 - t), (1, t)]
        weights += ws
        offsets.append(len(weights))
    out += struct.pack('<I', len(weights)) + struct.pack('<%dI' % len(offsets), *offsets)
    out += b''.join(struct.pack('<If', j, w) for j, w in weights)
    tris = []
    for y in range(grid - 1):
        for x in range(grid - 1):
            a = y * grid + x
            tris += [a, a + 1, a + grid, a + 1, a + grid + 1, a + grid]
    out += struct.pack('<I', len(tris) // 3) + struct.pack('<%dI' % len(tris), *tris)
    sample, noffsets = [], [0]
    for v in range(n):
        if neighbours:
            sample += [u for u in (v - 1, v + 1) if 0 <= u < n]
        noffsets.append(len(sample))
    out += struct.pack('<I', len(sample)) + struct.pack('<%dI' % len(noffsets), *noffsets)
    out += struct.pack('<%dI' % len(sample), *sample)
    return out

def file(chunks):
    body = b'RSCHUNKS' + struct.pack('<II', 1, len(chunks)) + b''.join(chunks)
    return body + struct.pack('<Q', fnv1a(body))

here = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'corpus')
two = [('skin.root', -1), ('skin.limb.0', 0)]
files = {
    'bind-pose.rschunks': file([chunk('body', 3, False, two, True)]),
    'posed.rschunks': file([chunk('body', 3, True, two, False)]),
    'two-chunks.rschunks': file([chunk('body', 2, False, two, True), chunk('eyes', 2, True, [('skin.head', -1)], False)]),
    'empty.rschunks': file([]),
}
for name, data in files.items():
    with open(os.path.join(here, name), 'wb') as f:
        f.write(data)
    print(name, len(data), 'bytes')
