#!/usr/bin/env bash
# Godot 3 (Debian's godot3-server, headless) imports a sample's range of motion
# at its default import settings and plays it within TOLERANCE metres of the
# glTF itself, sampled at every key and halfway between (every 1/6 s).
# LAYOUT: default (the export's default clips: one range of motion, split into
# clips of a minute at most) or per-control (--rom-clips per-control).
# Godot 3.2 bakes animations at 15 fps by adding 1/15 s to a float time, which
# drifts on a long clip (1.9 ms 170 s in, 23 ms 380 s in: the biped's range as
# one 380 s clip played 1.6 cm off at a toe), hence the export's minute.
# usage: check-godot-rom.sh CLI GUIDE OUTDIR [LAYOUT] [TOLERANCE]   (exit 77: no Godot)
set -euo pipefail
cli=$1 guide=$2 out=$3 layout=${4:-default} tolerance=${5:-0.01}
case $layout in
  default) clips=() ;;
  per-control) clips=(--rom-clips per-control) ;;
  *) echo "check-godot-rom.sh: LAYOUT is default or per-control, not '$layout'" >&2; exit 2 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
command -v godot3-server >/dev/null || { echo "godot3-server is not installed (./run.sh --with-test-tools)" >&2; exit 77; }
step=0.16666666666666666
rm -rf "$out" && mkdir -p "$out/project"
printf 'config_version=4\n\n[application]\n\nconfig/name="rom"\n' > "$out/project/project.godot"
cp "$here/godot-sample.gd" "$out/project/"
"$cli" build "$guide" --rom "${clips[@]}" --no-meshes -o "$out/project/rom.glb"
export HOME="$out" # Godot writes its editor settings under ~/.config and ~/.local
godot3-server --path "$out/project" --editor --quit >"$out/import.log" 2>&1 || { tail -20 "$out/import.log" >&2; exit 1; }
[ -f "$out/project/rom.glb.import" ] || { echo "Godot did not import rom.glb (log: $out/import.log)" >&2; exit 1; }
godot3-server --path "$out/project" -s godot-sample.gd --out "$out/played.json" --step "$step" >"$out/play.log" 2>&1 ||
  { tail -20 "$out/play.log" >&2; exit 1; }
python3 "$here/compare-godot-rom.py" "$out/project/rom.glb" "$out/played.json" "$step" "$tolerance"
