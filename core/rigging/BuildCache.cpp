#include "rigging/BuildCache.h"

#include "rigging/Fragment.h"
#include "rigging/RigAssembly.h"

#include <algorithm>
#include <utility>

namespace rs::rigging {

using model::kNoNode;
using model::RigNodeIndex;

BuildCache::BuildCache() : m_impl(std::make_unique<Impl>()) {}
BuildCache::~BuildCache() = default;
BuildCache::BuildCache(BuildCache&&) noexcept = default;
BuildCache& BuildCache::operator=(BuildCache&&) noexcept = default;

void BuildCache::clear()
{
    m_impl->fragments.clear();
    m_impl->templates = nullptr;
    m_impl->builders = nullptr;
}

const BuildCache::Stats& BuildCache::lastBuild() const { return m_impl->stats; }

std::optional<Result<eval::RigProgram>> BuildCache::takeProgram() { return std::exchange(m_impl->program, std::nullopt); }

void BuildCache::Impl::begin(const templates::TemplateRegistry& library, const BuilderRegistry& registry,
                             const model::NamingRules& rules)
{
    if (templates != &library || builders != &registry || !(naming == rules)) {
        fragments.clear();
        shapeSamples.clear();
        defaultSegments.clear();
        templates = &library;
        builders = &registry;
        naming = rules;
    }
    stats = {};
    program.reset();
}

namespace {

bool sameCopy(const BranchCopy& a, const BranchCopy& b)
{
    return a.original == b.original && a.twin == b.twin && a.baseName == b.baseName && a.id == b.id &&
           a.suffix == b.suffix && a.flip == b.flip && a.mirror == b.mirror;
}

bool sameAttributes(const std::vector<model::RigAttribute>& a, const std::vector<model::RigAttribute>& b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
        return x.name == y.name && x.value == y.value && x.min == y.min && x.max == y.max && x.labels == y.labels;
    });
}

// Everything of a node a builder can read through its context, indices by key.
bool sameAsRead(const Fragment::NodeRead& read, const model::Rig& rig, const model::RigNode& now)
{
    const model::RigNode& then = read.node;
    const NodeKey parent = now.parent == kNoNode ? NodeKey{} : rig.nodes[now.parent].key;
    return then.key == now.key && then.name == now.name && then.kind == now.kind && then.owner == now.owner &&
           then.worldMatrix == now.worldMatrix && then.guide == now.guide && then.hidden == now.hidden &&
           then.channels == now.channels && sameAttributes(then.attributes, now.attributes) && read.parent == parent;
}

} // namespace

void captureInputs(Fragment& f, const RigAssembly& a, const InstanceRecord& record, const TemplateBuilder* builder,
                   RigNodeIndex hook)
{
    f.instance = *record.instance;
    f.copy = a.copyOf(record.instance->id);
    f.manifest = record.manifest;
    f.builder = builder;
    f.options = record.options;
    f.hook = a.rig.nodes.at(hook).key;
}

