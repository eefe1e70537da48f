#pragma once
// The animatable channels of a built rig, laid out flat so a pose is one
// std::vector<double>: every controller's nine transform channels (tx ty tz,
// rx ry rz in degrees, sx sy sz, in the controller's rest frame), its rotate
// order `ro` (an enum, transform index 9, as Maya shows it in the channel box;
// changing it through the tools keeps the control's orientation), then its custom channels (the node's attributes: ik_blend, space, roll...).
// Attributes of other nodes (post_scale) are channels too, locked for
// animators. Nodes that are not controllers have no transform channels: they
// are locked by construction (seed 004's cleanup).
#include "model/GuideDocument.h"
#include "model/Rig.h"

#include <optional>
#include <string>
#include <vector>

namespace rs::eval {

using Pose = std::vector<double>;

struct Channel {
    model::RigNodeIndex node = model::kNoNode;
    std::string name;               // "tx".."sz" or the attribute name
    int transform = -1;             // 0..8 transform, 9 the rotate order, -1 a custom channel
    double defaultValue = 0.0;
    double min = 0.0, max = 0.0;    // meaningful when `limited`
    bool limited = false;
    bool locked = false;            // animators cannot change it (tools keep it too)
    bool keyable = true;            // false: shown, set by hand, never keyed
    bool hidden = false;            // not shown to animators (cleanup's lock and hide)
    const std::vector<std::string>* labels = nullptr; // enum labels (points into the rig)
    bool isEnum() const { return labels && !labels->empty(); }
};

class ChannelLayout {
public:
    ChannelLayout() = default;
    explicit ChannelLayout(const model::Rig& rig);

    const std::vector<Channel>& channels() const { return m_channels; }
    std::size_t size() const { return m_channels.size(); }
    std::size_t nodeCount() const { return m_first.size(); }
    const Channel& operator[](std::size_t i) const { return m_channels[i]; }
    // Index of a node's `tx` channel, -1 when the node has no transform channels.
    int transformOf(model::RigNodeIndex node) const { return m_transform[node]; }
    // All channels of a node: [first, first + count).
    int firstOf(model::RigNodeIndex node) const { return m_first[node]; }
    int countOf(model::RigNodeIndex node) const { return m_count[node]; }
    std::optional<int> find(model::RigNodeIndex node, const std::string& name) const;
    // The channel of a node's custom attribute (never a transform channel);
    // nullopt when the node is out of range or has no such attribute.
    std::optional<int> find(const model::AttributeRef& attribute) const;

    Pose defaults() const;
    double clamp(int channel, double value) const;

private:
    std::vector<Channel> m_channels;
    std::vector<int> m_transform, m_first, m_count;
};

// sin and cos of an angle in degrees.
void sinCosDegrees(double degrees, double& sine, double& cosine);
// Rotation of Euler angles in degrees applied in `order` (first letter first).
Mat3 eulerRotation(const Vec3& degrees, model::RotateOrder order);
// The Euler angles (degrees) of a rotation for `order`; the inverse of eulerRotation.
Vec3 eulerDegrees(const Mat3& rotation, model::RotateOrder order);
constexpr int kRotateOrderChannel = 9; // offset of `ro` from a controller's tx
// The rotate order the pose gives the controller whose tx is at `first`.
model::RotateOrder rotateOrderOf(const Pose& pose, int first);

// The document keeps the rigger's test pose by node id and channel name, only
// where it differs from the default, so it survives rebuilds.
Pose poseFromValues(const model::Rig& rig, const ChannelLayout& layout, const model::PoseValues& values);
// `values` with every unlocked channel of `pose` written in (defaults erased);
// entries for nodes this rig does not have, and for locked channels, are kept.
model::PoseValues valuesFromPose(const model::Rig& rig, const ChannelLayout& layout, const Pose& pose,
                                 model::PoseValues values = {});

} // namespace rs::eval
