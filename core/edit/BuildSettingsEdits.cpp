#include "edit/BuildSettingsEdits.h"

namespace rs::edit {

namespace {

class SetBuildSettings final : public Command {
public:
    SetBuildSettings(model::BuildSettings from, model::BuildSettings to, std::string what)
        : m_from(from), m_to(to), m_what(std::move(what))
    {
    }
    std::string text() const override { return m_what; }
    void redo(model::GuideDocument& d) override { d.build = m_to; }
    void undo(model::GuideDocument& d) override { d.build = m_from; }
    Change change() const override { return Change::of(ChangeKind::Build); }

private:
    model::BuildSettings m_from, m_to;
    std::string m_what;
};

} // namespace

Status setBuildSettings(History& history, const model::BuildSettings& settings, const std::string& what)
{
    const model::BuildSettings& current = history.document().build;
    if (settings == current)
        return Status::refused("the build settings are already so");
    history.push(std::make_unique<SetBuildSettings>(current, settings, what));
    return Status::success();
}

} // namespace rs::edit
