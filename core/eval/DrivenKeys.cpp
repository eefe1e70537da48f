// Driven keys: the curve (linear or monotone cubic, with pre and post
// infinity) and the order channel drives are computed in.
#include "eval/DrivenKeys.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

namespace rs::eval {

namespace {

// `x` brought into [first, last] by whole periods.
double wrapped(double x, double first, double last)
{
    const double period = last - first;
    if (!(period > 0.0))
        return first;
    const double t = std::fmod(x - first, period);
    return first + (t < 0.0 ? t + period : t);
}

// The slope at an end key: the tangent, else the end segment's.
double endSlope(const std::vector<model::CurveKey>& keys, const std::vector<double>& tangents, bool atStart)
{
    const std::size_t n = keys.size();
    if (!tangents.empty())
        return atStart ? tangents.front() : tangents.back();
    const model::CurveKey& a = keys[atStart ? 0 : n - 2];
    const model::CurveKey& b = keys[atStart ? 1 : n - 1];
    return (b.out - a.out) / (b.in - a.in);
}

} // namespace

std::string checkCurveKeys(const std::vector<model::CurveKey>& keys)
{
    if (keys.empty())
        return "needs at least one key";
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (!std::isfinite(keys[k].in) || !std::isfinite(keys[k].out))
            return "its keys must be finite numbers";
        if (k > 0 && !(keys[k].in > keys[k - 1].in))
            return "its keys must be sorted by driver value, each value once";
    }
    return {};
}

std::vector<double> smoothTangents(const std::vector<model::CurveKey>& keys)
{
    const std::size_t n = keys.size();
    std::vector<double> m(n, 0.0);
    if (n < 2)
        return m;
    std::vector<double> d(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k)
        d[k] = (keys[k + 1].out - keys[k].out) / (keys[k + 1].in - keys[k].in);
    m.front() = d.front();
    m.back() = d.back();
    for (std::size_t k = 1; k + 1 < n; ++k)
        m[k] = d[k - 1] * d[k] > 0.0 ? 0.5 * (d[k - 1] + d[k]) : 0.0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (d[k] == 0.0) {
            m[k] = m[k + 1] = 0.0;
            continue;
        }
        const double a = m[k] / d[k], b = m[k + 1] / d[k];
        const double r = a * a + b * b;
        if (r > 9.0) { // Fritsch-Carlson: keep the segment monotone
            const double tau = 3.0 / std::sqrt(r);
            m[k] = tau * a * d[k];
            m[k + 1] = tau * b * d[k];
        }
    }
    return m;
}

double evaluateCurve(const std::vector<model::CurveKey>& keys, const std::vector<double>& tangents, model::CurveInfinity pre,
                     model::CurveInfinity post, double x)
{
    if (keys.empty())
        return 0.0;
    const model::CurveKey& first = keys.front();
    const model::CurveKey& last = keys.back();
    if (keys.size() == 1)
        return first.out;
    if (x < first.in || x > last.in) {
        const bool before = x < first.in;
        const model::CurveInfinity mode = before ? pre : post;
        const model::CurveKey& end = before ? first : last;
        if (mode == model::CurveInfinity::Constant)
            return end.out;
        if (mode == model::CurveInfinity::Linear)
            return end.out + endSlope(keys, tangents, before) * (x - end.in);
        x = wrapped(x, first.in, last.in);
    }
    const auto upper = std::upper_bound(keys.begin(), keys.end(), x, [](double v, const model::CurveKey& k) { return v < k.in; });
    const std::size_t k1 = std::min<std::size_t>(std::max<std::ptrdiff_t>(upper - keys.begin(), 1), keys.size() - 1);
    const std::size_t k0 = k1 - 1;
    const double h = keys[k1].in - keys[k0].in;
    const double t = (x - keys[k0].in) / h;
    if (tangents.empty())
        return keys[k0].out + (keys[k1].out - keys[k0].out) * t;
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * keys[k0].out + (t3 - 2 * t2 + t) * h * tangents[k0] + (-2 * t3 + 3 * t2) * keys[k1].out +
           (t3 - t2) * h * tangents[k1];
}

std::vector<std::uint32_t> orderChannelDrives(const std::vector<ChannelDrive>& drives, int& loop)
{
    loop = -1;
    const std::size_t n = drives.size();
    std::multimap<int, std::uint32_t> drivenBy; // channel -> drives writing it
    for (std::uint32_t k = 0; k < n; ++k)
        drivenBy.emplace(drives[k].driven, k);
    std::vector<std::vector<std::uint32_t>> after(n);
    std::vector<int> pending(n, 0);
    for (std::uint32_t k = 0; k < n; ++k)
        for (auto [it, end] = drivenBy.equal_range(drives[k].driver); it != end; ++it) {
            after[it->second].push_back(k);
            ++pending[k];
        }
    std::vector<std::uint32_t> order;
    std::deque<std::uint32_t> ready;
    for (std::uint32_t k = 0; k < n; ++k)
        if (pending[k] == 0)
            ready.push_back(k);
    while (!ready.empty()) {
        const std::uint32_t k = ready.front();
        ready.pop_front();
        order.push_back(k);
        for (std::uint32_t next : after[k])
            if (--pending[next] == 0)
                ready.push_back(next);
    }
    if (order.size() != n) {
        for (std::uint32_t k = 0; k < n; ++k)
            if (pending[k] > 0) { loop = int(k); break; }
        return {};
    }
    return order;
}

} // namespace rs::eval
