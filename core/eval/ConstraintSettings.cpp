// Compiling a constraint's typed settings: every attribute reference becomes a
// channel index (or an error naming the constraint and the attribute), and the
// kinds that follow their targets get normalised weights and rest offsets.
#include "eval/Solvers.h"

#include "eval/DrivenKeys.h"
#include "eval/OffsetCarry.h"

#include <algorithm>

namespace rs::eval {

namespace {

class SettingsReader {
public:
    SettingsReader(const model::RigConstraint& rc, const model::Rig& rig, const ChannelLayout& channels,
                   CompiledConstraint& c, Diagnostics& diagnostics)
        : m_rc(rc), m_rig(rig), m_channels(channels), m_c(c), m_diagnostics(diagnostics)
    {
    }

    bool ok() const { return m_ok; }
    // What the weighted kinds and those that follow a target with an offset read.
    const std::vector<double>* weights() const { return m_weights; }
    bool followsTargets() const { return m_follows; }
    bool keepOffset() const { return m_keepOffset; }

    void operator()(const model::ParentConstraint& s) { weighted(s.weights, s.keepOffset); }
    void operator()(const model::OrientConstraint& s) { weighted(s.weights, s.keepOffset); }
    void operator()(const model::PointConstraint& s) { weighted(s.weights, s.keepOffset); }
    void operator()(const model::ScaleConstraint& s) { weighted(s.weights, s.keepOffset); }
    void operator()(const model::BlendConstraint& s)
    {
        m_c.weightChannel = channel(s.weight, "weight");
        follow(s.keepOffset);
    }
    void operator()(const model::IkConstraint& s)
    {
        m_c.stretchChannel = optionalChannel(s.stretch, "stretch");
        m_c.softChannel = optionalChannel(s.soft, "soft");
        m_c.volumeChannel = optionalChannel(s.volume, "volume");
        m_c.pinChannel = optionalChannel(s.pin, "pin");
        m_c.volumePower = std::clamp(s.volumePower, -1.0, 0.0);
    }
    void operator()(const model::TwistConstraint& s)
    {
        m_c.fraction = s.fraction;
        m_c.nonRolling = s.nonRolling;
        m_c.bendy = s.bendy;
        m_c.bendyLower = s.lower;
        m_c.byLength = s.byLength;
        m_c.biasChannel = optionalChannel(s.bias, "bias");
    }
    void operator()(const model::VisibilityConstraint& s)
    {
        m_c.valueChannel = channel(s.value, "value");
        m_c.showAbove = s.when == model::ShowWhen::Above;
        m_c.threshold = s.threshold;
    }
    void operator()(const model::SplineConstraint& s)
    {
        m_c.stretchChannel = optionalChannel(s.stretch, "stretch");
        m_c.volumeChannel = optionalChannel(s.volume, "volume");
        m_c.slideChannel = optionalChannel(s.slide, "slide");
        m_c.rigidityStartChannel = optionalChannel(s.rigidityStart, "rigidity_start");
        m_c.rigidityEndChannel = optionalChannel(s.rigidityEnd, "rigidity_end");
        m_c.scaleStretch = s.scaleStretch;
        // A sliding chain's joints travel the whole curve: a finer arc-length
        // table keeps their spacing along a bent path to 1e-5 m.
        if (s.slide)
            m_c.samplesPerSegment = 48;
    }
    void operator()(const model::SpaceConstraint& s)
    {
        m_c.spaceChannel = channel(s.choice, "choice");
        m_c.orientOnly = s.orientOnly;
        follow(s.keepOffset);
    }
    void operator()(const model::DriveConstraint& s)
    {
        m_c.valueChannel = channel(s.value, "value");
        m_c.scaleDrive = s.output == model::DriveOutput::Scale;
        m_c.axis = m_c.scaleDrive ? 0 : static_cast<int>(s.output);
        m_c.factor = s.factor;
        m_c.driveResponse = int(s.response.index());
        if (const auto* clamped = std::get_if<model::DriveClamped>(&s.response)) {
            m_c.low = clamped->low;
            m_c.high = clamped->high;
        } else if (const auto* up = std::get_if<model::DriveUpToBreak>(&s.response)) {
            m_c.breakChannel = channel(up->breakAngle, "break");
        } else if (const auto* past = std::get_if<model::DrivePastBreak>(&s.response)) {
            m_c.breakChannel = channel(past->breakAngle, "break");
        }
    }
    void operator()(const model::RollConstraint& s)
    {
        m_c.axle = static_cast<int>(s.axle);
        m_c.forward = static_cast<int>(s.forward);
        m_c.radius = s.radius;
        m_c.weightChannel = optionalChannel(s.amount, "amount");
        m_c.pathSlot = s.mode == model::RollMode::Path ? 0 : -1; // numbered by RigProgram::compile
        m_c.jump = s.jump;
    }
    void operator()(const model::AimConstraint& s)
    {
        m_c.aimAxis = static_cast<int>(s.aim);
        m_c.upAxis = static_cast<int>(s.up);
        m_c.weightChannel = optionalChannel(s.weight, "weight");
    }

