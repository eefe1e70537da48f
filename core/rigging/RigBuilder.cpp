#include "rigging/RigBuilder.h"

#include "rigging/CleanupStage.h"
#include "rigging/Fragment.h"
#include "rigging/ModStage.h"
#include "rigging/RigAssembly.h"
#include "templates/Structure.h"

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

namespace rs::rigging {

using model::JointId;
using model::kNoNode;
using model::RigNodeIndex;

namespace {

std::optional<Value> coerce(const Value& given, const Value& defaultValue)
{
    if (typeOf(given) == typeOf(defaultValue))
        return given;
    if (auto* i = std::get_if<long long>(&given); i && std::holds_alternative<double>(defaultValue))
        return Value(static_cast<double>(*i));
    if (std::holds_alternative<std::string>(defaultValue))
        return Value(formatValue(given)); // e.g. an enum label written as a number
    return std::nullopt;
}

// A finite bound as a long long, saturated: a cast out of range is undefined.
long long saturated(double bound)
{
    if (bound >= 9.2e18) return std::numeric_limits<long long>::max();
    if (bound <= -9.2e18) return std::numeric_limits<long long>::min();
    return static_cast<long long>(bound);
}

void clampToRange(const templates::Parameter& p, Value& v)
{
    if (auto* i = std::get_if<long long>(&v)) { // compared as doubles: a bound may not fit a long long
        if (p.min && double(*i) < *p.min) *i = saturated(std::ceil(*p.min));
        if (p.max && double(*i) > *p.max) *i = saturated(std::floor(*p.max));
    } else if (auto* d = std::get_if<double>(&v)) {
        if (p.min) *d = std::max(*d, *p.min);
        if (p.max) *d = std::min(*d, *p.max);
    }
}

// on/off given for an enum with an `off` label (an on/off option that grew
// choices, rig.spline's tweakers): off, or the first label after it, which the
// manifest lists as what `on` used to build. Other enums keep the text.
Value offOrFirstChoice(const templates::Parameter& p, bool on)
{
    const auto off = std::find_if(p.enumLabels.begin(), p.enumLabels.end(), [](auto& e) { return e.second == "off"; });
    if (off == p.enumLabels.end())
        return Value(on);
    if (!on)
        return Value(off->second);
    const auto first = std::find_if(p.enumLabels.begin(), p.enumLabels.end(), [](auto& e) { return e.second != "off"; });
    return first != p.enumLabels.end() ? Value(first->second) : Value(on);
}

// Where the guide file set an option (nothing when it was not read from a file).
SourceLocation optionLocation(const model::TemplateInstance& instance, const std::string& option)
{
    const auto at = instance.optionSources.at.find(option);
    return at != instance.optionSources.at.end() ? at->second : SourceLocation{};
}

void resolveList(const std::vector<templates::Parameter>& params, const model::TemplateInstance& instance,
                 std::map<std::string, Value>& out, Diagnostics& diagnostics)
{
    for (const templates::Parameter& p : params) {
        Value v = p.value;
        auto it = instance.options.find(p.name);
        // An option's other name (`legacy:` in its manifest: an older name, or
        // Mikan's where ours differs) loads as the option; the option's own name wins.
        if (auto other = p.legacy.empty() ? instance.options.end() : instance.options.find(p.legacy);
            other != instance.options.end()) {
            if (it == instance.options.end())
                it = other;
            else
                diagnostics.push_back(makeWarning(optionLocation(instance, p.legacy), "instance '" + instance.name + "': options '" + p.name + "' and '" +
                                                          p.legacy + "' are the same option; using '" + p.name + "'"));
        }
        if (it != instance.options.end()) {
            const SourceLocation where = optionLocation(instance, it->first);
            Value given = it->second;
            if (const auto* index = std::get_if<long long>(&given); index && p.isEnum()) // enum by index
                for (const auto& [i, label] : p.enumLabels)
                    if (i == *index) given = label;
            if (const auto* on = std::get_if<bool>(&given); on && p.isEnum()) // an on/off option that grew choices
                given = offOrFirstChoice(p, *on);
            if (const auto* d = std::get_if<double>(&given); d && !std::isfinite(*d)) {
                // Readers refuse nan and inf at their line; this catches an edit or an API caller.
                diagnostics.push_back(makeError(where, "instance '" + instance.name + "': option '" + p.name + "' = " +
                                                        formatValue(given) + " is not a finite number; using the default"));
            } else if (auto c = coerce(given, p.value)) {
                Value clamped = *c;
                clampToRange(p, clamped);
                if (clamped != *c)
                    diagnostics.push_back(makeWarning(where, "instance '" + instance.name + "': option '" + p.name + "' = " +
                                                              formatValue(*c) + " is out of range, using " + formatValue(clamped)));
                v = clamped;
                if (p.isEnum() && std::none_of(p.enumLabels.begin(), p.enumLabels.end(),
                                               [&](auto& e) { return e.second == formatValue(v); })) {
                    diagnostics.push_back(makeWarning(where, "instance '" + instance.name + "': option '" + p.name + "' = '" +
                                                              formatValue(v) + "' is not one of its labels, using the default"));
                    v = p.value;
                }
            } else {
                diagnostics.push_back(makeWarning(where, "instance '" + instance.name + "': option '" + p.name + "' expects " +
                                                          typeName(typeOf(p.value)) + ", got '" + formatValue(it->second) +
                                                          "'; using the default"));
            }
        }
        out[p.name] = v;
    }
}

// Instances come parents-first in the document; this keeps that order explicit:
// each top-level instance followed by its subtree, breadth first (as
// GuideDocument::subtree lists it), children in document order.
std::vector<const model::TemplateInstance*> rootToLeaf(const model::GuideDocument& guide)
{
    std::unordered_map<model::InstanceId, std::vector<const model::TemplateInstance*>> children;
    for (const auto& i : guide.instances())
        if (i.parent != model::kNoId)
            children[i.parent].push_back(&i);
    std::vector<const model::TemplateInstance*> order;
    std::set<model::InstanceId> placed;
    for (const auto& i : guide.instances()) {
        if (i.parent != model::kNoId || !placed.insert(i.id).second)
            continue;
        order.push_back(&i);
        for (std::size_t k = order.size() - 1; k < order.size(); ++k)
            if (auto it = children.find(order[k]->id); it != children.end())
                for (const model::TemplateInstance* child : it->second)
                    if (placed.insert(child->id).second)
                        order.push_back(child);
    }
    return order;
}

void computeLocalMatrices(model::Rig& rig)
{
    for (auto& node : rig.nodes)
        node.localMatrix = node.parent == kNoNode ? node.worldMatrix
                                                  : glm::inverse(rig.nodes[node.parent].worldMatrix) * node.worldMatrix;
}

} // namespace

std::map<std::string, Value> resolveOptions(const templates::TemplateManifest& manifest,
                                            const model::TemplateInstance& instance, Diagnostics& diagnostics)
{
    std::map<std::string, Value> out;
    resolveList(manifest.guides, instance, out, diagnostics);
    resolveList(manifest.opts, instance, out, diagnostics);
    for (const auto& [name, value] : instance.options)
        if (!out.count(name) && !manifest.findByOtherName(name))
            diagnostics.push_back(makeWarning(optionLocation(instance, name), "instance '" + instance.name + "': option '" + name +
                                                      "' is not declared by " + manifest.id + " (ignored)"));
    return out;
}

model::Rig buildRig(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                    const BuilderRegistry& builders)
{
    return buildRig(guide, templates, builders, {});
}

model::Rig buildRig(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                    const BuilderRegistry& builders, const BuildProgress& progress)
{
    return buildRig(guide, templates, builders, progress, nullptr);
}

model::Rig buildRig(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                    const BuilderRegistry& builders, const BuildProgress& progress, BuildCache* buildCache)
{
    return buildRig(guide, templates, builders, progress, buildCache, guide.build.restore);
}

model::Rig buildRig(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                    const BuilderRegistry& builders, const BuildProgress& progress, BuildCache* buildCache,
                    const model::RestoreToggles& restore)
{
    BuildCache::Impl* cache = buildCache ? &buildCache->impl() : nullptr;
    if (cache)
        cache->begin(templates, builders, guide.naming);
    auto report = [&](double fraction, const std::string& stage) { if (progress) progress(fraction, stage); };
    report(0.0, "gather");
    Diagnostics branchDiagnostics;
    const ExpandedGuide expanded = expandBranches(guide, templates, branchDiagnostics);
    RigAssembly a(expanded.document, expanded, templates);
    a.rig.diagnostics = branchDiagnostics;
    if (cache && cache->lastNodeCount > 0) { // no rehashing while a live rebuild adds the same nodes again
        a.rig.nodes.reserve(cache->lastNodeCount);
        a.rig.byKey.reserve(cache->lastNodeCount);
    }
    a.indexGuide();
    model::RigNode root;
    root.key = {model::kNoId, {}, "rig"};
    root.path = "::rig";
    root.name = guide.name.empty() ? "rig" : guide.name;
    a.addNode(root);

    // Stage 1: gather. Nothing is created; every instance is resolved and checked.
    std::vector<std::pair<InstanceRecord, const TemplateBuilder*>> plan;
    for (const model::TemplateInstance* instance : rootToLeaf(expanded.document)) {
        InstanceRecord record;
        record.instance = instance;
        record.manifest = templates.find(instance->templateId);
        if (!record.manifest) {
            a.report(Severity::Error, instance, "unknown template '" + instance->templateId +
                                                    "'; the instance is skipped and its children attach above it");
            continue;
        }
        Diagnostics optionDiagnostics;
        record.options = resolveOptions(*record.manifest, *instance, optionDiagnostics);
        for (auto& d : optionDiagnostics) {
            d.subject = a.subjectOf(*instance);
            a.rig.diagnostics.push_back(d);
        }
        Diagnostics builderDiagnostics;
        const TemplateBuilder& builder = builders.resolve(*record.manifest, builderDiagnostics);
        for (const auto& d : builderDiagnostics)
            a.report(d.severity, instance, d.message);
        BuildContext check(a, *record.manifest, *instance, record.options);
        if (!builder.gather(check) || check.failed())
            continue;
        plan.emplace_back(std::move(record), &builder);
    }

    // Stage 2: generate, root to leaf. A failing instance is rolled back whole.
    // With a cache, a copy whose inputs are unchanged is replayed instead.
    std::vector<std::pair<InstanceRecord, const TemplateBuilder*>> built;
    std::set<CopyKey> generatedCopies;
    for (std::size_t step = 0; step < plan.size(); ++step) {
        auto& [record, builder] = plan[step];
        report(0.1 + 0.6 * double(step) / double(plan.size()), "generate " + record.instance->name);
        const RigNodeIndex hook = record.instance->parentJoint != model::kNoId ? a.physicalHookFor(record.instance->parentJoint) : 0;
        const CopyKey copyKey = a.copyOf(record.instance->id).key();
        Fragment* cached = nullptr;
        if (cache) {
            generatedCopies.insert(copyKey);
            if (auto it = cache->fragments.find(copyKey); it != cache->fragments.end())
                cached = &it->second;
        }
        if (cached && matches(*cached, a, record, builder, hook) && replay(*cached, a)) {
            ++cache->stats.replayed;
            if (cached->failed)
                continue;
            record.built = true;
            a.records.push_back(record);
            built.emplace_back(record, builder);
            continue;
        }
        BuildContext ctx(a, *record.manifest, *record.instance, record.options);
        ctx.setHookNode(hook);
        const AssemblySizes before{a.rig.nodes.size(), a.rig.constraints.size(), a.rig.diagnostics.size()};
        const auto spacesBefore = a.spaces;
        Fragment fresh;
        if (cache) {
            captureInputs(fresh, a, record, builder, hook);
            ctx.recordInto(&fresh, static_cast<RigNodeIndex>(before.nodes));
        }
        builder->generate(ctx);
        const bool failed = ctx.failed();
        if (failed) {
            a.rig.truncate(before.nodes);
            a.rig.constraints.resize(before.constraints);
            for (const auto& joint : record.instance->joints) // setHook only takes the instance's own joints
                a.hooks.erase(joint.id);
            a.spaces = spacesBefore;
        } else {
            record.built = true;
            a.records.push_back(record);
            built.emplace_back(record, builder);
        }
        if (cache) {
            captureOutputs(fresh, a, before, spacesBefore, failed);
            cache->fragments[copyKey] = std::move(fresh);
            ++cache->stats.generated;
        }
    }
    if (cache) // copies that are gone (an instance removed, a branch dropped)
        std::erase_if(cache->fragments, [&](const auto& entry) { return !generatedCopies.count(entry.first); });

    // Stage 3: configure, root to leaf, now that every node exists.
    report(0.7, "configure");
    for (auto& [record, builder] : built) {
        BuildContext ctx(a, *record.manifest, *record.instance, record.options);
        const std::size_t constraintsBefore = a.rig.constraints.size();
        builder->configure(ctx);
        if (ctx.failed())
            a.rig.constraints.resize(constraintsBefore);
    }

    // Stage 4: finalize. Orphans, shapes, virtual hierarchy, matrices, plugins.
    report(0.85, "finalize");
    for (RigNodeIndex i = 1; i < a.rig.nodes.size(); ++i)
        if (a.rig.nodes[i].parent == kNoNode)
            a.rig.nodes[i].parent = 0;
    applyRigMods(a, guide); // before the overrides: an override may adjust a channel a mod made
    report(0.88, "overrides");
    applyRigOverrides(a, guide, restore);
    if (guide.build.cleanup)
        cleanUpRig(a.rig, guide, restore);
    computeControlScales(a, builders, cache ? &cache->defaultSegments : nullptr);
    compensateSegmentScale(a);
    // The program compiles on another core while the shapes, the hierarchy and
    // the checks run here: they write none of what it reads (see compileProgram).
    // Isolated: while it waits, this thread runs only its own task, never a
    // piece of unrelated parallel work (a skin job's loop) from the shared pool.
    // `isolate_skin` reparents skin joints along the virtual hierarchy and adds
    // constraints, which the program compiles: the hierarchy comes first then.
    const bool isolating = wantsIsolatedSkin(a);
    if (isolating) {
        buildVirtualHierarchy(a);
        applyHierarchyMods(a, guide);
        isolateSkin(a);
    }
    ShapeSamples samples; // a build without a cache samples its shapes once
    tbb::this_task_arena::isolate([&] {
        tbb::task_group compiling;
        compiling.run([&a] { compileProgram(a); });
        applyShapes(a, cache ? cache->shapeSamples : samples);
        applyShapeOverrides(a, guide, restore);
        if (!isolating) {
            buildVirtualHierarchy(a);
            applyHierarchyMods(a, guide);
        }
        computeLocalMatrices(a.rig);
        for (const auto& plugin : builtinPlugins())
            plugin->finalize(a);
        compiling.wait();
    });
    reportProgram(a);
    if (cache) {
        cache->program = std::move(a.program);
        cache->lastNodeCount = a.rig.nodes.size();
    }
    report(1.0, "done");
    return std::move(a.rig);
}

} // namespace rs::rigging
