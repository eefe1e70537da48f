// rigsmith-cli's usage text, its diagnostics printer and the build command
// (build, optionally pose, dump and export a guide's rig with its bound
// character). The template library's commands: TemplateCommands.cpp.
#include "cli/Commands.h"

#include "base/Paths.h"
#include "base/TextScalars.h"
#include "rigging/RigBuilder.h"
#include "eval/PoseTools.h"
#include "io/AtomicFile.h"
#include "io/ExportRequest.h"
#include "io/GuideFile.h"
#include "io/ModelImport.h"
#include "io/WeightsFile.h"
#include "skin/Refit.h"
#include "io/RigDump.h"
#include "io/TemplateFolders.h"
#include "io/YamlText.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <filesystem>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

namespace rs::cli {

void print(const Diagnostics& diagnostics)
{
    for (const auto& d : diagnostics)
        std::cerr << d.format() << '\n';
}

std::optional<Vec3> parseTriple(const std::string& command, const std::string& flag, const std::string& text, double limit,
                                const char* unit)
{
    double x, y, z;
    char tail;
    if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &x, &y, &z, &tail) != 3) {
        std::cerr << "rigsmith-cli " << command << ": " << flag << " expects X,Y,Z, got '" << text << "'\n";
        return std::nullopt;
    }
    if (!(std::abs(x) <= limit && std::abs(y) <= limit && std::abs(z) <= limit)) {
        std::cerr << "rigsmith-cli " << command << ": " << flag << " wants finite values from -" << limit << " to " << limit
                  << ' ' << unit << ", got '" << text << "'\n";
        return std::nullopt;
    }
    return Vec3(x, y, z);
}

