#pragma once
// The biped with bendy limbs for the bendy tests (LimbBendyTest,
// LimbBendyRigTest): its limb instances, the sample with options set on its
// arms and legs (`bendy` on), a limb's bend-plane normal and which way a
// joint's X axis points down its bone.
#include "EvalTestSupport.h"
#include "TestSupport.h"

#include <glm/geometric.hpp>

#include <map>
#include <string>

namespace rs::test::bendy {

using test::PosedRig;

inline const char* const kLimbs[] = {"arm.L", "arm.R", "leg.L", "leg.R"};

// The biped with `option` set on its arm and leg instances.
inline model::GuideDocument bipedWith(std::map<std::string, Value> options)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& i : guide.instances())
        if (i.name == "arm" || i.name == "leg")
            for (const auto& [name, value] : options)
                guide.instance(i.id)->options[name] = value;
    return guide;
}

inline model::GuideDocument bendyBiped(std::map<std::string, Value> more = {})
{
    more["bendy"] = Value(true);
    return bipedWith(std::move(more));
}

// The bend-plane normal of a limb (Z of its joint frames): across both bones.
inline Vec3 bendNormal(const PosedRig& r, const std::string& limb)
{
    return glm::normalize(Vec3(r.rig.nodes[r.index(limb + "::blend.0")].worldMatrix[2]));
}

// +1 when a joint's X axis points down its bone at rest, -1 on a mirrored branch.
inline double aimSign(const PosedRig& r, const std::string& id, const Vec3& bone)
{
    return glm::dot(Vec3(r.rig.nodes[r.index(id)].worldMatrix[0]), bone) >= 0.0 ? 1.0 : -1.0;
}

} // namespace rs::test::bendy
