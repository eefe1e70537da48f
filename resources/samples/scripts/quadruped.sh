#!/bin/sh
# How this sample was made with rigsmith-cli (run from the repository root after a build).
set -e
C=./build/app/rigsmith-cli
G=${1:-resources/samples/quadruped.yml}
rm -f $G
$C new $G --name quadruped
$C add $G world.character --name world
$C add $G spine.torso --under world --name spine --at 0,0.7,-0.4
$C add $G neck.head --under spine --name neck --at 0,0.04,0.08
$C add $G leg.limb --under spine --name front_leg --at 0,-0.04,-0.02 --set upper=0.3 --set lower=0.28
$C add $G quad.leg --under spine:hips --name hind_leg --set upper=0.18 --set lower=0.18
$C add $G rig.spline --under spine:hips --name tail --at 0,0.02,-0.08
# Then, by hand in the editor: the spine's joints 1-4 at t [0, 0.01, 0.175]
# (horizontal), the neck's joints 1-3 at [0, 0.12, 0.1], [0, 0.08, 0.06] and
# [0, -0.02, 0.25] (head looking forward).
