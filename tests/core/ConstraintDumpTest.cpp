// The rig dump writes every typed constraint setting by name: the constraints
// read back from a sample's dump have the same kinds, nodes and settings (to
// the dump's 6 decimals), no field the kind does not have, and the rig
// evaluates as before. Aim, point and scale constraints (no builder makes
// them) and a driven key are added to the prop, so every kind is covered (the
// vehicle brings the wheels' roll, the quadruped's chained tail tweakers the carry,
// the claw aims weighted by an attribute).
#include "EvalTestSupport.h"
#include "io/RigDump.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>

namespace rs {
namespace {

using eval::Affine;
using model::AttributeRef;

// One constraint entry of a dump, read strictly: every field its kind has must
// be there, and unread() lists the fields it has that its kind does not.
class ConstraintEntry {
public:
    ConstraintEntry(const model::Rig& rig, const YAML::Node& entry) : m_rig(rig), m_entry(entry) {}

    model::RigConstraint read()
    {
        model::RigConstraint c;
        c.path = field("id").as<std::string>();
        for (const auto& n : field("driven")) c.driven.push_back(node(n));
        for (const auto& n : field("targets")) c.targets.push_back(node(n));
        c.settings = settings(field("kind").as<std::string>());
        return c;
    }

    std::set<std::string> unread() const
    {
        std::set<std::string> out;
        for (const auto& item : m_entry)
            if (!m_read.count(item.first.as<std::string>()))
                out.insert(item.first.as<std::string>());
        return out;
    }

private:
    model::ConstraintSettings settings(const std::string& kind)
    {
        if (kind == "parent") return weighted<model::ParentConstraint>();
        if (kind == "orient") return weighted<model::OrientConstraint>();
        if (kind == "point") return weighted<model::PointConstraint>();
        if (kind == "scale") return weighted<model::ScaleConstraint>();
        if (kind == "blend") return model::BlendConstraint{attribute("weight"), flag("keep_offset")};
        if (kind == "ik") return model::IkConstraint{optionalAttribute("stretch"), optionalAttribute("soft"),
                                                         optionalAttribute("volume"), optionalAttribute("pin"),
                                                         m_entry["volume_power"] ? number("volume_power") : -0.5};
        if (kind == "twist") { // the bendy fields are written only for bendy twists
            model::TwistConstraint twist{number("fraction"), flag("non_rolling")};
            if (m_entry["bendy"]) {
                twist.bendy = flag("bendy");
                twist.lower = flag("lower");
                twist.byLength = flag("by_length");
            }
            if (m_entry["bias"]) // written only for advanced_twist
                twist.bias = optionalAttribute("bias");
            return twist;
        }
        if (kind == "visibility") return visibility();
        if (kind == "spline") return spline();
        if (kind == "space") return model::SpaceConstraint{attribute("choice"), flag("orient_only"), flag("keep_offset")};
        if (kind == "drive") return drive();
        if (kind == "aim") // the weight is written only when set
            return model::AimConstraint{axis("aim"), axis("up"), m_entry["weight"] ? optionalAttribute("weight") : std::nullopt};
        if (kind == "roll") return roll();
        if (kind == "driven_key") return drivenKey();
        if (kind == "carry") {
            model::CarryConstraint carry;
            for (const auto& n : field("carried")) carry.carried.push_back(node(n));
            return carry;
        }
        ADD_FAILURE() << "unknown kind " << kind;
        return {};
    }

    template <class Settings>
    Settings weighted()
    {
        return Settings{field("weights").as<std::vector<double>>(), flag("keep_offset")};
    }

    model::VisibilityConstraint visibility()
    {
        const std::string when = field("when").as<std::string>();
        if (when != "below" && when != "above") ADD_FAILURE() << "unknown visibility test " << when;
        return {attribute("value"), when == "above" ? model::ShowWhen::Above : model::ShowWhen::Below, number("threshold")};
    }

    model::DriveConstraint drive()
    {
        model::DriveConstraint d{attribute("value"), model::DriveOutput::RotateX, number("factor"), {}};
        const std::string output = field("output").as<std::string>();
        for (auto o : {model::DriveOutput::RotateX, model::DriveOutput::RotateY, model::DriveOutput::RotateZ, model::DriveOutput::Scale})
            if (output == model::driveOutputName(o)) d.output = o;
        const std::string response = field("response").as<std::string>();
        if (response == "clamped") d.response = model::DriveClamped{number("low"), number("high")};
        else if (response == "up_to_break") d.response = model::DriveUpToBreak{attribute("break")};
        else if (response == "past_break") d.response = model::DrivePastBreak{attribute("break")};
        else ADD_FAILURE() << "unknown drive response " << response;
        return d;
    }

