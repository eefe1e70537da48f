#include "ModsTestSupport.h"

namespace rs::test {

model::Mod modFromText(const model::GuideDocument& guide, const std::string& owner, const std::string& text)
{
    model::ModInstance instance;
    if (!owner.empty()) {
        const model::TemplateInstance* i = guide.instanceNamed(owner);
        EXPECT_TRUE(i) << owner;
        instance = {i ? i->id : kNoId, owner};
    }
    auto mod = io::readModText(guide, instance, text);
    EXPECT_TRUE(mod.ok()) << formatAll(mod.diagnostics()) << "\n" << text;
    return mod.ok() ? mod.take() : model::Mod{};
}

ModdedRig::ModdedRig(const model::GuideDocument& guide) : rig(rigging::buildRig(guide, builtinTemplates()))
{
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    auto compiled = eval::RigProgram::compile(rig);
    EXPECT_TRUE(compiled.ok()) << formatAll(compiled.diagnostics());
    if (!compiled.ok())
        return;
    program = std::make_unique<eval::RigProgram>(compiled.take());
    state = program->makeState();
    pose = program->channels().defaults();
}

model::RigNodeIndex ModdedRig::index(const std::string& id) const
{
    const auto i = rig.findPath(id);
    EXPECT_TRUE(i) << "no rig node " << id;
    return i.value_or(0);
}

int ModdedRig::channel(const std::string& id, const std::string& name) const
{
    const auto c = program ? program->channels().find(index(id), name) : std::nullopt;
    EXPECT_TRUE(c) << id << "@" << name;
    return c.value_or(0);
}

const eval::EvalState& ModdedRig::evaluate(std::initializer_list<std::tuple<std::string, std::string, double>> values)
{
    pose = program->channels().defaults();
    for (const auto& [id, name, value] : values)
        pose[channel(id, name)] = value;
    program->evaluate(pose, state);
    return state;
}

} // namespace rs::test
