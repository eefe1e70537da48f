#include "eval/Channels.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace rs::eval {

namespace {

// Axis sequence of each rotate order, first applied first.
constexpr int kOrderAxes[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};

// Left-multiplies `m` by the rotation about `axis`: only two rows change, which
// is much cheaper than a full matrix product (this runs for every controller).
void rotateRows(Mat3& m, int axis, double degrees)
{
    if (degrees == 0.0)
        return;
    double s, c;
    sinCosDegrees(degrees, s, c);
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int column = 0; column < 3; ++column) {
        const double ra = m[column][a], rb = m[column][b];
        m[column][a] = c * ra - s * rb;
        m[column][b] = s * ra + c * rb;
    }
}

} // namespace

ChannelLayout::ChannelLayout(const model::Rig& rig)
    : m_transform(rig.nodes.size(), -1), m_first(rig.nodes.size(), 0), m_count(rig.nodes.size(), 0)
{
    for (model::RigNodeIndex n = 0; n < rig.nodes.size(); ++n) {
        const model::RigNode& node = rig.nodes[n];
        m_first[n] = int(m_channels.size());
        const bool animatable = node.kind == model::RigNodeKind::Controller && !node.hidden;
        if (node.kind == model::RigNodeKind::Controller) {
            m_transform[n] = int(m_channels.size());
            for (int i = 0; i < model::ChannelSettings::kCount; ++i) {
                Channel c;
                c.node = n;
                c.name = model::channelName(i);
                c.transform = i;
                c.defaultValue = node.channels.defaults[i];
                c.limited = node.channels.isLimited(i);
                c.min = node.channels.minimum[i];
                c.max = node.channels.maximum[i];
                c.locked = !animatable || node.channels.isLocked(i);
                c.keyable = node.channels.isKeyable(i);
                c.hidden = node.channels.isHidden(i);
                m_channels.push_back(std::move(c));
            }
            static const std::vector<std::string> kOrders = {"xyz", "yzx", "zxy", "xzy", "yxz", "zyx"};
            Channel order;
            order.node = n;
            order.name = "ro";
            order.transform = kRotateOrderChannel;
            order.defaultValue = double(static_cast<int>(node.channels.rotateOrder));
            order.limited = true;
            order.min = 0.0;
            order.max = 5.0;
            order.locked = !animatable;
            order.labels = &kOrders;
            m_channels.push_back(std::move(order));
        }
        for (const auto& attribute : node.attributes) {
            Channel c;
            c.node = n;
            c.name = attribute.name;
            c.defaultValue = attribute.value;
            c.limited = true;
            c.min = attribute.min;
            c.max = attribute.max;
            c.locked = !animatable || attribute.locked;
            c.keyable = attribute.keyable;
            c.labels = &attribute.labels;
            m_channels.push_back(std::move(c));
        }
        m_count[n] = int(m_channels.size()) - m_first[n];
    }
}

std::optional<int> ChannelLayout::find(model::RigNodeIndex node, const std::string& name) const
{
    if (node >= m_first.size())
        return std::nullopt;
    for (int i = m_first[node]; i < m_first[node] + m_count[node]; ++i)
        if (m_channels[i].name == name)
            return i;
    return std::nullopt;
}

std::optional<int> ChannelLayout::find(const model::AttributeRef& attribute) const
{
    const auto channel = find(attribute.node, attribute.attribute);
    if (!channel || m_channels[*channel].transform >= 0)
        return std::nullopt;
    return channel;
}

Pose ChannelLayout::defaults() const
{
    Pose pose(m_channels.size());
    for (std::size_t i = 0; i < m_channels.size(); ++i)
        pose[i] = m_channels[i].defaultValue;
    return pose;
}

double ChannelLayout::clamp(int channel, double value) const
{
    const Channel& c = m_channels[channel];
    if (c.isEnum())
        value = std::round(value);
    return c.limited ? std::clamp(value, c.min, c.max) : value;
}

void sinCosDegrees(double degrees, double& sine, double& cosine)
{
    const double x = glm::radians(degrees);
    sine = std::sin(x); // one sincos call once inlined
    cosine = std::cos(x);
}

Mat3 eulerRotation(const Vec3& degrees, model::RotateOrder order)
{
    const int* axes = kOrderAxes[static_cast<int>(order)];
    Mat3 r(1.0);
    for (int k = 0; k < 3; ++k)
        rotateRows(r, axes[k], degrees[axes[k]]);
    return r;
}

Vec3 eulerDegrees(const Mat3& rotation, model::RotateOrder order)
{
    // R = Rk(c) Rj(b) Ri(a) with (i, j, k) the order; sign +1 for the cyclic orders.
    const int* axes = kOrderAxes[static_cast<int>(order)];
    const int i = axes[0], j = axes[1], k = axes[2];
    const double sign = (j == (i + 1) % 3) ? 1.0 : -1.0;
    auto at = [&](int row, int column) { return rotation[column][row]; };
    Vec3 out(0.0);
    const double sinB = std::clamp(-sign * at(k, i), -1.0, 1.0);
    const double b = std::asin(sinB);
    double a, c;
    if (std::abs(sinB) < 1.0 - 1e-12) {
        a = std::atan2(sign * at(k, j), at(k, k));
        c = std::atan2(sign * at(j, i), at(i, i));
    } else { // gimbal lock: only a - c (or a + c) is defined; put it all in a
        a = std::atan2(-sign * at(j, k), at(j, j));
        c = 0.0;
    }
    out[i] = glm::degrees(a);
    out[j] = glm::degrees(b);
    out[k] = glm::degrees(c);
    return out;
}

model::RotateOrder rotateOrderOf(const Pose& pose, int first)
{
    return static_cast<model::RotateOrder>(std::clamp(int(pose[first + kRotateOrderChannel]), 0, 5));
}

Pose poseFromValues(const model::Rig& rig, const ChannelLayout& layout, const model::PoseValues& values)
{
    Pose pose = layout.defaults();
    for (const auto& [id, channels] : values) {
        const auto node = rig.find(id);
        if (!node)
            continue;
        for (const auto& [name, value] : channels)
            if (auto index = layout.find(*node, name); index && !layout[*index].locked)
                pose[*index] = layout.clamp(*index, value);
    }
    return pose;
}

model::PoseValues valuesFromPose(const model::Rig& rig, const ChannelLayout& layout, const Pose& pose,
                                 model::PoseValues values)
{
    for (std::size_t i = 0; i < layout.size(); ++i) {
        const Channel& c = layout[i];
        if (c.locked)
            continue; // poseFromValues ignored its value: the record waits for the lock (or cleanup) to go
        const NodeKey& id = rig.nodes[c.node].key;
        if (std::abs(pose[i] - c.defaultValue) > 1e-12) {
            values[id][c.name] = pose[i];
        } else if (auto it = values.find(id); it != values.end()) {
            it->second.erase(c.name);
            if (it->second.empty())
                values.erase(it);
        }
    }
    return values;
}

} // namespace rs::eval
