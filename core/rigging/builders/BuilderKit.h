#pragma once
// Shared pieces of the built-in builders: joint frames from guide positions and
// the offset-group + controller + skin-joint pattern every template repeats.
#include "rigging/TemplateBuilder.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rs::rigging::kit {

// Frame at `origin` whose X axis points along `aim` and whose Z axis is as
// close to `normal` as X allows (Gram-Schmidt); Y completes a right-handed frame.
Mat4 aimFrame(const Vec3& origin, const Vec3& aim, const Vec3& normal);
// Unit normal of the plane through a, b, c (the bend plane of a limb), or
// nullopt when the points are (nearly) on one line.
std::optional<Vec3> planeNormal(const Vec3& a, const Vec3& b, const Vec3& c);
// Frames along a chain: each joint aims at the next, Z = the chain's bend
// normal (or `fallbackNormal` where the chain is straight); the last joint
// keeps the previous joint's orientation.
std::vector<Mat4> chainFrames(const std::vector<Vec3>& points, const Vec3& fallbackNormal);
// An axis-aligned frame at a position (world, COG, IK controllers).
Mat4 uprightFrame(const Vec3& origin);
// Frames along a chain that aim at the next joint and keep Z on one fixed side
// axis (spines and necks, whose S-curves would flip a bend normal).
std::vector<Mat4> sideFrames(const std::vector<Vec3>& points, const Vec3& side);
Vec3 positionOf(const Mat4& m);
// The point `share` (0..1) of the way along a polyline by length, and the
// index of the segment it lies on (the point before it).
std::pair<Vec3, std::size_t> alongChain(const std::vector<Vec3>& points, double share);
// Unit axis `column` (0 x, 1 y, 2 z) of a guide joint's world matrix, or `fallback`.
Vec3 guideAxis(const BuildContext& ctx, model::JointId joint, int column, const Vec3& fallback);

// An offset group with a controller under it: the pattern of every animatable
// control. Without `do_ctrl` only the group is made and drives the rig.
struct Control {
    model::RigNodeIndex offset = model::kNoNode;
    model::RigNodeIndex ctrl = model::kNoNode; // == offset when the instance has no controllers
};
// Tags "roots.<key>" and "ctrls.<key>"; names from `token` and `index`.
Control addControl(BuildContext& ctx, const std::string& key, const std::string& token, std::optional<int> index,
                   model::RigNodeIndex parent, const Mat4& world, model::JointId source = model::kNoId);
// The transform channels an animator touches on a controller (masks of
// model::ChannelSettings bits). Each builder declares them for every
// controller it makes, as data of its template: cleanup (rigging/CleanupStage.h)
// locks and hides every other transform channel. Custom attributes on a
// controller are all animatable.
constexpr std::uint16_t kTranslate = model::ChannelSettings::kTranslateChannels;
constexpr std::uint16_t kRotate = model::ChannelSettings::kRotateChannels;
constexpr std::uint16_t kScale = model::ChannelSettings::kScaleChannels;
constexpr std::uint16_t kNothing = model::ChannelSettings::kNoChannels;
// Declares `channels` animatable on `node` (nothing when it is not a
// controller: the offset group of an instance without controllers).
void animate(BuildContext& ctx, model::RigNodeIndex node, std::uint16_t channels);
// The same for a control made by addControl.
void animate(BuildContext& ctx, const Control& control, std::uint16_t channels);

// A skin joint "skin.<key>" when the instance has `do_skin`; kNoNode otherwise.
model::RigNodeIndex addSkin(BuildContext& ctx, const std::string& key, const std::string& token, std::optional<int> index,
                            model::RigNodeIndex parent, const Mat4& world, model::JointId source = model::kNoId);
// A setup joint or group that animators never see ("<domain>.<key>").
model::RigNodeIndex addSetup(BuildContext& ctx, model::RigNodeKind kind, const std::string& tag, const std::string& token,
                             std::optional<int> index, model::RigNodeIndex parent, const Mat4& world,
                             model::JointId source = model::kNoId);

// A space switch: `group` (the control's offset parent) follows one of
// `spaces` (named spaces of the rig; entry 0 is `first`, the group's own
// parent), chosen by an enum attribute "space" on `control` whose default is
// the option `option`. A space missing from this rig is not offered; when it
// is the option's value, a warning (on the option, naming the control and the
// space) says so and the switch defaults to `first`.
// orientOnly keeps the position from the parent.
// `attribute` names the enum attribute when a control has two switches.
void addSpaceSwitch(BuildContext& ctx, model::RigNodeIndex group, model::RigNodeIndex control, const std::string& option,
                    const std::string& tag, model::RigNodeIndex first, const std::vector<std::string>& spaces, bool orientOnly,
                    const std::string& attribute = "space");
// The same with the instance's own spaces: each entry names a space and gives
// its node, or kNoNode for the rig's named space of that name; entry 0 must
// have a node, and is the default when the option's space is missing.
struct Space {
    std::string name;
    model::RigNodeIndex node = model::kNoNode;
};
void addSpaceSwitch(BuildContext& ctx, model::RigNodeIndex group, model::RigNodeIndex control, const std::string& option,
                    const std::string& tag, const std::vector<Space>& spaces, bool orientOnly,
                    const std::string& attribute = "space");

// Guide positions of a structure tag; nullopt (with the error reported) when it fails.
std::optional<std::vector<Vec3>> positions(const BuildContext& ctx, const std::vector<model::JointId>& joints);
// The `chain` structure tag with at least `minimum` joints (else an error naming
// the `number` option: "<what> needs at least N guide joints<parts>; it has M"),
// spacing checked.
std::optional<std::vector<model::JointId>> chainOfAtLeast(const BuildContext& ctx, std::size_t minimum, const std::string& what,
                                                          const std::string& parts = {});
// Warns about consecutive guides closer than 1 mm; returns false when any overlap.
bool checkSpacing(const BuildContext& ctx, const std::vector<model::JointId>& joints, const std::string& what);

// Appends a straight chain of `count` guide joints, `step` apart, whose first
// joint sits at `first` under spec `parent` (-1: the instance root). Returns the
// index of its last joint.
int appendChain(std::vector<GuideJointSpec>& specs, int count, const Vec3& first, const Vec3& step, int parent = -1);
// Appends one guide joint; returns its index.
int appendJoint(std::vector<GuideJointSpec>& specs, int parent, const Vec3& translate,
                std::vector<std::string> tags = {}, std::string name = {});
// A guide parameter as a number (defaults when absent or of another type).
double guideNumber(const std::map<std::string, Value>& guides, const std::string& name, double fallback);

} // namespace rs::rigging::kit
