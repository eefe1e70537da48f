#pragma once
// The biped with mods written as the guide file writes them, built and
// evaluated: what the mod tests check as an animator would.
#include "TestSupport.h"

#include "eval/RigProgram.h"
#include "io/ModText.h"
#include "rigging/RigBuilder.h"

#include <initializer_list>
#include <memory>
#include <string>
#include <tuple>

namespace rs::test {

// A mod of instance `owner` (empty: global) from its text; fails the test when it does not read.
model::Mod modFromText(const model::GuideDocument& guide, const std::string& owner, const std::string& text);

// A guide built and compiled, evaluated in poses given by channel values.
struct ModdedRig {
    explicit ModdedRig(const model::GuideDocument& guide);

    model::RigNodeIndex index(const std::string& id) const;
    int channel(const std::string& id, const std::string& name) const;
    // Evaluates the default pose with `values` (node id, channel, value) set.
    const eval::EvalState& evaluate(std::initializer_list<std::tuple<std::string, std::string, double>> values = {});
    Vec3 position(const std::string& id) const { return translationOf(state.worldMatrix(index(id))); }
    Mat4 world(const std::string& id) const { return state.worldMatrix(index(id)); }
    // The build's warnings and errors as text.
    std::string log() const { return formatAll(rig.diagnostics); }

    model::Rig rig;
    std::unique_ptr<eval::RigProgram> program;
    eval::EvalState state;
    eval::Pose pose;
};

} // namespace rs::test
