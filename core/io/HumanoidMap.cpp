#include "io/HumanoidMap.h"

#include <array>
#include <map>
#include <set>
#include <variant>

namespace rs::io {

namespace {

enum class Side { Centre, Left, Right };

// One built copy of an authored instance, in document order.
struct Copy {
    const model::TemplateInstance* instance = nullptr;
    std::string branch;
    Side side = Side::Centre;
};

Side sideOf(const model::GuideDocument& guide, const model::TemplateInstance& instance, const std::string& branch)
{
    const std::string last = branch.substr(branch.rfind('.') == std::string::npos ? 0 : branch.rfind('.') + 1);
    if (last == "L")
        return Side::Left;
    if (last == "R")
        return Side::Right;
    if (instance.joints.empty())
        return Side::Centre;
    const double x = translationOf(guide.jointWorldMatrix(instance.joints.front().id)).x;
    return x > 1e-6 ? Side::Left : x < -1e-6 ? Side::Right : Side::Centre;
}

std::vector<Copy> copiesOf(const model::GuideDocument& guide, const model::Rig& rig)
{
    std::map<InstanceId, std::vector<std::string>> branches; // in node order
    std::set<CopyKey> seen;
    for (const model::RigNode& node : rig.nodes)
        if (!node.key.isRoot() && seen.insert(node.key.copy()).second)
            branches[node.key.instance].push_back(node.key.branch);
    std::vector<Copy> copies;
    for (const model::TemplateInstance& instance : guide.instances())
        for (const std::string& branch : branches[instance.id])
            copies.push_back({&instance, branch, sideOf(guide, instance, branch)});
    return copies;
}

bool isThumb(const model::TemplateInstance& instance)
{
    const auto it = instance.options.find("thumb");
    return it != instance.options.end() && std::holds_alternative<bool>(it->second) && std::get<bool>(it->second);
}

class Resolver {
public:
    Resolver(const model::GuideDocument& guide, const model::Rig& rig) : m_copies(copiesOf(guide, rig)) {}

    // The `index`th copy (document order) of `templateId` on `side` that `accepts`.
    template <typename Accept>
    const Copy* copy(const std::string& templateId, Side side, std::size_t index, Accept accepts) const
    {
        for (const Copy& c : m_copies)
            if (c.instance->templateId == templateId && c.side == side && accepts(*c.instance) && index-- == 0)
                return &c;
        return nullptr;
    }
    const Copy* copy(const std::string& templateId, Side side) const
    {
        return copy(templateId, side, 0, [](const model::TemplateInstance&) { return true; });
    }

    void add(std::vector<HumanoidBone>& bones, std::string bone, const Copy* copy, const std::string& tag,
             const std::string& looksFor) const
    {
        if (!copy) {
            bones.push_back({std::move(bone), std::nullopt, looksFor});
            return;
        }
        const std::string branch = copy->branch.empty() ? std::string() : "." + copy->branch;
        bones.push_back({std::move(bone), NodeKey{copy->instance->id, copy->branch, tag},
                         copy->instance->name + branch + "::" + tag});
    }

private:
    std::vector<Copy> m_copies;
};

const char* sideWord(Side side) { return side == Side::Left ? "left" : "right"; }

} // namespace

std::vector<HumanoidBone> unityHumanoidBones(const model::GuideDocument& guide, const model::Rig& rig)
{
    const Resolver r(guide, rig);
    std::vector<HumanoidBone> bones;
    const Copy* spine = r.copy("spine.torso", Side::Centre);
    for (const auto& [bone, tag] : {std::pair{"Hips", "skin.0"}, {"Spine", "skin.1"}, {"Chest", "skin.2"}, {"UpperChest", "skin.4"}})
        r.add(bones, bone, spine, tag, "spine.torso instance on the centre line");
    const Copy* neck = r.copy("neck.head", Side::Centre);
    r.add(bones, "Neck", neck, "skin.0", "neck.head instance on the centre line");
    r.add(bones, "Head", neck, "skin.head", "neck.head instance on the centre line");
    const char* phalanges[] = {"Proximal", "Intermediate", "Distal"};
    for (Side side : {Side::Left, Side::Right}) {
        const std::string w = side == Side::Left ? "Left" : "Right", s = sideWord(side);
        const Copy* arm = r.copy("arm.limb", side);
        for (const auto& [bone, tag] : {std::pair{"Shoulder", "skin.clavicle"}, {"UpperArm", "skin.limb.0"},
                                        {"LowerArm", "skin.limb.1"}, {"Hand", "skin.limb.2"}})
            r.add(bones, w + bone, arm, tag, s + " arm.limb instance");
        const Copy* leg = r.copy("leg.limb", side);
        for (const auto& [bone, tag] : {std::pair{"UpperLeg", "skin.limb.0"}, {"LowerLeg", "skin.limb.1"},
                                        {"Foot", "skin.limb.2"}, {"Toes", "skin.ball"}})
            r.add(bones, w + bone, leg, tag, s + " leg.limb instance");
        // The finger with `thumb: on`, else the side's first (thumb, index... is
        // the order hands are authored in).
        const Copy* thumb = r.copy("digit.finger", side, 0, isThumb);
        if (!thumb)
            thumb = r.copy("digit.finger", side);
        for (int i = 0; i < 3; ++i)
            r.add(bones, w + "Thumb" + phalanges[i], thumb, "skin." + std::to_string(i), s + " digit.finger instance");
        const std::array<const char*, 4> fingers{"Index", "Middle", "Ring", "Little"};
        const auto notThumb = [&](const model::TemplateInstance& i) { return !thumb || &i != thumb->instance; };
        for (std::size_t f = 0; f < fingers.size(); ++f) {
            const Copy* finger = r.copy("digit.finger", side, f, notThumb);
            for (int i = 0; i < 3; ++i) // skin.0 is the metacarpal, which Unity does not map
                r.add(bones, w + fingers[f] + phalanges[i], finger, "skin." + std::to_string(i + 1),
                      std::to_string(f + 1) + (f == 0 ? "st" : f == 1 ? "nd" : f == 2 ? "rd" : "th") + " " + s +
                          " digit.finger instance after the thumb");
        }
    }
    return bones;
}

NameMap unityHumanoidMap(const model::GuideDocument& guide, const model::Rig& rig)
{
    NameMap map;
    for (const HumanoidBone& bone : unityHumanoidBones(guide, rig))
        if (bone.node)
            map.byKey[*bone.node] = bone.bone;
    return map;
}

} // namespace rs::io
