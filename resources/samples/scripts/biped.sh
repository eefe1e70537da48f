#!/bin/sh
# How this sample was begun with rigsmith-cli (run from the repository root after a build); the
# sample was then refined in the editor (guide placement, the hand master, finger pose groups).
set -e
C=./build/app/rigsmith-cli
G=${1:-resources/samples/biped.yml}
rm -f $G
$C new $G --name biped
$C add $G world.character --name world
$C add $G spine.torso --under world --name spine
$C add $G neck.head --under spine --name neck
$C add $G arm.limb --under spine --name arm --set fk_space=chest --set bendy=on
$C add $G leg.limb --under spine:hips --name leg --set bendy=on
$C add $G digit.finger --under arm:hand --name thumb --at 0.015,-0.01,0.035 --set number=4 --set length=0.07
$C add $G digit.finger --under arm:hand --name index --at 0.03,0,0.035
$C add $G digit.finger --under arm:hand --name middle --at 0.03,0,0.012 --set length=0.11
$C add $G digit.finger --under arm:hand --name ring --at 0.028,0,-0.01
$C add $G digit.finger --under arm:hand --name pinky --at 0.025,-0.005,-0.03 --set length=0.08
