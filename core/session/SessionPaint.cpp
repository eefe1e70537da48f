// Weight painting: brush dabs, whole-mesh operations, mirroring, copy and
// paste, joint locks and the vertex selection, all as undoable weight edits
// on the guide's bindings (skin/WeightTools does the arithmetic).
#include "session/Session.h"

#include <algorithm>

namespace rs::session {

namespace {

std::string keyText(const NodeKey& key) { return key.tag + (key.branch.empty() ? "" : " (" + key.branch + ")"); }

edit::WeightEdit editOf(std::size_t binding, std::vector<skin::VertexInfluences> changes)
{
    edit::WeightEdit e;
    e.binding = binding;
    for (skin::VertexInfluences& c : changes)
        e.vertices.push_back({c.vertex, std::move(c.influences)});
    return e;
}

} // namespace

void Session::setJointLocked(const NodeKey& joint, bool locked)
{
    if (locked ? m_lockedJoints.insert(joint).second : m_lockedJoints.erase(joint) > 0)
        emitChange(Change::of(ChangeKind::Selection));
}

void Session::selectVertices(std::size_t mesh, std::vector<std::uint32_t> vertices, bool add)
{
    if (!add)
        m_selectedVertices.clear();
    if (mesh < m_characterMeshes.size()) {
        std::vector<std::uint32_t>& list = m_selectedVertices[mesh];
        const std::size_t count = m_characterMeshes[mesh].data(m_models).vertexCount();
        for (std::uint32_t v : vertices)
            if (v < count)
                list.push_back(v);
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        if (list.empty())
            m_selectedVertices.erase(mesh);
    }
    emitChange(Change::of(ChangeKind::Selection));
}

void Session::clearVertexSelection()
{
    if (m_selectedVertices.empty())
        return;
    m_selectedVertices.clear();
    emitChange(Change::of(ChangeKind::Selection));
}

const skin::Surface& Session::surfaceOf(std::size_t mesh)
{
    const model::Mesh& data = m_characterMeshes[mesh].data(m_models);
    auto& cached = m_surfaces[&data];
    if (!cached)
        cached = std::make_shared<const skin::Surface>(skin::makeSurface(data));
    return *cached;
}

std::uint32_t Session::jointIndex(edit::WeightEdit& e, const NodeKey& key) const
{
    const model::MeshWeights& w = m_document.bindings[e.binding].weights;
    const std::vector<NodeKey>& joints = e.joints.empty() ? w.joints : e.joints;
    if (auto it = std::find(joints.begin(), joints.end(), key); it != joints.end())
        return std::uint32_t(it - joints.begin());
    if (e.joints.empty()) {
        e.joints = w.joints;
        e.parents = w.parents;
    }
    // Its skin parent, when the binding has it, keeps the hierarchy gone joints are handed up.
    std::int32_t parent = -1;
    auto bone = std::find_if(m_skinBones.begin(), m_skinBones.end(), [&](const skin::SkinBone& b) { return b.key == key; });
    if (bone != m_skinBones.end() && bone->parent >= 0)
        if (auto it = std::find(e.joints.begin(), e.joints.end(), m_skinBones[std::size_t(bone->parent)].key); it != e.joints.end())
            parent = std::int32_t(it - e.joints.begin());
    e.joints.push_back(key);
    e.parents.push_back(parent);
    return std::uint32_t(e.joints.size() - 1);
}

skin::WeightContext Session::weightContext(std::size_t mesh, const model::MeshWeights& weights)
{
    skin::WeightContext c{&m_characterMeshes[mesh].data(m_models), &surfaceOf(mesh), &weights, {}};
    for (const NodeKey& key : weights.joints)
        c.locked.push_back(m_lockedJoints.count(key) > 0);
    return c;
}

Status Session::paintWeights(std::size_t mesh, const NodeKey& joint, skin::Brush brush)
{
    if (mesh >= m_characterMeshes.size() || m_characterMeshes[mesh].binding < 0)
        return Status::refused("bind the mesh before painting its weights");
    const CharacterMesh& cm = m_characterMeshes[mesh];
    const model::Mesh& data = cm.data(m_models);
    if (cm.changed)
        return Status::refused("mesh '" + data.name + "' changed since it was bound: bind it again before painting", Subject::ofMesh(data.name));
    if (m_lockedJoints.count(joint) && brush.mode != skin::BrushMode::Smooth)
        return Status::refused(keyText(joint) + " is locked: unlock it to paint it");
    edit::WeightEdit e;
    e.binding = std::size_t(cm.binding);
    brush.joint = jointIndex(e, joint);
    // The tools read the weights with the joint appended (it has no influence yet).
    model::MeshWeights grown;
    const model::MeshWeights* weights = &m_document.bindings[e.binding].weights;
    if (!e.joints.empty()) {
        grown = *weights;
        grown.joints = e.joints;
        grown.parents = e.parents;
        weights = &grown;
    }
    const skin::WeightContext context = weightContext(mesh, *weights);
    std::vector<skin::VertexInfluences> changes = skin::brushDab(context, brush);
    if (changes.empty())
        return Status::success(); // nothing under the brush changes: no step
    edit::WeightEdit dab = editOf(e.binding, std::move(changes));
    dab.joints = std::move(e.joints);
    dab.parents = std::move(e.parents);
    const char* verbs[] = {"Add", "Subtract", "Replace", "Smooth"};
    return edit::setVertexWeights(m_history, std::move(dab), std::string(verbs[int(brush.mode)]) + " weights of " + keyText(joint));
}

Status Session::applyWeightOperation(WeightOperation operation, double amount)
{
    const char* names[] = {"Smooth weights", "Prune weights", "Normalise weights", "Limit influences"};
    const std::string what = names[int(operation)];
    m_history.begin(what);
    bool any = false;
    for (std::size_t mesh = 0; mesh < m_characterMeshes.size(); ++mesh) {
        const CharacterMesh& cm = m_characterMeshes[mesh];
        if (cm.binding < 0 || cm.changed)
            continue;
        std::vector<std::uint32_t> vertices;
        if (!m_selectedVertices.empty()) {
            auto it = m_selectedVertices.find(mesh);
            if (it == m_selectedVertices.end())
                continue;
            vertices = it->second;
        }
        const model::MeshWeights& weights = m_document.bindings[std::size_t(cm.binding)].weights;
        const skin::WeightContext context = weightContext(mesh, weights);
        std::vector<skin::VertexInfluences> changes;
        switch (operation) {
        case WeightOperation::Smooth: changes = skin::smoothWeights(context, vertices, std::clamp(amount, 0.0, 1.0), 1); break;
        case WeightOperation::Prune: changes = skin::pruneWeights(context, vertices, amount); break;
        case WeightOperation::Normalise: changes = skin::normaliseWeights(context, vertices); break;
        case WeightOperation::Limit: changes = skin::limitWeights(context, vertices, int(amount)); break;
        }
        if (changes.empty())
            continue;
        if (Status s = edit::setVertexWeights(m_history, editOf(std::size_t(cm.binding), std::move(changes)), what); s.failed()) {
            m_history.rollback();
            return s;
        }
        any = true;
    }
    if (!any) {
        m_history.rollback();
        return Status::refused(m_characterMeshes.empty() ? "there is no bound mesh" : "nothing to change: the weights already are so");
    }
    m_history.commit(what);
    return {};
}

Status Session::mirrorWeights(bool fromPositive)
{
    if (!m_rig)
        return Status::refused("build the rig first: mirroring swaps each skin joint for its twin");
    const std::string what = fromPositive ? "Mirror weights +X to -X" : "Mirror weights -X to +X";
    m_history.begin(what);
    std::size_t unmatched = 0;
    bool any = false;
    for (std::size_t mesh = 0; mesh < m_characterMeshes.size(); ++mesh) {
        const CharacterMesh& cm = m_characterMeshes[mesh];
        if (cm.binding < 0 || cm.changed)
            continue;
        edit::WeightEdit e;
        e.binding = std::size_t(cm.binding);
        const model::MeshWeights& stored = m_document.bindings[e.binding].weights;
        std::vector<std::uint32_t> mirror(stored.joints.size());
        for (std::size_t j = 0; j < stored.joints.size(); ++j) {
            mirror[j] = std::uint32_t(j);
            if (auto node = m_rig->find(stored.joints[j]); node && m_rig->nodes[*node].twin != model::kNoNode)
                mirror[j] = jointIndex(e, m_rig->nodes[m_rig->nodes[*node].twin].key);
        }
        model::MeshWeights grown;
        const model::MeshWeights* weights = &stored;
        if (!e.joints.empty()) {
            grown = stored;
            grown.joints = e.joints;
            grown.parents = e.parents;
            weights = &grown;
            mirror.resize(e.joints.size());
            for (std::size_t j = stored.joints.size(); j < e.joints.size(); ++j) // the twins appended: their twins are known
                mirror[j] = std::uint32_t(std::find(mirror.begin(), mirror.begin() + std::ptrdiff_t(stored.joints.size()), std::uint32_t(j)) -
                                          mirror.begin());
        }
        const skin::WeightContext context = weightContext(mesh, *weights);
        skin::MirrorResult result = skin::mirrorWeights(context, mirror, 0, fromPositive, 1e-3);
        unmatched += result.unmatched;
        if (result.vertices.empty())
            continue;
        edit::WeightEdit m = editOf(e.binding, std::move(result.vertices));
        m.joints = std::move(e.joints);
        m.parents = std::move(e.parents);
        if (Status s = edit::setVertexWeights(m_history, std::move(m), what); s.failed()) {
            m_history.rollback();
            return s;
        }
        any = true;
    }
    if (!any) {
        m_history.rollback();
        return Status::refused(unmatched ? "no vertex has a mirror image within 1 mm across x = 0" : "nothing to mirror");
    }
    m_history.commit(what);
    Diagnostics notes;
    if (unmatched)
        notes.push_back(makeWarning({}, std::to_string(unmatched) +
                                            " vertices have no mirror image within 1 mm across x = 0 (the mesh is not symmetric there); they keep their weights"));
    return Status::success(std::move(notes));
}

Status Session::copyVertexWeights()
{
    for (const auto& [mesh, vertices] : m_selectedVertices) {
        const CharacterMesh& cm = m_characterMeshes[mesh];
        if (cm.binding < 0 || cm.changed || vertices.empty())
            continue;
        const model::MeshWeights& w = m_document.bindings[std::size_t(cm.binding)].weights;
        m_copiedWeights.clear();
        for (const model::Influence* i = w.begin(vertices.front()); i != w.end(vertices.front()); ++i)
            m_copiedWeights.emplace_back(w.joints[i->joint], i->weight);
        return {};
    }
    return Status::refused("select a vertex of a bound mesh to copy its weights");
}

Status Session::pasteVertexWeights()
{
    if (m_copiedWeights.empty())
        return Status::refused("copy a vertex's weights first");
    if (m_selectedVertices.empty())
        return Status::refused("select the vertices to paste the weights onto");
    m_history.begin("Paste vertex weights");
    bool any = false;
    for (const auto& [mesh, vertices] : m_selectedVertices) {
        const CharacterMesh& cm = m_characterMeshes[mesh];
        if (cm.binding < 0 || cm.changed)
            continue;
        edit::WeightEdit e;
        e.binding = std::size_t(cm.binding);
        std::vector<model::Influence> influences;
        for (const auto& [key, weight] : m_copiedWeights)
            influences.push_back({jointIndex(e, key), weight});
        const model::MeshWeights& w = m_document.bindings[e.binding].weights;
        for (std::uint32_t v : vertices)
            if (std::vector<model::Influence>(w.begin(v), w.end(v)) != influences)
                e.vertices.push_back({v, influences});
        if (e.vertices.empty() && e.joints.empty())
            continue;
        if (Status s = edit::setVertexWeights(m_history, std::move(e), "Paste vertex weights"); s.failed()) {
            m_history.rollback();
            return s;
        }
        any = true;
    }
    if (!any) {
        m_history.rollback();
        return Status::refused("the selected vertices already have these weights");
    }
    m_history.commit();
    return {};
}

} // namespace rs::session
