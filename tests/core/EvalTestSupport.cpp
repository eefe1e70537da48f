#include "EvalTestSupport.h"

#include "io/YamlText.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rs::test {

model::GuideDocument bipedLimbsWith(const std::map<std::string, Value>& options)
{
    model::GuideDocument guide = loadSample("biped");
    for (const auto& i : guide.instances())
        if (i.name == "arm" || i.name == "leg")
            for (const auto& [name, value] : options)
                guide.instance(i.id)->options[name] = value;
    return guide;
}

model::GuideDocument sampleWith(const std::string& sample, std::initializer_list<const char*> instances,
                                const std::string& option, Value value)
{
    model::GuideDocument guide = loadSample(sample);
    for (const char* name : instances) {
        const model::TemplateInstance* instance = guide.instanceNamed(name);
        EXPECT_TRUE(instance) << sample << " has no instance " << name;
        if (instance)
            guide.instance(instance->id)->options[option] = value;
    }
    return guide;
}

model::TemplateInstance addInstance(model::GuideDocument& doc, const std::string& templateId, model::JointId under,
                                    const std::map<std::string, Value>& options)
{
    auto made = rigging::makeInstance(doc, builtinTemplates(), templateId, under, options);
    EXPECT_TRUE(made.ok()) << formatAll(made.diagnostics());
    model::TemplateInstance instance = made.take();
    doc.insertInstance(instance, doc.instances().size());
    return instance;
}

PosedRig::PosedRig(const std::string& sample) : PosedRig(loadSample(sample)) {}

PosedRig::PosedRig(const model::GuideDocument& guide) : rig(rigging::buildRig(guide, builtinTemplates()))
{
    EXPECT_FALSE(hasErrors(rig.diagnostics));
    auto compiled = eval::RigProgram::compile(rig);
    EXPECT_TRUE(compiled.ok()) << (compiled.diagnostics().empty() ? "" : compiled.diagnostics().front().message);
    if (!compiled.ok())
        return;
    program = std::make_unique<eval::RigProgram>(compiled.take());
    posing = std::make_unique<eval::Posing>(rig, *program);
    posing->evaluate(defaults());
}

model::RigNodeIndex PosedRig::index(const std::string& id) const
{
    auto found = rig.findPath(id);
    EXPECT_TRUE(found.has_value()) << "no rig node " << id;
    return found.value_or(0);
}

int PosedRig::channel(const std::string& id, const std::string& name) const
{
    auto found = program->channels().find(index(id), name);
    EXPECT_TRUE(found.has_value()) << "no channel " << id << "." << name;
    return found.value_or(0);
}

Vec3 PosedRig::position(const std::string& id) const
{
    return translationOf(posing->state().worldMatrix(index(id)));
}

Vec3 PosedRig::restPosition(const std::string& id) const { return translationOf(rig.nodes[index(id)].worldMatrix); }

eval::Pose PosedRig::moveTo(const eval::Pose& pose, const std::string& control, const Vec3& target, const std::string& measured)
{
    Mat4 world = posing->evaluate(pose).worldMatrix(index(control));
    world[3] = Vec4(target + restPosition(control) - restPosition(measured), 1.0);
    return posing->placeAt(pose, index(control), world);
}

eval::Pose sweepPose(const eval::ChannelLayout& layout)
{
    eval::Pose pose = layout.defaults();
    for (std::size_t i = 0; i < layout.size(); ++i) {
        const eval::Channel& c = layout[i];
        const double s = std::sin(1.7 * double(i) + 0.3); // in [-1, 1], different for neighbouring channels
        double value;
        if (c.transform == eval::kRotateOrderChannel || (c.transform >= 0 && c.locked))
            continue;
        if (c.transform >= 0) // 5 cm, 25 degrees, 20 % of scale at most
            value = c.transform < 3 ? 0.05 * s : c.transform < 6 ? 25.0 * s : 1.0 + 0.2 * s;
        else if (c.min > 0.0) // a scale factor (post_scale): its range is too wide to sweep
            value = c.defaultValue * (1.0 + 0.25 * s);
        else
            value = c.min + (c.max - c.min) * (0.5 + 0.4 * s);
        pose[i] = layout.clamp(int(i), value);
    }
    return pose;
}

namespace {

std::string fixed(double v)
{
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.6f", v);
    return std::string(buffer) == "-0.000000" ? "0.000000" : buffer;
}

} // namespace

std::string worldDump(const model::Rig& rig, const eval::EvalState& state)
{
    std::ostringstream out;
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
        Vec3 t, s;
        Quat r;
        decompose(state.worldMatrix(i), t, r, s);
        if (r.w < 0.0)
            r = -r;
        out << io::quoteIfNeeded(rig.nodes[i].path) << ": {t: [" << fixed(t.x) << ", " << fixed(t.y) << ", " << fixed(t.z)
            << "], r: [" << fixed(r.x) << ", " << fixed(r.y) << ", " << fixed(r.z) << ", " << fixed(r.w) << "], s: ["
            << fixed(s.x) << ", " << fixed(s.y) << ", " << fixed(s.z) << "]}\n";
    }
    return out.str();
}

eval::Pose turned(PosedRig& r, const eval::Pose& pose, const std::string& control, const Vec3& axis, double degrees)
{
    Mat4 world = r.evaluate(pose).worldMatrix(r.index(control));
    const Mat3 turn = glm::mat3_cast(glm::angleAxis(glm::radians(degrees), axis));
    const Vec3 at(world[3]);
    world = Mat4(turn * Mat3(world));
    world[3] = Vec4(at, 1.0);
    return r.posing->placeAt(pose, r.index(control), world);
}

} // namespace rs::test
