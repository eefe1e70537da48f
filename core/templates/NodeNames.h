#pragma once
// The names a rigger gives extra groups in a control's hierarchy (the
// add_nodes option, rigging/builders/ControlNodes.h) and a limb's extra twist
// chains (add_chains), checked in one place so the guide file refuses them at
// their line and the build names the option.
#include <string>
#include <vector>

namespace rs::templates {

// Every problem with an add_nodes list (items in order; `c` marks the
// controller): a name that is no identifier ([A-Za-z_][A-Za-z0-9_]*), one
// the control's own nodes use (root, ctrl, skin...), a name given twice, `c`
// twice. Empty when the list is good.
std::vector<std::string> addNodesProblems(const std::vector<std::string>& names);

// Every problem with a limb's add_chains list (rigging/builders/LimbTwist.h):
// a name that is no identifier, or one given twice. Empty when it is good.
std::vector<std::string> addChainsProblems(const std::vector<std::string>& names);

} // namespace rs::templates
