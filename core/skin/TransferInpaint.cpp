// Weight inpainting (skin/TransferInpaint.h): the unknowns split into the
// connected regions of the squared Laplacian, each region a system of its own
// solved for the joints around it, with CHOLMOD (through Eigen).
//
// Why this shape (BM_TransferInpainting, README figures): Eigen's simplicial
// LDL' spent ~60% of the time factorising one 95k-unknown system and ~25% in
// the 80 joint solves, streaming the factor once per joint group. CHOLMOD's
// supernodal factorisation and multi-column solve run as dense BLAS blocks
// (OpenBLAS, one thread: oneTBB owns the cores): 4 to 8 times faster on the
// same matrix, to the same residual. Regions are independent (no entry of Q joins two of them), so a
// joint no known vertex next to a region carries is exactly zero there and is
// never solved for; a region next to one joint only is exactly that joint.
#include "skin/TransferInpaint.h"

#include "skin/Surface.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <numeric>

namespace rs::skin {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

constexpr Eigen::Index kSolveColumns = 16;     // joints per solve: a cancel point, and wide enough for BLAS 3
constexpr std::size_t kSmallRegion = 4096;     // regions below this solve side by side; larger ones one by one, with progress inside
constexpr std::size_t kSmallBatch = 256;       // small regions between two progress reports

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

// Which surface vertices are solved for, and which file vertex gives each
// surface vertex its weights (the matched one, else any).
struct Split {
    std::vector<std::int64_t> from;     // per surface vertex: a file vertex, -1 when none
    std::vector<std::int64_t> unknown;  // per surface vertex: its unknown index, -1 when known
    std::size_t unknowns = 0;
};

Split split(const Surface& s, const model::Mesh& target, const std::vector<std::uint8_t>& matched)
{
    const std::size_t n = s.positions.size();
    Split out;
    std::vector<std::int64_t> any(n, -1);
    out.from.assign(n, -1);
    for (std::size_t v = 0; v < target.vertexCount(); ++v) {
        const std::uint32_t w = s.welded[v];
        if (any[w] < 0)
            any[w] = std::int64_t(v);
        if (matched[v] && out.from[w] < 0)
            out.from[w] = std::int64_t(v);
    }
    // A part without a known vertex keeps what it has (nothing to inpaint from);
    // a vertex on no edge has no energy to minimise.
    std::vector<std::uint8_t> partKnown(s.partCount, 0), onEdge(n, 0);
    for (std::size_t w = 0; w < n; ++w)
        if (out.from[w] >= 0)
            partKnown[s.part[w]] = 1;
    for (const Surface::Edge& e : s.edges)
        onEdge[e.a] = onEdge[e.b] = 1;
    out.unknown.assign(n, -1);
    for (std::size_t w = 0; w < n; ++w) {
        if (out.from[w] < 0 && partKnown[s.part[w]] && onEdge[w])
            out.unknown[w] = std::int64_t(out.unknowns++);
        if (out.from[w] < 0)
            out.from[w] = any[w];
    }
    return out;
}

// Q's columns of the unknowns: rows among the unknowns (Quu) and among the
// known surface vertices (by surface index, for the right-hand sides).
struct Blocks {
    Sparse quu, qku;
};

Blocks blocks(const Sparse& q, const Split& split)
{
    // Columns in order and each column's rows ascending (the unknown numbering
    // keeps the surface's order): both blocks fill by appending.
    const auto u = Eigen::Index(split.unknowns);
    Blocks out{Sparse(u, u), Sparse(q.rows(), u)};
    out.quu.reserve(q.nonZeros());
    out.qku.reserve(q.nonZeros() / 4);
    for (Eigen::Index c = 0; c < q.outerSize(); ++c) {
        const std::int64_t col = split.unknown[std::size_t(c)];
        if (col < 0)
            continue;
        out.quu.startVec(col);
        out.qku.startVec(col);
        for (Sparse::InnerIterator it(q, c); it; ++it)
            if (const std::int64_t row = split.unknown[std::size_t(it.row())]; row >= 0)
                out.quu.insertBack(row, col) = it.value();
            else
                out.qku.insertBack(it.row(), col) = it.value();
    }
    out.quu.finalize();
    out.qku.finalize();
    return out;
}

// The connected regions of Quu's graph, each a list of unknowns (ascending),
// largest first; `local`: each unknown's place in its region's list.
std::vector<std::vector<std::uint32_t>> regions(const Sparse& quu, std::vector<std::uint32_t>& local)
{
    const auto u = std::size_t(quu.cols());
    std::vector<std::int64_t> region(u, -1);
    std::vector<std::vector<std::uint32_t>> out;
    std::vector<std::uint32_t> stack;
    for (std::size_t seed = 0; seed < u; ++seed) {
        if (region[seed] >= 0)
            continue;
        out.emplace_back();
        region[seed] = std::int64_t(out.size() - 1);
        stack.assign(1, std::uint32_t(seed));
        while (!stack.empty()) {
            const std::uint32_t v = stack.back();
            stack.pop_back();
            out.back().push_back(v);
            for (Sparse::InnerIterator it(quu, v); it; ++it)
                if (region[std::size_t(it.row())] < 0) {
                    region[std::size_t(it.row())] = region[seed];
                    stack.push_back(std::uint32_t(it.row()));
                }
        }
        std::sort(out.back().begin(), out.back().end());
    }
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    local.assign(u, 0);
    for (const auto& members : out)
        for (std::size_t i = 0; i < members.size(); ++i)
            local[members[i]] = std::uint32_t(i);
    return out;
}

// Everything a region's solve reads; results are written per unknown.
struct Problem {
    const Blocks& q;
    const Split& split;
    const std::vector<std::uint32_t>& local; // see regions()
    int capacity;
    const std::vector<model::Influence>& slots;
    const std::vector<std::uint8_t>& counts;
    std::vector<model::Influence>& result;   // `capacity` per unknown
    std::vector<std::uint8_t>& resultCounts; // per unknown; 0: keeps its copied weights
};

// The largest `capacity` positive weights of one solved row, normalised, into
// `out`; none when nothing reached it (it keeps its copied weights).
std::uint8_t strongest(const Eigen::MatrixXd& x, Eigen::Index row, const std::vector<std::uint32_t>& joints, int capacity,
                       model::Influence* out)
{
    int kept = 0;
    for (std::size_t c = 0; c < joints.size(); ++c) {
        const double w = x(row, Eigen::Index(c));
        if (!(w > 1e-6))
            continue;
        // Kept heaviest first; on a tie the lower joint (met first) stays ahead.
        const float weight = float(std::min(w, 1.0));
        if (kept == capacity && !(weight > out[capacity - 1].weight))
            continue;
        int at = kept < capacity ? kept++ : capacity - 1;
        for (; at > 0 && out[at - 1].weight < weight; --at)
            out[at] = out[at - 1];
        out[at] = {joints[c], weight};
    }
    float sum = 0.0f;
    for (int k = 0; k < kept; ++k)
        sum += out[k].weight;
    if (!(sum > 0.0f))
        return 0;
    for (int k = 0; k < kept; ++k)
        out[k].weight /= sum;
    return std::uint8_t(kept);
}

// A region's right-hand sides -Qku' Wk, one column per joint the known
// vertices next to it carry (`joints`, ascending).
Eigen::MatrixXd rightHandSides(const Problem& p, const std::vector<std::uint32_t>& members, std::vector<std::uint32_t>& joints)
{
    auto influences = [&](Eigen::Index surfaceVertex) {
        const auto v = std::size_t(p.split.from[std::size_t(surfaceVertex)]);
        const model::Influence* first = p.slots.data() + v * std::size_t(p.capacity);
        return std::pair(first, first + p.counts[v]);
    };
    joints.clear();
    for (const std::uint32_t u : members)
        for (Sparse::InnerIterator it(p.q.qku, u); it; ++it)
            if (p.split.from[std::size_t(it.row())] >= 0)
                for (auto [i, end] = influences(it.row()); i != end; ++i)
                    joints.push_back(i->joint);
    std::sort(joints.begin(), joints.end());
    joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(Eigen::Index(members.size()), Eigen::Index(joints.size()));
    for (std::size_t r = 0; r < members.size(); ++r)
        for (Sparse::InnerIterator it(p.q.qku, members[r]); it; ++it)
            if (p.split.from[std::size_t(it.row())] >= 0)
                for (auto [i, end] = influences(it.row()); i != end; ++i) {
                    const auto c = std::lower_bound(joints.begin(), joints.end(), i->joint) - joints.begin();
                    rhs(Eigen::Index(r), c) -= it.value() * double(i->weight);
                }
    return rhs;
}

// The lower triangle of Quu restricted to a region (its members ascending,
// so each column's rows stay ascending and it fills by appending).
Sparse regionMatrix(const Problem& p, const std::vector<std::uint32_t>& members)
{
    const auto m = Eigen::Index(members.size());
    Sparse out(m, m);
    out.reserve(p.q.quu.nonZeros() * m / std::max<Eigen::Index>(p.q.quu.cols(), 1) / 2 + m);
    for (Eigen::Index c = 0; c < m; ++c) {
        out.startVec(c);
        for (Sparse::InnerIterator it(p.q.quu, members[std::size_t(c)]); it; ++it)
            if (const auto r = Eigen::Index(p.local[std::size_t(it.row())]); r >= c)
                out.insertBack(r, c) = it.value();
    }
    out.finalize();
    return out;
}

enum class Solved { Done, Failed, Cancelled };

// One region: factorise, solve kSolveColumns joints at a time (`tick` hears
// the fraction of the region done; false cancels), keep each row's strongest.
Solved solveRegion(const Problem& p, const std::vector<std::uint32_t>& members, const std::function<bool(double)>& tick)
{
    std::vector<std::uint32_t> joints;
    const Eigen::MatrixXd rhs = rightHandSides(p, members, joints);
    Eigen::MatrixXd x = Eigen::MatrixXd::Ones(rhs.rows(), rhs.cols());
    const bool large = members.size() >= kSmallRegion;
    // One joint around: Q's rows sum to zero, so all-ones is the solution.
    if (joints.size() > 1) {
        Eigen::CholmodDecomposition<Sparse, Eigen::Lower> solver;
        solver.cholmod().print = 0; // failures come back as a Result, not on stderr
        solver.compute(regionMatrix(p, members));
        if (solver.info() != Eigen::Success)
            return Solved::Failed;
        if (tick && !tick(0.5))
            return Solved::Cancelled;
        for (Eigen::Index first = 0; first < rhs.cols(); first += kSolveColumns) {
            const Eigen::Index count = std::min(kSolveColumns, rhs.cols() - first);
            x.middleCols(first, count) = solver.solve(Eigen::MatrixXd(rhs.middleCols(first, count)));
            if (tick && !tick(0.5 + 0.5 * double(first + count) / double(rhs.cols())))
                return Solved::Cancelled;
        }
        if (!x.allFinite())
            return Solved::Failed;
    }
    auto keep = [&](std::size_t r) {
        const std::size_t u = members[r];
        p.resultCounts[u] = joints.empty() ? 0 : strongest(x, Eigen::Index(r), joints, p.capacity, &p.result[u * std::size_t(p.capacity)]);
    };
    if (large)
        tbb::parallel_for(std::size_t(0), members.size(), keep);
    else
        for (std::size_t r = 0; r < members.size(); ++r)
            keep(r);
    return Solved::Done;
}

// Every region, the large first; `progress` as inpaintWeights' (from 5%:
// the assembly's share), by unknowns solved, a region's cost growing with its size.
Solved solveRegions(const Problem& p, const std::vector<std::vector<std::uint32_t>>& parts, const std::function<bool(double)>& progress)
{
    std::size_t done = 0;
    auto report = [&](std::size_t extra) { return !progress || progress(0.05 + 0.95 * double(done + extra) / double(p.split.unknowns)); };
    std::size_t next = 0;
    for (; next < parts.size() && parts[next].size() >= kSmallRegion; ++next) {
        const auto size = parts[next].size();
        if (const Solved solved = solveRegion(p, parts[next], [&](double f) { return report(std::size_t(f * double(size))); });
            solved != Solved::Done)
            return solved;
        done += size;
    }
    // The small regions in batches, in parallel; each solve is single-threaded.
    for (; next < parts.size(); next = std::min(parts.size(), next + kSmallBatch)) {
        const std::size_t last = std::min(parts.size(), next + kSmallBatch);
        std::atomic<bool> failed{false};
        tbb::parallel_for(next, last, [&](std::size_t r) {
            if (solveRegion(p, parts[r], {}) != Solved::Done)
                failed = true;
        });
        if (failed)
            return Solved::Failed;
        for (std::size_t r = next; r < last; ++r)
            done += parts[r].size();
        if (!report(0))
            return Solved::Cancelled;
    }
    return Solved::Done;
}

} // namespace

