// The fallback methods of skin/Transfer.h over a target mesh: per target
// vertex the query of skin/TransferQuery.h (closest point on triangles or
// closest neighbours, with the normal filter), then inpainting
// (skin/TransferInpaint.h) or the smoothing steps. Target vertices are done in
// one parallel loop (oneTBB), progress and cancel between chunks.
#include "skin/TransferInpaint.h"
#include "skin/TransferQuery.h"

#include <glm/trigonometric.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace rs::skin {

using namespace detail;

namespace {

// The inpainting match distance: the option, or 5% of the target's bounding box diagonal (the paper's).
double inpaintDistance(const TransferOptions& options, const model::Mesh& target)
{
    if (options.inpaintDistance > 0.0)
        return options.inpaintDistance;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : target.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return target.positions.empty() ? 0.0 : 0.05 * double(glm::length(hi - lo));
}

} // namespace

Result<model::MeshWeights> transferWeights(const TransferSource& source, const model::Mesh& target, const TransferOptions& options,
                                           MeshImportReport* report)
{
    using Out = Result<model::MeshWeights>;
    const Status valid = validateTransferOptions(options);
    if (valid.failed())
        return Out::failure(valid.diagnostics());
    if (!source.m_data)
        return Out::failure(makeError({}, "mesh '" + target.name + "': no source to transfer weights from"));
    const auto start = std::chrono::steady_clock::now();
    const Data& d = *source.m_data;
    const std::size_t n = target.vertexCount();
    Slots slots;
    slots.capacity = std::clamp(options.maxInfluences > 0 ? options.maxInfluences : d.maxInfluences, 1, 16);
    slots.slot.resize(n * std::size_t(slots.capacity));
    slots.count.assign(n, 0);
    std::uint32_t fallbackJoint = 0; // a vertex nothing weighs goes to the first root
    for (std::size_t j = 0; j < d.weights.parents.size(); ++j)
        if (d.weights.parents[j] < 0) {
            fallbackJoint = std::uint32_t(j);
            break;
        }
    // Inpainting copies by closest point (no filter: its own test is below).
    const bool inpainting = options.method == TransferMethod::Inpainting;
    TransferOptions queryOptions = options;
    if (inpainting)
        queryOptions.normalFilter = false;
    const bool needNormals = options.normalFilter || inpainting;
    const std::vector<glm::vec3> normals = needNormals && target.normals.size() != n ? vertexNormals(target) : std::vector<glm::vec3>();
    const std::vector<glm::vec3>& targetNormals = target.normals.size() == n ? target.normals : normals;
    std::vector<float> nearest(n, 0.0f);
    std::vector<std::uint8_t> route(n, kClosestPoint), matched(inpainting ? n : 0, 0);
    const Query query{d, queryOptions};
    const float matchDistance2 = inpainting ? float(std::pow(inpaintDistance(options, target), 2.0)) : 0.0f;
    const float matchCosine = float(std::cos(glm::radians(double(options.inpaintAngleDegrees))));
    // Inpainting: the closest points are about a fifth of the work (BM_TransferInpainting), the solve the rest.
    const double queryShare = inpainting ? 0.2 : 1.0;
    // One parallel loop over every target vertex in chunks of kChunk (no
    // barrier between slices: on a shared machine every barrier waits for
    // the slowest thread); the calling thread reports progress between its
    // chunks, every 2%, and a cancel stops the chunks not yet started.
    constexpr std::size_t kChunk = 1024;
    const std::size_t step = std::max<std::size_t>(kChunk, n / 50);
    const auto caller = std::this_thread::get_id();
    std::atomic<std::size_t> done{0};
    std::atomic<bool> cancelled{false};
    std::size_t nextReport = step; // the calling thread's
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, kChunk),
        [&](const tbb::blocked_range<std::size_t>& range) {
            if (cancelled.load(std::memory_order_relaxed))
                return;
            Mix mix;
            for (std::size_t v = range.begin(); v != range.end(); ++v) {
                mix.size = 0;
                const glm::vec3 normal = needNormals ? glm::normalize(targetNormals[v]) : glm::vec3(0.0f);
                Hit hit;
                route[v] = query.transfer(target.positions[v], normal, mix, nearest[v], inpainting ? &hit : nullptr);
                slots.store(v, mix, fallbackJoint);
                if (inpainting) // near, and facing the target's way
                    matched[v] = hit.distance2 <= matchDistance2 && glm::dot(hit.normal, normal) >= matchCosine;
            }
            const std::size_t total = done.fetch_add(range.size(), std::memory_order_relaxed) + range.size();
            if (options.progress && std::this_thread::get_id() == caller && total >= nextReport && total < n) {
                nextReport = total + step;
                if (!options.progress(queryShare * double(total) / double(n)))
                    cancelled = true;
            }
        },
        tbb::simple_partitioner());
    if (cancelled || (options.progress && !options.progress(queryShare)))
        return Out::failure(makeError({}, "mesh '" + target.name + "': the transfer was cancelled"));
    Diagnostics notes;
    std::size_t inpainted = 0;
    std::vector<std::uint32_t> inpaintedIds;
    if (inpainting) {
        bool cancelled = false;
        std::function<bool(double)> progress;
        if (options.progress)
            progress = [&](double f) { return !(cancelled = !options.progress(queryShare + (1.0 - queryShare) * f)); };
        auto solved = inpaintWeights(target, matched, slots.capacity, slots.slot, slots.count, progress, report ? &inpaintedIds : nullptr);
        if (cancelled)
            return Out::failure(solved.takeDiagnostics());
        if (solved)
            inpainted = *solved;
        else {
            inpaintedIds.clear();
            for (Diagnostic diagnostic : solved.diagnostics()) {
                diagnostic.severity = Severity::Warning;
                diagnostic.message += "; its vertices keep the closest point's weights";
                notes.push_back(std::move(diagnostic));
            }
        }
    }
    std::size_t smoothed = 0;
    if (options.smoothSteps > 0 && n > d.positions.size())
        smoothed = smooth(target, nearest, options, slots, fallbackJoint);

    // The slots become the influences, compacted in place (each vertex's move left).
    model::MeshWeights out;
    out.joints = d.weights.joints;
    out.parents = d.weights.parents;
    out.offsets.resize(n + 1);
    out.offsets[0] = 0;
    std::size_t used = 0;
    for (std::size_t v = 0; v < n; ++v) {
        for (int k = 0; k < slots.count[v]; ++k)
            slots.slot[used++] = slots.slot[v * std::size_t(slots.capacity) + std::size_t(k)];
        out.offsets[v + 1] = std::uint32_t(used);
    }
    slots.slot.resize(used);
    out.influences = std::move(slots.slot);
    if (report) {
        report->vertices = n;
        report->closestPoint += std::size_t(std::count(route.begin(), route.end(), kClosestPoint)) +
                                std::size_t(std::count(route.begin(), route.end(), kFilterFallback));
        report->closestNeighbours += std::size_t(std::count(route.begin(), route.end(), kNeighbours));
        report->normalFilterFallbacks += std::size_t(std::count(route.begin(), route.end(), kFilterFallback));
        report->smoothed += smoothed;
        report->inpainted += inpainted;
        report->inpaintedVertices.insert(report->inpaintedVertices.end(), inpaintedIds.begin(), inpaintedIds.end());
        report->closestPoint -= std::min(report->closestPoint, inpainted);
        report->milliseconds += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
    return Out(std::move(out), std::move(notes));
}

} // namespace rs::skin