std::string usage()
{
    return "usage: rigsmith-cli build GUIDE [--posed] [--dump RIG.yml]\n"
           "                          [-o OUT.glb|OUT.gltf|OUT.fbx] [--preset gltf|unreal|unity] [--controllers] [--rom]\n"
           "                          [--current-pose] [--names unity|MAP.yml] [--fix-names] [--fix-weights] [--force]\n"
           "                          [--proxy-mesh VERTICES] [--no-meshes] [--reference EXPORT.json]\n"
           "                          [--fps FPS] [--rom-clips markers|per-control] [--clip CLIP.yml]... [--no-restore KIND]...\n"
           "                          [--cleanup|--no-cleanup]\n"
           "                          [--textures embedded|relative]\n"
           "       (--no-restore KIND: build without the guide's overrides of that kind (shapes, defaults, limits,\n"
           "        locks, post, names, pose; repeatable), on top of those the guide's build settings leave out;\n"
           "        the records stay in the guide; --cleanup / --no-cleanup: clean the rig up for animators (hide\n"
           "        setup groups and skin joints, lock and hide what templates do not make animatable, record the\n"
           "        controllers' default values, which --controllers exports) or not, whatever the guide says;\n"
           "        --posed: build the rig rebound in the guide's test pose instead of its rest pose;\n"
           "        -o exports for engines: --preset gltf (Y-up metres), unreal (FBX Z-up centimetres, a root\n"
           "        joint at the origin), unity (humanoid names); --controllers adds the controllers as tagged\n"
           "        nodes with their custom attributes (glTF extras, FBX user properties), --rom a range-of-motion clip from the guide's test pose (keys on whole frames at --fps,\n"
           "        30 by default; a marker per controller, in clips of a minute at most, or one clip per controller\n"
           "        with --rom-clips per-control),\n"
           "        --current-pose the guide's pose on the nodes (with --posed the rig already is in it);\n"
           "        --names export names from a name map; the export validator's errors refuse -o unless\n"
           "        --force; --fix-names and --fix-weights apply its safe fixes; the guide's models' meshes are\n"
           "        exported with their weights (GUIDE.weights, from skin bind), normals, UVs and materials\n"
           "        (an FBX's textures inside it, or with --textures relative copied beside it) unless --no-meshes; a mesh without weights is an error (--force: rigid on the root);\n"
           "        --proxy-mesh binds a generated mesh of about VERTICES vertices; --reference writes\n"
           "        what was exported as JSON)\n"
           "       rigsmith-cli new GUIDE.yml [--name NAME]   (an empty guide)\n"
           "       rigsmith-cli add GUIDE.yml TEMPLATE [--under INSTANCE[:HOOK]] [--name NAME] [--at X,Y,Z] [--set OPTION=VALUE]...\n"
           "       rigsmith-cli joint GUIDE.yml INSTANCE JOINT [--at X,Y,Z | --move DX,DY,DZ] [--rotate RX,RY,RZ]\n"
           "                          [--space parent|world] [--symmetric]\n"
           "                          (places a guide joint as the editor's move tool does: its children follow, a mirrored\n"
           "                          branch follows its authored side, --symmetric moves the twin instance (arm_L / arm_R)\n"
           "                          mirrored; JOINT is a structure tag of the instance's template naming one joint (toe,\n"
           "                          heel, limb2), an address (/3) or the joint's name; --at sets the position, --move adds\n"
           "                          to it (metres), --rotate sets the rotation (XYZ degrees), in the joint's parent space\n"
           "                          as the guide file writes them (default) or in world space)\n"
           "       rigsmith-cli model add GUIDE.yml FILE   (a character model: OBJ, FBX, glTF, Collada...)\n"
           "       rigsmith-cli skin bind GUIDE.yml [--model FILE] [--method heat|envelope|closest] [--max-influences N]\n"
           "                          [-o WEIGHTS] [--json WEIGHTS.json]   (automatic weights of every mesh of the guide's\n"
           "                          models, or of FILE, for the guide's rig, written to GUIDE.weights unless -o;\n"
           "                          --json also writes the bones and each vertex's position and weights as JSON)\n"
           "       rigsmith-cli skin export GUIDE.yml -o FILE.rschunks|--depot DIR [--asset NAME] [--mesh NAME]...\n"
           "                          [--vertices MESH:0-99,120]... [--joints NAME,...] [--bind-pose] [--dual-quaternion]\n"
           "                          [--neighbours N] [--json REPORT|-]   (skin chunks of the guide's bound meshes, or of the selection: whole\n"
           "                          meshes, vertex ranges, the vertices those joints weight (all their weights); weights,\n"
           "                          influences, bind positions and those in the guide's test pose unless --bind-pose;\n"
           "                          --depot: one file per mesh, DIR/<asset>/<mesh>.rschunks, asset the guide's file name)\n"
           "       rigsmith-cli skin import GUIDE.yml FILE.rschunks... [--depot DIR [--asset NAME]] [--method closest|neighbours|inpaint]\n"
           "                          [--normal-filter T] [--neighbours N] [--distance-multiplier X] [--inpaint-distance M]\n"
           "                          [--inpaint-angle DEG] [--smooth STEPS] [--smooth-threshold X] [--max-influences N]\n"
           "                          [--no-search] [--uber] [--export-pose] [--mesh NAME]... [--vertices MESH:RANGES]...\n"
           "                          [--append] [--missing stop|map|create] [--map OLD=NEW]... [--name-map FILE]\n"
           "                          [--progress] [--json REPORT|-]\n"
           "                          (weights onto the guide's meshes, written to GUIDE.weights: by mesh name, 1:1 when the\n"
           "                          vertex count and order match, else a chunk of the same count and order unless --no-search,\n"
           "                          else transferred from the name's chunk or from all chunks; the newest chunk of a name wins;\n"
           "                          the chunks' pre-deformed points unless --export-pose; influences by identity, then name;\n"
           "                          a missing one stops the import (stop), is mapped by the name map (map; OLD: NEW lines)\n"
           "                          or created as a joint of the guide (saved) under its matched parent (create); the weights replace the mesh's\n"
           "                          unless --append (vertices a subset chunk leaves out keep theirs); --mesh/--vertices\n"
           "                          write only those vertices)\n"
           "       rigsmith-cli skin transfer SOURCE TARGET -o FILE.rschunks|FILE.glb|FILE.gltf [the import's method options]\n"
           "                          [--mesh NAME]... [--progress] [--json REPORT|-]   (no guide: TARGET's meshes (any model\n"
           "                          file) get weights on the source's influences by the same decision tree; SOURCE is a\n"
           "                          chunk file or a skinned model file (.glb, .fbx, .dae...: each skinned mesh a chunk, its\n"
           "                          joints by name); -o .glb/.gltf writes TARGET's meshes skinned on the source's skeleton)\n"
           "       rigsmith-cli skin info FILE.rschunks [--mesh NAME] [--from I] [--limit N] [--json REPORT|-]\n"
           "                          (what a chunk file holds)\n"
           "       --json -: the report alone on stdout (the lines for people go to stderr)\n"
           "       rigsmith-cli check-templates [DIR...]\n"
           "       rigsmith-cli describe-template ID   (what Rigsmith understood of every key)\n"
           "       rigsmith-cli shape-icons [--check] [SHAPES_DIR]   (writes SHAPES_DIR/icons/<shape>.svg)\n";
}

