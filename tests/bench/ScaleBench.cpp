// Issue 18 item 12: how the build and the export scale with the size of the
// guide. Guides are generated here: one core.joints chain of N joints, and N
// small instances (core.xform and three-joint core.joints, alternating) hung
// in a binary tree, each under a joint of its parent instance.
#include "rigging/RigBuilder.h"
#include "io/RigExport.h"
#include "io/TemplateFolders.h"
#include "session/Session.h"

#include <benchmark/benchmark.h>

#include <filesystem>

using namespace rs;

namespace {

const std::string kSource = RIGSMITH_SOURCE_DIR;

const templates::TemplateRegistry& registry()
{
    static const auto r = [] {
        auto out = std::make_shared<templates::TemplateRegistry>();
        io::scanTemplates(*out, {kSource + "/templates"}, kSource + "/resources/icons");
        return out;
    }();
    return *r;
}

model::GuideJoint guideJoint(model::JointId id, model::JointId parent, double x, double y)
{
    model::GuideJoint j;
    j.id = id;
    j.parent = parent;
    j.local.translate = Vec3(x, y, 0.0);
    return j;
}

// One core.joints instance whose chain has `joints` guide joints, 1 cm apart.
model::GuideDocument longChain(int joints)
{
    model::TemplateInstance chain;
    chain.id = 1;
    chain.templateId = "core.joints";
    chain.name = "chain";
    for (int k = 0; k < joints; ++k)
        chain.joints.push_back(guideJoint(model::JointId(k + 1), k == 0 ? model::kNoId : model::JointId(k), 0.0, 0.01));
    model::GuideDocument doc;
    doc.name = "chain";
    doc.insertInstance(std::move(chain), 0);
    return doc;
}

// `count` instances in a binary tree: instance k hangs under the last joint of
// instance (k - 1) / 2; even ones are core.xform, odd ones three-joint core.joints.
model::GuideDocument instanceTree(int count)
{
    model::GuideDocument doc;
    doc.name = "tree";
    std::vector<model::JointId> lastJoint;
    model::JointId nextJoint = 1;
    for (int k = 0; k < count; ++k) {
        model::TemplateInstance instance;
        instance.id = model::InstanceId(k + 1);
        const bool isXform = k % 2 == 0;
        instance.templateId = isXform ? "core.xform" : "core.joints";
        instance.name = (isXform ? "xform" : "joints") + std::to_string(k);
        if (k > 0) {
            instance.parent = model::InstanceId((k - 1) / 2 + 1);
            instance.parentJoint = lastJoint[std::size_t((k - 1) / 2)];
        }
        const int joints = isXform ? 1 : 3;
        for (int j = 0; j < joints; ++j) {
            const model::JointId id = nextJoint++;
            instance.joints.push_back(guideJoint(id, j == 0 ? model::kNoId : id - 1, k % 2 ? 0.1 : -0.1, 0.05));
        }
        lastJoint.push_back(instance.joints.back().id);
        doc.insertInstance(std::move(instance), doc.instances().size());
    }
    return doc;
}

void countRig(benchmark::State& state, const model::Rig& rig)
{
    state.counters["nodes"] = double(rig.nodes.size());
    state.counters["constraints"] = double(rig.constraints.size());
    state.counters["diagnostics"] = double(rig.diagnostics.size());
}

// Target: a 2,000-joint chain builds in <= 50 ms.
void BM_BuildLongJointChain(benchmark::State& state)
{
    const auto doc = longChain(int(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(rigging::buildRig(doc, registry()));
    countRig(state, rigging::buildRig(doc, registry()));
}
BENCHMARK(BM_BuildLongJointChain)->Arg(250)->Arg(500)->Arg(2000)->Unit(benchmark::kMillisecond);

// Target: 10,000 instances build and export (.glb) in <= 2 s together.
void BM_BuildAndExportInstanceTree(benchmark::State& state)
{
    const auto doc = instanceTree(int(state.range(0)));
    const std::string path = (std::filesystem::temp_directory_path() / "rigsmith-bench-tree.glb").string();
    for (auto _ : state) {
        const model::Rig rig = rigging::buildRig(doc, registry());
        const Diagnostics d = io::exportRig(rig, path);
        if (hasErrors(d))
            state.SkipWithError(d.front().format().c_str());
    }
    countRig(state, rigging::buildRig(doc, registry()));
}
BENCHMARK(BM_BuildAndExportInstanceTree)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

// The build alone, and the export alone, of the same tree.
void BM_BuildInstanceTree(benchmark::State& state)
{
    const auto doc = instanceTree(int(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(rigging::buildRig(doc, registry()));
}
BENCHMARK(BM_BuildInstanceTree)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_ExportInstanceTree(benchmark::State& state, const std::string& extension)
{
    const model::Rig rig = rigging::buildRig(instanceTree(int(state.range(0))), registry());
    const std::string path = (std::filesystem::temp_directory_path() / ("rigsmith-bench-tree" + extension)).string();
    for (auto _ : state) {
        const Diagnostics d = io::exportRig(rig, path);
        if (hasErrors(d))
            state.SkipWithError(d.front().format().c_str());
    }
}
BENCHMARK_CAPTURE(BM_ExportInstanceTree, glb, std::string(".glb"))->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExportInstanceTree, fbx, std::string(".fbx"))->Arg(10000)->Unit(benchmark::kMillisecond);

// The editor's path: a session opens the tree and builds it (with its build
// cache), then one joint of the last instance moves and the rig is rebuilt live
// (every other instance copy replayed).
void BM_SessionInstanceTree(benchmark::State& state)
{
    const auto doc = instanceTree(int(state.range(0)));
    const auto templates = std::make_shared<templates::TemplateRegistry>(registry());
    const model::JointId last = doc.instances().back().joints.front().id;
    for (auto _ : state) {
        session::Session s(templates);
        s.replaceDocument(doc);
        s.build();
        s.selectGuideJoints({last}, false);
        s.beginGuideDrag(last);
        s.dragGuideTo(translationMatrix(Vec3(0.0, 1.0, 0.0)));
        s.endGuideDrag("bench");
        benchmark::DoNotOptimize(s.evaluation());
        state.counters["copies_replayed"] = double(s.lastBuildReuse().replayed);
    }
}
BENCHMARK(BM_SessionInstanceTree)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

} // namespace
