#pragma once
// Driven keys (model::DrivenKeyConstraint): a keyed curve from one channel of
// the pose to another, computed before any node is placed. Internal to eval
// and its tests: RigProgram compiles and runs them.
#include "base/Diagnostic.h"
#include "model/Constraint.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rs::eval {

// The slopes at each key of a smooth curve: monotone cubic (Fritsch-Carlson),
// so the curve never overshoots a key. Keys sorted by `in`, strictly increasing.
std::vector<double> smoothTangents(const std::vector<model::CurveKey>& keys);
// The curve's value at `x`: linear between keys, or cubic Hermite with
// `tangents` (one per key; empty: linear). Before the first key `pre`, after the
// last `post` (model::CurveInfinity); one key is a constant.
double evaluateCurve(const std::vector<model::CurveKey>& keys, const std::vector<double>& tangents, model::CurveInfinity pre,
                     model::CurveInfinity post, double x);
// Why the keys cannot make a curve ("needs at least one key", "its keys must
// be sorted by driver value, each once"), or empty.
std::string checkCurveKeys(const std::vector<model::CurveKey>& keys);

// One compiled driven key: channel indices into the pose.
struct ChannelDrive {
    int driver = -1;
    int driven = -1;
};
// The order to compute `drives` in (indices into it): a drive whose driven
// channel is another's driver comes first; otherwise document order. Empty,
// with `loop` set to the index of a drive in the loop, when they form one.
std::vector<std::uint32_t> orderChannelDrives(const std::vector<ChannelDrive>& drives, int& loop);

} // namespace rs::eval
