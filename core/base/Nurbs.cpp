#include "base/Nurbs.h"

namespace rs {

namespace {

// de Boor's algorithm for one parameter value; `span` is the knot span index.
Vec3 deBoor(int degree, const std::vector<double>& knots, const std::vector<Vec3>& cvs, int span, double t)
{
    std::vector<Vec3> d(cvs.begin() + (span - degree), cvs.begin() + span + 1);
    for (int r = 1; r <= degree; ++r)
        for (int j = degree; j >= r; --j) {
            const int i = span - degree + j;
            const double denom = knots[i + degree - r + 1] - knots[i];
            const double alpha = denom == 0.0 ? 0.0 : (t - knots[i]) / denom;
            d[j] = (1.0 - alpha) * d[j - 1] + alpha * d[j];
        }
    return d[degree];
}

} // namespace

std::vector<Vec3> evaluateNurbs(const std::vector<Vec3>& points, int degree, bool periodic, int samplesPerSpan)
{
    const int p = degree;
    std::vector<Vec3> cvs = points;
    if (p <= 1 || int(points.size()) <= p) {
        if (periodic && !cvs.empty())
            cvs.push_back(cvs.front());
        return cvs;
    }
    std::vector<double> knots;
    if (periodic) {
        for (int i = 0; i < p; ++i)
            cvs.push_back(points[i]);
        for (int i = 0; i < int(cvs.size()) + p + 1; ++i)
            knots.push_back(i);
    } else {
        const int n = int(cvs.size());
        for (int i = 0; i <= p; ++i) knots.push_back(0.0);
        for (int i = 1; i < n - p; ++i) knots.push_back(i);
        for (int i = 0; i <= p; ++i) knots.push_back(n - p);
    }
    const int n = int(cvs.size());
    std::vector<Vec3> out;
    for (int span = p; span < n; ++span) {
        const double t0 = knots[span], t1 = knots[span + 1];
        if (t1 <= t0)
            continue;
        for (int s = 0; s < samplesPerSpan; ++s)
            out.push_back(deBoor(p, knots, cvs, span, t0 + (t1 - t0) * s / samplesPerSpan));
    }
    out.push_back(periodic ? out.front() : deBoor(p, knots, cvs, n - 1, knots[n]));
    return out;
}

} // namespace rs
