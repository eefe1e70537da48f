#include "OptionsEditor.h"

#include "WheelGuard.h"
#include "io/YamlText.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLineEdit>
#include <QRegularExpressionValidator>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace rs::widgets {

namespace {

constexpr double kUnbounded = 1e9;
constexpr int kSliderSteps = 1000;

QString text(const std::string& s) { return QString::fromStdString(s); }

// A guide's number, written either way (`ik_blend: 0` reads as an integer).
std::optional<double> numberOf(const Value& value)
{
    if (const auto* i = std::get_if<long long>(&value))
        return double(*i);
    if (const auto* d = std::get_if<double>(&value))
        return *d;
    return std::nullopt;
}

// A spin box that lets a number outside its range be typed (so the field can
// say why it is refused) and, when entered, clamps it to the range.
template <class Box>
class RangeBox : public Box {
public:
    explicit RangeBox(QWidget* parent) : Box(parent) { this->setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue); }

protected:
    QValidator::State validate(QString& input, int& position) const override
    {
        const QValidator::State state = Box::validate(input, position);
        bool number = false;
        QLocale().toDouble(input.trimmed(), &number);
        return state == QValidator::Invalid && number ? QValidator::Intermediate : state;
    }
};

QDoubleSpinBox* numberBox(QWidget* parent, double value, std::optional<double> min, std::optional<double> max)
{
    auto* box = new RangeBox<QDoubleSpinBox>(parent);
    box->setDecimals(4);
    box->setRange(min.value_or(-kUnbounded), max.value_or(kUnbounded));
    box->setSingleStep(min && max ? (*max - *min) / 100.0 : 0.1);
    box->setValue(value);
    box->setKeyboardTracking(false); // one edit per finished value, not per keystroke
    return box;
}

QString rangeText(std::optional<double> min, std::optional<double> max)
{
    const QString lo = min ? QString::number(*min) : QStringLiteral("-\u221E");
    const QString hi = max ? QString::number(*max) : QStringLiteral("\u221E");
    return QStringLiteral("%1 \u2026 %2").arg(lo, hi);
}

// The range next to a number field, and its error state: a value outside it
// (typed, or read from the guide) turns the field red and the range label
// into the error, until the text is back in range.
void watchRange(QAbstractSpinBox* box, QLabel* range, std::optional<double> min, std::optional<double> max,
                std::optional<double> stored)
{
    const QString allowed = rangeText(min, max);
    auto show = [box, range, min, max, allowed](std::optional<double> value) {
        const bool bad = value && ((min && *value < *min) || (max && *value > *max));
        box->setProperty("rangeError", bad);
        box->setStyleSheet(bad ? "QAbstractSpinBox { border: 1px solid #d04040; }" : QString());
        range->setText(bad ? QObject::tr("%1 is outside %2").arg(QString::number(*value), allowed) : allowed);
        range->setStyleSheet(bad ? "color: #e05050" : "color: gray");
    };
    show(stored);
    if (auto* line = box->findChild<QLineEdit*>())
        QObject::connect(line, &QLineEdit::textEdited, box, [show](const QString& text) {
            bool ok = false;
            const double value = QLocale().toDouble(text.trimmed(), &ok);
            show(ok ? std::optional<double>(value) : std::nullopt);
        });
    QObject::connect(box, &QAbstractSpinBox::editingFinished, box, [show] { show(std::nullopt); }); // corrected back
}

} // namespace

OptionsEditor::OptionsEditor(QWidget* parent) : QWidget(parent)
{
    setObjectName("optionsEditor");
    auto* layout = new QVBoxLayout(this);
    m_title = new QLabel(tr("Select a template instance to edit its options"), this);
    m_title->setWordWrap(true);
    auto* header = new QHBoxLayout;
    header->addWidget(m_title, 1);
    m_help = new QToolButton(this);
    m_help->setObjectName("templateHelp");
    m_help->setText("?");
    m_help->setToolTip(tr("The template's help page: what it builds, a picture, its hooks and options (F1)"));
    m_help->setEnabled(false);
    connect(m_help, &QToolButton::clicked, this, [this] {
        if (!m_templateId.empty())
            emit helpRequested(m_templateId);
    });
    header->addWidget(m_help, 0, Qt::AlignTop);
    layout->addLayout(header);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    layout->addWidget(m_scroll, 1);
}

QWidget* OptionsEditor::editorFor(const std::string& name) const
{
    auto it = m_editors.find(name);
    return it == m_editors.end() ? nullptr : it->second;
}

