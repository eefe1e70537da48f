// Core timings on the bundled samples: guide load/save, rig build, glTF export.
#include "rigging/RigBuilder.h"
#include "eval/RigProgram.h"
#include "io/RigExport.h"
#include "io/GuideFile.h"
#include "io/TemplateFolders.h"
#include "io/RigDump.h"
#include "model/Skeleton.h"
#include "session/Session.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rs;

namespace {

const std::string kSource = RIGSMITH_SOURCE_DIR;

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const templates::TemplateRegistry& registry()
{
    static const auto r = [] {
        auto out = std::make_shared<templates::TemplateRegistry>();
        io::scanTemplates(*out, {kSource + "/templates"}, kSource + "/resources/icons");
        return out;
    }();
    return *r;
}

model::GuideDocument biped()
{
    return io::readGuideFile(kSource + "/resources/samples/biped.yml").take();
}

void BM_LoadBipedGuide(benchmark::State& state)
{
    const std::string text = readText(kSource + "/resources/samples/biped.yml");
    for (auto _ : state)
        benchmark::DoNotOptimize(io::readGuideText(text, "biped.yml"));
}
BENCHMARK(BM_LoadBipedGuide)->Unit(benchmark::kMicrosecond);

void BM_SaveBipedGuideText(benchmark::State& state)
{
    const auto doc = biped();
    for (auto _ : state)
        benchmark::DoNotOptimize(io::writeGuideText(doc));
}
BENCHMARK(BM_SaveBipedGuideText)->Unit(benchmark::kMicrosecond);

void BM_ScanTemplates(benchmark::State& state)
{
    for (auto _ : state) {
        templates::TemplateRegistry r;
        benchmark::DoNotOptimize(io::scanTemplates(r, {kSource + "/templates"}, kSource + "/resources/icons"));
    }
}
BENCHMARK(BM_ScanTemplates)->Unit(benchmark::kMillisecond);

// A library of state.range(0) templates (the golden-test manifests, which use every
// key, copied under distinct ids) plus the shipped shapes library, scanned cold.
void BM_ScanTemplateLibrary(benchmark::State& state)
{
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / ("rigsmith-bench-library-" + std::to_string(state.range(0)));
    fs::remove_all(folder);
    std::vector<fs::path> sources;
    for (const auto& entry : fs::directory_iterator(kSource + "/tests/data/ManifestReader"))
        sources.push_back(entry.path() / "template.yml");
    std::sort(sources.begin(), sources.end());
    for (long i = 0; i < state.range(0); ++i) {
        const fs::path module = folder / ("category" + std::to_string(i % 10)) / ("module" + std::to_string(i));
        fs::create_directories(module);
        fs::copy_file(sources[std::size_t(i) % sources.size()], module / "template.yml");
    }
    fs::create_directories(folder / "shapes");
    for (const auto& entry : fs::directory_iterator(kSource + "/templates/shapes"))
        if (entry.path().extension() == ".yml")
            fs::copy_file(entry.path(), folder / "shapes" / entry.path().filename());
    std::size_t templates = 0, shapes = 0;
    for (auto _ : state) {
        templates::TemplateRegistry r;
        benchmark::DoNotOptimize(io::scanTemplates(r, {folder.string()}, kSource + "/resources/icons"));
        templates = r.all().size();
        shapes = r.shapes().size();
    }
    state.counters["templates"] = double(templates);
    state.counters["shapes"] = double(shapes);
    fs::remove_all(folder);
}
BENCHMARK(BM_ScanTemplateLibrary)->Arg(100)->Unit(benchmark::kMillisecond);

// What a build made, as JSON counters next to the time.
void countRig(benchmark::State& state, const model::Rig& rig)
{
    state.counters["nodes"] = double(rig.nodes.size());
    state.counters["controllers"] = double(rig.count(model::RigNodeKind::Controller));
    state.counters["skin_joints"] = double(rig.skinJointCount());
    state.counters["constraints"] = double(rig.constraints.size());
    state.counters["diagnostics"] = double(rig.diagnostics.size());
}

// Issue 17's target (core edit -> rig <= 2 ms): a session with the biped built;
// each iteration is one preview of a guide-joint drag (the arm's elbow, as the
// editor's gizmo sends it): revert the last preview, apply the new one, rebuild
// the rig live, compile it and evaluate the test pose.
void BM_SessionGuideJointDragToEvaluatedRig(benchmark::State& state)
{
    session::Session s(std::make_shared<templates::TemplateRegistry>(registry()));
    s.replaceDocument(biped());
    s.build();
    const model::JointId elbow = s.document().instanceNamed("arm")->joints[2].id;
    const Mat4 start = s.document().jointWorldMatrix(elbow);
    s.selectGuideJoints({elbow}, false);
    s.beginGuideDrag(elbow);
    int step = 0;
    for (auto _ : state) {
        Mat4 world = start;
        world[3][1] += 0.001 * double(++step % 50);
        s.dragGuideTo(world);
        benchmark::DoNotOptimize(s.evaluation()->world.data());
    }
    state.counters["copies_replayed"] = double(s.lastBuildReuse().replayed);
    state.counters["copies_generated"] = double(s.lastBuildReuse().generated);
    s.endGuideDrag("bench");
}
BENCHMARK(BM_SessionGuideJointDragToEvaluatedRig)->Unit(benchmark::kMicrosecond);

// One committed option change (the spine's stretch toggled) -> rebuilt, evaluated rig.
void BM_SessionOptionChangeToEvaluatedRig(benchmark::State& state)
{
    session::Session s(std::make_shared<templates::TemplateRegistry>(registry()));
    s.replaceDocument(biped());
    s.build();
    const model::InstanceId spine = s.document().instanceNamed("spine")->id;
    bool stretch = true;
    for (auto _ : state) {
        stretch = !stretch;
        s.setOption(spine, "stretch", Value(stretch));
        benchmark::DoNotOptimize(s.evaluation()->world.data());
    }
    state.counters["copies_replayed"] = double(s.lastBuildReuse().replayed);
    state.counters["copies_generated"] = double(s.lastBuildReuse().generated);
}
BENCHMARK(BM_SessionOptionChangeToEvaluatedRig)->Unit(benchmark::kMicrosecond);

void BM_BuildBipedRig(benchmark::State& state)
{
    const auto doc = biped();
    const auto& templates = registry();
    for (auto _ : state)
        benchmark::DoNotOptimize(rigging::buildRig(doc, templates));
    countRig(state, rigging::buildRig(doc, templates));
}
BENCHMARK(BM_BuildBipedRig)->Unit(benchmark::kMicrosecond);

// Issue 23: 1,000 override entries (a channel's default, limit or lock, a test
// pose value, a display name, a shape edit with its colour: each one entry)
// spread over the biped's controllers, applied to the built rig by the build's
// override stage. The rig is copied outside the timing each iteration.
void BM_ApplyOverrides1000(benchmark::State& state)
{
    model::GuideDocument doc = biped();
    const auto& templates = registry();
    const model::Rig plain = rigging::buildRig(doc, templates);
    std::vector<const model::RigNode*> controllers;
    for (const auto& node : plain.nodes)
        if (node.kind == model::RigNodeKind::Controller)
            controllers.push_back(&node);
    std::size_t entries = 0;
    for (std::size_t k = 0; entries < 1000; ++k) {
        const model::RigNode& node = *controllers[k % controllers.size()];
        model::Override& o = doc.overrides[node.key];
        const int channel = int((k / controllers.size()) % 9);
        const std::string name = model::channelName(channel);
        switch (k % 6) {
        case 0: o.defaults[name] = channel >= 6 ? 1.0 : 0.01 * double(k % 7); break;
        case 1: o.limits[name] = {-100.0, 100.0}; break;
        case 2: o.locks[name] = {false, (k % 2) == 0}; break;
        case 3: o.pose[name] = channel >= 6 ? 1.0 : 0.5; break;
        case 4: o.displayName = node.name + "_ovr"; break;
        case 5: o.shape.emplace().edit.transform.scale = Vec3(1.1); o.shape->color = Vec3(1.0, 0.0, 0.0); break;
        }
        ++entries;
    }
    doc.overrides[model::rigRootKey()].post = Transform{Vec3(0.0, 0.0, 1.0), Vec3(0.0), Vec3(1.5)};
    model::Rig rig = plain;
    for (auto _ : state) {
        state.PauseTiming();
        rig = plain;
        state.ResumeTiming();
        rigging::applyOverrides(rig, doc, {});
        benchmark::DoNotOptimize(rig.nodes.data());
    }
    state.counters["override_entries"] = double(entries + 1);
    state.counters["records"] = double(doc.overrides.size());
    state.counters["controllers"] = double(controllers.size());
}
BENCHMARK(BM_ApplyOverrides1000)->Unit(benchmark::kMicrosecond);

void BM_BuildSampleRig(benchmark::State& state, const std::string& sample)
{
    const auto doc = io::readGuideFile(kSource + "/resources/samples/" + sample + ".yml").take();
    for (auto _ : state)
        benchmark::DoNotOptimize(rigging::buildRig(doc, registry()));
    countRig(state, rigging::buildRig(doc, registry()));
}
BENCHMARK_CAPTURE(BM_BuildSampleRig, quadruped, std::string("quadruped"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BuildSampleRig, prop, std::string("prop"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BuildSampleRig, face, std::string("face"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BuildSampleRig, vehicle, std::string("vehicle"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BuildSampleRig, robot, std::string("robot"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BuildSampleRig, claw, std::string("claw"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BuildSampleRig, cart, std::string("cart"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BuildSampleRig, strider, std::string("strider"))->Unit(benchmark::kMicrosecond);

// N bipeds side by side in one guide (fresh ids and names per copy): how the
// build scales past the ~900 nodes of a production biped.
model::GuideDocument crowd(int copies)
{
    const auto one = biped();
    model::GuideDocument out;
    out.name = "crowd";
    const auto instanceStride = one.nextInstanceId(), jointStride = one.nextJointId();
    for (int k = 0; k < copies; ++k)
        for (model::TemplateInstance instance : one.instances()) {
            auto shift = [&](model::JointId j) { return j == model::kNoId ? j : j + model::JointId(k) * jointStride; };
            instance.id += model::InstanceId(k) * instanceStride;
            if (instance.parent != model::kNoId)
                instance.parent += model::InstanceId(k) * instanceStride;
            instance.parentJoint = shift(instance.parentJoint);
            if (k > 0)
                instance.name += std::string(1, '_') + std::to_string(k);
            for (auto& joint : instance.joints) {
                joint.id = shift(joint.id);
                joint.parent = shift(joint.parent);
            }
            if (instance.parent == model::kNoId)
                instance.joints.front().local.translate.x += 2.0 * k;
            out.insertInstance(std::move(instance), out.instances().size());
        }
    return out;
}

void BM_BuildBipedCrowd(benchmark::State& state)
{
    const auto doc = crowd(static_cast<int>(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(rigging::buildRig(doc, registry()));
    countRig(state, rigging::buildRig(doc, registry()));
}
BENCHMARK(BM_BuildBipedCrowd)->Arg(3)->Arg(10)->Unit(benchmark::kMicrosecond);

// One full evaluation of the built biped: every controller animated (all
// rotations and custom channels change each iteration, so no step is skipped),
// IK limbs on, feet rolled, spline spine. One core, no allocation.
void BM_EvaluateBiped(benchmark::State& state)
{
    const model::Rig rig = rigging::buildRig(biped(), registry());
    const auto program = eval::RigProgram::compile(rig).take();
    eval::EvalState evaluation = program.makeState();
    const auto& layout = program.channels();
    // 64 poses made up front, so the timing is the evaluation alone.
    std::vector<eval::Pose> poses(64, layout.defaults());
    for (std::size_t p = 0; p < poses.size(); ++p)
        for (std::size_t i = 0; i < layout.size(); ++i) {
            const auto& c = layout[i];
            const double wave = std::sin(0.1 * double(p) + double(i));
            if (c.locked) continue;
            if (c.transform >= 3 && c.transform < 6) poses[p][i] = 20.0 * wave;
            else if (c.transform < 0 && !c.isEnum()) poses[p][i] = layout.clamp(int(i), c.min + (c.max - c.min) * (0.5 + 0.5 * wave));
        }
    std::size_t next = 0;
    for (auto _ : state) {
        program.evaluate(poses[next++ & 63], evaluation);
        benchmark::DoNotOptimize(evaluation.world.data());
        benchmark::ClobberMemory();
    }
    countRig(state, rig);
    state.counters["steps"] = double(program.stepCount());
    state.counters["channels"] = double(layout.size());
}
BENCHMARK(BM_EvaluateBiped)->Unit(benchmark::kMicrosecond);

// Compiling the built biped into its evaluation program (every build does it
// once to check for cycles; the editor once more to pose the rig).
void BM_CompileBipedProgram(benchmark::State& state)
{
    const model::Rig rig = rigging::buildRig(biped(), registry());
    for (auto _ : state)
        benchmark::DoNotOptimize(eval::RigProgram::compile(rig));
}
BENCHMARK(BM_CompileBipedProgram)->Unit(benchmark::kMicrosecond);

// The same evaluation without the pose update: the evaluator alone.
void BM_EvaluateBipedFixedPose(benchmark::State& state)
{
    const model::Rig rig = rigging::buildRig(biped(), registry());
    const auto program = eval::RigProgram::compile(rig).take();
    eval::EvalState evaluation = program.makeState();
    eval::Pose pose = program.channels().defaults();
    for (std::size_t i = 0; i < pose.size(); ++i)
        if (!program.channels()[i].locked && program.channels()[i].transform >= 3 && program.channels()[i].transform < 6)
            pose[i] = 10.0;
    for (auto _ : state) {
        program.evaluate(pose, evaluation);
        benchmark::DoNotOptimize(evaluation.world.data());
        benchmark::ClobberMemory();
    }
    state.counters["steps"] = double(program.stepCount());
}
BENCHMARK(BM_EvaluateBipedFixedPose)->Unit(benchmark::kMicrosecond);

void BM_DumpBipedRig(benchmark::State& state)
{
    const auto rig = rigging::buildRig(biped(), registry());
    for (auto _ : state)
        benchmark::DoNotOptimize(io::writeRigDump(rig));
}
BENCHMARK(BM_DumpBipedRig)->Unit(benchmark::kMicrosecond);

void BM_ExportBipedGlb(benchmark::State& state)
{
    const auto rig = rigging::buildRig(biped(), registry());
    const std::string path = (std::filesystem::temp_directory_path() / "rigsmith-bench-biped.glb").string();
    for (auto _ : state)
        benchmark::DoNotOptimize(io::exportRig(rig, path));
}
BENCHMARK(BM_ExportBipedGlb)->Unit(benchmark::kMicrosecond);

// Issue 6: the biped with a generated 100k-vertex skinned mesh (io::proxyMesh),
// validated and written to a file, per format (arg 0 .glb, 1 .fbx).
void BM_ExportBipedSkinned100k(benchmark::State& state)
{
    const auto rig = rigging::buildRig(biped(), registry());
    const std::vector<io::SkinnedMesh> meshes{io::proxyMesh(*model::extractSkeleton(rig), 100000)};
    io::ExportOptions options;
    options.meshes = &meshes;
    const char* name = state.range(0) == 0 ? "rigsmith-bench-skinned.glb" : "rigsmith-bench-skinned.fbx";
    const std::string path = (std::filesystem::temp_directory_path() / name).string();
    for (auto _ : state) {
        const Diagnostics d = io::exportRig(rig, path, options);
        if (hasErrors(d))
            state.SkipWithError(d.front().format().c_str());
    }
    state.counters["vertices"] = double(meshes[0].vertexCount());
    state.counters["bytes"] = double(std::filesystem::file_size(path));
}
BENCHMARK(BM_ExportBipedSkinned100k)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace
