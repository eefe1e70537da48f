// Automatic weights (issue 19): the human of Debian's assimp-testmodels
// (HUMAN.blend, 14,444 welded vertices) bound to the biped sample's 87 skin
// joints, and the same human subdivided to about 58k and 231k vertices
// (Blender's bone heat fails on those). The human is scaled and moved onto the
// biped (same height, feet on the ground, centred): a stand-in for a guide
// fitted to it.
#include "io/GuideFile.h"
#include "io/ModelImport.h"
#include "io/TemplateFolders.h"
#include "rigging/RigBuilder.h"
#include "skin/AutoWeights.h"
#include "skin/Surface.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>

using namespace rs;

namespace {

const std::string kSource = RIGSMITH_SOURCE_DIR;
const std::string kHuman = "/usr/share/assimp/models/BLEND/HUMAN.blend";

const std::vector<skin::SkinBone>& bipedBones()
{
    static const auto bones = [] {
        templates::TemplateRegistry templates;
        io::scanTemplates(templates, {kSource + "/templates"}, kSource + "/resources/icons");
        const auto rig = rigging::buildRig(io::readGuideFile(kSource + "/resources/samples/biped.yml").take(), templates);
        return skin::skinBones(rig).take();
    }();
    return bones;
}

// The human's meshes as one, welded, scaled and moved onto the biped's bones.
model::Mesh humanOnBiped()
{
    auto imported = io::importModel(kHuman);
    model::Mesh joined;
    joined.name = "human";
    if (!imported)
        return joined;
    for (const auto& mesh : imported->meshes) {
        const auto base = std::uint32_t(joined.positions.size());
        joined.positions.insert(joined.positions.end(), mesh.positions.begin(), mesh.positions.end());
        for (auto i : mesh.indices)
            joined.indices.push_back(base + i);
    }
    const skin::Surface surface = skin::makeSurface(joined);
    model::Mesh welded;
    welded.name = "human";
    for (const Vec3& p : surface.positions)
        welded.positions.emplace_back(p);
    for (const auto& t : surface.triangles)
        welded.indices.insert(welded.indices.end(), t.begin(), t.end());
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const auto& p : welded.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    Vec3 boneLo(1e30), boneHi(-1e30);
    for (const auto& bone : bipedBones()) {
        boneLo = glm::min(boneLo, bone.head);
        boneHi = glm::max(boneHi, bone.head);
    }
    const double height = (boneHi.y - 0.0) * 1.08; // the head joint sits below the top of the head
    const double scale = height / double(hi.y - lo.y);
    const Vec3 centre((lo.x + hi.x) * 0.5, lo.y, (lo.z + hi.z) * 0.5);
    const Vec3 target((boneLo.x + boneHi.x) * 0.5, 0.0, (boneLo.z + boneHi.z) * 0.5);
    for (auto& p : welded.positions)
        p = glm::vec3((Vec3(p) - centre) * scale + target);
    return welded;
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

const model::Mesh& human(int subdivisions)
{
    static std::map<int, model::Mesh> meshes;
    auto it = meshes.find(subdivisions);
    if (it == meshes.end()) {
        model::Mesh mesh = humanOnBiped();
        for (int k = 0; k < subdivisions; ++k)
            mesh = subdivide(mesh);
        it = meshes.emplace(subdivisions, std::move(mesh)).first;
    }
    return it->second;
}

void BM_AutoWeightsHumanBiped(benchmark::State& state)
{
    const model::Mesh& mesh = human(int(state.range(0)));
    if (mesh.positions.empty()) {
        state.SkipWithError(("cannot read " + kHuman + " (install assimp-testmodels)").c_str());
        return;
    }
    skin::BindStats stats;
    for (auto _ : state) {
        auto weights = skin::bindMesh(mesh, bipedBones(), {}, &stats);
        benchmark::DoNotOptimize(weights.ok());
    }
    state.counters["vertices"] = double(stats.surfaceVertices);
    state.counters["bones"] = double(bipedBones().size());
    state.counters["bones_solved"] = double(stats.bonesSolved);
    state.counters["parts"] = double(stats.parts);
    state.counters["parts_by_closest_bone"] = double(stats.partsByClosestBone);
}
BENCHMARK(BM_AutoWeightsHumanBiped)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)
    ->ReportAggregatesOnly(false);

} // namespace
