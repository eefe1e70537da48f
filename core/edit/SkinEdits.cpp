#include "edit/SkinEdits.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace rs::edit {

using model::GuideDocument;
using model::MeshBinding;

namespace {

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// The models list and the bindings, swapped wholesale: adding or removing a model.
class SetModels final : public Command {
public:
    SetModels(const GuideDocument& d, std::vector<std::string> models, std::vector<MeshBinding> bindings, std::string what)
        : m_models(std::move(models)), m_bindings(std::move(bindings)), m_what(std::move(what)),
          m_bindingsChange(m_bindings != d.bindings) {}
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override { swap(d); }
    void undo(GuideDocument& d) override { swap(d); }
    Change change() const override
    {
        return Change::of(m_bindingsChange ? ChangeKind::Models | ChangeKind::Weights : std::uint32_t(ChangeKind::Models));
    }

private:
    void swap(GuideDocument& d)
    {
        std::swap(d.models, m_models);
        std::swap(d.bindings, m_bindings);
    }
    std::vector<std::string> m_models;
    std::vector<MeshBinding> m_bindings;
    std::string m_what;
    bool m_bindingsChange;
};

class SetBindings final : public Command {
public:
    SetBindings(std::vector<MeshBinding> bindings, std::vector<std::size_t> changed, std::string what)
        : m_bindings(std::move(bindings)), m_changed(std::move(changed)), m_what(std::move(what)) {}
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override { std::swap(d.bindings, m_bindings); }
    void undo(GuideDocument& d) override { std::swap(d.bindings, m_bindings); }
    // Records are only replaced or appended, so the changed indices hold both ways.
    Change change() const override
    {
        Change c = Change::of(ChangeKind::Weights);
        c.bindings = m_changed;
        return c;
    }

private:
    std::vector<MeshBinding> m_bindings;
    std::vector<std::size_t> m_changed;
    std::string m_what;
};

// Sparse: only the vertices an edit touched, before and after.
class SetVertexWeights final : public Command {
public:
    SetVertexWeights(WeightEdit after, WeightEdit before, std::string what)
        : m_after(std::move(after)), m_before(std::move(before)), m_what(std::move(what)) {}
    std::string text() const override { return m_what; }
    void redo(GuideDocument& d) override { apply(d.bindings[m_after.binding].weights, m_after); }
    void undo(GuideDocument& d) override { apply(d.bindings[m_before.binding].weights, m_before); }
    Change change() const override
    {
        Change c = Change::of(ChangeKind::Weights);
        c.bindings = {m_after.binding};
        return c;
    }

private:
    static void apply(model::MeshWeights& w, const WeightEdit& edit)
    {
        if (!edit.joints.empty()) {
            w.joints = edit.joints;
            w.parents = edit.parents;
        }
        model::MeshWeights out;
        out.joints = std::move(w.joints);
        out.parents = std::move(w.parents);
        out.offsets.reserve(w.offsets.size());
        out.influences.reserve(w.influences.size() + edit.vertices.size() * 2);
        out.offsets.push_back(0);
        auto next = edit.vertices.begin();
        for (std::size_t v = 0; v < w.vertexCount(); ++v) {
            if (next != edit.vertices.end() && next->vertex == v) {
                out.influences.insert(out.influences.end(), next->influences.begin(), next->influences.end());
                ++next;
            } else {
                out.influences.insert(out.influences.end(), w.begin(v), w.end(v));
            }
            out.offsets.push_back(std::uint32_t(out.influences.size()));
        }
        w = std::move(out);
    }
    WeightEdit m_after, m_before;
    std::string m_what;
};

Subject meshSubject(const MeshBinding& b) { return Subject::ofMesh(b.mesh); }

} // namespace

Status addModel(History& history, const std::string& path)
{
    const GuideDocument& d = history.document();
    if (path.empty())
        return Status::refused("no model file given");
    if (std::find(d.models.begin(), d.models.end(), path) != d.models.end())
        return Status::refused(path + " is already one of the guide's models", Subject::ofFile(path));
    auto models = d.models;
    models.push_back(path);
    history.push(std::make_unique<SetModels>(d, std::move(models), d.bindings, "Add model " + fileName(path)));
    return {};
}

