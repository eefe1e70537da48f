#pragma once
// Shared helpers for core tests: paths of test data, samples and golden files.
#include "base/Status.h"
#include "model/GuideDocument.h"
#include "model/Rig.h"
#include "templates/TemplateRegistry.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace rs::test {

std::string dataPath(const std::string& relative);   // tests/data/<relative>
std::string samplePath(const std::string& name);     // resources/samples/<name>.yml
std::string readText(const std::string& path);
// The built-in templates (fails the test on any error diagnostic).
const templates::TemplateRegistry& builtinTemplates();
model::GuideDocument loadSample(const std::string& name);
model::GuideDocument loadGuide(const std::string& dataRelativePath); // tests/data/<path>
// The FK-chain fixture of the builder machinery tests (core.joints arms and legs with [L, R]).
inline model::GuideDocument loadChains() { return loadGuide("RigBuilder/chains/guide.yml"); }
// Compares `actual` with the golden file; RIGSMITH_UPDATE_GOLDEN=1 rewrites it.
void expectMatchesGolden(const std::string& actual, const std::string& goldenRelativePath);
std::string temporaryPath(const std::string& name);
// For ASSERT_TRUE: success, or a failure whose diagnostics become the test's message.
::testing::AssertionResult succeeded(const Status& status);
// The first error's message of a refused edit; "" when it succeeded.
std::string refusal(const Status& status);
// Runs `write` in a forked child whose files may not grow past `limitBytes`
// (a write past it fails with EFBIG, SIGXFSZ ignored: a full disk without
// mounting one); true when the child returned true.
bool runWithFileSizeLimit(std::size_t limitBytes, const std::function<bool()>& write);
// A rig node by id; fails the test (and returns an empty node) when it is missing.
const model::RigNode& node(const model::Rig& rig, const std::string& id);

} // namespace rs::test
