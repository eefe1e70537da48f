#!/bin/sh
# How this sample was made with rigsmith-cli (run from the repository root after a build): a
# creature's forelimbs whose three talons and dewclaw close on targets (digit.finger's aim rig).
# The sample's first line was then given its description.
set -e
C=./build/app/rigsmith-cli
G=${1:-resources/samples/claw.yml}
rm -f $G
$C new $G --name claw
$C add $G world.character --name world
$C add $G spine.torso --under world --name spine
$C add $G arm.limb --under spine --name arm --set volume=on --set stomp_power=-0.35 --set auto_clavicle=0.5 --set ik_space=chest --set "add_chains=[muscle]" --set soft_ik=0.02
$C add $G digit.hand --under arm:hand --name hand
$C add $G digit.finger --under hand --name talon_in --at -0.02,-0.035,0.03 --set number=4 --set length=0.09 --set base=off --set "target_weights=[1, 1, 0.6]"
$C add $G digit.finger --under hand --name talon_mid --at -0.02,-0.035,0 --set number=4 --set length=0.11 --set base=off --set "target_weights=[1, 1, 0.6]"
$C add $G digit.finger --under hand --name talon_out --at -0.02,-0.035,-0.03 --set number=4 --set length=0.09 --set base=off --set "target_weights=[1, 1, 0.6]"
$C add $G digit.finger --under hand --name dewclaw --set thumb=on --set number=3 --set length=0.05 --set base=off --set "target_weights=[1]" --set "target_parent=*::space.world"
# Then, by hand in the editor: the arm's elbow (joint 10) at t [0.28, 0, -0.08] and its wrist (joint 11) at
# [0.26, 0, 0.08], a deeper bend (23 mm short of full reach) so that the soft IK's 2 cm leave the rest pose as it is.
