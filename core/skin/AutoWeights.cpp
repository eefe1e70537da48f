#include "skin/AutoWeights.h"

#include "skin/Surface.h"
#include "skin/Visibility.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>

namespace rs::skin {

const char* bindMethodName(BindMethod method)
{
    switch (method) {
    case BindMethod::Heat: return "heat";
    case BindMethod::Envelope: return "envelope";
    case BindMethod::Closest: return "closest";
    }
    return "heat";
}

std::optional<BindMethod> parseBindMethod(const std::string& text)
{
    for (BindMethod m : {BindMethod::Heat, BindMethod::Envelope, BindMethod::Closest})
        if (text == bindMethodName(m))
            return m;
    return std::nullopt;
}

namespace {

constexpr std::uint32_t kNone = std::uint32_t(-1);
constexpr int kVisibilityTries = 8; // nearest bones tested for line of sight per vertex

// Per surface vertex: bones by distance, the nearest one, the nearest visible one.
struct Nearest {
    std::uint32_t closest = kNone;
    double closestDistance = 0.0;
    std::uint32_t visible = kNone;
    double visibleDistance = 0.0;
};

// Up to `limit` (bone, share) pairs, largest first.
struct TopInfluences {
    std::vector<std::pair<std::uint32_t, double>> items;
    void offer(std::uint32_t bone, double share, std::size_t limit)
    {
        if (!(share > 0.0))
            return;
        if (items.size() == limit && share <= items.back().second)
            return;
        auto at = std::find_if(items.begin(), items.end(), [&](const auto& x) { return share > x.second; });
        items.insert(at, {bone, share});
        if (items.size() > limit)
            items.pop_back();
    }
};

// Right-hand sides side by side: row r holds vertex r's value for each bone.
using RowBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Cholesky = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>;

// Solves A X = B in place for every column of B at once, as Cholesky::solve
// does for one (X = P^-1 L^-T L^-1 P B). Why not solve() per bone: at a
// million vertices the factor is hundreds of megabytes, streamed from memory
// twice per solve; here it is streamed twice per block. Rows left zero by the
// forward pass (far from every bone of the block) are skipped, as Eigen does.
void solveInPlace(const Cholesky& cholesky, RowBlock& x)
{
    const Eigen::SparseMatrix<double>& factor = cholesky.matrixL().nestedExpression();
    const auto& to = cholesky.permutationP().indices();
    RowBlock y(x.rows(), x.cols());
    for (Eigen::Index r = 0; r < x.rows(); ++r)
        y.row(to[r]) = x.row(r);
    // L y' = y: column by column (the diagonal entry comes first).
    for (Eigen::Index c = 0; c < factor.outerSize(); ++c) {
        Eigen::SparseMatrix<double>::InnerIterator it(factor, c);
        if (y.row(c).isZero(0.0))
            continue;
        y.row(c) /= it.value();
        for (++it; it; ++it)
            y.row(it.index()) -= it.value() * y.row(c);
    }
    // L^T x = y': the same columns, last first.
    for (Eigen::Index c = factor.outerSize() - 1; c >= 0; --c) {
        Eigen::SparseMatrix<double>::InnerIterator it(factor, c);
        const double diagonal = it.value();
        for (++it; it; ++it)
            y.row(c) -= it.value() * y.row(it.index());
        y.row(c) /= diagonal;
    }
    for (Eigen::Index r = 0; r < x.rows(); ++r)
        x.row(r) = y.row(to[r]);
}

double distanceTo(const SkinBone& bone, const Vec3& p) { return glm::length(p - nearestPointOn(bone, p)); }

} // namespace

Result<model::MeshWeights> bindMesh(const model::Mesh& mesh, const std::vector<SkinBone>& bones, const BindOptions& options,
                                    BindStats* statsOut)
{
    using Out = Result<model::MeshWeights>;
    if (bones.empty())
        return Out::failure(makeError({}, "the rig has no skin joint to bind to"));
    if (options.maxInfluences < 1 || options.maxInfluences > 8)
        return Out::failure(makeError({}, "--max-influences must be 1 to 8, not " + std::to_string(options.maxInfluences)));
    if (!(options.pruneBelow >= 0.0 && options.pruneBelow < 1.0))
        return Out::failure(makeError({}, "the prune threshold must be in [0, 1)"));
    auto progress = [&](double fraction) { return !options.progress || options.progress(fraction); };
    auto cancelled = [] { return Out::failure(makeError({}, "the bind was cancelled; the weights are unchanged")); };

    Diagnostics notes;
    auto addNote = [&](std::string message) {
        Diagnostic d = makeWarning({}, std::move(message));
        d.severity = Severity::Note;
        notes.push_back(std::move(d));
    };
    BindStats stats;
    stats.vertices = mesh.vertexCount();
    const Surface surface = makeSurface(mesh);
    const std::size_t n = surface.positions.size();
    stats.surfaceVertices = n;
    stats.parts = surface.partCount;
    if (!progress(0.05))
        return cancelled();

    // Nearest bone and nearest visible bone of every surface vertex.
    std::vector<Nearest> nearest(n);
    // Each bone's bounding sphere (centre, radius), to skip far bones quickly.
    std::vector<std::pair<Vec3, double>> spheres;
    for (const SkinBone& bone : bones) {
        Vec3 lo = bone.head, hi = bone.head;
        for (const Vec3& tail : bone.tails) {
            lo = glm::min(lo, tail);
            hi = glm::max(hi, tail);
        }
        const Vec3 centre = 0.5 * (lo + hi);
        double radius = glm::length(bone.head - centre);
        for (const Vec3& tail : bone.tails)
            radius = std::max(radius, glm::length(tail - centre));
        spheres.emplace_back(centre, radius);
    }
    const bool heat = options.method == BindMethod::Heat;
    std::unique_ptr<Visibility> visibility = heat ? std::make_unique<Visibility>(surface, options.occluders) : nullptr;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<std::pair<double, std::uint32_t>> order; // squared distance, bone
        std::vector<std::pair<double, std::uint32_t>> bounds(bones.size()); // a lower bound of the distance, bone
        const std::size_t tries = std::min<std::size_t>(bones.size(), kVisibilityTries);
        for (std::size_t v = range.begin(); v != range.end(); ++v) {
            const Vec3& p = surface.positions[v];
            // Exact distances only to bones whose bounding sphere could beat the
            // `tries` nearest found so far (bones in order of their lower bound).
            for (std::uint32_t b = 0; b < bones.size(); ++b)
                bounds[b] = {std::max(glm::length(p - spheres[b].first) - spheres[b].second, 0.0), b};
            std::sort(bounds.begin(), bounds.end());
            order.clear();
            double kth = std::numeric_limits<double>::infinity();
            for (const auto& [bound, b] : bounds) {
                if (order.size() >= tries && bound * bound > kth)
                    break;
                const Vec3 d = p - nearestPointOn(bones[b], p);
                order.emplace_back(glm::dot(d, d), b);
                if (order.size() >= tries) {
                    std::nth_element(order.begin(), order.begin() + std::ptrdiff_t(tries - 1), order.end());
                    kth = order[tries - 1].first;
                }
            }
            std::sort(order.begin(), order.end());
            nearest[v].closest = order[0].second;
            nearest[v].closestDistance = std::sqrt(order[0].first);
            if (!visibility || surface.area[v] <= 0.0)
                continue;
            for (std::size_t k = 0; k < tries; ++k)
                if (visibility->clear(p, nearestPointOn(bones[order[k].second], p))) {
                    nearest[v].visible = order[k].second;
                    nearest[v].visibleDistance = std::sqrt(order[k].first);
                    break;
                }
        }
    });
    if (!progress(0.2))
        return cancelled();

    std::vector<TopInfluences> top(n);
    const std::size_t limit = std::size_t(options.maxInfluences);
    std::vector<bool> byClosest(n, false);

    if (options.method == BindMethod::Closest) {
        for (std::size_t v = 0; v < n; ++v)
            top[v].offer(nearest[v].closest, 1.0, limit);
    } else if (options.method == BindMethod::Envelope) {
        tbb::parallel_for(std::size_t(0), n, [&](std::size_t v) {
            for (std::uint32_t b = 0; b < bones.size(); ++b) {
                const double d = std::max(distanceTo(bones[b], surface.positions[v]), 1e-6);
                top[v].offer(b, 1.0 / (d * d), limit);
            }
        });
    } else {
        // Parts no vertex of which sees a bone cannot be heated: closest bone.
        std::vector<bool> reachable(surface.partCount, false);
        for (std::size_t v = 0; v < n; ++v)
            if (nearest[v].visible != kNone)
                reachable[surface.part[v]] = true;
        std::vector<std::size_t> partSize(surface.partCount, 0);
        for (std::size_t v = 0; v < n; ++v)
            ++partSize[surface.part[v]];
        for (std::size_t part = 0; part < surface.partCount; ++part)
            if (!reachable[part]) {
                ++stats.partsByClosestBone;
                if (partSize[part] > 1) // single loose points need no note
                    addNote("mesh '" + mesh.name + "': a part of " + std::to_string(partSize[part]) +
                            " vertices sees no bone (inside another part, or only loose points); it takes its closest bone");
            }

        // The solved vertices, renumbered.
        std::vector<std::uint32_t> row(n, kNone);
        std::vector<std::uint32_t> vertexOf;
        for (std::uint32_t v = 0; v < n; ++v)
            if (reachable[surface.part[v]]) {
                row[v] = std::uint32_t(vertexOf.size());
                vertexOf.push_back(v);
            }
        const auto m = Eigen::Index(vertexOf.size());
        if (m > 0) {
            double meanArea = 0.0;
            for (std::uint32_t v : vertexOf)
                meanArea += surface.area[v];
            meanArea = std::max(meanArea / double(m), 1e-30);
            double extent = 0.0;
            for (const Vec3& p : surface.positions)
                extent = std::max(extent, glm::length(p - surface.positions.front()));
            const double minDistance = std::max(1e-4 * extent, 1e-9);
            std::vector<Eigen::Triplet<double>> entries;
            entries.reserve(std::size_t(m) + 4 * surface.edges.size());
            std::vector<double> diagonal(std::size_t(m), 0.0), heatIn(std::size_t(m), 0.0);
            for (const Surface::Edge& e : surface.edges) {
                if (row[e.a] == kNone || e.weight <= 0.0)
                    continue;
                entries.emplace_back(Eigen::Index(row[e.a]), Eigen::Index(row[e.b]), -e.weight);
                entries.emplace_back(Eigen::Index(row[e.b]), Eigen::Index(row[e.a]), -e.weight);
                diagonal[row[e.a]] += e.weight;
                diagonal[row[e.b]] += e.weight;
            }
            for (Eigen::Index r = 0; r < m; ++r) {
                const std::uint32_t v = vertexOf[std::size_t(r)];
                const double area = std::max(surface.area[v], 1e-6 * meanArea);
                if (nearest[v].visible != kNone) {
                    const double d = std::max(nearest[v].visibleDistance, minDistance);
                    heatIn[std::size_t(r)] = area / (d * d);
                }
                // A tiny leak keeps the system definite where edges are missing.
                entries.emplace_back(r, r, diagonal[std::size_t(r)] + heatIn[std::size_t(r)] + 1e-9 * area / (extent * extent + 1e-30));
            }
            Eigen::SparseMatrix<double> system(m, m);
            system.setFromTriplets(entries.begin(), entries.end());
            if (!progress(0.3))
                return cancelled();

            // Bones that heat some vertex; the others stay at zero everywhere.
            std::vector<std::uint32_t> heated;
            {
                std::vector<bool> used(bones.size(), false);
                for (std::uint32_t v : vertexOf)
                    if (nearest[v].visible != kNone)
                        used[nearest[v].visible] = true;
                for (std::uint32_t b = 0; b < bones.size(); ++b)
                    if (used[b])
                        heated.push_back(b);
            }
            stats.bonesSolved = heated.size();

            Cholesky cholesky(system);
            const bool factored = cholesky.info() == Eigen::Success;
            std::unique_ptr<Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper>> iterative;
            if (!factored) {
                addNote("mesh '" + mesh.name + "': the direct solver failed; solving iteratively");
                iterative = std::make_unique<Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper>>(system);
                iterative->setTolerance(1e-8);
            }
            if (!progress(0.45))
                return cancelled();

            // Bones in blocks of 16, each block in two groups solved in
            // parallel, merged into each vertex's top influences in order.
            const std::size_t block = 16;
            std::atomic<bool> stop{false};
            for (std::size_t first = 0; first < heated.size() && !stop; first += block) {
                const std::size_t count = std::min(block, heated.size() - first);
                const std::size_t groups = std::min<std::size_t>(count, 2);
                std::vector<RowBlock> solutions(groups);
                tbb::parallel_for(std::size_t(0), groups, [&](std::size_t g) {
                    const std::size_t begin = first + count * g / groups, end = first + count * (g + 1) / groups;
                    RowBlock& x = solutions[g];
                    x.setZero(m, Eigen::Index(end - begin));
                    for (Eigen::Index r = 0; r < m; ++r) {
                        const std::uint32_t visible = nearest[vertexOf[std::size_t(r)]].visible;
                        for (std::size_t k = begin; k < end; ++k)
                            if (visible == heated[k])
                                x(r, Eigen::Index(k - begin)) = heatIn[std::size_t(r)];
                    }
                    if (factored)
                        solveInPlace(cholesky, x);
                    else
                        for (Eigen::Index k = 0; k < x.cols(); ++k)
                            x.col(k) = iterative->solve(Eigen::VectorXd(x.col(k)));
                });
                for (std::size_t g = 0; g < groups; ++g) {
                    const std::size_t begin = first + count * g / groups;
                    for (Eigen::Index k = 0; k < solutions[g].cols(); ++k)
                        for (Eigen::Index r = 0; r < m; ++r)
                            if (solutions[g](r, k) > 1e-6) // far below any share that survives pruning
                                top[vertexOf[std::size_t(r)]].offer(heated[begin + std::size_t(k)], std::min(solutions[g](r, k), 1.0), limit);
                }
                if (!progress(0.45 + 0.5 * double(first + count) / double(heated.size())))
                    stop = true;
            }
            if (stop)
                return cancelled();
        }
        for (std::size_t v = 0; v < n; ++v)
            if (!reachable[surface.part[v]])
                byClosest[v] = true;
    }

    // Per file vertex: its surface vertex's influences, pruned and normalised;
    // a vertex the heat left (nearly) cold takes its nearest visible, else closest, bone.
    model::MeshWeights weights;
    for (const SkinBone& bone : bones) {
        weights.joints.push_back(bone.key);
        weights.parents.push_back(bone.parent);
    }
    std::vector<std::vector<std::pair<std::uint32_t, double>>> perSurface(n);
    for (std::size_t v = 0; v < n; ++v) {
        auto& items = top[v].items;
        double sum = 0.0;
        for (const auto& item : items)
            sum += item.second;
        if (!(sum > 1e-12) || byClosest[v]) {
            const std::uint32_t bone = !byClosest[v] && nearest[v].visible != kNone ? nearest[v].visible : nearest[v].closest;
            items = {{bone, 1.0}};
            ++stats.verticesByClosestBone;
            continue;
        }
        for (auto& item : items)
            item.second /= sum;
        const double keep = items.front().second;
        std::erase_if(items, [&](const auto& item) { return item.second < options.pruneBelow && item.second < keep; });
        sum = 0.0;
        for (const auto& item : items)
            sum += item.second;
        for (auto& item : items)
            item.second /= sum;
    }
    weights.offsets.reserve(mesh.vertexCount() + 1);
    weights.offsets.push_back(0);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        for (const auto& [bone, share] : top[surface.welded[v]].items)
            weights.influences.push_back({bone, float(share)});
        weights.offsets.push_back(std::uint32_t(weights.influences.size()));
    }
    if (statsOut)
        *statsOut = stats;
    progress(1.0);
    return Out(std::move(weights), std::move(notes));
}

} // namespace rs::skin
