// Weight transfer (issue 20): a 100k-vertex source chunk (a 316 x 316 wavy
// sheet, 1 m square, 80 joints, four influences per vertex) onto a 1M-vertex
// target (a 1000 x 1000 sheet over the same square), by closest point on
// triangles and by closest neighbours, without and with the normal filter.
// Two targets: a denser remesh of the same surface 1 mm above it (first Arg
// 0), and a mismatched one whose waves are out of phase, up to 12 mm off the
// source (first Arg 1; most of its queries leave the nearest-point grid for
// the KD-tree). Each iteration builds the source's search structures and
// transfers every target vertex (file reading is not timed). Target: <= 0.4 s
// on two cores.
#include "skin/NearestPoints.h"
#include "skin/Refit.h"
#include "skin/Transfer.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>

using namespace rs;

namespace {

model::Mesh sheet(const std::string& name, int n, float phase, float lift)
{
    model::Mesh mesh;
    mesh.name = name;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float u = float(x) / float(n - 1), v = float(y) / float(n - 1);
            mesh.positions.push_back({u, v, lift + 0.03f * std::sin(6.0f * u + phase) * std::cos(5.0f * v)});
        }
    for (int y = 0; y + 1 < n; ++y)
        for (int x = 0; x + 1 < n; ++x) {
            const auto a = std::uint32_t(y * n + x), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, c, b, d, c});
        }
    return mesh;
}

// 80 joints on a 10 x 8 lattice; each vertex weighted to its four nearest, by inverse distance.
skin::SkinChunk sourceChunk()
{
    const model::Mesh mesh = sheet("cloth", 316, 0.0f, 0.0f);
    model::MeshWeights weights; // 80 joints on a 10 x 8 lattice, each vertex on its cell's four corners
    for (int j = 0; j < 80; ++j) {
        weights.joints.push_back({1, "", "skin.j" + std::to_string(j)});
        weights.parents.push_back(j == 0 ? -1 : 0);
    }
    weights.offsets.push_back(0);
    for (const glm::vec3& p : mesh.positions) {
        const int jx = std::min(int(p.x * 9.0f), 8), jy = std::min(int(p.y * 7.0f), 6);
        const int corners[4] = {jy * 10 + jx, jy * 10 + jx + 1, (jy + 1) * 10 + jx, (jy + 1) * 10 + jx + 1};
        float sum = 0.0f, w[4];
        for (int k = 0; k < 4; ++k) {
            const float cx = float(corners[k] % 10) / 9.0f, cy = float(corners[k] / 10) / 7.0f;
            w[k] = 1.0f / (0.01f + std::hypot(p.x - cx, p.y - cy));
            sum += w[k];
        }
        for (int k = 0; k < 4; ++k)
            weights.influences.push_back({std::uint32_t(corners[k]), w[k] / sum});
        weights.offsets.push_back(std::uint32_t(weights.influences.size()));
    }
    return skin::bindingChunk({"", mesh.name, mesh.vertexCount(), model::topologyFingerprint(mesh), std::move(weights)}, mesh, nullptr);
}

double processSeconds()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

const model::Mesh& target(bool mismatched)
{
    static const model::Mesh remesh = sheet("cloth", 1000, 0.0f, 0.001f), offPhase = sheet("cloth", 1000, 0.4f, 0.001f);
    return mismatched ? offPhase : remesh;
}

void transfer(benchmark::State& state, skin::TransferMethod method)
{
    static const skin::SkinChunk source = sourceChunk();
    const model::Mesh& target = ::target(state.range(0) != 0);
    skin::TransferOptions options;
    options.method = method;
    options.normalFilter = state.range(1) != 0;
    double cpu = 0.0;
    for (auto _ : state) {
        const double before = processSeconds();
        auto built = skin::TransferSource::fromChunk(source, true);
        auto weights = skin::transferWeights(*built, target, options);
        benchmark::DoNotOptimize(weights.ok());
        cpu += processSeconds() - before;
    }
    // CPU time of every thread per iteration: on a loaded machine the wall
    // time says how much of the cores it got; this says what the work costs
    // (two idle cores: about half of it, the loops being parallel).
    state.counters["cpu_s_all_threads"] = cpu / double(state.iterations());
    state.counters["source_vertices"] = double(source.vertexCount());
    state.counters["target_vertices"] = double(target.vertexCount());
}

void BM_TransferClosestPoint(benchmark::State& state) { transfer(state, skin::TransferMethod::ClosestPoint); }
void BM_TransferClosestNeighbours(benchmark::State& state) { transfer(state, skin::TransferMethod::ClosestNeighbours); }
// Args: target (0 remesh, 1 mismatched), normal filter (0 off, 1 on).
BENCHMARK(BM_TransferClosestPoint)->ArgsProduct({{0, 1}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TransferClosestNeighbours)->ArgsProduct({{0, 1}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

namespace {

// The nearest-vertex search alone, on one thread: the two nearest of the 100k
// source vertices for each of the 1M target vertices (Arg: the target, as above).
void BM_TransferNearestPoints(benchmark::State& state)
{
    static const model::Mesh source = sheet("cloth", 316, 0.0f, 0.0f);
    const skin::NearestPoints points(source.positions);
    for (auto _ : state) {
        std::uint64_t sum = 0;
        std::uint32_t index[2];
        float distance2[2];
        for (const glm::vec3& p : target(state.range(0) != 0).positions)
            sum += std::uint64_t(points.nearest(p, 2, index, distance2)) + index[0];
        benchmark::DoNotOptimize(sum);
    }
}
BENCHMARK(BM_TransferNearestPoints)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace

namespace {

// Inpainting onto a 100k-vertex target (the mismatched sheet, 316 x 316): the
// vertices whose closest point's normal turns more than Arg degrees from
// theirs are solved for (the counter says how many: at 30 degrees, the
// default, none here). Target: <= 3 s.
void BM_TransferInpainting(benchmark::State& state)
{
    static const skin::SkinChunk source = sourceChunk();
    static const model::Mesh target = sheet("cloth", 316, 0.4f, 0.001f);
    skin::TransferOptions options;
    options.method = skin::TransferMethod::Inpainting;
    options.inpaintAngleDegrees = double(state.range(0));
    skin::MeshImportReport report;
    double cpu = 0.0;
    for (auto _ : state) {
        report = {};
        const double before = processSeconds();
        auto built = skin::TransferSource::fromChunk(source, true);
        auto weights = skin::transferWeights(*built, target, options, &report);
        benchmark::DoNotOptimize(weights.ok());
        cpu += processSeconds() - before;
    }
    state.counters["cpu_s_all_threads"] = cpu / double(state.iterations());
    state.counters["target_vertices"] = double(target.vertexCount());
    state.counters["inpainted"] = double(report.inpainted);
}
BENCHMARK(BM_TransferInpainting)->Arg(3)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
