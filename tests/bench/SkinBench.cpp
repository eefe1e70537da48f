// Automatic weights (issue 19): the human of Debian's assimp-testmodels
// (Collada/human.zae: a body and eyes, 14,444 welded vertices) bound to the
// biped sample's 87 skin joints, and the same human subdivided to about 57k and
// 230k vertices (Blender's bone heat fails on those). The biped sample is not
// fitted to this human: the figure is the binder's speed, not its quality.
#include "io/GuideFile.h"
#include "io/ModelImport.h"
#include "io/TemplateFolders.h"
#include "rigging/RigBuilder.h"
#include "skin/AutoWeights.h"
#include "skin/Skinning.h"
#include "skin/Surface.h"

#include <benchmark/benchmark.h>
#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>
#include <map>

using namespace rs;

namespace {

const std::string kSource = RIGSMITH_SOURCE_DIR;
const std::string kHuman = "/usr/share/assimp/models/Collada/human.zae";

std::vector<skin::SkinBone> bonesOf(const std::string& guide)
{
    templates::TemplateRegistry templates;
    io::scanTemplates(templates, {kSource + "/templates"}, kSource + "/resources/icons");
    const auto rig = rigging::buildRig(io::readGuideFile(guide).take(), templates);
    return skin::skinBones(rig).take();
}

const std::vector<skin::SkinBone>& bipedBones()
{
    static const auto bones = bonesOf(kSource + "/resources/samples/biped.yml");
    return bones;
}

// The biped fitted to the human (tests/data/Skin/human/guide.yml).
const std::vector<skin::SkinBone>& fittedBones()
{
    static const auto bones = bonesOf(kSource + "/tests/data/Skin/human/guide.yml");
    return bones;
}

// The human's meshes (body and eyes), each welded across its seams. The human
// is 1.66 m tall and stands at the origin like the biped.
std::vector<model::Mesh> humanMeshes()
{
    std::vector<model::Mesh> out;
    auto imported = io::importModel(kHuman);
    if (!imported)
        return out;
    for (const auto& mesh : imported->meshes) {
        const skin::Surface surface = skin::makeSurface(mesh);
        model::Mesh welded;
        welded.name = mesh.name;
        for (const Vec3& p : surface.positions)
            welded.positions.emplace_back(p);
        for (const auto& t : surface.triangles)
            welded.indices.insert(welded.indices.end(), t.begin(), t.end());
        out.push_back(std::move(welded));
    }
    return out;
}

// Each triangle split in four at its edge midpoints (shared between neighbours).
model::Mesh subdivide(const model::Mesh& mesh)
{
    model::Mesh out = mesh;
    out.indices.clear();
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const auto key = std::minmax(a, b);
        auto [it, added] = midpoints.try_emplace({key.first, key.second}, std::uint32_t(out.positions.size()));
        if (added)
            out.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
        return it->second;
    };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        out.indices.insert(out.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    return out;
}

const std::vector<model::Mesh>& human(int subdivisions)
{
    static std::map<int, std::vector<model::Mesh>> models;
    auto it = models.find(subdivisions);
    if (it == models.end()) {
        std::vector<model::Mesh> meshes = humanMeshes();
        for (int k = 0; k < subdivisions; ++k)
            for (auto& mesh : meshes)
                mesh = subdivide(mesh);
        it = models.emplace(subdivisions, std::move(meshes)).first;
    }
    return it->second;
}

// The whole human (body, then eyes, each hidden by the other) bound by heat.
void bindHuman(benchmark::State& state, const std::vector<skin::SkinBone>& bones)
{
    const std::vector<model::Mesh>& meshes = human(int(state.range(0)));
    if (meshes.empty()) {
        state.SkipWithError(("cannot read " + kHuman + " (install assimp-testmodels)").c_str());
        return;
    }
    std::size_t vertices = 0, solved = 0, parts = 0, byClosest = 0;
    for (auto _ : state) {
        vertices = solved = parts = byClosest = 0;
        for (const model::Mesh& mesh : meshes) {
            skin::BindOptions options;
            for (const model::Mesh& other : meshes)
                if (&other != &mesh)
                    options.occluders.push_back(&other);
            skin::BindStats stats;
            auto weights = skin::bindMesh(mesh, bones, options, &stats);
            benchmark::DoNotOptimize(weights.ok());
            vertices += stats.surfaceVertices;
            solved = std::max(solved, stats.bonesSolved);
            parts += stats.parts;
            byClosest += stats.partsByClosestBone;
        }
    }
    state.counters["vertices"] = double(vertices);
    state.counters["bones"] = double(bones.size());
    state.counters["bones_solved"] = double(solved);
    state.counters["parts"] = double(parts);
    state.counters["parts_by_closest_bone"] = double(byClosest);
}
void BM_AutoWeightsHumanBiped(benchmark::State& state) { bindHuman(state, bipedBones()); }
BENCHMARK(BM_AutoWeightsHumanBiped)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);
void BM_AutoWeightsHumanFitted(benchmark::State& state) { bindHuman(state, fittedBones()); }
BENCHMARK(BM_AutoWeightsHumanFitted)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);
// Subdivided three times: about 920k vertices. Once, so ./bench.sh stays short.
BENCHMARK(BM_AutoWeightsHumanBiped)->Arg(3)->Unit(benchmark::kSecond)->Iterations(1);

} // namespace

