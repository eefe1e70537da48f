#!/bin/sh
# How this sample was made with rigsmith-cli (run from the repository root after a build): a mine cart on a
# 600 mm gauge track (forward is +Z), a game prop at a fixed scale (no scale control). Its wheels (0.15 m) roll
# only as the chassis is pushed along the rails (hook world: the move control places the cart on the track
# without rolling them); the front axle by its displacement along the rails (roll axis: a pose gives the same
# roll whatever came before), the back axle by the path it takes (roll path, through the track's curves) with
# roll_jump 1.5 m: a runaway cart's step of a frame (25 m/s, 1 m at 24 fps) is more than the wheels'
# circumference (0.94 m, the default limit) and still rolls them, a snap of metres does not. The tub tips
# sideways on its pivot. The sample's first line was then given its description.
set -e
C=./build/app/rigsmith-cli
G=${1:-resources/samples/cart.yml}
rm -f $G
$C new $G --name cart
$C add $G world.prop --name world --set do_scale=off
$C add $G core.xform --under world --name chassis --at 0,0.3,0 --set copy_orient=off --set do_scale=off
$C add $G core.xform --under chassis --name tub --at 0,0.25,0 --set copy_orient=off --set do_translate=off --set do_scale=off
$C add $G wheel.legacy --under chassis --name wheel_front --at 0.2,-0.15,0.35 --set radius=0.15 --set "branches=[L, R]" --set hook=world --set roll=axis
$C add $G wheel.legacy --under chassis --name wheel_back --at 0.2,-0.15,-0.35 --set radius=0.15 --set "branches=[L, R]" --set hook=world --set roll_jump=1.5
