#include "model/StateCommand.h"

#include "model/MaterialDocument.h"
#include "model/MaterialSaver.h"

#include <QHash>

namespace px::studio {

StateCommand::StateCommand(MaterialDocument* document, const QString& text, DocumentState before,
                           DocumentState after, const QString& mergeKey, int generation)
    : QUndoCommand(text), m_document(document), m_before(std::move(before)),
      m_after(std::move(after)), m_mergeKey(mergeKey), m_generation(generation),
      m_id(mergeKey.isEmpty() ? -1 : static_cast<int>(qHash(mergeKey) & 0x7fffffff)) {}

void StateCommand::undo() {
    m_document->setState(m_before);
}

void StateCommand::redo() {
    m_document->setState(m_after);
}

void StateCommand::adoptSavedMaps(const DocumentState& saved) {
    px::studio::adoptSavedMaps(m_before, saved);
    px::studio::adoptSavedMaps(m_after, saved);
}

bool StateCommand::mergeWith(const QUndoCommand* other) {
    const auto* next = dynamic_cast<const StateCommand*>(other);
    if (!next || next->m_mergeKey != m_mergeKey || next->m_generation != m_generation ||
        m_mergeKey.isEmpty())
        return false;
    m_after = next->m_after;
    return true;
}

} // namespace px::studio