namespace {

// CPU skinning, issue 19's target: 100k vertices, 80 joints, 4 influences each,
// positions and normals. Argument: 0 linear blend, 1 dual quaternion. The
// weights are prepared once (PreparedSkin), outside the timed loop, as a
// player prepares them once per bind; each iteration skins one pose.
struct SkinningCase {
    std::vector<glm::vec3> positions, normals, outPositions, outNormals;
    model::MeshWeights weights;
    std::vector<Mat4> matrices;

    SkinningCase(std::size_t vertices, std::size_t joints)
        : positions(vertices), normals(vertices), outPositions(vertices), outNormals(vertices), matrices(joints)
    {
        weights.joints.resize(joints);
        weights.offsets.push_back(0);
        std::uint32_t seed = 12345;
        auto next = [&] { return (seed = seed * 1664525u + 1013904223u) >> 8; };
        auto unit = [&] { return float(next() % 1000) * 1e-3f; };
        for (std::size_t v = 0; v < vertices; ++v) {
            positions[v] = glm::vec3(unit(), unit(), unit());
            normals[v] = glm::normalize(glm::vec3(unit() - 0.5f, unit() - 0.5f, unit() + 0.1f));
            for (int k = 0; k < 4; ++k)
                weights.influences.push_back({std::uint32_t(next() % joints), 0.25f});
            weights.offsets.push_back(std::uint32_t(weights.influences.size()));
        }
        for (std::size_t j = 0; j < joints; ++j)
            matrices[j] = glm::translate(Mat4(1.0), Vec3(0.01 * double(j), 0, 0)) * glm::rotate(Mat4(1.0), 0.02 * double(j), Vec3(0, 0, 1));
    }

    skin::SkinningJob job(skin::SkinningMethod method) const
    {
        skin::SkinningJob job;
        job.method = method;
        job.positions = positions;
        job.normals = normals;
        job.skinMatrices = matrices;
        job.outPositions = std::span(const_cast<std::vector<glm::vec3>&>(outPositions));
        job.outNormals = std::span(const_cast<std::vector<glm::vec3>&>(outNormals));
        return job;
    }
};

void runSkinning(benchmark::State& state, const SkinningCase& data, skin::SkinningJob job)
{
    if (job.validate().failed()) {
        state.SkipWithError("invalid job");
        return;
    }
    for (auto _ : state) {
        job.run();
        benchmark::DoNotOptimize(job.outPositions.data());
        benchmark::DoNotOptimize(job.outNormals.data());
        benchmark::ClobberMemory();
    }
    state.counters["vertices"] = double(data.positions.size());
}

skin::SkinningMethod methodOf(const benchmark::State& state)
{
    return state.range(0) == 0 ? skin::SkinningMethod::Linear : skin::SkinningMethod::DualQuaternion;
}

void BM_SkinningCpu(benchmark::State& state)
{
    const SkinningCase data(100000, 80);
    const skin::PreparedSkin prepared = skin::PreparedSkin::prepare(data.weights).take();
    skin::SkinningJob job = data.job(methodOf(state));
    job.prepared = &prepared;
    state.counters["fixed_layout"] = prepared.hasFixedLayout() ? 1 : 0;
    runSkinning(state, data, job);
}
BENCHMARK(BM_SkinningCpu)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The same, reading the MeshWeights in place (the general loops, no preparation).
void BM_SkinningCpuInPlace(benchmark::State& state)
{
    const SkinningCase data(100000, 80);
    skin::SkinningJob job = data.job(methodOf(state));
    job.weights = &data.weights;
    runSkinning(state, data, job);
}
BENCHMARK(BM_SkinningCpuInPlace)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

} // namespace
