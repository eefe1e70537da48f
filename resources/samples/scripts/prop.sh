#!/bin/sh
# How this sample was made with rigsmith-cli (run from the repository root after a build).
set -e
C=./build/app/rigsmith-cli
G=${1:-resources/samples/prop.yml}
rm -f $G
$C new $G --name prop
$C add $G world.prop --name world
$C add $G core.xform --under world --name chest --at 0,0.25,0
$C add $G core.xform --under chest --name lid --at 0,0.25,-0.2
$C add $G core.joints --under lid --name antenna --at 0,0.05,0.2 --set number=4 --set length=0.1 --set orient=auto
