#include "io/RangeOfMotion.h"

#include "eval/PoseTools.h"
#include "io/JointWatch.h"
#include "io/RigSwitches.h"
#include "io/StretchGauge.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rs::io {

namespace {

constexpr double kHingeDegrees = 90.0;
constexpr double kOtherDegrees = 30.0;
constexpr double kTranslateShare = 0.25;   // of the skeleton's size
constexpr double kMaxStretch = 0.005;      // what a peak may add, relative
constexpr double kMovesJoint = 1e-4;       // metres a motion must move some deform joint
constexpr double kKeptShare = 0.1;         // a translation cut below this share of its nominal is left out
constexpr int kBisections = 12;
constexpr double kWidestStep = 120.0;      // degrees one key may turn a channel from the one before
constexpr int kPathSteps = 10;             // samples of the way to a peak (a frame each at 30 fps), looking for a flip or a fold
constexpr double kFlipDegrees = 45.0;      // a deform joint turning more than this in one step flips
constexpr double kFoldShare = 0.5;         // of a joint's rest distance ahead of its parent: closer, the chain folds

// What the planner evaluates with: the rig, its program, a scratch state.
struct Planner {
    const model::Rig& rig;
    const eval::RigProgram& program;
    eval::Posing posing;
    std::vector<FkIkSwitch> switches;
    std::vector<int> driving;
    StretchGauge gauge;
    JointWatch watch;
    std::vector<double> aimReach; // io/JointWatch.h's aimReaches
    double size = 1.0;            // the skeleton's bounding box diagonal, metres

    Planner(const model::Rig& r, const eval::RigProgram& p)
        : rig(r), program(p), posing(r, p), switches(switchesOf(r, p.channels())), driving(drivingChannels(r, p.channels())),
          gauge(r, p), watch(r), aimReach(aimReaches(r)), size(watch.size())
    {
    }

    double stretch(const eval::Pose& pose) { return gauge.measure(pose, posing.evaluate(pose)); }

    int folds(const eval::EvalState& state) const { return watch.folds(state, kFoldShare); }
    std::vector<eval::Affine> deformPositions(const eval::Pose& pose) { return watch.positions(posing.evaluate(pose)); }
    // Whether `pose` moves or turns some deform joint from where `from` has it.
    bool movesAJoint(const std::vector<eval::Affine>& from, const eval::Pose& pose)
    {
        const auto to = deformPositions(pose);
        for (std::size_t i = 0; i < to.size(); ++i) {
            if (glm::length(to[i].translation - from[i].translation) > kMovesJoint)
                return true;
            for (int k = 0; k < 3; ++k) // a joint that turns in place (a hand without fingers) moves too
                if (glm::length(to[i].linear[k] - from[i].linear[k]) > 1e-3)
                    return true;
        }
        return false;
    }

    // `base` with the switch's chain on its FK side, FK snapped onto where the chain is.
    eval::Pose toFk(const eval::Pose& base, const FkIkSwitch& s)
    {
        if (std::abs(base[std::size_t(s.weight)] - s.fk) < 1e-9)
            return base;
        const auto& state = posing.evaluate(base);
        std::vector<std::pair<model::RigNodeIndex, Mat4>> targets;
        for (const auto* b : s.blends) {
            const auto fk = b->targets[0];
            if (rig.nodes[fk].kind == model::RigNodeKind::Controller) // the FK control where the blended joint is
                targets.push_back({fk, (state.world[b->driven[0]] * program.restWorld(b->driven[0]).inverse() *
                                        program.restWorld(fk)).matrix()});
        }
        eval::Pose out = base;
        for (const auto& [fk, world] : targets) // parents first (blends are made in chain order)
            out = posing.placeAt(out, fk, world);
        out[std::size_t(s.weight)] = s.fk;
        return out;
    }
    // `base` with the chain on its IK side, the IK controls matched to FK when the rig knows how.
    eval::Pose toIk(const eval::Pose& base, const FkIkSwitch& s)
    {
        if (std::abs(base[std::size_t(s.weight)] - s.ik) < 1e-9)
            return base;
        eval::Pose out = base;
        if (!s.fkControls.empty())
            if (auto matched = posing.fkToIk(base, s.fkControls.front()))
                out = matched.take();
        out[std::size_t(s.weight)] = s.ik;
        return out;
    }
    eval::Pose allFk(eval::Pose base)
    {
        for (const auto& s : switches)
            base = toFk(base, s);
        return base;
    }

    std::vector<Mat3> deformRotations(const eval::Pose& pose) { return watch.rotations(posing.evaluate(pose)); }

