// rigsmith-cli joint: places one guide joint without a display, through the
// session's typed move (Session::moveGuideJoints), the edit the editor's
// transform panel and gizmo make: the joint's children follow it, a mirrored
// branch copy (`branches: [L, R]`) follows its authored side, and with
// --symmetric the twin instance (arm_L / arm_R) moves mirrored.
#include "cli/Commands.h"

#include "rigging/BranchStage.h"
#include "session/Session.h"
#include "templates/GuideTemplates.h"
#include "templates/Structure.h"
#include "io/GuideFile.h"
#include "io/TemplateFolders.h"

#include <cmath>
#include <iostream>
#include <optional>

namespace rs::cli {

namespace {

// Rotations in degrees, one turn either way.
constexpr double kMaxDegrees = 360.0;

struct JointRequest {
    std::string path, instance, joint;
    std::optional<Vec3> at, move, rotate;
    bool world = false; // --space world; parent (the guide file's local values) by default
    bool symmetric = false;
};

// Nullopt (after the message) for bad usage.
std::optional<JointRequest> parseRequest(const std::vector<std::string>& args)
{
    JointRequest r;
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool hasValue = i + 1 < args.size();
        std::optional<Vec3>* target = a == "--at" ? &r.at : a == "--move" ? &r.move : a == "--rotate" ? &r.rotate : nullptr;
        if (target && hasValue) {
            *target = parseTriple("joint", a, args[++i], a == "--rotate" ? kMaxDegrees : kMaxCoordinate,
                                  a == "--rotate" ? "degrees" : "metres");
            if (!*target) return std::nullopt;
        } else if (a == "--space" && hasValue) {
            const std::string& space = args[++i];
            if (space != "world" && space != "parent") {
                std::cerr << "rigsmith-cli joint: --space is world or parent, not '" << space << "'\n";
                return std::nullopt;
            }
            r.world = space == "world";
        } else if (a == "--symmetric") r.symmetric = true;
        else if (!a.empty() && a[0] != '-' && positional.size() < 3) positional.push_back(a);
        else { std::cerr << "rigsmith-cli joint: unexpected argument '" << a << "'\n" << usage(); return std::nullopt; }
    }
    if (positional.size() != 3) { std::cerr << usage(); return std::nullopt; }
    r.path = positional[0], r.instance = positional[1], r.joint = positional[2];
    if (r.at && r.move) { std::cerr << "rigsmith-cli joint: give --at or --move, not both\n"; return std::nullopt; }
    if (!r.at && !r.move && !r.rotate) { std::cerr << "rigsmith-cli joint: nothing to do: give --at, --move or --rotate\n"; return std::nullopt; }
    return r;
}

// The authored instance a branch copy's name ("front_leg_R", "front_leg.R") comes from, or "".
std::string branchCopyMessage(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                              const std::string& name)
{
    Diagnostics ignored; // the build reports branch problems
    const rigging::ExpandedGuide expanded = rigging::expandBranches(guide, templates, ignored);
    for (const auto& [id, copy] : expanded.copies) {
        if (copy.id.empty() || (name != copy.baseName + copy.suffix && name != copy.baseName + copy.id))
            continue;
        const bool mirrored = copy.mirror != Mat4(1.0);
        return "'" + name + "' is the " + (mirrored ? "mirrored " : "") + copy.branch() + " branch of instance '" +
               copy.baseName + "', which the guide file holds once: edit '" + copy.baseName + "'" +
               (mirrored ? ", and its " + copy.branch() + " side follows mirrored" : "");
    }
    return {};
}

// JOINT within `instance`: a joint's own name, a structure tag of its template
// naming one joint (toe, heel, limb2), or an address ("/3", "."). kNoId after the message.
model::JointId resolveJoint(const std::string& path, const model::TemplateInstance& instance,
                            const templates::TemplateManifest* manifest, const std::string& name)
{
    for (const auto& joint : instance.joints)
        if (joint.name == name) return joint.id;
    std::string why = "no template '" + instance.templateId + "'";
    if (manifest) {
        const templates::StructureResolver resolver(*manifest, instance);
        const bool isAddress = !name.empty() && (name[0] == '/' || name == ".");
        if (manifest->structureAddress(name) || isAddress) {
            auto joints = isAddress ? resolver.address(name) : resolver.tag(name);
            if (joints && joints->size() == 1) return joints->front();
            why = joints ? std::to_string(joints->size()) + " joints, not one" : joints.diagnostics().front().message;
            std::cerr << path << ": error: joint '" << name << "' of instance '" << instance.name << "' names " << why << '\n';
            return model::kNoId;
        }
        why.clear();
        for (const auto& [tag, address] : manifest->structure)
            if (auto joints = resolver.tag(tag); joints && joints->size() == 1) why += (why.empty() ? "" : ", ") + tag;
        for (const auto& joint : instance.joints)
            if (!joint.name.empty()) why += (why.empty() ? "" : ", ") + joint.name;
        why = "joints: " + why;
    }
    std::cerr << path << ": error: instance '" << instance.name << "' has no joint '" << name << "' (" << why << ")\n";
    return model::kNoId;
}

// The lead joint's new world matrix; nullopt (after the message) when it leaves the allowed range.
std::optional<Mat4> targetWorld(const model::GuideDocument& guide, model::JointId joint, const JointRequest& r)
{
    const Mat4 parent = guide.parentWorldMatrix(joint);
    Mat4 world(1.0);
    Vec3 position(0.0);
    if (!r.world) {
        Transform local = guide.joint(joint)->local;
        if (r.at) local.translate = *r.at;
        if (r.move) local.translate += *r.move;
        if (r.rotate) local.rotateDegrees = *r.rotate;
        position = local.translate;
        world = parent * local.matrix();
    } else {
        world = guide.jointWorldMatrix(joint);
        if (r.rotate) {
            Transform turn;
            turn.rotateDegrees = *r.rotate;
            const Mat4 rotation = turn.matrix();
            for (int c = 0; c < 3; ++c)
                world[c] = rotation[c] * glm::length(Vec3(world[c]));
        }
        if (r.at) world[3] = glm::dvec4(*r.at, 1.0);
        if (r.move) world[3] += glm::dvec4(*r.move, 0.0);
        position = Vec3(world[3]);
    }
    if (!(std::abs(position.x) <= kMaxCoordinate && std::abs(position.y) <= kMaxCoordinate &&
          std::abs(position.z) <= kMaxCoordinate)) {
        std::cerr << "rigsmith-cli joint: the joint would end at (" << position.x << ", " << position.y << ", "
                  << position.z << "), past " << kMaxCoordinate << " metres from the origin\n";
        return std::nullopt;
    }
    return world;
}

} // namespace

