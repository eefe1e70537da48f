#!/usr/bin/python3
# Writes tests/data/Skin/human/guide.yml: resources/samples/biped.yml with its
# guide joints moved into the human of Debian's assimp-testmodels
# (Collada/human.zae: 1.66 m, Y-up, +Z forward, A-pose with the elbows bent
# forward). The trunk, leg and arm joints were read off cross-sections of the
# mesh (the centre of each limb's section, the narrowest points at the knee and
# elbow, the crotch, the foot's extremes); the fingers are found here, from the
# hand's own frame (its principal axes), as the centre of the hand's vertices
# around each finger's line. Only the left side is authored; the rig mirrors it.
# usage: rigsmith-cli skin bind resources/samples/biped.yml --model HUMAN -o /tmp/h.weights --json /tmp/h.json
#        /usr/bin/python3 tests/tools/fit-human-guide.py /tmp/h.json > tests/data/Skin/human/guide.yml
import json
import sys

import numpy as np

body = np.array(json.load(open(sys.argv[1]))['meshes'][0]['positions'])
body = np.unique(np.round(body, 5), axis=0)

# World positions (metres) of the left side and the centre.
world = {
    1: (0, 0, 0), 2: (0, 0, 0),
    # spine: hips, spine1..3, chest (the spine runs a little behind the trunk's middle)
    3: (0, 0.93, 0.02), 4: (0, 1.03, 0.02), 5: (0, 1.12, 0.015), 6: (0, 1.21, 0.01), 7: (0, 1.30, 0.0),
    # neck: neck base, neck middle, head, head top
    8: (0, 1.37, 0.005), 9: (0, 1.41, 0.015), 10: (0, 1.455, 0.025), 11: (0, 1.655, 0.03),
    # arm: clavicle, shoulder, elbow, wrist, hand tip
    12: (0.03, 1.32, 0.02), 13: (0.185, 1.305, 0.0), 14: (0.345, 1.13, 0.04), 15: (0.452, 1.005, 0.18),
    # leg: root, hip, knee, ankle, ball, toe tip, heel, bank in, bank out
    17: (0, 0.91, 0.02), 18: (0.095, 0.845, 0.03), 19: (0.145, 0.455, 0.025), 20: (0.185, 0.075, 0.012),
    21: (0.19, 0.02, 0.13), 22: (0.19, 0.01, 0.2), 23: (0.187, 0.0, -0.028), 24: (0.145, 0.0, 0.13), 25: (0.232, 0.0, 0.12),
}

# The left hand's frame: the wrist, the axis along the hand, across the fingers, and the palm's normal.
wrist, elbow = np.array(world[15]), np.array(world[14])
forearm = (wrist - elbow) / np.linalg.norm(wrist - elbow)
hand = body[((body - wrist) @ forearm > -0.01) & (body[:, 0] > 0.3)]
_, _, axes = np.linalg.svd(hand - hand.mean(0))
along = axes[0] * np.sign(axes[0] @ forearm)
across, normal = axes[1], axes[2]
local = np.c_[(hand - wrist) @ along, (hand - wrist) @ across, (hand - wrist) @ normal]

# Each finger's joints as (along, across) in the hand's frame, read off a plot of
# the hand in that plane: base (in the palm), knuckle, middle joints, tip.
fingers = {
    'thumb': (26, [(0.012, 0.05), (0.03, 0.08), (0.042, 0.1), (0.052, 0.118)]),
    'index': (30, [(0.02, 0.07), (0.09, 0.086), (0.106, 0.095), (0.121, 0.104), (0.134, 0.111)]),
    'middle': (35, [(0.02, 0.05), (0.095, 0.064), (0.12, 0.066), (0.142, 0.067), (0.16, 0.068)]),
    'ring': (40, [(0.02, 0.03), (0.095, 0.035), (0.12, 0.036), (0.143, 0.037), (0.162, 0.037)]),
    'pinky': (45, [(0.02, 0.01), (0.085, 0.01), (0.105, 0.011), (0.124, 0.012), (0.139, 0.013)]),
}
for name, (first, joints) in fingers.items():
    for k, (a, b) in enumerate(joints):
        near = local[(np.abs(local[:, 0] - a) < 0.008) & (np.abs(local[:, 1] - b) < 0.012)]
        c = 0.5 * (near[:, 2].min() + near[:, 2].max()) if len(near) else 0.0  # the middle of the finger's thickness
        world[first + k] = tuple(wrist + a * along + b * across + c * normal)
world[16] = tuple(wrist + 0.16 * along + 0.066 * across)  # the hand's tip: the middle finger's

sample = open(sys.argv[2] if len(sys.argv) > 2 else 'resources/samples/biped.yml').read().splitlines()
parents = {}
out = []
import re
current_hook = None
for line in sample:
    m = re.match(r'(\s*)- \{id: (\d+), (parent: (\d+), )?t: \[[^\]]*\](.*)', line)
    hook = re.match(r'\s*hook: (\d+)', line)
    if hook:
        current_hook = int(hook.group(1))
    if re.match(r'\s*- id: \d+', line):
        current_hook = None
    if not m:
        if line.startswith('name: biped'):
            line = 'name: human'
        out.append(line)
        if line.startswith('name: human'):
            out.append('models:')
            out.append('  - /usr/share/assimp/models/Collada/human.zae')
        continue
    joint = int(m.group(2))
    parent = int(m.group(4)) if m.group(4) else current_hook
    origin = np.array(world[parent]) if parent else np.zeros(3)
    t = np.array(world[joint]) - origin
    text = ', '.join('%.4g' % (0.0 if abs(x) < 5e-5 else x) for x in t)
    out.append('%s- {id: %d, %st: [%s]%s' % (m.group(1), joint, m.group(3) or '', text, m.group(5)))
print('# Rigsmith guide: the biped sample fitted to the human of assimp-testmodels')
print('# (written by tests/tools/fit-human-guide.py; metres, degrees).')
print('\n'.join(out[1:]))
