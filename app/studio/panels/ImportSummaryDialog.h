#pragma once
// What an import did, shown once it is done: the decision on how the height file reads (and how
// sure), with one click to flip it, then every file assigned, ignored or duplicate, and the notes.
// Non-modal: the new material is already in the viewports while the user reads.

#include "parallax/material/TextureSetImport.h"

#include <QDialog>

class QLabel;
class QPlainTextEdit;
class QPushButton;

namespace px::studio {

class ImportSummaryDialog : public QDialog {
    Q_OBJECT
public:
    ImportSummaryDialog(const ImportedSet& set, QWidget* parent = nullptr);

    QString decision() const; // the relief line, as shown
    QString text() const;     // the whole summary
    QPushButton* flipButton() const { return m_flip; }

signals:
    void flipRequested(); // read the height file the other way (height <-> depth)

private:
    QLabel* m_decision;
    QPlainTextEdit* m_list;
    QPushButton* m_flip;
};

} // namespace px::studio
