// The one build stage that applies the rigger's overrides (model/Override.h)
// to a generated rig, in two halves. Channels, display names and the post
// transform come first, before the evaluation program compiles and before the
// generator plugins (so a display name override is checked for clashes, and the
// evaluation check sees the final channels). Shape edits (after the template
// shapes) and the mirrored copies' curves come second, beside the compile,
// which reads no curve. A kind switched off by the build's restore toggles is
// left as the templates make it; its records stay in the guide.
#include "rigging/RigAssembly.h"
#include "rigging/RigBuilder.h"

#include <algorithm>
#include <functional>
#include <set>

namespace rs::rigging {

namespace {

std::string labelOf(const model::GuideDocument& guide, const NodeKey& key)
{
    if (key.isRoot())
        return "::" + key.tag;
    const model::TemplateInstance* instance = guide.instance(key.instance);
    std::string label = instance ? instance->name : "#" + std::to_string(key.instance);
    if (!key.branch.empty())
        label.append(".").append(key.branch);
    return label.append("::").append(key.tag);
}

struct Stage {
    model::Rig& rig;
    const model::GuideDocument& guide; // the authored guide: its overrides and names
    const model::RestoreToggles& restore;
    const std::set<CopyKey>& mirrored; // copies that take their twin's curves
    std::set<NodeKey>& applied;        // records that found their node

    void warn(const NodeKey& key, const std::string& message)
    {
        Diagnostic d = makeWarning({}, "override of '" + labelOf(guide, key) + "': " + message);
        d.subject = key.isRoot() ? Subject{} : Subject::ofNode(key);
        rig.diagnostics.push_back(std::move(d));
    }

    // Shape edits in the controller's space, on every copy that is not a
    // mirrored branch (those take their twin's edited curves afterwards).
    void applyShape(model::RigNode& node, const NodeKey& key, const model::ShapeOverride& shape)
    {
        std::vector<bool> moved(node.curves.size(), false);
        for (const auto& [at, offset] : shape.edit.cvs) {
            const auto [curve, cv] = at;
            if (curve < 0 || std::size_t(curve) >= node.curves.size() || cv < 0 ||
                std::size_t(cv) >= node.curves[curve].cvs.size()) {
                warn(key, "the shape has no CV " + std::to_string(cv) + " on curve " + std::to_string(curve) +
                              " (the edit is ignored; was the shape changed?)");
                continue;
            }
            node.curves[curve].cvs[cv] += offset;
            moved[curve] = true;
        }
        const Mat4 m = shape.edit.transform.matrix();
        for (std::size_t k = 0; k < node.curves.size(); ++k) {
            model::ControllerCurve& curve = node.curves[k];
            if (moved[k])
                curve.resample();
            if (m != Mat4(1.0))
                curve.transform(m);
            if (shape.color) curve.color = *shape.color;
            if (shape.lineWidth) curve.lineWidth = *shape.lineWidth;
            if (shape.visible) curve.visible = *shape.visible;
        }
    }

    // The node's own record, else its instance's authored side's (branch "").
    const std::pair<const NodeKey, model::Override>* shapeRecordFor(const model::RigNode& node)
    {
        for (const NodeKey& key : {node.key, NodeKey{node.key.instance, {}, node.key.tag}}) {
            auto it = guide.overrides.find(key);
            if (it != guide.overrides.end() && it->second.shape) {
                applied.insert(key);
                return &*it;
            }
        }
        return nullptr;
    }

    void applyShapes()
    {
        for (auto& node : rig.nodes) {
            if (node.kind != model::RigNodeKind::Controller || node.key.isRoot())
                continue;
            const auto* record = shapeRecordFor(node);
            if (record && restore.restores(model::OverrideKind::Shapes) && !mirrored.count(node.key.copy()))
                applyShape(node, record->first, *record->second.shape);
        }
    }

