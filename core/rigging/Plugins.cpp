// Built-in generator plugins: cross-cutting work that needs the whole rig.
#include "rigging/RigAssembly.h"
#include "eval/RigProgram.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

namespace rs::rigging {

namespace {

// Seed 004's "set of every animatable controller": animators select it to key
// or reset the whole character. Hidden setup nodes are never in it.
class ControllerSetPlugin final : public GeneratorPlugin {
public:
    const char* name() const override { return "controller set"; }
    void finalize(RigAssembly& a) const override
    {
        auto& set = a.rig.sets["controllers"];
        set.clear();
        for (model::RigNodeIndex i = 0; i < a.rig.nodes.size(); ++i)
            if (a.rig.nodes[i].kind == model::RigNodeKind::Controller && !a.rig.nodes[i].hidden)
                set.push_back(i);
        if (set.empty())
            a.rig.sets.erase("controllers");
    }
};

// The rig's cameras (util.camera's view node, tag `camera`: it looks down its
// -Z with +Y up, aimed and rolled, and its controller carries the lens
// attributes), the set "cameras" that exports write as real cameras
// (io/ExportCamera.h), in node order.
class CameraSetPlugin final : public GeneratorPlugin {
public:
    const char* name() const override { return "camera set"; }
    void finalize(RigAssembly& a) const override
    {
        auto& set = a.rig.sets["cameras"];
        set.clear();
        for (const InstanceRecord& r : a.records) {
            // util.camera, or a template built by its builder (based on it)
            if (!r.built || !r.manifest || (r.manifest->id != "util.camera" && r.manifest->base != "util.camera"))
                continue;
            const CopyKey copy = a.copyOf(r.instance->id).key();
            if (const auto node = a.rig.find(NodeKey{copy.instance, copy.branch, "camera"}))
                set.push_back(*node);
        }
        std::sort(set.begin(), set.end());
        if (set.empty())
            a.rig.sets.erase("cameras");
    }
};

// Controller groups from the common options `group` and `parent`. Each
// instance copy's visible controllers join a group: by default its own, named
// after it ("arm.L") and nested in its parent instance's group; `group: name`
// names it, and every instance naming the same group shares it (created where
// the first one is); `parent: merge up` puts the controllers in the parent
// instance's group instead; `parent: merge down` makes the group take in the
// controllers of every instance below it that does not name a group of its own.
class ControllerGroupPlugin final : public GeneratorPlugin {
public:
    const char* name() const override { return "controller groups"; }
    void finalize(RigAssembly& a) const override
    {
        auto& groups = a.rig.groups;
        groups.clear();
        constexpr std::size_t none = model::ControllerGroup::kNoGroup;
        struct Placed {
            std::size_t group = none;
            bool absorbs = false; // merge down: the instances below join this group
        };
        std::unordered_map<model::InstanceId, Placed> placed;   // by expanded instance
        std::map<std::string, std::size_t> named;               // `group` option -> group
        std::map<CopyKey, std::size_t> byCopy;
        for (const InstanceRecord& r : a.records) {
            const std::string group = text(r, "group");
            const std::string mode = text(r, "parent");
            Placed parent;
            if (r.instance->parent != model::kNoId)
                if (auto it = placed.find(r.instance->parent); it != placed.end())
                    parent = it->second;
            Placed self;
            if (!group.empty()) {
                auto it = named.find(group);
                if (it == named.end()) {
                    groups.push_back({group, parent.group, {}});
                    it = named.emplace(group, groups.size() - 1).first;
                }
                self.group = it->second;
            } else if (parent.group != none && (mode == "merge up" || parent.absorbs)) {
                self = parent;
            } else {
                groups.push_back({r.instance->name, parent.group, {}});
                self.group = groups.size() - 1;
            }
            if (mode == "merge down")
                self.absorbs = true;
            placed[r.instance->id] = self;
            byCopy[a.copyOf(r.instance->id).key()] = self.group;
        }
        for (model::RigNodeIndex i = 0; i < a.rig.nodes.size(); ++i) {
            const model::RigNode& node = a.rig.nodes[i];
            if (node.kind != model::RigNodeKind::Controller || node.hidden)
                continue;
            if (auto it = byCopy.find(node.key.copy()); it != byCopy.end())
                groups[it->second].controllers.push_back(i);
        }
    }

private:
    static std::string text(const InstanceRecord& r, const std::string& option)
    {
        auto it = r.options.find(option);
        const std::string* value = it == r.options.end() ? nullptr : std::get_if<std::string>(&it->second);
        return value ? *value : std::string();
    }
};

// Engines take one skeleton: the skin hierarchy must have one root.
class SkinRootPlugin final : public GeneratorPlugin {
public:
    const char* name() const override { return "skin root"; }
    void finalize(RigAssembly& a) const override
    {
        std::vector<model::RigNodeIndex> roots;
        for (model::RigNodeIndex i : a.rig.virtualRoots("skin"))
            if (a.rig.nodes[i].kind == model::RigNodeKind::Joint)
                roots.push_back(i);
        if (roots.size() <= 1)
            return;
        std::string list;
        for (auto i : roots)
            list += (list.empty() ? "" : ", ") + a.rig.nodes[i].path;
        a.report(Severity::Warning, nullptr, "the skin hierarchy has " + std::to_string(roots.size()) + " roots (" + list +
                                                 "); engines expect one: add a world template or enable its skin joint");
    }
};

// Names must be unique (the export and the animator's keys depend on them) and
// portable: letters, digits and underscores, not starting with a digit.
class NamingCheckPlugin final : public GeneratorPlugin {
public:
    const char* name() const override { return "naming checks"; }
    void finalize(RigAssembly& a) const override
    {
        // Clashes by name hash first (integer compares; this runs on every live
        // rebuild), then by the names within one hash; reported in name order.
        const auto& nodes = a.rig.nodes;
        std::vector<std::pair<std::size_t, model::RigNodeIndex>> byHash(nodes.size());
        for (model::RigNodeIndex i = 0; i < nodes.size(); ++i) {
            byHash[i] = {std::hash<std::string>{}(nodes[i].name), i};
            if (i != 0 && !portable(nodes[i].name))
                a.report(Severity::Warning, nullptr, "node name '" + nodes[i].name + "' (" + nodes[i].path +
                                                         ") is not portable: use letters, digits and '_', not starting with a digit");
        }
        std::sort(byHash.begin(), byHash.end());
        std::vector<std::vector<model::RigNodeIndex>> clashes;
        for (std::size_t first = 0, last = 0; first < byHash.size(); first = last) {
            for (last = first + 1; last < byHash.size() && byHash[last].first == byHash[first].first;)
                ++last;
            if (last - first < 2)
                continue;
            std::vector<model::RigNodeIndex> same; // one hash: group by name, nodes in index order
            for (std::size_t k = first; k < last; ++k)
                same.push_back(byHash[k].second);
            std::stable_sort(same.begin(), same.end(), [&](auto x, auto y) { return nodes[x].name < nodes[y].name; });
            for (std::size_t s = 0, e = 0; s < same.size(); s = e) {
                for (e = s + 1; e < same.size() && nodes[same[e]].name == nodes[same[s]].name;)
                    ++e;
                if (e - s >= 2)
                    clashes.emplace_back(same.begin() + std::ptrdiff_t(s), same.begin() + std::ptrdiff_t(e));
            }
        }
        std::sort(clashes.begin(), clashes.end(), [&](const auto& x, const auto& y) { return nodes[x[0]].name < nodes[y[0]].name; });
        for (const auto& clash : clashes) {
            std::string list;
            for (model::RigNodeIndex n : clash)
                list += (list.empty() ? "" : ", ") + nodes[n].path;
            a.report(Severity::Error, nullptr, "name clash: '" + nodes[clash[0]].name + "' is used by " + list);
        }
    }

private:
    static bool portable(const std::string& text)
    {
        auto digit = [](char c) { return c >= '0' && c <= '9'; }; // ASCII, whatever the locale
        if (text.empty() || digit(text.front()))
            return false;
        for (char c : text)
            if (!digit(c) && !(c >= 'a' && c <= 'z') && !(c >= 'A' && c <= 'Z') && c != '_')
                return false;
        return true;
    }
};

} // namespace

void compensateSegmentScale(RigAssembly& a)
{
    // Templates with a parent_scale option (builders/ControlNodes.h) set it themselves.
    std::set<model::InstanceId> deciding;
    for (const InstanceRecord& r : a.records)
        if (r.manifest && r.manifest->findOpt("parent_scale"))
            deciding.insert(a.copyOf(r.instance->id).original);
    for (auto& node : a.rig.nodes) {
        if (node.parent == model::kNoNode || node.key.tag.rfind("roots.fk.", 0) != 0 || deciding.count(node.owner))
            continue;
        const auto& parent = a.rig.nodes[node.parent];
        node.scaleCompensate = parent.kind == model::RigNodeKind::Controller && parent.key.tag.rfind("ctrls.fk.", 0) == 0;
    }
}

void compileProgram(RigAssembly& a)
{
    a.program = eval::RigProgram::compile(a.rig);
}

void reportProgram(RigAssembly& a)
{
    for (const Diagnostic& d : a.program->diagnostics())
        a.report(d.severity, nullptr, d.message);
}

const std::vector<std::unique_ptr<GeneratorPlugin>>& builtinPlugins()
{
    static const auto plugins = [] {
        std::vector<std::unique_ptr<GeneratorPlugin>> list;
        list.push_back(std::make_unique<ControllerSetPlugin>());
        list.push_back(std::make_unique<ControllerGroupPlugin>());
        list.push_back(std::make_unique<CameraSetPlugin>());
        list.push_back(std::make_unique<SkinRootPlugin>());
        list.push_back(std::make_unique<NamingCheckPlugin>());
        return list;
    }();
    return plugins;
}

} // namespace rs::rigging
