// Cleanup (CleanupStage.h). Only the channels a template did not declare are
// locked: nothing here guesses from names; each builder says what its
// controllers animate (rigging/builders/BuilderKit.h, kit::animate).
#include "rigging/CleanupStage.h"

#include <map>
#include <string>

namespace rs::rigging {

namespace {

using model::ChannelSettings;

// The rigger's lock records of one node (none when the build leaves locks out).
const std::map<std::string, model::ChannelState>* lockRecords(const model::GuideDocument& guide,
                                                              const model::RestoreToggles& restore, const NodeKey& key)
{
    if (!restore.restores(model::OverrideKind::Locks))
        return nullptr;
    const auto it = guide.overrides.find(key);
    return it == guide.overrides.end() || it->second.locks.empty() ? nullptr : &it->second.locks;
}

void lockAndHide(ChannelSettings& channels, int channel)
{
    const auto bit = std::uint16_t(1u << channel);
    channels.locked = std::uint16_t(channels.locked | bit);
    channels.unkeyable = std::uint16_t(channels.unkeyable | bit);
    channels.hidden = std::uint16_t(channels.hidden | bit);
}

void cleanUpController(model::RigNode& node, const std::map<std::string, model::ChannelState>* records)
{
    ChannelSettings& channels = node.channels;
    for (int c = 0; c < ChannelSettings::kCount; ++c) {
        if (records && records->count(model::channelName(c)))
            continue; // the rigger said how this channel is
        if (!channels.isAnimatable(c) || channels.isLocked(c))
            lockAndHide(channels, c);
    }
    node.defaultValues.clear();
    for (int c = 0; c < ChannelSettings::kCount; ++c)
        if (!channels.isLocked(c))
            node.defaultValues.emplace_back(model::channelName(c), channels.defaults[c]);
    for (const model::RigAttribute& attribute : node.attributes)
        if (!attribute.locked)
            node.defaultValues.emplace_back(attribute.name, attribute.value);
}

} // namespace

void cleanUpRig(model::Rig& rig, const model::GuideDocument& guide, const model::RestoreToggles& restore)
{
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
        model::RigNode& node = rig.nodes[i];
        switch (node.kind) {
        case model::RigNodeKind::Group:
            node.hidden = node.hidden || i != 0; // the rig root stays: it is where the animator finds the rig
            break;
        case model::RigNodeKind::Joint:
            node.hidden = true;
            break;
        case model::RigNodeKind::Controller:
            if (!node.hidden) // a hidden controller is no animator's: the evaluator locks it whole
                cleanUpController(node, lockRecords(guide, restore, node.key));
            break;
        }
    }
}

} // namespace rs::rigging
