// View > Display > Skin Chunk Steps (issue 20): each vertex of the character
// coloured by the step that placed its weights, outside weight painting: the
// routes of the last chunk import or preview, or of the re-fit of a changed
// mesh; a bound mesh nothing imported onto since the guide was opened shows
// its record loaded 1:1. The Skin Chunks dock has the same switch and the legend.
#include "MainWindow.h"

#include "ActionKit.h"
#include "SkinChunkPanel.h"
#include "templates/Color.h"

#include <QAction>
#include <QCheckBox>
#include <QMenu>

#include <cmath>

namespace rs::app {

namespace {

using session::VertexRoute;

struct Step {
    VertexRoute route;
    glm::vec3 colour; // linear RGB, as the renderer shades it
    const char* text;
};

constexpr Step kSteps[] = {
    {VertexRoute::OneToOne, {0.10f, 0.80f, 0.20f}, "1:1"},
    {VertexRoute::Transferred, {1.00f, 0.55f, 0.02f}, "transferred"},
    {VertexRoute::Inpainted, {0.85f, 0.08f, 0.90f}, "inpainted"},
    {VertexRoute::SingleInfluence, {0.10f, 0.55f, 1.00f}, "single influence"},
};

glm::vec3 colourOf(VertexRoute route)
{
    for (const Step& s : kSteps)
        if (s.route == route)
            return s.colour;
    return glm::vec3(0.5f);
}

} // namespace

glm::vec3 MainWindow::routeColour(session::VertexRoute route) { return colourOf(route); }

void MainWindow::createRouteOverlay()
{
    QAction* show = makeAction(this, "display:routes", tr("Skin Chunk &Steps"), {});
    show->setCheckable(true);
    show->setToolTip(tr("Colour each vertex by the step that placed its weights: 1:1 green, transferred orange, inpainted "
                        "magenta, single influence blue (the last import, preview or re-fit)"));
    if (QMenu* display = findChild<QMenu*>("displayMenu"))
        display->addAction(show);
    QList<QPair<QColor, QString>> legend;
    for (const Step& s : kSteps) // the renderer's linear colours, shown as sRGB
        legend.push_back({QColor::fromRgbF(float(templates::linearToSrgb(s.colour.r)), float(templates::linearToSrgb(s.colour.g)),
                                           float(templates::linearToSrgb(s.colour.b))),
                          tr(s.text)});
    m_chunkPanel->setRouteLegend(legend);
    connect(show, &QAction::toggled, this, [this](bool on) {
        m_showRoutes = on;
        m_chunkPanel->setRouteColours(on);
        refreshScene();
    });
    connect(m_chunkPanel, &widgets::SkinChunkPanel::routeColoursToggled, show, &QAction::setChecked);
}

void MainWindow::setRoutes(std::size_t characterMesh, std::vector<session::VertexRoute> routes)
{
    m_routes[characterMesh] = std::move(routes);
    m_routeColours.erase(characterMesh);
}

void MainWindow::clearRoutes()
{
    m_routes.clear();
    m_routeColours.clear();
}

void MainWindow::applyRouteColours(viewport::Scene& scene)
{
    const auto& meshes = m_session.characterMeshes();
    for (viewport::SceneMesh& m : scene.meshes) {
        if (m.characterMesh >= meshes.size())
            continue;
        const session::CharacterMesh& c = meshes[m.characterMesh];
        const std::size_t count = m.data().vertexCount();
        auto routes = m_routes.find(m.characterMesh);
        const bool known = routes != m_routes.end() && routes->second.size() == count;
        if (!known && !c.weights)
            continue; // unbound or changed, and no import said how: no colour
        RouteColours& cached = m_routeColours[m.characterMesh];
        if (!cached.colours || cached.mesh != &m.data() || cached.fromRoutes != known) {
            auto colours = std::make_shared<std::vector<glm::vec3>>(count, colourOf(VertexRoute::OneToOne));
            if (known)
                for (std::size_t v = 0; v < count; ++v)
                    (*colours)[v] = colourOf(routes->second[v]);
            cached = {&m.data(), known, std::move(colours)};
        }
        m.vertexColors = cached.colours;
    }
}

} // namespace rs::app