void OptionsEditor::setInstance(const model::TemplateInstance* instance, const templates::TemplateManifest* manifest)
{
    m_instance = instance ? instance->id : model::kNoId;
    m_templateId = manifest ? manifest->id : std::string();
    m_help->setEnabled(manifest != nullptr);
    m_editors.clear();
    m_marks.clear();
    m_body = new QWidget; // a fresh page; setWidget below deletes the previous one
    auto* layout = new QVBoxLayout(m_body);
    if (!instance || !manifest) {
        m_scroll->setWidget(m_body);
        m_title->setText(instance ? tr("%1: template %2 is not loaded").arg(text(instance->name), text(instance->templateId))
                                  : tr("Select a template instance to edit its options"));
        return;
    }
    m_title->setText(tr("<b>%1</b> (%2)").arg(text(instance->name), text(manifest->id)));
    m_title->setToolTip(text(manifest->desc));
    auto group = [&](const QString& title, const std::vector<templates::Parameter>& parameters) {
        if (parameters.empty())
            return;
        auto* box = new QGroupBox(title, m_body);
        auto* form = new QFormLayout(box);
        for (const auto& p : parameters) {
            auto stored = instance->options.find(p.name);
            addParameter(form, p, stored == instance->options.end() ? p.value : stored->second);
        }
        layout->addWidget(box);
    };
    group(tr("Guides"), manifest->guides);
    group(tr("Options"), manifest->opts);
    addNames(layout, *instance, *manifest);
    layout->addStretch(1);
    m_scroll->setWidget(m_body); // shown whole, once filled
    guardWheel(m_body);
}

void OptionsEditor::addNames(QVBoxLayout* layout, const model::TemplateInstance& instance,
                             const templates::TemplateManifest& manifest)
{
    if (manifest.names.empty())
        return;
    auto* box = new QGroupBox(tr("Names"), m_body);
    box->setToolTip(tr("The name each part of the rig takes (c_<instance>_<name>_L); empty keeps the template's"));
    auto* form = new QFormLayout(box);
    const model::InstanceId id = m_instance;
    for (const auto& [token, fallback] : manifest.names) {
        const auto stored = instance.names.find(token);
        auto* edit = new QLineEdit(stored == instance.names.end() ? QString() : text(stored->second), box);
        edit->setObjectName(text("name:" + token));
        edit->setPlaceholderText(text(fallback));
        edit->setValidator(new QRegularExpressionValidator(QRegularExpression("[A-Za-z0-9_]*"), edit));
        connect(edit, &QLineEdit::editingFinished, this, [this, id, token = token, edit] {
            emit nameEdited(id, token, edit->text());
        });
        auto* label = new QLabel(text(token), box);
        if (stored != instance.names.end())
            label->setStyleSheet("font-weight: bold");
        m_editors["name:" + token] = edit;
        form->addRow(label, edit);
    }
    layout->addWidget(box);
}

void OptionsEditor::addParameter(QFormLayout* form, const templates::Parameter& parameter, const Value& value)
{
    const bool changed = !sameValue(value, parameter.value);
    auto* label = new QLabel(text(parameter.name), m_body);
    label->setToolTip(text(parameter.help));
    if (changed)
        label->setStyleSheet("font-weight: bold");
    auto* row = new QWidget(m_body);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    QWidget* editor = makeEditor(parameter, value);
    layout->addWidget(editor, 1);
    if (auto* box = editor->findChild<QSpinBox*>(); box && !parameter.isEnum())
        editor = box; // an integer's field, beside its range
    editor->setObjectName(text("option:" + parameter.name));
    editor->setToolTip(text(parameter.help));
    auto* reset = new QToolButton(row);
    reset->setObjectName(text("reset:" + parameter.name));
    reset->setText(QStringLiteral("\u21BA"));
    reset->setToolTip(tr("Reset to the default (%1)").arg(text(formatValue(parameter.value))));
    reset->setEnabled(changed);
    const model::InstanceId id = m_instance;
    connect(reset, &QToolButton::clicked, this,
            [this, id, name = parameter.name, fallback = parameter.value] { emit optionEdited(id, name, fallback); });
    layout->addWidget(reset);
    m_editors[parameter.name] = editor;
    m_marks[parameter.name] = {label, reset, parameter.value};
    form->addRow(label, row);
}

void OptionsEditor::showChanged(const model::TemplateInstance& instance)
{
    if (instance.id != m_instance)
        return;
    for (auto& [name, marks] : m_marks) {
        const auto stored = instance.options.find(name);
        const bool changed = stored != instance.options.end() && stored->second != marks.defaultValue;
        marks.label->setStyleSheet(changed ? "font-weight: bold" : "");
        marks.reset->setEnabled(changed);
    }
}

void OptionsEditor::addRange(QHBoxLayout* layout, const templates::Parameter& p, QAbstractSpinBox* box, double stored)
{
    auto* range = new QLabel(layout->parentWidget());
    range->setObjectName(text("range:" + p.name));
    range->setToolTip(tr("The values %1 takes").arg(text(p.name)));
    layout->addWidget(range);
    watchRange(box, range, p.min, p.max, stored);
}

