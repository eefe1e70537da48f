#include "io/ExportCheck.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

namespace rs::io {

namespace {

constexpr double kScaleTolerance = 1e-4;  // relative difference of axis lengths
constexpr double kShearTolerance = 1e-5;  // cosine between two axes

std::string lowercase(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

std::string safeCharacters(const std::string& name)
{
    std::string out;
    for (char c : name)
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out.front())))
        out.insert(out.begin(), '_');
    return out;
}

Diagnostic problem(Severity severity, const model::Rig& rig, const model::SkeletonJoint& joint, const std::string& message)
{
    Diagnostic d = severity == Severity::Error ? makeError({}, "joint '" + joint.name + "': " + message)
                                               : makeWarning({}, "joint '" + joint.name + "': " + message);
    if (joint.node != model::kNoNode && joint.node < rig.nodes.size())
        d.subject = Subject::ofNode(rig.nodes[joint.node].key);
    return d;
}

void checkMatrix(const model::Rig& rig, const model::SkeletonJoint& joint, Diagnostics& out)
{
    const Mat3 m(joint.bindWorld);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(joint.bindWorld[c][r])) {
                out.push_back(problem(Severity::Error, rig, joint, "its bind matrix is not finite"));
                return;
            }
    const Vec3 lengths(glm::length(m[0]), glm::length(m[1]), glm::length(m[2]));
    const double largest = std::max({lengths.x, lengths.y, lengths.z});
    if (std::min({lengths.x, lengths.y, lengths.z}) < 1e-9 * std::max(largest, 1.0)) {
        out.push_back(problem(Severity::Error, rig, joint, "its bind matrix cannot be inverted (a zero scale)"));
        return;
    }
    if (largest - std::min({lengths.x, lengths.y, lengths.z}) > kScaleTolerance * largest)
        out.push_back(problem(Severity::Error, rig, joint,
                              "non-uniform scale (" + std::to_string(lengths.x) + ", " + std::to_string(lengths.y) + ", " +
                                  std::to_string(lengths.z) + ") in its bind pose; engines skin it wrongly"));
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
            if (std::abs(glm::dot(m[a] / lengths[a], m[b] / lengths[b])) > kShearTolerance) {
                out.push_back(problem(Severity::Error, rig, joint, "shear in its bind pose (axes are not perpendicular)"));
                return;
            }
    if (glm::determinant(m) < 0.0)
        out.push_back(problem(Severity::Error, rig, joint, "a mirrored bind matrix (negative scale); engines flip its skin"));
}

} // namespace

bool isEngineSafeName(const std::string& name)
{
    return !name.empty() && safeCharacters(name) == name;
}

ExportCheck checkSkeleton(const model::Rig& rig, const model::Skeleton& skeleton)
{
    ExportCheck check;
    int roots = 0;
    for (const auto& joint : skeleton.joints) {
        roots += joint.parent < 0 ? 1 : 0;
        checkMatrix(rig, joint, check.problems);
    }
    if (roots != 1)
        check.problems.push_back(makeError({}, "the skeleton has " + std::to_string(roots) + " roots; engines need exactly one"));

    // Names: engine-safe and unique ignoring case. The fix keeps good names and
    // makes the others safe, numbering clashes (_2, _3...).
    std::set<std::string> taken;
    for (const auto& joint : skeleton.joints)
        if (isEngineSafeName(joint.name))
            taken.insert(lowercase(joint.name));
    std::set<std::string> seen;
    for (std::size_t i = 0; i < skeleton.joints.size(); ++i) {
        const auto& joint = skeleton.joints[i];
        const bool safe = isEngineSafeName(joint.name);
        const bool duplicate = !seen.insert(lowercase(joint.name)).second;
        if (!safe)
            check.problems.push_back(problem(Severity::Error, rig, joint,
                                             "the name is not engine-safe (use letters, digits and '_', not starting with a digit)"));
        else if (duplicate)
            check.problems.push_back(problem(Severity::Error, rig, joint,
                                             "the name is used by another joint (names are compared ignoring case)"));
        if (!safe || duplicate) {
            const std::string base = safeCharacters(joint.name);
            std::string name = base;
            for (int n = 2; taken.count(lowercase(name)); ++n)
                name = base + "_" + std::to_string(n);
            taken.insert(lowercase(name));
            check.renames[int(i)] = name;
            check.problems.back().message += "; safe fix: rename to '" + name + "'";
        }
    }
    return check;
}

model::Skeleton applyRenames(model::Skeleton skeleton, const ExportCheck& check)
{
    for (const auto& [index, name] : check.renames)
        if (index >= 0 && std::size_t(index) < skeleton.joints.size())
            skeleton.joints[std::size_t(index)].name = name;
    return skeleton;
}

} // namespace rs::io
