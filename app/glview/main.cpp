// rigsmith-glview: shows a built guide in a plain GLFW window (no Qt), through
// the same renderer as the editor's viewport.
//   rigsmith-glview GUIDE.yml      left drag orbits, middle drag pans, wheel zooms, F frames
#include "GlfwHost.h"

#include "rigging/RigBuilder.h"
#include "io/GuideFile.h"
#include "io/TemplateFolders.h"

#include <algorithm>
#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: rigsmith-glview GUIDE.yml\n";
        return 2;
    }
    auto guide = rs::io::readGuideFile(argv[1]);
    std::cerr << rs::formatAll(guide.diagnostics());
    if (!guide)
        return 1;
    rs::Diagnostics diagnostics;
    auto templates = rs::io::loadDefaultTemplates(diagnostics);
    const rs::model::Rig rig = rs::rigging::buildRig(*guide, *templates);
    std::cerr << rs::formatAll(diagnostics) << rs::formatAll(rig.diagnostics);
    std::string error;
    auto host = rs::viewport::GlfwHost::create(1280, 800, std::string("Rigsmith - ") + argv[1], true, error);
    if (!host) {
        std::cerr << "rigsmith-glview: " << error << '\n';
        return 1;
    }
    const rs::viewport::Scene scene = rs::viewport::makeScene(*guide, &rig, {});
    rs::viewport::Camera camera;
    glm::dvec3 lo, hi;
    if (scene.bounds(lo, hi))
        camera.frame(lo, hi, double(host->width()) / std::max(1, host->height()));
    host->run(scene, camera);
    return 0;
}
