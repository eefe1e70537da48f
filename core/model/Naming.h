#pragma once
// Naming rules of a document: how a rig node's name is made from its role, the
// core name (manifest `names`, per-instance overrides, index) and the branch.
//   mikan (default): prefix + core + side  -> c_arm1_L, sk_arm1_L, root_arm1_L
//   suffix:          core + side + suffix  -> arm1_L_ctrl, arm1_L_jnt, arm1_L_gp
// (the second follows the prop-rig conventions of seed 004: _gp/_jnt/_ctrl, _L_/_R_).
#include <optional>
#include <string>

namespace rs::model {

enum class NameRole { Offset, Controller, Skin, Group };

struct NamingRules {
    std::string preset = "mikan";
    std::string offset = "root_", controller = "c_", skin = "sk_", group = "grp_";
    bool suffixes = false;     // role marks go after the name instead of before
    std::string side = "_";    // separator before each branch id: "_L"
    bool lowercase = false;

    // `core` is the instance/token/index part; `branch` the branch ids joined ("L", "A_L").
    std::string make(NameRole role, const std::string& core, const std::string& branch) const;
    bool operator==(const NamingRules&) const = default;
};

// "mikan" or "suffix"; nullopt for an unknown preset.
std::optional<NamingRules> namingPreset(const std::string& name);

// The name with its side token swapped ("arm_L" -> "arm_R", "eye.left" ->
// "eye.right"; L/R, l/r, Left/Right, left/right after '_' or '.'); empty when
// the name has no side.
std::string mirroredName(const std::string& name);

} // namespace rs::model
