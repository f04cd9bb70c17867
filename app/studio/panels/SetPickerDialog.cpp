#include "panels/SetPickerDialog.h"

#include "parallax/material/TextureSet.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

namespace px::studio {

namespace {

bool givesRelief(const SetFile& file) {
    if (!file.role)
        return false;
    switch (*file.role) {
    case MapRole::Height:
    case MapRole::Depth:
    case MapRole::Bump:
    case MapRole::Normal:
    case MapRole::NormalGloss:
        return true;
    default:
        return false;
    }
}

// The filter field's arrows and Enter act on the list, so the keyboard never leaves the field.
class ListKeys : public QObject {
public:
    ListKeys(QListWidget* list, QObject* parent) : QObject(parent), m_list(list) {}
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::KeyPress) {
            const int key = static_cast<QKeyEvent*>(event)->key();
            if (key == Qt::Key_Up || key == Qt::Key_Down || key == Qt::Key_PageUp ||
                key == Qt::Key_PageDown) {
                QCoreApplication::sendEvent(m_list, event);
                return true;
            }
        }
        return QObject::eventFilter(watched, event);
    }

private:
    QListWidget* m_list;
};

} // namespace

std::vector<SetChoice> setChoices(const std::vector<std::string>& files) {
    std::vector<SetChoice> choices;
    for (const std::string& name : textureSetNames(files)) {
        SetChoice choice;
        choice.name = QString::fromStdString(name);
        if (Result<TextureSetPlan> plan = planTextureSet(files, name, name)) {
            choice.files = static_cast<int>(plan->files.size());
            choice.relief = std::any_of(plan->files.begin(), plan->files.end(), givesRelief);
        } else {
            choice.relief = false;
        }
        choices.push_back(choice);
    }
    return choices;
}

SetPickerDialog::SetPickerDialog(const QString& source, const std::vector<SetChoice>& sets,
                                 QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Which texture set?"));
    setObjectName(QStringLiteral("set-picker"));
    auto* question = new QLabel(
        tr("%1 holds %2 texture sets. Import which one?").arg(source).arg(sets.size()), this);
    question->setWordWrap(true);
    m_filter = new QLineEdit(this);
    m_filter->setPlaceholderText(tr("Filter by name"));
    m_filter->setClearButtonEnabled(true);
    m_list = new QListWidget(this);
    for (const SetChoice& set : sets) {
        auto* item = new QListWidgetItem(m_list);
        item->setData(Qt::UserRole, set.name);
        if (set.relief) {
            item->setText(tr("%1  (%n file(s))", nullptr, set.files).arg(set.name));
        } else {
            item->setText(
                tr("%1  (no relief: no height, bump or normal map by name)").arg(set.name));
            item->setForeground(palette().color(QPalette::Disabled, QPalette::Text));
            QFont italic = item->font();
            italic.setItalic(true);
            item->setFont(italic);
            item->setToolTip(tr("No file of %1 is named as a height, depth, bump or normal map: "
                                "the import refuses it unless a file's texels are a height map.")
                                 .arg(set.name));
        }
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(question);
    layout->addWidget(m_filter);
    layout->addWidget(m_list, 1);
    layout->addWidget(buttons);
    m_filter->installEventFilter(new ListKeys(m_list, this));

    connect(m_filter, &QLineEdit::textChanged, this, &SetPickerDialog::applyFilter);
    connect(m_list, &QListWidget::itemDoubleClicked, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_list, &QListWidget::currentItemChanged, this,
            [ok = buttons->button(QDialogButtonBox::Ok)](QListWidgetItem* current) {
                ok->setEnabled(current != nullptr && !current->isHidden());
            });
    m_list->setCurrentRow(0);
    m_filter->setFocus();
    resize(480, 420);
}

void SetPickerDialog::applyFilter(const QString& text) {
    QListWidgetItem* first = nullptr;
    for (int i = 0; i < m_list->count(); ++i) {
        QListWidgetItem* item = m_list->item(i);
        const bool match = item->data(Qt::UserRole).toString().contains(text, Qt::CaseInsensitive);
        item->setHidden(!match);
        if (match && !first)
            first = item;
    }
    if (!m_list->currentItem() || m_list->currentItem()->isHidden())
        m_list->setCurrentItem(first); // Enter imports the first match
}

QString SetPickerDialog::chosen() const {
    const QListWidgetItem* item = m_list->currentItem();
    return item && !item->isHidden() ? item->data(Qt::UserRole).toString() : QString();
}

QStringList SetPickerDialog::shown() const {
    QStringList names;
    for (int i = 0; i < m_list->count(); ++i)
        if (!m_list->item(i)->isHidden())
            names << m_list->item(i)->data(Qt::UserRole).toString();
    return names;
}

} // namespace px::studio
