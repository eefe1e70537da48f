#pragma once
// The options editor dock (issue 7): typed widgets generated from the selected
// instance's template manifest, `opts` (and `guides`, shown apart): a check box
// for booleans, a combo with the labels for enums, a spin box within min/max
// (with a slider when both are given) for numbers, a line edit for text and
// YAML text (validated), three spin boxes for vectors. `help` is the tooltip;
// values that differ from the default are shown bold with a reset button.
// Edits are not applied here: optionEdited(instance, name, value) goes to the
// owner, which makes it one undo step (edit::setOption).
#include "model/GuideDocument.h"
#include "templates/Manifest.h"

#include <QWidget>

class QFormLayout;
class QLabel;
class QScrollArea;

namespace rs::widgets {

class OptionsEditor : public QWidget {
    Q_OBJECT
public:
    explicit OptionsEditor(QWidget* parent = nullptr);

    // Shows `instance`'s options (null clears). Keeps the widget under the
    // keyboard focus when the same instance is shown again.
    void setInstance(const model::TemplateInstance* instance, const templates::TemplateManifest* manifest);
    model::InstanceId instance() const { return m_instance; }
    // The editing widget of an option (tests), null when not shown.
    QWidget* editorFor(const std::string& name) const;

signals:
    void optionEdited(rs::model::InstanceId instance, const std::string& name, const rs::Value& value);

private:
    void addParameter(QFormLayout* form, const templates::Parameter& parameter, const Value& value);
    QWidget* makeEditor(const templates::Parameter& parameter, const Value& value);

    model::InstanceId m_instance = model::kNoId;
    QLabel* m_title = nullptr;
    QScrollArea* m_scroll = nullptr;
    QWidget* m_body = nullptr;
    std::map<std::string, QWidget*> m_editors;
};

} // namespace rs::widgets