namespace {

struct BuildArguments {
    std::string guide, dump;
    bool posed = false;
    bool meshes = true;
    std::vector<model::OverrideKind> noRestore; // --no-restore KIND: added to the guide's build settings
    std::optional<bool> cleanup;                // --cleanup / --no-cleanup: replaces the guide's
    io::ExportRequest exportRequest;
};

// Parses `args`; prints the problem and returns false on a bad argument.
bool parseBuildArguments(const std::vector<std::string>& args, BuildArguments& b)
{
    io::ExportRequest& e = b.exportRequest;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool hasValue = i + 1 < args.size();
        if (a == "--posed") b.posed = true;
        else if (a == "--force") e.force = true;
        else if (a == "--fix-names") e.fixNames = true;
        else if (a == "--fix-weights") e.fixWeights = true;
        else if (a == "--controllers") e.controllers = true;
        else if (a == "--rom") e.rangeOfMotion = true;
        else if (a == "--current-pose") e.currentPose = true;
        else if (a == "--no-meshes") b.meshes = false;
        else if (a == "--no-restore" && hasValue) {
            const auto kind = model::parseOverrideKind(args[++i]);
            if (!kind) {
                std::cerr << "rigsmith-cli: --no-restore wants shapes, defaults, limits, locks, post, names or pose, not '"
                          << args[i] << "'\n";
                return false;
            }
            b.noRestore.push_back(*kind);
        }
        else if (a == "--cleanup" || a == "--no-cleanup") b.cleanup = a == "--cleanup";
        else if (a == "--fps" && hasValue) {
            const auto fps = parseInteger(args[++i]);
            if (!fps || *fps < 1 || *fps > 1000) {
                std::cerr << "rigsmith-cli: --fps wants a whole frame rate from 1 to 1000, not '" << args[i] << "'\n";
                return false;
            }
            e.framesPerSecond = double(*fps);
        } else if (a == "--rom-clips" && hasValue) {
            const std::string& layout = args[++i];
            if (layout != "markers" && layout != "per-control") {
                std::cerr << "rigsmith-cli: --rom-clips wants markers or per-control, not '" << layout << "'\n";
                return false;
            }
            e.clipPerControl = layout == "per-control";
        } else if (a == "--textures" && hasValue) {
            const std::string& mode = args[++i];
            if (mode != "embedded" && mode != "relative") {
                std::cerr << "rigsmith-cli: --textures wants embedded or relative, not '" << mode << "'\n";
                return false;
            }
            e.embedTextures = mode == "embedded";
        }
        else if (a == "--preset" && hasValue) {
            const auto preset = io::presetNamed(args[++i]);
            if (!preset) {
                std::cerr << "rigsmith-cli: unknown preset '" << args[i] << "' (gltf, unreal or unity)\n";
                return false;
            }
            e.preset = *preset;
        } else if (a == "--proxy-mesh" && hasValue) {
            const auto n = parseInteger(args[++i]); // digits only: no overflow, spaces or hex
            if (!n || *n <= 0 || std::size_t(*n) > io::kMaxProxyVertices) {
                std::cerr << "rigsmith-cli: --proxy-mesh wants a vertex count from 1 to " << io::kMaxProxyVertices
                          << ", not '" << args[i] << "'\n";
                return false;
            }
            e.proxyVertices = std::size_t(*n);
        } else if (a == "--clip" && hasValue) {
            if (args[i + 1].empty()) {
                std::cerr << "rigsmith-cli: --clip wants a clip file, not an empty path\n";
                return false;
            }
            e.clips.push_back(args[++i]);
        } else if ((a == "--dump" || a == "-o" || a == "--reference" || a == "--names") && hasValue) {
            if (args[i + 1].empty()) { // an empty path would write nothing and still succeed
                std::cerr << "rigsmith-cli: " << a << " wants a file path, not an empty one\n";
                return false;
            }
            (a == "--dump" ? b.dump : a == "-o" ? e.path : a == "--names" ? e.names : e.referencePath) = args[++i];
        }
        else if (!a.empty() && a[0] != '-' && b.guide.empty())
            b.guide = a;
        else {
            std::cerr << "rigsmith-cli: unexpected argument '" << a << "'\n" << usage();
            return false;
        }
    }
    if (b.guide.empty())
        std::cerr << usage();
    return !b.guide.empty();
}

