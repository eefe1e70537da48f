#pragma once
// A rig.spline tail as a rigger drags its guides, shared by the tail tests.
#include "core/TestSupport.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace rs::test {

// A curling tail of `count` guide joints named "tail", unevenly spaced (long
// near the base, short at the tip), with `options`.
inline model::GuideDocument curledTail(const std::map<std::string, Value>& options, int count = 7)
{
    model::GuideDocument doc;
    std::map<std::string, Value> all = options;
    all["number"] = Value(static_cast<long long>(count));
    auto made = rigging::makeInstance(doc, builtinTemplates(), "rig.spline", model::kNoId, all);
    EXPECT_TRUE(made.ok()) << formatAll(made.diagnostics());
    model::TemplateInstance instance = made.take();
    for (std::size_t i = 0; i < instance.joints.size(); ++i) {
        const double step = 0.2 - 0.025 * double(i);
        instance.joints[i].local.translate = i == 0 ? Vec3(0.3, 1.0, 0.0) : Vec3(0.0, 0.6 * step * double(i) / count, -step);
        instance.joints[i].local.rotateDegrees = Vec3(0.0);
    }
    doc.insertInstance(instance, 0);
    return doc;
}

} // namespace rs::test
