#pragma once
// The material being edited: its state, the file it lives in, and the undo stack through which
// every edit goes. Views hold no copy of the state; they read it here and listen to changed().
//
// Map paths are kept absolute in memory (relative paths are a file-format matter, written by
// MaterialSaver), so undo steps taken before a Save As into another folder stay valid.

#include "model/DocumentState.h"

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <functional>

namespace px::studio {

class MaterialDocument : public QObject {
    Q_OBJECT
public:
    enum Change : unsigned {
        MaterialChanged = 1, // any saved setting (scale, technique of viewport 1, shadow, ...)
        MapsChanged = 2,     // the maps in memory
        ViewsChanged = 4,    // viewports 2..4's techniques
        FileChanged = 8,     // opened, saved, renamed
    };
    Q_DECLARE_FLAGS(Changes, Change)

    explicit MaterialDocument(QObject* parent = nullptr);

    const DocumentState& state() const { return m_state; }
    const Material& material() const { return m_state.material; }
    QUndoStack* undoStack() { return &m_undo; }

    QString filePath() const { return m_filePath; } // empty: never saved
    QString displayName() const;
    // Differs from what was opened or last saved (view-only edits do not count).
    bool isDirty() const;

    // One undoable edit: `change` turns a copy of the state into the next one. Edits with the
    // same non-empty mergeKey merge into one undo step until endMerge() (a slider drag is one
    // step). An edit that changes nothing pushes nothing; one that changes only viewports 2..4's
    // techniques (view settings) applies at once without an undo step.
    void edit(const QString& text, const std::function<void(DocumentState&)>& change,
              const QString& mergeKey = {});
    void endMerge() { ++m_mergeGeneration; }

    // Replaces the whole document (new, open): the undo history starts afresh. `unsavedWork`:
    // the state holds work that is on no disk and not made again by opening it (a height map
    // derived from a normal map): dirty until saved, so replacing it asks first.
    void reset(DocumentState state, const QString& filePath, bool unsavedWork = false);
    // After a save: the state as saved (maps now on disk) becomes the clean state; the undo
    // history is kept.
    void markSaved(DocumentState saved, const QString& filePath);

    // Used by the undo commands: the step's state, with the viewports' techniques as they are.
    void setState(const DocumentState& stepState);

signals:
    void changed(px::studio::MaterialDocument::Changes what);
    void dirtyChanged(bool dirty);

private:
    void notify(Changes what);

    DocumentState m_state;
    QString m_filePath;
    QUndoStack m_undo;
    int m_mergeGeneration = 0;
    // The clean state: what is on disk (or the sample as made).
    std::string m_cleanJson;
    std::shared_ptr<const MaterialAssets> m_cleanAssets;
    bool m_lastDirty = false;
};

Q_DECLARE_OPERATORS_FOR_FLAGS(MaterialDocument::Changes)

} // namespace px::studio