// Prints `d`; the status becomes 1 when it has an error.
int report(const Diagnostics& d, int status)
{
    print(d);
    return hasErrors(d) ? 1 : status;
}

// The guide's models and weights, as the editor's session holds them. A model
// that cannot be read stays in the list without its meshes (the export says so).
struct LoadedCharacter {
    std::vector<std::unique_ptr<model::Model>> models;
    io::ExportCharacter character;
};

// Records whose mesh changed topology since it was bound are re-fitted from
// the meshes as bound (<guide>.weights.rschunks), as the editor does on open;
// the guide's files are left as they are (the export carries the re-fit).
void refitChangedMeshes(const std::string& guidePath, const model::Rig& rig, LoadedCharacter& out)
{
    std::vector<std::string> paths;
    std::vector<const model::Model*> models;
    for (const io::CharacterModel& m : out.character.models) {
        paths.push_back(m.path);
        models.push_back(m.model);
    }
    const auto pairs = model::pairBindings(paths, models, out.character.bindings);
    std::optional<std::vector<skin::SkinChunk>> chunks;
    for (std::size_t m = 0; m < pairs.size(); ++m)
        for (std::size_t k = 0; k < pairs[m].size(); ++k) {
            const int b = pairs[m][k];
            const model::Mesh& mesh = models[m]->meshes[k];
            if (b < 0 || model::bindingFits(out.character.bindings[std::size_t(b)], mesh))
                continue;
            if (!chunks) {
                auto loaded = io::loadGuideChunks(guidePath);
                print(loaded.diagnostics());
                chunks = loaded ? loaded.take() : std::vector<skin::SkinChunk>{};
            }
            model::MeshBinding& was = out.character.bindings[std::size_t(b)];
            const skin::SkinChunk* previous = skin::previousChunk(*chunks, was);
            if (!previous)
                continue; // the export says the mesh changed since it was bound
            auto refit = skin::refitBinding(was, *previous, mesh, &rig, skin::defaultRefitOptions());
            print(refit.diagnostics());
            if (!refit)
                continue;
            refit->note.message += " (for this export; open and save the guide in the editor, or bind again, to keep it)";
            print({refit->note});
            was = std::move(refit->binding);
        }
}

