#pragma once
// The options editor dock (issue 7): typed widgets generated from the selected
// instance's template manifest, `opts` (and `guides`, shown apart): a check box
// for booleans, a combo with the labels for enums, a spin box within min/max
// (with a slider when both are given) for numbers, a line edit for text and
// YAML text (validated), three spin boxes for vectors. Enums (an index or a
// label list, `enum:` in the manifest) are combo boxes; a number with a min or
// max shows its range beside it, and a value outside it (typed or stored)
// turns the field red with the error in place of the range. `help` is the tooltip;
// values that differ from the default are shown bold with a reset button.
// A "Names" group lists the manifest's name tokens with the instance's
// overrides (placeholder: the default name). The "?" button asks for the
// template's help page. Edits are not applied here:
// optionEdited / nameEdited go to the owner, which makes each one undo step.
#include "model/GuideDocument.h"
#include "templates/Manifest.h"

#include <QWidget>

class QAbstractSpinBox;
class QFormLayout;
class QHBoxLayout;
class QLabel;
class QScrollArea;
class QToolButton;
class QVBoxLayout;

namespace rs::widgets {

class OptionsEditor : public QWidget {
    Q_OBJECT
public:
    explicit OptionsEditor(QWidget* parent = nullptr);

    // Shows `instance`'s options (null clears). Keeps the widget under the
    // keyboard focus when the same instance is shown again.
    void setInstance(const model::TemplateInstance* instance, const templates::TemplateManifest* manifest);
    model::InstanceId instance() const { return m_instance; }
    // After an edit made in this editor: marks the shown options that differ
    // from their defaults (bold, reset enabled) without rebuilding any widget,
    // so a spinner being turned keeps turning.
    void showChanged(const model::TemplateInstance& instance);
    // The editing widget of an option (tests), null when not shown.
    QWidget* editorFor(const std::string& name) const;

signals:
    void optionEdited(rs::model::InstanceId instance, const std::string& name, const rs::Value& value);
    // An empty name removes the override.
    void nameEdited(rs::model::InstanceId instance, const std::string& token, const QString& name);
    // The header's "?" button: the shown template's help page is wanted.
    void helpRequested(const std::string& templateId);

private:
    void addParameter(QFormLayout* form, const templates::Parameter& parameter, const Value& value);
    QWidget* makeEditor(const templates::Parameter& parameter, const Value& value);
    // The range label after a number field ("range:<name>"), red with the error when out of range.
    void addRange(QHBoxLayout* layout, const templates::Parameter& parameter, QAbstractSpinBox* box, double stored);
    void addNames(QVBoxLayout* layout, const model::TemplateInstance& instance, const templates::TemplateManifest& manifest);

    model::InstanceId m_instance = model::kNoId;
    QLabel* m_title = nullptr;
    QToolButton* m_help = nullptr;
    std::string m_templateId;
    QScrollArea* m_scroll = nullptr;
    QWidget* m_body = nullptr;
    std::map<std::string, QWidget*> m_editors;
    struct Marks {
        QLabel* label = nullptr;
        QWidget* reset = nullptr;
        Value defaultValue;
    };
    std::map<std::string, Marks> m_marks; // by option name
};

} // namespace rs::widgets