Status removeModel(History& history, const std::string& path)
{
    const GuideDocument& d = history.document();
    auto models = d.models;
    auto it = std::find(models.begin(), models.end(), path);
    if (it == models.end())
        return Status::refused(path + " is not one of the guide's models", Subject::ofFile(path));
    models.erase(it);
    auto bindings = d.bindings;
    std::erase_if(bindings, [&](const MeshBinding& b) { return b.model == path; });
    history.push(std::make_unique<SetModels>(d, std::move(models), std::move(bindings), "Remove model " + fileName(path)));
    return {};
}

Status setBindings(History& history, std::vector<MeshBinding> bindings, const std::string& what)
{
    const GuideDocument& d = history.document();
    if (bindings.empty())
        return Status::refused("no weights to set");
    auto result = d.bindings;
    std::vector<std::size_t> changed;
    for (MeshBinding& b : bindings) {
        if (std::find(d.models.begin(), d.models.end(), b.model) == d.models.end())
            return Status::refused("mesh '" + b.mesh + "': " + b.model + " is not one of the guide's models", meshSubject(b));
        if (b.weights.vertexCount() != b.vertexCount || b.weights.parents.size() != b.weights.joints.size())
            return Status::refused("mesh '" + b.mesh + "': its weights do not fit its " + std::to_string(b.vertexCount) + " vertices",
                                   meshSubject(b));
    }
    // The n-th new record of a (model, mesh) pairs with the n-th existing one.
    std::vector<std::size_t> used;
    for (MeshBinding& b : bindings) {
        std::size_t at = result.size();
        for (std::size_t i = 0; i < d.bindings.size(); ++i)
            if (d.bindings[i].model == b.model && d.bindings[i].mesh == b.mesh &&
                std::find(used.begin(), used.end(), i) == used.end()) {
                at = i;
                break;
            }
        if (at < d.bindings.size()) {
            used.push_back(at);
            result[at] = std::move(b);
        } else {
            result.push_back(std::move(b));
        }
        changed.push_back(at < d.bindings.size() ? at : result.size() - 1);
    }
    history.push(std::make_unique<SetBindings>(std::move(result), std::move(changed), what));
    return {};
}

Status setVertexWeights(History& history, WeightEdit edit, const std::string& what)
{
    const GuideDocument& d = history.document();
    if (edit.binding >= d.bindings.size())
        return Status::refused("no skin weights record " + std::to_string(edit.binding));
    const MeshBinding& b = d.bindings[edit.binding];
    const model::MeshWeights& w = b.weights;
    if (!edit.joints.empty()) {
        if (edit.joints.size() < w.joints.size() || !std::equal(w.joints.begin(), w.joints.end(), edit.joints.begin()) ||
            edit.parents.size() != edit.joints.size())
            return Status::refused("mesh '" + b.mesh + "': a weight edit may only add joints", meshSubject(b));
    }
    const std::size_t jointCount = edit.joints.empty() ? w.joints.size() : edit.joints.size();
    WeightEdit before;
    before.binding = edit.binding;
    if (!edit.joints.empty()) {
        before.joints = w.joints;
        before.parents = w.parents;
    }
    bool changes = edit.joints.size() > w.joints.size();
    std::int64_t last = -1;
    for (const VertexWeights& v : edit.vertices) {
        if (v.vertex >= w.vertexCount() || std::int64_t(v.vertex) <= last)
            return Status::refused("mesh '" + b.mesh + "': vertex " + std::to_string(v.vertex) + " is out of range or out of order",
                                   meshSubject(b));
        last = v.vertex;
        double sum = 0.0;
        for (const model::Influence& i : v.influences) {
            if (i.joint >= jointCount || !std::isfinite(i.weight) || i.weight < 0.0f)
                return Status::refused("mesh '" + b.mesh + "': vertex " + std::to_string(v.vertex) + " has a bad influence", meshSubject(b));
            sum += i.weight;
        }
        if (std::abs(sum - 1.0) > 1e-3)
            return Status::refused("mesh '" + b.mesh + "': vertex " + std::to_string(v.vertex) + "'s weights sum to " + std::to_string(sum),
                                   meshSubject(b));
        VertexWeights old{v.vertex, std::vector<model::Influence>(w.begin(v.vertex), w.end(v.vertex))};
        changes = changes || old.influences != v.influences;
        before.vertices.push_back(std::move(old));
    }
    if (!changes)
        return Status::refused("the weights did not change");
    history.push(std::make_unique<SetVertexWeights>(std::move(edit), std::move(before), what));
    return {};
}

} // namespace rs::edit
