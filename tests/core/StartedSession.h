#pragma once
// A core session on the built biped sample, recording every change event it
// emits: the common start of the session command tests.
#include "TestSupport.h"

#include "session/Session.h"

#include <memory>
#include <string>
#include <vector>

namespace rs::test {

struct StartedSession {
    session::Session s{std::make_shared<templates::TemplateRegistry>(builtinTemplates())};
    std::vector<edit::Change> changes;
    StartedSession()
    {
        s.replaceDocument(loadSample("biped"));
        s.build();
        s.subscribe([this](const edit::Change& c) { changes.push_back(c); });
    }
    const model::RigNode& node(const std::string& id) const { return test::node(*s.rig(), id); }
};

} // namespace rs::test
