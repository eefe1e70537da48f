#include "model/Override.h"

namespace rs::model {

namespace {

constexpr std::array<const char*, kOverrideKindCount> kKindNames{"shapes", "defaults", "limits", "locks",
                                                                 "post",   "names",    "pose"};

} // namespace

const char* overrideKindName(OverrideKind kind)
{
    return kKindNames[static_cast<int>(kind)];
}

std::optional<OverrideKind> parseOverrideKind(const std::string& name)
{
    for (int k = 0; k < kOverrideKindCount; ++k)
        if (name == kKindNames[k])
            return static_cast<OverrideKind>(k);
    return std::nullopt;
}

bool Override::has(OverrideKind kind) const
{
    switch (kind) {
    case OverrideKind::Shapes: return shape.has_value();
    case OverrideKind::Defaults: return !defaults.empty();
    case OverrideKind::Limits: return !limits.empty();
    case OverrideKind::Locks: return !locks.empty();
    case OverrideKind::Post: return post.has_value();
    case OverrideKind::Names: return displayName.has_value();
    case OverrideKind::Pose: return !pose.empty();
    }
    return false;
}

void Override::clear(OverrideKind kind)
{
    switch (kind) {
    case OverrideKind::Shapes: shape.reset(); break;
    case OverrideKind::Defaults: defaults.clear(); break;
    case OverrideKind::Limits: limits.clear(); break;
    case OverrideKind::Locks: locks.clear(); break;
    case OverrideKind::Post: post.reset(); break;
    case OverrideKind::Names: displayName.reset(); break;
    case OverrideKind::Pose: pose.clear(); break;
    }
}

bool Override::isEmpty() const
{
    for (int k = 0; k < kOverrideKindCount; ++k)
        if (has(static_cast<OverrideKind>(k)))
            return false;
    return true;
}

NodeKey rigRootKey()
{
    return {kNoId, {}, "rig"};
}

PoseValues testPose(const Overrides& overrides)
{
    PoseValues pose;
    for (const auto& [key, record] : overrides)
        if (!record.pose.empty())
            pose.emplace(key, record.pose);
    return pose;
}

void setTestPose(Overrides& overrides, const PoseValues& pose)
{
    for (auto it = overrides.begin(); it != overrides.end();) {
        it->second.pose.clear();
        it = it->second.isEmpty() ? overrides.erase(it) : std::next(it);
    }
    for (const auto& [key, channels] : pose)
        if (!channels.empty())
            overrides[key].pose = channels;
}

} // namespace rs::model
