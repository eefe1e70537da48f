// Mod commands: each edits the guide's mods through the history
// (edit/ModEdits.h), so it is one undo step with a typed change event; the
// live rebuild then applies it.
#include "session/Session.h"

#include "edit/ModEdits.h"

namespace rs::session {

Status Session::addMod(const model::Mod& mod)
{
    return edit::addMod(m_history, mod);
}

Status Session::setMod(std::size_t index, const model::Mod& mod)
{
    return edit::setMod(m_history, index, mod);
}

Status Session::removeMod(std::size_t index)
{
    return edit::removeMod(m_history, index);
}

} // namespace rs::session
