#pragma once
// Internal to rs::rigging: the mod stage (model/Mod.h). buildRig runs it in
// two parts: `applyRigMods` after generation, before the override stage and
// the evaluation program's compile (spaces, constraints, parents, hidden
// nodes, plugs, driven keys: what evaluation and the overrides of mod-made
// channels need), and `applyHierarchyMods` after the virtual hierarchy is
// built (virtual parents, and the curves of hidden controllers), beside the
// compile, which reads neither.
//
// Each mod applies once per copy of its owner (each branch copy of a branched
// instance) or once when global. A reference that finds no node, a node of the
// wrong kind, or a change that would make a cycle is a build warning naming
// the mod (its file:line when read from a file) with the instance or node as
// subject; the mod (or that copy of it) is skipped and stays in the guide.
#include "rigging/RigAssembly.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rs::rigging {

void applyRigMods(RigAssembly& assembly, const model::GuideDocument& guide);
void applyHierarchyMods(RigAssembly& assembly, const model::GuideDocument& guide);

// One mod applied to one copy: resolution and reporting shared by the kinds.
class ModApplication {
public:
    ModApplication(RigAssembly& a, const model::GuideDocument& guide, const model::Mod& mod, std::size_t index,
                   std::string branch, bool quiet)
        : a(a), guide(guide), mod(mod), index(index), branch(std::move(branch)), quiet(quiet)
    {
    }

    // The node a reference names in this copy, or nullopt (reported).
    std::optional<model::RigNodeIndex> resolve(const model::ModRef& ref, const std::string& role);
    // A warning about this mod; `subject` none: the mod's owner copy.
    void warn(const std::string& message, Subject subject = {});
    // "arm.L::ctrls.ik@rz" (for messages).
    std::string text(const model::ModRef& ref) const;
    // The key of a constraint the mod adds: the owner copy's (or the root's) "mods.<index>.<what>".
    NodeKey constraintKey(const std::string& what) const;
    std::string constraintPath(const std::string& what) const;
    // Whether `node`'s world placement depends on `source`'s (parents, constraint targets).
    bool dependsOn(model::RigNodeIndex node, model::RigNodeIndex source) const;
    // A transform channel of a controller (0..8) or a custom attribute of `node`; reports when it has neither.
    bool hasChannel(model::RigNodeIndex node, const std::string& channel, const std::string& role);
    // Locks a channel for animators (it is driven).
    void lockChannel(model::RigNodeIndex node, const std::string& channel);
    // Adds a driven key, refusing (reported) a loop of driven keys.
    bool addDrivenKey(model::DrivenKeyConstraint settings, const std::string& what);
    // -1 where the value a mod gives a channel is negated on this copy: a mod
    // of a mirrored branch copy (its values are written for the authored side)
    // on a transform channel of a node of a mirrored copy whose mirror image
    // negates it (reflected through the x plane: tx, ry, rz); else 1. So the R
    // copy's driven keys and defaults move as the mirror image of the L's.
    double channelSign(model::RigNodeIndex node, const std::string& channel) const;

    // The kinds (ModKinds.cpp).
    void space(const model::SpaceMod& m);
    void constraint(const model::ConstraintMod& m);
    bool parent(const model::ParentMod& m); // true: the node now comes before its parent
    void hide(const model::HideMod& m);
    void hideCurves(const model::HideMod& m);
    void plug(const model::PlugMod& m);
    bool plugTransform(model::RigNodeIndex node, int channel, const model::PlugMod& m); // false: not a controller
    void plugAttribute(model::RigNodeIndex node, const model::PlugMod& m);
    void addSpace(model::RigConstraint& spaces, model::RigNodeIndex ctrl, model::RigNodeIndex target, const std::string& label,
                  const model::SpaceMod& m);
    void makeSpaceSwitch(model::RigNodeIndex ctrl, model::RigNodeIndex target, const std::string& label, const model::SpaceMod& m);
    void drive(const model::DriveMod& m);
    void vdag(const model::VdagMod& m);

    RigAssembly& a;
    const model::GuideDocument& guide;
    const model::Mod& mod;
    std::size_t index; // in guide.mods
    std::string branch; // the copy's
    bool quiet;         // the second part re-resolving what the first reported
    // The mirror plane (0 x, 1 y, 2 z) of each mirrored branch copy this build made.
    const std::map<CopyKey, int>* mirrorPlanes = nullptr;
};

} // namespace rs::rigging