    void operator()(const model::CarryConstraint& s) { m_ok = readCarry(s, m_rc, m_rig, m_channels, m_c, m_diagnostics) && m_ok; }

    void operator()(const model::DrivenKeyConstraint& s)
    {
        m_c.valueChannel = anyChannel(s.driver, "driver");
        m_c.drivenChannel = anyChannel(s.driven, "driven");
        m_c.keys = s.keys;
        m_c.pre = s.pre;
        m_c.post = s.post;
        m_c.tangents.clear();
        if (s.smooth && checkCurveKeys(s.keys).empty())
            m_c.tangents = smoothTangents(s.keys);
    }

private:
    // A transform channel or a custom attribute of the node.
    int anyChannel(const model::ChannelRef& ref, const char* role)
    {
        if (const auto found = m_channels.find(ref.node, ref.channel))
            return *found;
        const std::string where = ref.node < m_rig.nodes.size() ? "is not a channel of node '" + m_rig.nodes[ref.node].path + "'"
                                                                : "names no node of the rig";
        m_diagnostics.push_back(makeError({}, "constraint '" + m_rc.path + "': its " + role + " channel '" + ref.channel + "' " +
                                                  where));
        m_ok = false;
        return -1;
    }

    void weighted(const std::vector<double>& weights, bool keepOffset)
    {
        m_weights = &weights;
        follow(keepOffset);
    }
    void follow(bool keepOffset)
    {
        m_follows = true;
        m_keepOffset = keepOffset;
    }

    int channel(const model::AttributeRef& ref, const char* role)
    {
        if (const auto found = m_channels.find(ref))
            return *found;
        const std::string where = ref.node < m_rig.nodes.size() ? "is not an attribute of node '" + m_rig.nodes[ref.node].path + "'"
                                                                : "names no node of the rig";
        m_diagnostics.push_back(makeError({}, "constraint '" + m_rc.path + "': its " + role + " attribute '" + ref.attribute +
                                                  "' " + where));
        m_ok = false;
        return -1;
    }
    int optionalChannel(const std::optional<model::AttributeRef>& ref, const char* role)
    {
        return ref ? channel(*ref, role) : -1;
    }

    const model::RigConstraint& m_rc;
    const model::Rig& m_rig;
    const ChannelLayout& m_channels;
    CompiledConstraint& m_c;
    Diagnostics& m_diagnostics;
    bool m_ok = true;
    const std::vector<double>* m_weights = nullptr;
    bool m_follows = false;
    bool m_keepOffset = true;
};

// Normalised to sum 1; equal shares when none are given or their sum is not
// positive. A count that does not match the targets is kept as it is, for
// prepareConstraint to reject.
std::vector<double> normalisedWeights(const std::vector<double>& weights, std::size_t targets)
{
    if (!weights.empty() && weights.size() != targets)
        return weights;
    std::vector<double> out = weights.empty() ? std::vector<double>(targets, 1.0) : weights;
    double total = 0.0;
    for (double w : out) total += w;
    for (double& w : out) w = total > 0.0 ? w / total : 1.0 / double(targets);
    return out;
}

} // namespace

bool readSettings(const model::RigConstraint& rc, const model::Rig& rig, const ChannelLayout& channels,
                  const std::vector<Affine>& rest, CompiledConstraint& c, Diagnostics& diagnostics)
{
    SettingsReader reader(rc, rig, channels, c, diagnostics);
    std::visit(reader, rc.settings);
    if (!reader.ok() || c.driven.empty())
        return reader.ok();
    if (reader.weights())
        c.weights = normalisedWeights(*reader.weights(), c.targets.size());
    if (reader.followsTargets()) {
        for (model::RigNodeIndex target : c.targets)
            c.offsets.push_back(reader.keepOffset() ? rest[target].inverse() * rest[c.driven.front()] : Affine{});
        for (const Affine& offset : c.offsets)
            c.identityOffset.push_back(maxAbsDifference(offset.matrix(), Mat4(1.0)) < 1e-12);
    }
    return true;
}

} // namespace rs::eval