    // Whether some deform joint flips on the way from `from` to `to` (all
    // channels linear, as the export samples them: turns more than
    // kFlipDegrees in one of kPathSteps steps: a solver's twist or up vector
    // giving way, not a motion to keep: no interpolation between keys can
    // follow it), or a chain folds on the way (more joints than `folded`)
    // and unfolds before the end.
    bool flipsBetween(const eval::Pose& from, const eval::Pose& to, int folded)
    {
        const double cosFlip = std::cos(glm::radians(kFlipDegrees));
        eval::Pose p = from;
        std::vector<Mat3> previous = deformRotations(p);
        for (int step = 1; step <= kPathSteps; ++step) {
            for (std::size_t c = 0; c < p.size(); ++c)
                if (program.channels()[c].transform != eval::kRotateOrderChannel && !program.channels()[c].isEnum())
                    p[c] = from[c] + (to[c] - from[c]) * double(step) / double(kPathSteps);
            std::vector<Mat3> current = deformRotations(p);
            if (folds(posing.state()) > folded)
                return true;
            for (std::size_t j = 0; j < current.size(); ++j) {
                const Mat3 turn = glm::transpose(previous[j]) * current[j];
                if (0.5 * (turn[0][0] + turn[1][1] + turn[2][2] - 1.0) < cosFlip)
                    return true;
            }
            previous = std::move(current);
        }
        return false;
    }
    bool flipsOnTheWay(const eval::Pose& base, int channel, double value, int folded)
    {
        eval::Pose to = base;
        to[std::size_t(channel)] = value;
        return flipsBetween(base, to, folded);
    }

    // The share (0..1) of `offset` on `channel` from `base` that stretches
    // nothing more than allowed, folds no chain and flips no joint on the way.
    double allowedShare(const eval::Pose& base, int channel, double offset, double limit)
    {
        const int folded = folds(posing.evaluate(base));
        auto fits = [&](double share) {
            eval::Pose p = base;
            p[std::size_t(channel)] = program.channels().clamp(channel, base[std::size_t(channel)] + share * offset);
            const auto& state = posing.evaluate(p);
            return gauge.measure(p, state) <= limit && folds(state) <= folded &&
                   !flipsOnTheWay(base, channel, p[std::size_t(channel)], folded);
        };
        if (fits(1.0))
            return 1.0;
        double low = 0.0, high = 1.0;
        for (int i = 0; i < kBisections; ++i) {
            const double mid = 0.5 * (low + high);
            (fits(mid) ? low : high) = mid;
        }
        return low;
    }

    double hingeDegrees(model::RigNodeIndex control, int axis) const
    {
        for (const auto& s : switches)
            if (std::find(s.fkControls.begin(), s.fkControls.end(), control) != s.fkControls.end() &&
                glm::length(s.bendNormal) > 0.0) {
                const Mat4& world = rig.nodes[control].worldMatrix;
                int best = 0;
                for (int k = 1; k < 3; ++k)
                    if (std::abs(glm::dot(glm::normalize(Vec3(world[k])), s.bendNormal)) >
                        std::abs(glm::dot(glm::normalize(Vec3(world[best])), s.bendNormal)))
                        best = k;
                return best == axis ? kHingeDegrees : kOtherDegrees;
            }
        return kOtherDegrees;
    }

    // The offsets a channel is exercised by, from `base` (before stretch limits).
    std::vector<double> nominalOffsets(model::RigNodeIndex control, int channel, const eval::Pose& base) const
    {
        const auto& c = program.channels()[std::size_t(channel)];
        const double value = base[std::size_t(channel)];
        if (c.limited) {
            std::vector<double> out;
            for (double bound : {c.max, c.min})
                if (std::abs(bound - value) > 1e-6)
                    out.push_back(bound - value);
            return out;
        }
        if (c.transform >= 3 && c.transform < 6) {
            const double degrees = hingeDegrees(control, c.transform - 3);
            return {degrees, -degrees};
        }
        if (c.transform >= 0 && c.transform < 3) {
            const double reach = aimReach[control] > 0.0 ? aimReach[control] : kTranslateShare * size;
            return {reach, -reach};
        }
        return {};
    }

    std::vector<int> exercisedChannels(model::RigNodeIndex control) const
    {
        const auto& layout = program.channels();
        std::vector<int> out;
        if (const int tx = layout.transformOf(control); tx >= 0)
            for (int i = 0; i < 6; ++i)
                if (!layout[std::size_t(tx + i)].locked)
                    out.push_back(tx + i);
        const int first = layout.firstOf(control);
        for (int i = first; i < first + layout.countOf(control); ++i)
            if (layout[std::size_t(i)].transform < 0 && std::find(driving.begin(), driving.end(), i) != driving.end())
                out.push_back(i);
        return out;
    }

    // The peaks of one channel from `base`, cut to what stretches nothing; empty when none is worth keeping.
    std::vector<eval::Pose> peaks(model::RigNodeIndex control, int channel, const eval::Pose& base, double limit,
                                  const std::vector<eval::Affine>& baseJoints)
    {
        std::vector<eval::Pose> out;
        const bool translation = program.channels()[std::size_t(channel)].transform >= 0 &&
                                 program.channels()[std::size_t(channel)].transform < 3;
        for (double offset : nominalOffsets(control, channel, base)) {
            const double share = allowedShare(base, channel, offset, limit);
            if (share <= 0.0 || (translation && share < kKeptShare))
                continue;
            eval::Pose p = base;
            p[std::size_t(channel)] = program.channels().clamp(channel, base[std::size_t(channel)] + share * offset);
            if (movesAJoint(baseJoints, p))
                out.push_back(std::move(p));
        }
        return out;
    }