int runJoint(const std::vector<std::string>& args)
{
    const auto request = parseRequest(args);
    if (!request)
        return 2;
    const std::string& path = request->path;
    Diagnostics templateDiagnostics;
    std::shared_ptr<const templates::TemplateRegistry> templates = io::loadDefaultTemplates(templateDiagnostics);
    auto guide = io::readGuideFile(path);
    print(guide.diagnostics());
    if (!guide)
        return 1;
    print(templates::checkGuideTemplates(*guide, *templates, path));

    const model::TemplateInstance* instance = guide->instanceNamed(request->instance);
    if (!instance) {
        const std::string branch = branchCopyMessage(*guide, *templates, request->instance);
        std::cerr << path << ": error: " << (branch.empty() ? "no instance named '" + request->instance + "'" : branch) << '\n';
        return 1;
    }
    const model::JointId joint = resolveJoint(path, *instance, templates->find(instance->templateId), request->joint);
    if (joint == model::kNoId)
        return 1;
    const auto world = targetWorld(*guide, joint, *request);
    if (!world)
        return 2;

    // A joint already where it is asked to be: nothing to write, and not an error (scripts rerun).
    edit::GuideDragOptions options;
    options.symmetric = request->symmetric;
    const edit::GuideDrag check(*guide, joint, {joint}, options);
    if (check.transformsFor(*world) == check.start()) {
        std::cerr << path << ": note: joint '" << request->joint << "' of '" << request->instance
                  << "' is already there; the guide is unchanged\n";
        return 0;
    }
    session::Session session(templates);
    session.replaceDocument(std::move(*guide));
    session.setGuideDragOptions(options);
    Status moved = session.moveGuideJoints(joint, *world, "Move guide joint");
    if (moved.failed()) {
        Diagnostics refusal = moved.takeDiagnostics();
        for (Diagnostic& d : refusal)
            if (d.where.file.empty()) d.where.file = path;
        print(refusal);
        return 1;
    }
    const Status saved = io::saveGuideFile(session.document(), path);
    print(saved.diagnostics());
    return saved.failed() ? 1 : 0;
}

} // namespace rs::cli
