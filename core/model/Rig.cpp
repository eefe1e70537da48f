#include "model/Rig.h"

#include "base/Nurbs.h"

#include <algorithm>

namespace rs::model {

void ControllerCurve::transform(const Mat4& m)
{
    for (Vec3& p : points)
        p = Vec3(m * Vec4(p, 1.0));
    for (Vec3& p : cvs)
        p = Vec3(m * Vec4(p, 1.0));
}

void ControllerCurve::resample()
{
    if (!cvs.empty())
        points = evaluateNurbs(cvs, degree, periodic);
}

const char* kindName(RigNodeKind kind)
{
    switch (kind) {
    case RigNodeKind::Group: return "group";
    case RigNodeKind::Controller: return "controller";
    case RigNodeKind::Joint: return "joint";
    }
    return "group";
}

namespace {
constexpr const char* kRotateOrders[] = {"xyz", "yzx", "zxy", "xzy", "yxz", "zyx"};
constexpr const char* kChannels[] = {"tx", "ty", "tz", "rx", "ry", "rz", "sx", "sy", "sz"};
} // namespace

const char* rotateOrderName(RotateOrder order) { return kRotateOrders[static_cast<int>(order)]; }

std::optional<RotateOrder> parseRotateOrder(const std::string& name)
{
    for (int i = 0; i < 6; ++i)
        if (name == kRotateOrders[i])
            return static_cast<RotateOrder>(i);
    return std::nullopt;
}

const char* channelName(int channel)
{
    return channel >= 0 && channel < ChannelSettings::kCount ? kChannels[channel] : "?";
}

int channelIndex(const std::string& name)
{
    for (int i = 0; i < ChannelSettings::kCount; ++i)
        if (name == kChannels[i])
            return i;
    return -1;
}

ChannelSettings ChannelSettings::controllerDefaults()
{
    ChannelSettings c;
    for (int axis = 6; axis < 9; ++axis)
        c.limit(axis, 0.01, 100.0);
    return c;
}

void ChannelSettings::lock(int first, int count)
{
    for (int i = first; i < first + count; ++i)
        locked = static_cast<std::uint16_t>(locked | (1u << i));
}

void ChannelSettings::limit(int channel, double low, double high)
{
    limited = static_cast<std::uint16_t>(limited | (1u << channel));
    minimum[channel] = low;
    maximum[channel] = high;
}

const RigAttribute* RigNode::attribute(const std::string& attributeName) const
{
    for (const auto& a : attributes)
        if (a.name == attributeName)
            return &a;
    return nullptr;
}

std::optional<RigNodeIndex> Rig::find(const NodeKey& key) const
{
    auto it = byKey.find(key);
    if (it == byKey.end())
        return std::nullopt;
    return it->second;
}

std::optional<RigNodeIndex> Rig::findPath(std::string_view path) const
{
    auto it = byPath.find(std::string(path));
    if (it == byPath.end())
        return std::nullopt;
    return it->second;
}

RigNodeIndex Rig::add(RigNode node)
{
    const auto index = static_cast<RigNodeIndex>(nodes.size());
    byKey[node.key] = index;
    byPath[node.path] = index;
    nodes.push_back(std::move(node));
    return index;
}

void Rig::truncate(std::size_t count)
{
    for (std::size_t i = count; i < nodes.size(); ++i) {
        byKey.erase(nodes[i].key);
        byPath.erase(nodes[i].path);
    }
    nodes.resize(std::min(count, nodes.size()));
}

std::vector<RigNodeIndex> Rig::virtualRoots(const std::string& domain) const
{
    std::vector<RigNodeIndex> out;
    for (RigNodeIndex i = 0; i < nodes.size(); ++i)
        if (nodes[i].isInVirtualHierarchy() && nodes[i].virtualParent == kNoNode && nodes[i].domain() == domain)
            out.push_back(i);
    return out;
}

std::vector<RigNodeIndex> Rig::virtualChildren(RigNodeIndex node) const
{
    std::vector<RigNodeIndex> out;
    for (RigNodeIndex i = 0; i < nodes.size(); ++i)
        if (nodes[i].virtualParent == node)
            out.push_back(i);
    return out;
}

std::vector<RigNodeIndex> Rig::children(RigNodeIndex node) const
{
    std::vector<RigNodeIndex> out;
    for (RigNodeIndex i = 0; i < nodes.size(); ++i)
        if (nodes[i].parent == node)
            out.push_back(i);
    return out;
}

std::vector<std::vector<RigNodeIndex>> Rig::virtualChildTable() const
{
    std::vector<std::vector<RigNodeIndex>> out(nodes.size());
    for (RigNodeIndex i = 0; i < nodes.size(); ++i)
        if (nodes[i].virtualParent < nodes.size())
            out[nodes[i].virtualParent].push_back(i);
    return out;
}

std::vector<std::vector<RigNodeIndex>> Rig::childTable() const
{
    std::vector<std::vector<RigNodeIndex>> out(nodes.size());
    for (RigNodeIndex i = 0; i < nodes.size(); ++i)
        if (nodes[i].parent < nodes.size())
            out[nodes[i].parent].push_back(i);
    return out;
}

std::size_t Rig::count(RigNodeKind kind) const
{
    return static_cast<std::size_t>(std::count_if(nodes.begin(), nodes.end(), [&](const RigNode& n) { return n.kind == kind; }));
}

std::size_t Rig::skinJointCount() const
{
    return static_cast<std::size_t>(std::count_if(nodes.begin(), nodes.end(), [](const RigNode& n) {
        return n.kind == RigNodeKind::Joint && n.domain() == "skin";
    }));
}

} // namespace rs::model