    void applyChannels(model::RigNode& node, const NodeKey& key, const model::Override& o)
    {
        auto attribute = [&](const std::string& name) {
            auto it = std::find_if(node.attributes.begin(), node.attributes.end(), [&](auto& x) { return x.name == name; });
            return it == node.attributes.end() ? nullptr : &*it;
        };
        const bool controller = node.kind == model::RigNodeKind::Controller;
        auto resolve = [&](const std::string& channel, int& transform, model::RigAttribute*& custom) {
            transform = controller ? model::channelIndex(channel) : -1;
            custom = transform < 0 ? attribute(channel) : nullptr;
            if (transform < 0 && !custom)
                warn(key, "the node has no channel '" + channel + "' (kept in the guide)");
            return transform >= 0 || custom;
        };
        int t = -1;
        model::RigAttribute* c = nullptr;
        if (restore.restores(model::OverrideKind::Limits))
            for (const auto& [channel, limit] : o.limits)
                if (resolve(channel, t, c)) {
                    if (t >= 0) node.channels.limit(t, limit.min, limit.max);
                    else { c->min = limit.min; c->max = limit.max; c->value = std::clamp(c->value, c->min, c->max); }
                }
        if (restore.restores(model::OverrideKind::Locks))
            for (const auto& [channel, state] : o.locks)
                if (resolve(channel, t, c)) {
                    if (t >= 0) {
                        const auto bit = std::uint16_t(1u << t);
                        node.channels.locked = std::uint16_t(state.locked ? node.channels.locked | bit : node.channels.locked & ~bit);
                        node.channels.unkeyable = std::uint16_t(state.keyable ? node.channels.unkeyable & ~bit : node.channels.unkeyable | bit);
                    } else { c->locked = state.locked; c->keyable = state.keyable; }
                }
        if (restore.restores(model::OverrideKind::Defaults))
            for (const auto& [channel, value] : o.defaults)
                if (resolve(channel, t, c)) {
                    const double low = t >= 0 ? node.channels.minimum[t] : c->min, high = t >= 0 ? node.channels.maximum[t] : c->max;
                    const bool limited = t >= 0 ? node.channels.isLimited(t) : true;
                    const double kept = limited ? std::clamp(value, low, high) : value;
                    if (kept != value)
                        warn(key, "the default " + formatNumber(value) + " of '" + channel + "' is outside its limits; using " + formatNumber(kept));
                    (t >= 0 ? node.channels.defaults[t] : c->value) = kept;
                }
    }

    void applyPost(const Transform& post)
    {
        const Mat4 m = post.matrix();
        for (auto& node : rig.nodes) // the whole rig: relative transforms stay, local matrices follow
            node.worldMatrix = m * node.worldMatrix;
    }

    // Channels (defaults, limits, locks), display names and the post transform:
    // what the evaluation program reads.
    void applyRig(Mat4* post)
    {
        for (const auto& [key, o] : guide.overrides) {
            const auto index = rig.find(key);
            if (!index)
                continue;
            applied.insert(key);
            model::RigNode& node = rig.nodes[*index];
            applyChannels(node, key, o);
            if (o.displayName && restore.restores(model::OverrideKind::Names))
                node.name = *o.displayName;
            if (o.post && key.isRoot() && restore.restores(model::OverrideKind::Post)) {
                applyPost(*o.post);
                if (post)
                    *post = o.post->matrix() * *post;
            }
        }
    }

    // Records whose node this build does not make: reported and kept (a
    // rebuild that brings the node back applies them again).
    void reportOrphans()
    {
        for (const auto& [key, o] : guide.overrides) {
            if (applied.count(key) || o.isEmpty())
                continue;
            std::string kinds;
            for (int k = 0; k < model::kOverrideKindCount; ++k)
                if (o.has(static_cast<model::OverrideKind>(k)))
                    kinds += std::string(kinds.empty() ? "" : ", ") + model::overrideKindName(static_cast<model::OverrideKind>(k));
            Diagnostic d = makeWarning({}, "orphan override of '" + labelOf(guide, key) + "' (" + kinds +
                                               "): the rig has no such node; it is kept in the guide and applied again if the node comes back");
            d.subject = guide.instance(key.instance) ? Subject::ofInstance(key.instance, key.branch) : Subject{};
            rig.diagnostics.push_back(std::move(d));
        }
        for (const auto& [text, channels] : guide.legacyPose)
            rig.diagnostics.push_back(makeWarning({}, "the test pose of '" + text + "' (an older guide's record) names no "
                                                        "instance of this guide; it is kept in the guide"));
    }
};

} // namespace

model::PoseValues restoredPose(const model::GuideDocument& guide, const model::RestoreToggles& restore)
{
    return restore.restores(model::OverrideKind::Pose) ? model::testPose(guide.overrides) : model::PoseValues{};
}

void applyOverrides(model::Rig& rig, const model::GuideDocument& guide, const model::RestoreToggles& restore,
                    const std::set<CopyKey>& mirroredCopies, const std::function<void()>& afterShapes)
{
    std::set<NodeKey> applied;
    Stage stage{rig, guide, restore, mirroredCopies, applied};
    stage.applyShapes(); // with the kind off, it only notes which records have a node
    if (afterShapes)
        afterShapes();
    stage.applyRig(nullptr);
    stage.reportOrphans();
}

void applyRigOverrides(RigAssembly& a, const model::GuideDocument& guide, const model::RestoreToggles& restore)
{
    a.mirroredCopies.clear();
    for (const InstanceRecord& r : a.records)
        if (const BranchCopy& copy = a.copyOf(r.instance->id); copy.mirror != Mat4(1.0))
            a.mirroredCopies.insert(CopyKey{copy.original, copy.branch()});
    Stage{a.rig, guide, restore, a.mirroredCopies, a.appliedOverrides}.applyRig(&a.post);
}

void applyShapeOverrides(RigAssembly& a, const model::GuideDocument& guide, const model::RestoreToggles& restore)
{
    Stage stage{a.rig, guide, restore, a.mirroredCopies, a.appliedOverrides};
    stage.applyShapes();
    mirrorBranchShapes(a);
    stage.reportOrphans();
}

} // namespace rs::rigging
