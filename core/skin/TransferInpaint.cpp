// Weight inpainting (skin/TransferInpaint.h) with Eigen's sparse LDL'.
#include "skin/TransferInpaint.h"

#include "skin/Surface.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>

namespace rs::skin {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

// L + L M^-1 L over the welded surface (L positive semi-definite).
Sparse energy(const Surface& s)
{
    const auto n = Eigen::Index(s.positions.size());
    std::vector<Eigen::Triplet<double>> entries;
    for (const Surface::Edge& e : s.edges) {
        entries.emplace_back(e.a, e.b, -e.weight);
        entries.emplace_back(e.b, e.a, -e.weight);
        entries.emplace_back(e.a, e.a, e.weight);
        entries.emplace_back(e.b, e.b, e.weight);
    }
    Sparse laplacian(n, n);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    const double meanArea = std::accumulate(s.area.begin(), s.area.end(), 0.0) / double(std::max<std::size_t>(s.area.size(), 1));
    Eigen::VectorXd inverseArea(n);
    for (Eigen::Index v = 0; v < n; ++v)
        inverseArea[v] = 1.0 / std::max(s.area[std::size_t(v)], 1e-8 * meanArea + 1e-300);
    return laplacian + Sparse(laplacian * inverseArea.asDiagonal() * laplacian);
}

} // namespace

Result<std::size_t> inpaintWeights(const model::Mesh& target, const std::vector<std::uint8_t>& matched, int capacity,
                                   std::vector<model::Influence>& slots, std::vector<std::uint8_t>& counts)
{
    const Surface s = makeSurface(target);
    const std::size_t n = s.positions.size();
    // A surface vertex is known when a file vertex of it matched (its weights
    // then come from that one); a part without one keeps what it has.
    std::vector<std::int64_t> from(n, -1), any(n, -1);
    for (std::size_t v = 0; v < target.vertexCount(); ++v) {
        const std::uint32_t w = s.welded[v];
        if (any[w] < 0)
            any[w] = std::int64_t(v);
        if (matched[v] && from[w] < 0)
            from[w] = std::int64_t(v);
    }
    std::vector<std::uint8_t> partKnown(s.partCount, 0), onEdge(n, 0);
    for (std::size_t w = 0; w < n; ++w)
        if (from[w] >= 0)
            partKnown[s.part[w]] = 1;
    for (const Surface::Edge& e : s.edges)
        onEdge[e.a] = onEdge[e.b] = 1;
    std::vector<std::int64_t> unknown(n, -1), known(n, -1);
    std::size_t unknowns = 0, knowns = 0;
    for (std::size_t w = 0; w < n; ++w) {
        const bool solve = from[w] < 0 && partKnown[s.part[w]] && onEdge[w];
        if (solve)
            unknown[w] = std::int64_t(unknowns++);
        else
            known[w] = std::int64_t(knowns++);
        if (from[w] < 0)
            from[w] = any[w];
    }
    if (unknowns == 0)
        return std::size_t(0);
    // The joints the known vertices use: one right-hand side each.
    std::map<std::uint32_t, Eigen::Index> column;
    for (std::size_t w = 0; w < n; ++w)
        if (known[w] >= 0 && from[w] >= 0)
            for (int k = 0; k < counts[std::size_t(from[w])]; ++k)
                column.try_emplace(slots[std::size_t(from[w]) * std::size_t(capacity) + std::size_t(k)].joint, Eigen::Index(column.size()));
    Eigen::MatrixXd fixed = Eigen::MatrixXd::Zero(Eigen::Index(knowns), Eigen::Index(column.size()));
    for (std::size_t w = 0; w < n; ++w)
        if (known[w] >= 0 && from[w] >= 0)
            for (int k = 0; k < counts[std::size_t(from[w])]; ++k) {
                const model::Influence& i = slots[std::size_t(from[w]) * std::size_t(capacity) + std::size_t(k)];
                fixed(known[w], column[i.joint]) = i.weight;
            }
    const Sparse q = energy(s);
    std::vector<Eigen::Triplet<double>> uu, uk;
    for (Eigen::Index c = 0; c < q.outerSize(); ++c)
        for (Sparse::InnerIterator it(q, c); it; ++it) {
            const std::int64_t row = unknown[std::size_t(it.row())];
            if (row < 0)
                continue;
            if (unknown[std::size_t(it.col())] >= 0)
                uu.emplace_back(row, unknown[std::size_t(it.col())], it.value());
            else
                uk.emplace_back(row, known[std::size_t(it.col())], it.value());
        }
    const auto u = static_cast<Eigen::Index>(unknowns), k = static_cast<Eigen::Index>(knowns);
    Sparse quu(u, u), quk(u, k);
    quu.setFromTriplets(uu.begin(), uu.end());
    quk.setFromTriplets(uk.begin(), uk.end());
    Eigen::SimplicialLDLT<Sparse> solver(quu);
    if (solver.info() != Eigen::Success)
        return Result<std::size_t>::failure(makeError({}, "mesh '" + target.name + "': the inpainting system could not be factorised"));
    const Eigen::MatrixXd rhs = -(quk * fixed);
    // The joints in groups of eight, solved in parallel against the one factor
    // (solve() only reads it).
    Eigen::MatrixXd solved(rhs.rows(), rhs.cols());
    const Eigen::Index groups = (rhs.cols() + 7) / 8;
    tbb::parallel_for(Eigen::Index(0), groups, [&](Eigen::Index g) {
        const Eigen::Index first = g * 8, count = std::min<Eigen::Index>(8, rhs.cols() - first);
        solved.middleCols(first, count) = solver.solve(rhs.middleCols(first, count));
    });
    if (!solved.allFinite())
        return Result<std::size_t>::failure(makeError({}, "mesh '" + target.name + "': the inpainting system could not be solved"));

    // Each inpainted surface vertex: its largest `capacity` positive weights, normalised.
    std::vector<std::pair<float, std::uint32_t>> row;
    std::vector<std::vector<model::Influence>> result(unknowns);
    for (std::size_t w = 0; w < n; ++w) {
        if (unknown[w] < 0)
            continue;
        row.clear();
        for (const auto& [joint, c] : column)
            if (const double x = solved(unknown[w], c); x > 1e-6)
                row.emplace_back(float(std::min(x, 1.0)), joint);
        std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
        row.resize(std::min(row.size(), std::size_t(capacity)));
        float sum = 0.0f;
        for (const auto& r : row)
            sum += r.first;
        if (!(sum > 0.0f))
            continue; // nothing reached it: it keeps its copied weights
        for (const auto& r : row)
            result[std::size_t(unknown[w])].push_back({r.second, r.first / sum});
    }
    std::size_t inpainted = 0;
    for (std::size_t v = 0; v < target.vertexCount(); ++v) {
        const std::int64_t u = unknown[s.welded[v]];
        if (u < 0 || result[std::size_t(u)].empty())
            continue;
        const auto& weights = result[std::size_t(u)];
        std::copy(weights.begin(), weights.end(), slots.begin() + std::ptrdiff_t(v * std::size_t(capacity)));
        counts[v] = std::uint8_t(weights.size());
        ++inpainted;
    }
    return inpainted;
}

} // namespace rs::skin
