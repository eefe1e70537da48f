#!/bin/sh
# How this sample was made with rigsmith-cli (run from the repository root after a build): a mechanical
# four-legged strider, a hull carried 0.86 m up on two pairs of four-segment legs (quad.leg, L/R) whose toe
# tips stand on the ground with the legs bent like a mechanical walker's (rigsmith-cli joint: the stifle
# forward, the hock back, the fetlock under the hip; each leg at 82% of its reach at rest, so the hull rises
# 10 cm with the feet planted). Rigid segments (stretch off: pulled past reach a leg straightens and stops),
# no foot to roll (reverse_lock off: the IK control carries the leg's end, no roll or bank attributes), no
# blend joints at the bends, no twist joints (twist_upper, twist_lower 0) and no twist flesh (non_rolling off:
# the thigh's skin joint turns with the thigh). The IK feet stay planted in world while the hull moves. The
# script then gives the sample's first line its description.
set -e
C=./build/app/rigsmith-cli
G=${1:-resources/samples/strider.yml}
LEG="--set upper=0.35 --set lower=0.35 --set reverse_lock=off --set stretch=off --set blend_joints=off \
  --set non_rolling=off --set twist_upper=0 --set twist_lower=0"
rm -f $G
$C new $G --name strider
$C add $G world.character --name world
$C add $G core.xform --under world --name hull --at 0,0.86,0
$C add $G quad.leg --under hull --name front_leg --at 0.15,-0.05,0.35 $LEG
$C add $G quad.leg --under hull --name hind_leg --at 0.15,-0.05,-0.35 $LEG
for L in front_leg hind_leg; do
  $C joint $G $L limb2 --at 0,-0.25,0.24
  $C joint $G $L limb3 --at 0,-0.28,-0.28
  $C joint $G $L limb4 --at 0,-0.18,0.04
done
sed -i '1s/.*/# Rigsmith guide (a mechanical four-legged strider: a hull on two pairs of rigid four-segment legs ending in toe tips, no foot roll, no stretch, no blend or twist joints; the IK feet stay planted while the hull moves): template instances and their guide joints (metres, degrees; forward is +Z)./' $G
