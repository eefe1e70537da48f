# Run by check-godot-rom.sh inside a Godot 3 project holding rom.glb (imported
# with Godot's default settings): plays each animation and writes every
# node's world position every STEP seconds as JSON:
#   {"animations": [{"name": N, "frames": [{node: [x, y, z]}...]}...]}
#   godot3-server --path PROJECT -s godot-sample.gd --out FILE.json --step STEP
extends SceneTree

func find_player(node):
	if node is AnimationPlayer:
		return node
	for child in node.get_children():
		var found = find_player(child)
		if found:
			return found
	return null

func collect(node, out):
	if node is Spatial:
		out.append(node)
	for child in node.get_children():
		collect(child, out)

func positions(nodes, skeletons):
	var frame = {}
	for n in nodes:
		var p = n.global_transform.origin
		frame[n.name] = [p.x, p.y, p.z]
	for s in skeletons:
		for i in range(s.get_bone_count()):
			var p = s.global_transform.xform(s.get_bone_global_pose(i).origin)
			frame[s.get_bone_name(i)] = [p.x, p.y, p.z]
	return frame

func _init():
	var args = OS.get_cmdline_args()
	var out_path = ""
	var step = 0.1
	for i in range(args.size() - 1):
		if args[i] == "--out":
			out_path = args[i + 1]
		elif args[i] == "--step":
			step = float(args[i + 1])
	var scene = load("res://rom.glb").instance()
	get_root().add_child(scene)
	var player = find_player(scene)
	var nodes = []
	collect(scene, nodes)
	var skeletons = []
	for n in nodes:
		if n is Skeleton:
			skeletons.append(n)
	var result = {"animations": []}
	if player:
		for name in player.get_animation_list():
			var animation = player.get_animation(name)
			var frames = []
			player.play(name)
			var k = 0
			while k * step <= animation.length + 1e-6:
				player.seek(k * step, true)
				frames.append(positions(nodes, skeletons))
				k += 1
			player.stop()
			result["animations"].append({"name": name, "frames": frames})
	var file = File.new()
	file.open(out_path, File.WRITE)
	file.store_string(to_json(result))
	file.close()
	quit()