    // The base pose a control is exercised from: its chain switched as the control needs.
    eval::Pose baseFor(model::RigNodeIndex control, const eval::Pose& start, bool& owned)
    {
        eval::Pose base = start;
        owned = false;
        for (const auto& s : switches) {
            if (std::find(s.fkControls.begin(), s.fkControls.end(), control) != s.fkControls.end()) {
                base = toFk(base, s);
                owned = true;
            } else if (std::find(s.ikControls.begin(), s.ikControls.end(), control) != s.ikControls.end()) {
                base = toIk(base, s);
                owned = true;
            }
        }
        return base;
    }

    // The peaks, then back to `base`: through it between two peaks more than
    // kWidestStep apart, so interpolation never takes a rotation the short
    // way round, or whose way from one to the other flips a joint or folds a
    // chain (twice as fast as the way from `base` to each, which was checked).
    void appendPeaks(std::vector<eval::Pose>& keys, std::vector<eval::Pose> found, const eval::Pose& base, int channel)
    {
        const bool angle = program.channels()[std::size_t(channel)].transform < 0 ||
                           program.channels()[std::size_t(channel)].transform >= 3;
        for (std::size_t i = 0; i < found.size(); ++i) {
            if (i > 0 && ((angle && std::abs(found[i][std::size_t(channel)] - keys.back()[std::size_t(channel)]) > kWidestStep) ||
                          flipsBetween(keys.back(), found[i], folds(posing.evaluate(base)))))
                keys.push_back(base);
            keys.push_back(std::move(found[i]));
        }
        keys.push_back(base);
    }

    // Keys for one control: its base, each channel's peaks with the base between them.
    std::vector<eval::Pose> motionOf(model::RigNodeIndex control, const eval::Pose& start)
    {
        bool owned = false;
        const eval::Pose base = baseFor(control, start, owned);
        const double limit = std::max(stretch(base), kMaxStretch);
        const auto baseJoints = deformPositions(base);
        std::vector<eval::Pose> keys;
        for (int channel : exercisedChannels(control)) {
            auto found = peaks(control, channel, base, limit, baseJoints);
            // How far the peaks go, in the channel's unit.
            auto reach = [&](const std::vector<eval::Pose>& peaksFound, const eval::Pose& from) {
                double sum = 0.0;
                for (const auto& p : peaksFound)
                    sum += std::abs(p[std::size_t(channel)] - from[std::size_t(channel)]);
                return sum;
            };
            double nominal = 0.0;
            for (double offset : nominalOffsets(control, channel, base))
                nominal += std::abs(offset);
            if (!owned && !switches.empty() && reach(found, base) < 0.999 * nominal) {
                // Held back by limbs in IK: try the same move with every switched chain in FK.
                const eval::Pose loose = allFk(base);
                const auto looseJoints = deformPositions(loose);
                auto freer = peaks(control, channel, loose, std::max(stretch(loose), kMaxStretch), looseJoints);
                if (reach(freer, loose) > reach(found, base) + 1e-6) {
                    keys.push_back(loose);
                    appendPeaks(keys, std::move(freer), loose, channel);
                    keys.push_back(base);
                    continue;
                }
            }
            if (found.empty())
                continue; // moves no deform joint (a pin while unpinned): left out
            appendPeaks(keys, std::move(found), base, channel);
        }
        if (keys.empty())
            return keys;
        if (base != start) {
            keys.insert(keys.begin(), base);
            keys.push_back(start);
        }
        return keys;
    }
};

} // namespace

int framesPerKey(double framesPerSecond)
{
    const int frames = int(std::lround(framesPerSecond / 3.0));
    return std::max(2, frames + (frames % 2));
}

double stretchOf(const model::Rig& rig, const eval::RigProgram& program, const eval::Pose& pose, const eval::EvalState& state)
{
    return StretchGauge(rig, program).measure(pose, state);
}

RangeOfMotionPlan planRangeOfMotion(const model::Rig& rig, const eval::RigProgram& program, const eval::Pose& start,
                                    const std::function<bool(double)>& progress)
{
    Planner planner(rig, program);
    RangeOfMotionPlan plan;
    plan.keys.push_back(start);
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
        if (progress && i % 8 == 0 && !progress(0.1 + 0.4 * double(i) / double(rig.nodes.size())))
            return {};
        if (rig.nodes[i].kind != model::RigNodeKind::Controller)
            continue;
        auto keys = planner.motionOf(i, start);
        if (keys.empty())
            continue;
        RangeOfMotionPart part{i, plan.keys.size() - 1, 0};
        if (keys.back() != start)
            keys.push_back(start);
        for (auto& k : keys)
            plan.keys.push_back(std::move(k));
        part.lastKey = plan.keys.size() - 1;
        plan.parts.push_back(part);
    }
    return plan;
}

} // namespace rs::io