Result<std::size_t> inpaintWeights(const model::Mesh& target, const std::vector<std::uint8_t>& matched, int capacity,
                                   std::vector<model::Influence>& slots, std::vector<std::uint8_t>& counts,
                                   const std::function<bool(double)>& progress, std::vector<std::uint32_t>* inpaintedVertices)
{
    auto stopped = [&](Solved why) {
        return Result<std::size_t>::failure(makeError(
            {}, "mesh '" + target.name + "': " + (why == Solved::Cancelled ? "the inpainting was cancelled" : "the inpainting system could not be solved")));
    };
    const Surface s = makeSurface(target);
    const Split unknowns = split(s, target, matched);
    if (unknowns.unknowns == 0)
        return progress && !progress(1.0) ? stopped(Solved::Cancelled) : Result<std::size_t>(std::size_t(0));
    const Blocks q = blocks(energy(s), unknowns);
    std::vector<std::uint32_t> local;
    const std::vector<std::vector<std::uint32_t>> parts = regions(q.quu, local);
    std::vector<model::Influence> result(unknowns.unknowns * std::size_t(capacity));
    std::vector<std::uint8_t> resultCounts(unknowns.unknowns, 0);
    const Problem problem{q, unknowns, local, capacity, slots, counts, result, resultCounts};
    const bool cancelled = progress && !progress(0.05); // the system is assembled: about 5% of the work
    if (const Solved solved = cancelled ? Solved::Cancelled : solveRegions(problem, parts, progress); solved != Solved::Done)
        return stopped(solved);
    std::size_t inpainted = 0;
    for (std::size_t v = 0; v < target.vertexCount(); ++v) {
        const std::int64_t u = unknowns.unknown[s.welded[v]];
        if (u < 0 || resultCounts[std::size_t(u)] == 0)
            continue;
        const auto first = result.begin() + std::ptrdiff_t(std::size_t(u) * std::size_t(capacity));
        std::copy(first, first + resultCounts[std::size_t(u)], slots.begin() + std::ptrdiff_t(v * std::size_t(capacity)));
        counts[v] = resultCounts[std::size_t(u)];
        ++inpainted;
        if (inpaintedVertices)
            inpaintedVertices->push_back(std::uint32_t(v));
    }
    return inpainted;
}

} // namespace rs::skin
