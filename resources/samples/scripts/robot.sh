#!/bin/sh
# How this sample was begun with rigsmith-cli (run from the repository root after a build): a mech whose
# rigid parts use the template options a soft character leaves at their defaults. The antennas' and the
# hose's guide joints were then placed in the editor (bent back, hanging down the back), and the pincer's
# curved up, so that its curl (up_auto: about its bend) closes it onto the claw; the jaw's, the eyes' and the
# cables' (down the sides of its back to its hips) too.
set -e
C=./build/app/rigsmith-cli
G=${1:-resources/samples/robot.yml}
rm -f $G
$C new $G --name robot
$C add $G world.character --name world --set isolate_skin=on
$C add $G spine.torso --under world --name spine --set isolate_skin=on
$C add $G neck.head --under spine --name neck --set spline=off --set space_switch=off --set orient_neck=off \
  --set head_orient=joint --set isolate_skin=on
$C add $G arm.limb --under spine --name arm --set clavicle=off --set twist_upper=0 --set twist_lower=0 \
  --set blend_joints=off --set stretch=off --set ik_orient=joint --set effector_plane=y --set ik_fk_visibility=off \
  --set ik_blend=0 --set isolate_skin=on --set non_rolling=off --set pin=off
$C add $G leg.limb --under spine:hips --name leg --set pelvis=on --set twist_upper=0 --set twist_lower=0 \
  --set blend_joints=off --set stretch=off --set non_rolling=off --set effector_plane=ground --set ik_orient=joint \
  --set ik_space=cog --set pv_space=ik --set reverse_lock=off --set isolate_skin=on
$C add $G digit.hand --under arm:hand --name hand --set isolate_skin=on
$C add $G digit.finger --under hand --name claw --at 0.01,-0.025,0 --set base=off --set number=3 --set length=0.08 \
  --set fist=25 --set parent_scale=on --set flip_orient=on --set add_nodes=[inf] --set isolate_skin=on
$C add $G digit.finger --under hand --name pincer --at 0.01,-0.065,0 --set base=off --set number=3 --set length=0.08 \
  --set fist=25 --set orient=auto --set aim_axis=y --set up_axis=x --set up_auto=on --set rotate_order=auto --set isolate_skin=on
$C add $G core.joints --under neck --name antenna --at 0.08,0.2,-0.03 --set "branches=[L, R]" --set number=3 \
  --set length=0.08 --set orient=auto --set up_auto=on --set "up_dir=[1, 0, 0]" --set flip_orient=on --set isolate_skin=on
$C add $G core.joints --under spine --name hose --at 0,-0.05,-0.15 --set number=4 --set length=0.1 --set orient=auto \
  --set do_ctrl=off --set aim_axis=y --set up_axis=z --set isolate_skin=on
$C add $G face.jaw --under neck --name jaw --set chin=off --set isolate_skin=on
$C add $G face.eye --under neck --name eye --set "branches=[L, R]" --set sym=x --set blink_height=0.5 \
  --set isolate_skin=on
$C add $G rig.spline --under spine --name cable --at 0.09,-0.04,-0.12 --set "branches=[L, R]" --set number=5 \
  --set length=0.45 --set controls=3 --set stretch=on --set flip_orient=on --set rotate_order=yxz --set isolate_skin=on