void captureOutputs(Fragment& f, const RigAssembly& a, AssemblySizes before,
                    const std::map<std::string, RigNodeIndex>& spacesBefore, bool failed)
{
    f.failed = failed;
    const auto start = static_cast<RigNodeIndex>(before.nodes);
    auto encode = [&](RigNodeIndex& index) {
        if (index == kNoNode)
            return;
        if (index >= start) {
            index -= start;
            return;
        }
        const NodeKey& key = a.rig.nodes.at(index).key;
        auto it = std::find(f.externals.begin(), f.externals.end(), key);
        if (it == f.externals.end())
            it = f.externals.insert(f.externals.end(), key);
        index = Fragment::kExternal | RigNodeIndex(it - f.externals.begin());
    };
    f.diagnostics.assign(a.rig.diagnostics.begin() + std::ptrdiff_t(before.diagnostics), a.rig.diagnostics.end());
    if (failed)
        return;
    f.nodes.assign(a.rig.nodes.begin() + std::ptrdiff_t(before.nodes), a.rig.nodes.end());
    for (model::RigNode& node : f.nodes) {
        encode(node.parent);
        encode(node.virtualParent);
        encode(node.twin);
    }
    f.constraints.assign(a.rig.constraints.begin() + std::ptrdiff_t(before.constraints), a.rig.constraints.end());
    for (model::RigConstraint& constraint : f.constraints)
        model::forEachNodeIndex(constraint, encode);
    for (const model::GuideJoint& joint : f.instance.joints)
        if (auto it = a.hooks.find(joint.id); it != a.hooks.end()) {
            RigNodeIndex node = it->second;
            encode(node);
            f.hooks.emplace_back(joint.id, node);
        }
    for (const auto& [name, node] : a.spaces)
        if (auto was = spacesBefore.find(name); was == spacesBefore.end() || was->second != node) {
            RigNodeIndex encoded = node;
            encode(encoded);
            f.spaces.emplace_back(name, encoded);
        }
}

bool matches(const Fragment& f, const RigAssembly& a, const InstanceRecord& record, const TemplateBuilder* builder,
             RigNodeIndex hook)
{
    if (!f.replayable || f.manifest != record.manifest || f.builder != builder || a.rig.nodes.at(hook).key != f.hook ||
        !sameCopy(f.copy, a.copyOf(record.instance->id)) || !(f.options == record.options) || !(f.instance == *record.instance))
        return false;
    for (const auto& [joint, world] : f.guideReads)
        if (a.guideWorldMatrix(a.authoredJoint(joint)) != world)
            return false;
    for (const auto& [name, key] : f.spaceReads) {
        auto it = a.spaces.find(name);
        const std::optional<NodeKey> now = it == a.spaces.end() ? std::nullopt : std::optional<NodeKey>(a.rig.nodes.at(it->second).key);
        if (now != key)
            return false;
    }
    for (const Fragment::NodeRead& read : f.nodeReads) {
        const auto node = a.rig.find(read.node.key);
        if (!node || !sameAsRead(read, a.rig, a.rig.nodes[*node]))
            return false;
    }
    return true;
}

bool replay(const Fragment& f, RigAssembly& a)
{
    std::vector<RigNodeIndex> externals;
    externals.reserve(f.externals.size());
    for (const NodeKey& key : f.externals) {
        const auto node = a.rig.find(key);
        if (!node)
            return false;
        externals.push_back(*node);
    }
    const auto start = static_cast<RigNodeIndex>(a.rig.nodes.size());
    auto decode = [&](RigNodeIndex& index) {
        if (index == kNoNode)
            return;
        index = (index & Fragment::kExternal) ? externals[index & ~Fragment::kExternal] : index + start;
    };
    a.rig.diagnostics.insert(a.rig.diagnostics.end(), f.diagnostics.begin(), f.diagnostics.end());
    if (f.failed)
        return true;
    // Grown geometrically: reserving the exact size per fragment reallocated the
    // whole node table for every replayed copy (quadratic in the instance count).
    if (const std::size_t needed = a.rig.nodes.size() + f.nodes.size(); needed > a.rig.nodes.capacity())
        a.rig.nodes.reserve(std::max(needed, 2 * a.rig.nodes.capacity()));
    for (model::RigNode node : f.nodes) {
        decode(node.parent);
        decode(node.virtualParent);
        decode(node.twin);
        a.addNode(std::move(node));
    }
    for (model::RigConstraint constraint : f.constraints) {
        model::forEachNodeIndex(constraint, decode);
        a.rig.constraints.push_back(std::move(constraint));
    }
    for (auto [joint, node] : f.hooks) {
        decode(node);
        a.hooks[joint] = node;
    }
    for (auto [name, node] : f.spaces) {
        decode(node);
        a.spaces[name] = node;
    }
    return true;
}

} // namespace rs::rigging
