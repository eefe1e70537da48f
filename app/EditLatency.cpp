// rigsmith --edit-latency GUIDE: replays guide-joint drags in the real editor
// and reports how long each edit took to reach the screen (a swapped frame).
#include "EditLatency.h"

#include "ViewportWidget.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace rs::app {

namespace {

double cpuClockMs(clockid_t clock)
{
    timespec t{};
    clock_gettime(clock, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// CPU time one frame took: the GUI thread's and the whole process's (llvmpipe's
// rasterisers included). Unlike wall time, it does not grow when the machine
// runs something else or the hypervisor takes the CPU away ("steal").
struct FrameCpu {
    double gui = 0.0, process = 0.0;
};

// Runs `edit` and waits for the viewport's next swapped frame; milliseconds.
// `editMs`, when given, gets the part spent in `edit` itself (the session's
// rebuild and the views' refresh, before any painting); `cpu` the frame's CPU time.
double timeToFrame(viewport::ViewportWidget* view, const std::function<void()>& edit, std::vector<double>* editMs = nullptr,
                   FrameCpu* cpu = nullptr)
{
    const double gui0 = cpuClockMs(CLOCK_THREAD_CPUTIME_ID), process0 = cpuClockMs(CLOCK_PROCESS_CPUTIME_ID);
    QEventLoop loop;
    QElapsedTimer timer;
    double ms = -1.0;
    const auto connection = QObject::connect(view, &viewport::ViewportWidget::frameSwapped, &loop, [&] {
        ms = double(timer.nsecsElapsed()) / 1e6;
        loop.quit();
    });
    QTimer::singleShot(2000, &loop, &QEventLoop::quit); // a frame that never comes counts as 2 s
    timer.start();
    edit();
    if (editMs)
        editMs->push_back(double(timer.nsecsElapsed()) / 1e6);
    view->update();
    loop.exec();
    QObject::disconnect(connection);
    if (cpu)
        *cpu = {cpuClockMs(CLOCK_THREAD_CPUTIME_ID) - gui0, cpuClockMs(CLOCK_PROCESS_CPUTIME_ID) - process0};
    return ms < 0.0 ? 2000.0 : ms;
}

// CPU milliseconds the process has used so far, all threads (llvmpipe's
// rasterisers included) and the calling (GUI) thread alone: unlike wall time,
// they barely change with the machine's load.
struct CpuTime {
    double process = 0.0, thread = 0.0;
};
CpuTime cpuNow()
{
    auto ms = [](const rusage& u) {
        return (double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3) + double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e3;
    };
    rusage self{}, thread{};
    getrusage(RUSAGE_SELF, &self);
    getrusage(RUSAGE_THREAD, &thread);
    return {ms(self), ms(thread)};
}

// The guide joint with the most joints below it in its instance (an arm's
// shoulder, a spine's hips): a drag that moves a lot and rebuilds the limb.
model::JointId busiestJoint(const model::GuideDocument& guide)
{
    model::JointId best = model::kNoId;
    std::size_t most = 0;
    for (const auto& instance : guide.instances())
        for (const auto& joint : instance.joints) {
            std::size_t below = 0;
            for (model::JointId parent = joint.id; parent != model::kNoId;) {
                const auto children = instance.childJoints(parent);
                below += children.size();
                parent = children.empty() ? model::kNoId : children.front();
            }
            if (below > most || best == model::kNoId) {
                most = below;
                best = joint.id;
            }
        }
    return best;
}

} // namespace

int reportEditLatency(MainWindow& window, int drags)
{
    auto* view = window.viewportWidget();
    window.setAutosaveEnabled(false); // a measurement, not an editing session
    window.buildRig();
    window.session().setMode(EditorMode::Guide);
    QApplication::processEvents();
    const model::JointId joint = busiestJoint(window.session().document());
    if (joint == model::kNoId) {
        std::fprintf(stderr, "rigsmith: the guide has no joints to drag\n");
        return 1;
    }
    window.session().selectGuideJoints({joint}, false);
    timeToFrame(view, [] {}); // the first frame pays for shader and buffer setup
    const std::uint64_t sceneVertices = view->sceneVerticesUploaded(); // the whole scene, once
    // The floor: a repaint with nothing changed (the GL driver and Qt's compositing).
    std::vector<double> idle;
    for (int i = 0; i < 20; ++i)
        idle.push_back(timeToFrame(view, [] {}));
    std::vector<double> moves, commits, edits;
    struct Frame {
        int drag = 0;
        bool commit = false;
        double ms = 0.0, editMs = 0.0;
        FrameCpu cpu;
    };
    std::vector<Frame> frames; // every frame in order, to name the slowest
    const CpuTime cpuStart = cpuNow();
    const int steps = 4; // mouse moves per drag
    moves.reserve(std::size_t(drags * steps));
    commits.reserve(std::size_t(drags));
    for (int d = 0; d < drags; ++d) {
        const Mat4 start = window.session().document().jointWorldMatrix(joint);
        emit view->gizmoDragStarted(joint);
        for (int s = 1; s <= steps; ++s) {
            Mat4 world = start;
            world[3][1] += 0.002 * s * (d % 2 == 0 ? 1.0 : -1.0); // up, then back down: the guide stays put
            FrameCpu cpu;
            moves.push_back(timeToFrame(view, [&] { emit view->gizmoDragged(joint, world); }, &edits, &cpu));
            frames.push_back({d, false, moves.back(), edits.back(), cpu});
        }
        FrameCpu cpu;
        commits.push_back(timeToFrame(view, [&] { emit view->gizmoDragFinished(joint); }, &edits, &cpu));
        frames.push_back({d, true, commits.back(), edits.back(), cpu});
    }
    const CpuTime cpuEnd = cpuNow();
    const std::uint64_t sceneVerticesSent = view->sceneVerticesUploaded() - sceneVertices;
    window.session().discardAutosave(); // a measurement leaves no recovery behind
    std::vector<double> all = moves;
    all.insert(all.end(), commits.begin(), commits.end());
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    };
    auto ms = [](double v) { return std::round(v * 100.0) / 100.0; };
    double worstGuiCpu = 0.0, worstProcessCpu = 0.0;
    for (const Frame& f : frames) {
        worstGuiCpu = std::max(worstGuiCpu, f.cpu.gui);
        worstProcessCpu = std::max(worstProcessCpu, f.cpu.process);
    }
    std::sort(frames.begin(), frames.end(), [](const Frame& a, const Frame& b) { return a.ms > b.ms; });
    nlohmann::json slowest = nlohmann::json::array();
    for (std::size_t i = 0; i < std::min<std::size_t>(5, frames.size()); ++i)
        slowest.push_back({{"drag", frames[i].drag},
                           {"kind", frames[i].commit ? "commit" : "move"},
                           {"ms", ms(frames[i].ms)},
                           {"edit_ms", ms(frames[i].editMs)},
                           {"gui_cpu_ms", ms(frames[i].cpu.gui)},
                           {"process_cpu_ms", ms(frames[i].cpu.process)}});
    const nlohmann::json report{{"drags", drags},
                                {"frames", all.size()},
                                {"median_ms", ms(median(all))},
                                {"worst_ms", ms(*std::max_element(all.begin(), all.end()))},
                                {"preview_median_ms", ms(median(moves))},
                                {"commit_median_ms", ms(median(commits))},
                                {"idle_frame_median_ms", ms(median(idle))},
                                // What an edit adds to a repaint: the session's rebuild, the views' refresh and the uploads.
                                {"edit_over_idle_median_ms", ms(median(all) - median(idle))},
                                {"edit_median_ms", ms(median(edits))},
                                {"edit_worst_ms", ms(*std::max_element(edits.begin(), edits.end()))},
                                {"cpu_ms_per_frame", ms((cpuEnd.process - cpuStart.process) / double(all.size()))},
                                {"gui_thread_cpu_ms_per_frame", ms((cpuEnd.thread - cpuStart.thread) / double(all.size()))},
                                {"viewport_px", {int(view->width() * view->devicePixelRatio()), int(view->height() * view->devicePixelRatio())}},
                                {"window_px", {window.width(), window.height()}},
                                {"build_ms", ms(window.session().lastBuildMilliseconds())},
                                // The scene layers' vertices: a full upload, and what an edit's frame sent on average
                                // (the dragged joint's instance and those hanging from it or above it).
                                {"scene_vertices", sceneVertices},
                                {"scene_vertices_per_frame", sceneVerticesSent / std::max<std::size_t>(1, all.size())},
                                {"slowest_frames", slowest},
                                // The most CPU one frame took: what the worst frame would be without contention.
                                {"worst_frame_gui_cpu_ms", ms(worstGuiCpu)},
                                {"worst_frame_process_cpu_ms", ms(worstProcessCpu)},
                                {"undo_steps", window.session().history().size()}};
    std::printf("%s\n", report.dump().c_str());
    std::fflush(stdout);
    return 0;
}

int reportRigEditLatency(MainWindow& window, const std::string& path, int drags)
{
    auto* view = window.viewportWidget();
    window.setAutosaveEnabled(false);
    window.buildRig();
    auto& session = window.session();
    session.setMode(EditorMode::Rig);
    QApplication::processEvents();
    const auto* rig = session.rig();
    const auto node = rig ? rig->findPath(path) : std::nullopt;
    if (!node || !session.evaluation()) {
        std::fprintf(stderr, "rigsmith: no controller %s in the built rig\n", path.c_str());
        return 1;
    }
    session.selectControllers({*node}, false);
    timeToFrame(view, [] {}); // shaders, buffers, the meshes' first upload
    std::vector<double> idle;
    for (int i = 0; i < 20; ++i)
        idle.push_back(timeToFrame(view, [] {}));
    const std::uint64_t meshVertices = view->meshVerticesUploaded(), weights = view->weightVerticesUploaded();
    std::vector<double> moves, commits;
    const int steps = 4;
    for (int d = 0; d < drags; ++d) {
        const Mat4 start = session.evaluation()->worldMatrix(*node);
        emit view->gizmoDragStarted(*node);
        for (int s = 1; s <= steps; ++s) {
            const double angle = 0.15 * s * (d % 2 == 0 ? 1.0 : -1.0); // out and back: the pose stays put
            Mat4 world = start * glm::dmat4(rotationMatrix(Vec3(0.0, 0.0, 1.0), angle));
            moves.push_back(timeToFrame(view, [&] { emit view->gizmoDragged(*node, world); }));
        }
        commits.push_back(timeToFrame(view, [&] { emit view->gizmoDragFinished(*node); }));
    }
    session.discardAutosave();
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    };
    auto ms = [](double v) { return std::round(v * 100.0) / 100.0; };
    std::vector<double> all = moves;
    all.insert(all.end(), commits.begin(), commits.end());
    std::size_t meshVertexCount = 0;
    for (const auto& m : session.characterMeshes())
        meshVertexCount += m.data(session.models()).vertexCount();
    const nlohmann::json report{{"controller", path},
                                {"drags", drags},
                                {"frames", all.size()},
                                {"median_ms", ms(median(all))},
                                {"worst_ms", ms(*std::max_element(all.begin(), all.end()))},
                                {"preview_median_ms", ms(median(moves))},
                                {"idle_frame_median_ms", ms(median(idle))},
                                {"edit_over_idle_median_ms", ms(median(all) - median(idle))},
                                {"meshes", session.characterMeshes().size()},
                                {"mesh_vertices", meshVertexCount},
                                {"skin_bones", session.skinBones().size()},
                                {"mesh_vertices_sent_while_posing", view->meshVerticesUploaded() - meshVertices},
                                {"weights_sent_while_posing", view->weightVerticesUploaded() - weights},
                                {"viewport_px", {int(view->width() * view->devicePixelRatio()), int(view->height() * view->devicePixelRatio())}}};
    std::printf("%s\n", report.dump().c_str());
    std::fflush(stdout);
    return 0;
}

} // namespace rs::app
