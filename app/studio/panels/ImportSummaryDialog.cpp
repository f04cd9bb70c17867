#include "panels/ImportSummaryDialog.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace px::studio {

ImportSummaryDialog::ImportSummaryDialog(const ImportedSet& set, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Imported %1").arg(QString::fromStdString(set.material.name)));
    auto* layout = new QVBoxLayout(this);

    // The guess a file name makes is worth a warning; a reading told by the data is not.
    m_decision = new QLabel(QString::fromStdString(set.relief.summary), this);
    m_decision->setWordWrap(true);
    m_decision->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont bold = m_decision->font();
    bold.setBold(true);
    m_decision->setFont(bold);
    if (!set.relief.fromData)
        m_decision->setStyleSheet(QStringLiteral("QLabel { color: #b35c00; }"));
    layout->addWidget(m_decision);

    QStringList lines;
    for (const std::string& line : importSummary(set))
        lines << QString::fromStdString(line);
    m_list = new QPlainTextEdit(lines.join(QLatin1Char('\n')), this);
    m_list->setReadOnly(true);
    m_list->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    m_list->setMinimumSize(420, 160);
    layout->addWidget(m_list, 1);

    // Enter keeps what the data decided: OK is the default, the flip never is.
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok, this);
    QPushButton* ok = buttons->button(QDialogButtonBox::Ok);
    ok->setDefault(true);
    ok->setAutoDefault(true);
    m_flip = buttons->addButton(set.material.heightIsDepth ? tr("Read as height instead")
                                                           : tr("Read as depth instead"),
                                QDialogButtonBox::ActionRole);
    m_flip->setAutoDefault(false);
    m_flip->setDefault(false);
    m_flip->setEnabled(!set.material.maps.height.empty()); // a derived height has no reading
    m_flip->setToolTip(tr("Read the height file the other way: white = high or white = deep "
                          "(the Depth map box of the Parameters panel)."));
    connect(m_flip, &QPushButton::clicked, this, [this] {
        emit flipRequested();
        m_flip->setEnabled(false); // once: the Depth map box flips it back
    });
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    layout->addWidget(buttons);
}

QString ImportSummaryDialog::decision() const {
    return m_decision->text();
}

QString ImportSummaryDialog::text() const {
    return m_list->toPlainText();
}

} // namespace px::studio
