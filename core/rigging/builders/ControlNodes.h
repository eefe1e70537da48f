#pragma once
// The node stack of one animatable control, as Mikan's core.bones hierarchy
// options build it (core.joints, core.bones, digit.finger; any builder whose
// manifest declares the options):
//
//   offset "roots.<key>"  (the rest frame; the chain's next link hangs under the controller)
//   > pose group "nodes.pose.<key>"  (do_pose: where driven keys and hand drives land)
//   > add_nodes groups "nodes.<name>.<key>", in order  (names before `c`)
//   > controller "ctrls.<key>"  (rotate_order)
//   > add_nodes after `c`, in order  (between the controller and its skin joint)
//   > skin joint (the builder's)
//
// parent_scale off: the link's offset compensates its parent controller's
// scale (a child link keeps its size when the parent control is scaled; it
// still follows the parent's scaled position). flip_orient on a mirrored
// branch copy: the offset, the groups and the controller take the reflected
// frame M W instead of the mirror image M W M, so the same channel values move
// and turn both sides as mirror images (translations too); skin joints and
// hooks keep M W M. Frames are in authored space, as createNode takes them.
#include "rigging/TemplateBuilder.h"
#include "rigging/builders/BuilderKit.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::rigging {

struct ControlNodeOptions {
    std::vector<std::string> above;  // group names between the offset and the controller, outermost first
    std::vector<std::string> below;  // group names between the controller and its skin joint
    bool parentScale = true;         // off: segment scale compensation between links
    model::RotateOrder rotateOrder = model::RotateOrder::Xyz;
    bool flipOrient = false;
    bool hasPose() const;            // "pose" is among `above` (do_pose or add_nodes)
};

// Reads do_pose, add_nodes, parent_scale, rotate_order and flip_orient; an
// option the manifest does not declare keeps the default above. Reports every
// problem as an error naming its option (so it lands on the guide's line) and
// returns nullopt: add_nodes that is no list, a name that is not an
// identifier ([A-Za-z_][A-Za-z0-9_]*), one given twice, `c` twice, a name the
// stack already uses (root, ctrl, skin...), an unknown rotate order.
std::optional<ControlNodeOptions> readControlNodes(const BuildContext& ctx);

struct ControlStack {
    model::RigNodeIndex offset = model::kNoNode;
    model::RigNodeIndex pose = model::kNoNode;  // the pose group, kNoNode without one
    model::RigNodeIndex ctrl = model::kNoNode;  // the controller; the innermost group without do_ctrl
    model::RigNodeIndex skinParent = model::kNoNode; // the last `below` group, else ctrl
    bool flipped = false;                       // its groups and controller have reflected frames
    // Where drives that pose the control land: the pose group, else the offset.
    model::RigNodeIndex driven() const { return pose != model::kNoNode ? pose : offset; }
    kit::Control control() const { return {offset, ctrl}; }
};

// Builds one control's stack at `world` under `parent` (kNoNode: the hook)
// with tags "<domain>.<key>" and names from `token` and `index` (the offset
// and controller as kit::addControl names them, groups marked with their
// name: pose_finger_1_L). `chained`: `parent` is the previous link's
// controller, so parent_scale applies.
ControlStack addControlStack(BuildContext& ctx, const ControlNodeOptions& options, const std::string& key,
                             const std::string& token, std::optional<int> index, model::RigNodeIndex parent,
                             const Mat4& world, model::JointId source, bool chained);

// A drive's rotation factor for a node of `stack`: BuildContext::addConstraint
// turns factors for mirror images (M W M); a flipped stack is already a
// reflection, so the factor is pre-turned to come out unchanged.
double driveFactor(const BuildContext& ctx, const ControlStack& stack, model::DriveOutput output, double factor);

} // namespace rs::rigging