QWidget* OptionsEditor::makeEditor(const templates::Parameter& p, const Value& value)
{
    const model::InstanceId id = m_instance;
    auto emitValue = [this, id, name = p.name](const Value& v) { emit optionEdited(id, name, v); };
    if (p.isEnum()) { // the manifest's values; stored as the default is (a label, or an index)
        auto* combo = new QComboBox(m_body);
        for (const auto& [index, label] : p.enumLabels)
            combo->addItem(text(label), QVariant::fromValue(index));
        if (const auto* index = std::get_if<long long>(&value))
            combo->setCurrentIndex(combo->findData(QVariant::fromValue(*index)));
        else
            combo->setCurrentIndex(combo->findText(text(formatValue(value))));
        const bool byLabel = typeOf(p.value) == ValueType::String;
        connect(combo, &QComboBox::activated, this, [combo, byLabel, emitValue](int) {
            emitValue(byLabel ? Value(combo->currentText().toStdString()) : Value(combo->currentData().toLongLong()));
        });
        return combo;
    }
    // A number edits as the option's kind, integer or not; a value of another
    // kind than the option's is shown as it is, read-only, not edited.
    const std::optional<double> number = numberOf(value);
    const bool numeric = typeOf(p.value) == ValueType::Int || typeOf(p.value) == ValueType::Float;
    if (numeric ? !number : typeOf(value) != typeOf(p.value)) {
        auto* label = new QLabel(text(formatValue(value)), m_body);
        label->setToolTip(tr("Not a value of this option's kind: edit it in the guide file"));
        return label;
    }
    switch (typeOf(p.value)) {
    case ValueType::Bool: {
        auto* box = new QCheckBox(m_body);
        box->setChecked(std::get<bool>(value));
        connect(box, &QCheckBox::toggled, this, [emitValue](bool on) { emitValue(Value(on)); });
        return box;
    }
    case ValueType::Int: {
        const long long current = std::llround(*number);
        auto* holder = new QWidget(m_body);
        auto* layout = new QHBoxLayout(holder);
        layout->setContentsMargins(0, 0, 0, 0);
        auto* box = new RangeBox<QSpinBox>(holder);
        box->setRange(int(p.min.value_or(-kUnbounded)), int(p.max.value_or(kUnbounded)));
        box->setValue(int(current));
        box->setKeyboardTracking(false);
        layout->addWidget(box, 1);
        if (p.min || p.max)
            addRange(layout, p, box, double(current));
        connect(box, &QSpinBox::valueChanged, this, [emitValue](int v) { emitValue(Value(static_cast<long long>(v))); });
        return holder;
    }
    case ValueType::Float: {
        auto* holder = new QWidget(m_body);
        auto* layout = new QHBoxLayout(holder);
        layout->setContentsMargins(0, 0, 0, 0);
        auto* box = numberBox(holder, *number, p.min, p.max);
        layout->addWidget(box);
        if (p.min || p.max)
            addRange(layout, p, box, *number);
        if (p.min && p.max && *p.max > *p.min) {
            auto* slider = new QSlider(Qt::Horizontal, holder);
            slider->setRange(0, kSliderSteps);
            const double lo = *p.min, span = *p.max - *p.min;
            slider->setValue(int(std::lround((*number - lo) / span * kSliderSteps)));
            connect(slider, &QSlider::sliderReleased, this,
                    [slider, box, lo, span] { box->setValue(lo + span * slider->value() / kSliderSteps); });
            layout->addWidget(slider, 1);
        }
        connect(box, &QDoubleSpinBox::valueChanged, this, [emitValue](double v) { emitValue(Value(v)); });
        return holder;
    }
    case ValueType::String: {
        auto* line = new QLineEdit(text(std::get<std::string>(value)), m_body);
        const bool yaml = p.yaml;
        connect(line, &QLineEdit::editingFinished, this, [line, yaml, emitValue] {
            if (yaml && !io::isValidYaml(line->text().toStdString())) {
                line->setStyleSheet("border: 1px solid #d04040");
                line->setToolTip(tr("Not valid YAML: the option keeps its value"));
                return;
            }
            line->setStyleSheet(QString());
            emitValue(Value(line->text().toStdString()));
        });
        return line;
    }
    case ValueType::Vec3: {
        auto* holder = new QWidget(m_body);
        auto* layout = new QHBoxLayout(holder);
        layout->setContentsMargins(0, 0, 0, 0);
        const Vec3 v = std::get<Vec3>(value);
        std::array<QDoubleSpinBox*, 3> boxes{};
        for (int axis = 0; axis < 3; ++axis) {
            boxes[std::size_t(axis)] = numberBox(holder, v[axis], p.min, p.max);
            layout->addWidget(boxes[std::size_t(axis)]);
        }
        for (auto* box : boxes)
            connect(box, &QDoubleSpinBox::valueChanged, this,
                    [boxes, emitValue] { emitValue(Value(Vec3(boxes[0]->value(), boxes[1]->value(), boxes[2]->value()))); });
        return holder;
    }
    }
    return new QLabel(text(formatValue(value)), m_body);
}

} // namespace rs::widgets
