#!/usr/bin/env bash
# Godot 3 (Debian's godot3-server, headless) imports a sample's range of motion
# (one clip per controller) at its default import settings and plays it within
# TOLERANCE metres of the glTF itself, sampled at every key and halfway between (every 1/6 s).
# One clip per controller: Godot 3.2 bakes animations at 15 fps by adding
# 1/15 s to a float time, which drifts on a clip minutes long (the single
# range-of-motion clip of the biped is 380 s: 1.7 cm off after 120 s).
# usage: check-godot-rom.sh CLI GUIDE OUTDIR [TOLERANCE]   (exit 77: no Godot)
set -euo pipefail
cli=$1 guide=$2 out=$3 tolerance=${4:-0.01}
here=$(cd "$(dirname "$0")" && pwd)
command -v godot3-server >/dev/null || { echo "godot3-server is not installed (./run.sh --with-test-tools)" >&2; exit 77; }
step=0.16666666666666666
rm -rf "$out" && mkdir -p "$out/project"
printf 'config_version=4\n\n[application]\n\nconfig/name="rom"\n' > "$out/project/project.godot"
cp "$here/godot-sample.gd" "$out/project/"
"$cli" build "$guide" --rom --rom-clips per-control --no-meshes -o "$out/project/rom.glb"
export HOME="$out" # Godot writes its editor settings under ~/.config and ~/.local
godot3-server --path "$out/project" --editor --quit >"$out/import.log" 2>&1 || { tail -20 "$out/import.log" >&2; exit 1; }
[ -f "$out/project/rom.glb.import" ] || { echo "Godot did not import rom.glb (log: $out/import.log)" >&2; exit 1; }
godot3-server --path "$out/project" -s godot-sample.gd --out "$out/played.json" --step "$step" >"$out/play.log" 2>&1 ||
  { tail -20 "$out/play.log" >&2; exit 1; }
python3 "$here/compare-godot-rom.py" "$out/project/rom.glb" "$out/played.json" "$step" "$tolerance"
