#pragma once
// An undo step: the document state before and after one edit. Consecutive edits with the same
// merge key (one slider drag) collapse into one step.

#include "model/DocumentState.h"

#include <QUndoCommand>

namespace px::studio {

class MaterialDocument;

class StateCommand : public QUndoCommand {
public:
    StateCommand(MaterialDocument* document, const QString& text, DocumentState before,
                 DocumentState after, const QString& mergeKey, int generation);

    void undo() override;
    void redo() override;
    int id() const override { return m_id; }
    bool mergeWith(const QUndoCommand* other) override;
    // After a save: the maps it wrote have their files in this step's states too.
    void adoptSavedMaps(const DocumentState& saved);

private:
    MaterialDocument* m_document;
    DocumentState m_before;
    DocumentState m_after;
    QString m_mergeKey;
    int m_generation;
    int m_id;
};

} // namespace px::studio