LoadedCharacter loadCharacter(const std::string& guidePath, model::GuideDocument guide, const model::Rig& rig)
{
    LoadedCharacter out;
    if (guide.models.empty())
        return out;
    const auto start = std::chrono::steady_clock::now();
    const Status weights = io::loadGuideWeights(guidePath, guide);
    print(weights.diagnostics());
    for (const std::string& path : guide.models) {
        auto read = io::importModel(path);
        print(read.diagnostics());
        out.models.push_back(read ? std::make_unique<model::Model>(read.take()) : nullptr);
        out.character.models.push_back({path, out.models.back().get()});
    }
    out.character.bindings = std::move(guide.bindings);
    refitChangedMeshes(guidePath, rig, out);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::cerr << "read " << guide.models.size() << " model(s) and " << out.character.bindings.size() << " mesh weight record(s) in "
              << ms << " ms\n";
    return out;
}

int exportBuiltRig(const model::Rig& rig, const model::GuideDocument& guide, const BuildArguments& b, int status)
{
    const io::ExportRequest& request = b.exportRequest;
    if (request.path.empty() && request.referencePath.empty())
        return status;
    const LoadedCharacter loaded = b.meshes ? loadCharacter(b.guide, guide, rig) : LoadedCharacter{};
    const auto start = std::chrono::steady_clock::now();
    // A rig built --posed already is in the guide's pose: the pose relative to
    // it is the rest, or --current-pose (and the range of motion) would apply it twice.
    const model::PoseValues none;
    const model::PoseValues restored = rigging::restoredPose(guide, guide.build.restore);
    const model::PoseValues& pose = b.posed ? none : restored;
    const Diagnostics d = io::runExport(guide, rig, pose, request, {}, loaded.models.empty() ? nullptr : &loaded.character);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    status = report(d, status);
    if (status == 0 && !request.path.empty())
        std::cerr << "exported " << request.path << " (preset " << io::presetName(request.preset) << ") in " << ms << " ms\n";
    return status;
}

} // namespace

int runBuild(const std::vector<std::string>& args)
{
    BuildArguments b;
    if (!parseBuildArguments(args, b))
        return 2;
    Diagnostics templateDiagnostics;
    auto templates = io::loadDefaultTemplates(templateDiagnostics);
    print(templateDiagnostics);
    auto guide = io::readGuideFile(b.guide);
    print(guide.diagnostics());
    if (!guide)
        return 1;
    for (const model::OverrideKind kind : b.noRestore)
        guide->build.restore.set(kind, false);
    if (b.cleanup)
        guide->build.cleanup = *b.cleanup;
    const auto start = std::chrono::steady_clock::now();
    model::Rig rig = rigging::buildRig(*guide, *templates, rigging::BuilderRegistry::builtin(), {}, nullptr, guide->build.restore);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    print(rig.diagnostics);
    if (b.posed && !hasErrors(rig.diagnostics)) {
        const model::PoseValues pose = rigging::restoredPose(*guide, guide->build.restore);
        auto withPose = eval::posedRig(rig, pose);
        print(withPose.diagnostics());
        if (!withPose)
            return 1;
        rig = withPose.take();
        std::cerr << "posed with " << pose.size() << " posed nodes from the guide\n";
    }
    std::cerr << "built " << rig.nodes.size() << " nodes (" << rig.count(model::RigNodeKind::Controller)
              << " controllers, " << rig.skinJointCount() << " skin joints) in " << ms << " ms\n";
    int status = hasErrors(rig.diagnostics) ? 1 : 0;
    if (!b.dump.empty()) {
        const std::string text = io::writeRigDump(rig);
        if (b.dump == "-")
            std::cout << text;
        else
            status = report(io::writeFileAtomically(b.dump, text).diagnostics(), status);
    }
    return exportBuiltRig(rig, *guide, b, status);
}

} // namespace rs::cli