    model::RollConstraint roll()
    {
        model::RollConstraint r{axis("axle"), axis("forward"), number("radius"), optionalAttribute("amount")};
        const std::string mode = field("mode").as<std::string>();
        if (mode != "path" && mode != "axis") ADD_FAILURE() << "unknown roll mode " << mode;
        r.mode = mode == "axis" ? model::RollMode::Axis : model::RollMode::Path;
        r.jump = number("jump");
        return r;
    }

    // Rigidity and the stretch mode are written only when set.
    model::SplineConstraint spline()
    {
        model::SplineConstraint s{optionalAttribute("stretch"), optionalAttribute("volume"), optionalAttribute("slide")};
        if (m_entry["rigidity_start"]) s.rigidityStart = attribute("rigidity_start");
        if (m_entry["rigidity_end"]) s.rigidityEnd = attribute("rigidity_end");
        if (m_entry["stretch_mode"]) s.scaleStretch = field("stretch_mode").as<std::string>() == "scale";
        return s;
    }

    model::DrivenKeyConstraint drivenKey()
    {
        model::DrivenKeyConstraint d{channel("driver_channel"), channel("driven_channel"), {}, flag("smooth"), infinity("pre"), infinity("post")};
        for (const auto& key : field("keys"))
            d.keys.push_back({key[0].as<double>(), key[1].as<double>()});
        return d;
    }
    model::ChannelRef channel(const std::string& name)
    {
        const YAML::Node n = field(name);
        return {node(n["node"]), n["channel"].as<std::string>()};
    }
    model::CurveInfinity infinity(const std::string& name)
    {
        const std::string text = field(name).as<std::string>();
        for (auto i : {model::CurveInfinity::Constant, model::CurveInfinity::Linear, model::CurveInfinity::Cycle})
            if (text == model::curveInfinityName(i)) return i;
        ADD_FAILURE() << "unknown infinity " << text;
        return {};
    }

    YAML::Node field(const std::string& name)
    {
        m_read.insert(name);
        const YAML::Node n = m_entry[name];
        if (!n) ADD_FAILURE() << m_entry["id"].as<std::string>("?") << " has no field " << name;
        return n;
    }
    model::RigNodeIndex node(const YAML::Node& path) const
    {
        const auto found = m_rig.findPath(path.as<std::string>());
        EXPECT_TRUE(found) << "no node " << path.as<std::string>();
        return found.value_or(model::kNoNode);
    }
    AttributeRef attribute(const std::string& name)
    {
        const YAML::Node n = field(name);
        return {node(n["node"]), n["attribute"].as<std::string>()};
    }
    std::optional<AttributeRef> optionalAttribute(const std::string& name)
    {
        if (field(name).IsNull()) return std::nullopt;
        return attribute(name);
    }
    double number(const std::string& name) { return field(name).as<double>(); }
    bool flag(const std::string& name) { return field(name).as<bool>(); }
    model::Axis axis(const std::string& name)
    {
        const std::string text = field(name).as<std::string>();
        return text == "z" ? model::Axis::Z : text == "y" ? model::Axis::Y : model::Axis::X;
    }

    const model::Rig& m_rig;
    const YAML::Node m_entry;
    std::set<std::string> m_read;
};

// `settings` with every number as the dump writes it (6 decimals).
model::ConstraintSettings asDumped(model::ConstraintSettings settings)
{
    auto round = [](double& v) {
        if (std::isfinite(v)) v = std::round(v * 1e6) / 1e6;
    };
    std::visit([&](auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (requires { s.weights; })
            for (double& w : s.weights) round(w);
        if constexpr (std::is_same_v<S, model::TwistConstraint>)
            round(s.fraction);
        if constexpr (std::is_same_v<S, model::VisibilityConstraint>)
            round(s.threshold);
        if constexpr (std::is_same_v<S, model::RollConstraint>) {
            round(s.radius);
            round(s.jump);
        }
        if constexpr (std::is_same_v<S, model::DrivenKeyConstraint>)
            for (model::CurveKey& key : s.keys) { round(key.in); round(key.out); }
        if constexpr (std::is_same_v<S, model::DriveConstraint>) {
            round(s.factor);
            if (auto* clamped = std::get_if<model::DriveClamped>(&s.response)) {
                round(clamped->low);
                round(clamped->high);
            }
        }
    }, settings);
    return settings;
}

// The rig with its constraints replaced by those read back from its dump.
model::Rig readBack(const model::Rig& rig)
{
    model::Rig out = rig;
    out.constraints.clear();
    const YAML::Node dump = YAML::Load(io::writeRigDump(rig));
    for (const auto& entry : dump["constraints"]) {
        ConstraintEntry reader(rig, entry);
        out.constraints.push_back(reader.read());
        EXPECT_TRUE(reader.unread().empty()) << out.constraints.back().path << " has fields its kind does not: "
                                             << *reader.unread().begin();
    }
    return out;
}

// Every node's world transform in the swept pose (empty when the rig does not compile).
std::vector<Affine> sweptWorld(const model::Rig& rig)
{
    auto program = eval::RigProgram::compile(rig);
    EXPECT_TRUE(program.ok()) << formatAll(program.diagnostics());
    if (!program.ok()) return {};
    eval::EvalState state = program->makeState();
    program->evaluate(test::sweepPose(program->channels()), state);
    return state.world;
}

void addAimPointScaleAndDrivenKey(model::Rig& rig)
{
    const auto antenna = *rig.findPath("antenna::skin.3"), lid = *rig.findPath("lid::ctrls.xform"),
               chest = *rig.findPath("chest::ctrls.xform");
    rig.constraints.push_back({{}, "t::aim", model::kNoId, {antenna}, {lid, chest},
                               model::AimConstraint{.aim = model::Axis::Y, .up = model::Axis::Z}});
    rig.constraints.push_back({{}, "t::point", model::kNoId, {*rig.findPath("antenna::skin.0")}, {chest, lid},
                               model::PointConstraint{.weights = {1.0, 2.0 / 3.0}, .keepOffset = false}});
    rig.constraints.push_back({{}, "t::scale", model::kNoId, {*rig.findPath("antenna::skin.1")}, {chest},
                               model::ScaleConstraint{.weights = {}, .keepOffset = true}});
    rig.constraints.push_back({{}, "t::driven_key", model::kNoId, {lid}, {chest},
                               model::DrivenKeyConstraint{.driver = {chest, "ry"}, .driven = {lid, "rx"},
                                                          .keys = {{-30.0, 1.0 / 3.0}, {0.0, 0.0}, {60.0, -45.0}},
                                                          .smooth = true, .pre = model::CurveInfinity::Linear,
                                                          .post = model::CurveInfinity::Cycle}});
}

} // namespace

TEST(ConstraintDump, EveryKindReadsBackFromTheDumpWithItsTypedSettingsAndEvaluatesTheSame)
{
    std::set<model::ConstraintKind> kinds;
    for (const std::string sample : {"biped", "quadruped", "prop", "vehicle", "robot", "claw", "cart", "strider"}) {
        SCOPED_TRACE(sample);
        test::PosedRig built(sample);
        model::Rig rig = built.rig;
        if (sample == "prop")
            addAimPointScaleAndDrivenKey(rig);
        const model::Rig back = readBack(rig);
        ASSERT_EQ(back.constraints.size(), rig.constraints.size());
        for (std::size_t i = 0; i < rig.constraints.size(); ++i) {
            const auto &a = rig.constraints[i], &b = back.constraints[i];
            kinds.insert(a.kind());
            EXPECT_EQ(b.path, a.path);
            EXPECT_EQ(b.kind(), a.kind()) << a.path;
            EXPECT_EQ(b.driven, a.driven) << a.path;
            EXPECT_EQ(b.targets, a.targets) << a.path;
            EXPECT_TRUE(b.settings == asDumped(a.settings)) << a.path;
        }
        EXPECT_EQ(io::writeRigDump(back), io::writeRigDump(rig));
        const std::vector<Affine> before = sweptWorld(rig), after = sweptWorld(back);
        ASSERT_EQ(before.size(), after.size());
        // Equal but for the dump's rounding of twist fractions (1/3 -> 0.333333):
        // up to 5e-7 of the swept twist, in radians, times the joint's offsets;
        // a bendy twist joint also moves that much along its curve, which the
        // sweep bends hard (its bend controls pulled), turning its aim more,
        // and so does what hangs on it (add_chains' tweaks and joints); the
        // advanced twist's rolls are drives by (rounded) fractions of the
        // swept roll attributes, on top.
        std::set<model::RigNodeIndex> bendy;
        for (const auto& c : rig.constraints)
            if (const auto* twist = std::get_if<model::TwistConstraint>(&c.settings); twist && twist->bendy)
                bendy.insert(c.driven.begin(), c.driven.end());
        for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i)
            if (rig.nodes[i].parent != model::kNoNode && bendy.count(rig.nodes[i].parent))
                bendy.insert(i);
        for (std::size_t i = 0; i < before.size(); ++i)
            EXPECT_LT(maxAbsDifference(before[i].matrix(), after[i].matrix()), bendy.count(i) ? 2e-5 : 2e-6) << rig.nodes[i].path;
    }
    EXPECT_EQ(kinds.size(), std::variant_size_v<model::ConstraintSettings>) << "every kind is covered";
}

} // namespace rs
