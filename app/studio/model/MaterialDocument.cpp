#include "model/MaterialDocument.h"

#include "model/StateCommand.h"
#include "parallax/material/MaterialFile.h"

#include <QFileInfo>

namespace px::studio {

MaterialDocument::MaterialDocument(QObject* parent) : QObject(parent) {
    m_cleanJson = materialToJson(m_state.material);
    m_cleanAssets = m_state.assets;
}

QString MaterialDocument::displayName() const {
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).fileName();
    return QString::fromStdString(m_state.material.name);
}

bool MaterialDocument::isDirty() const {
    return m_state.assets != m_cleanAssets || materialToJson(m_state.material) != m_cleanJson;
}

void MaterialDocument::edit(const QString& text, const std::function<void(DocumentState&)>& change,
                            const QString& mergeKey) {
    DocumentState next = m_state;
    change(next);
    const bool sameMaterial = next.assets == m_state.assets && next.unsaved == m_state.unsaved &&
                              materialToJson(next.material) == materialToJson(m_state.material);
    if (sameMaterial && next.views == m_state.views)
        return;
    if (sameMaterial) {
        // Viewports 2..4's techniques are view settings, like the camera: applied at once and
        // kept out of the material's history.
        m_state.views = next.views;
        notify(ViewsChanged);
        return;
    }
    m_undo.push(
        new StateCommand(this, text, m_state, std::move(next), mergeKey, m_mergeGeneration));
}

void MaterialDocument::reset(DocumentState state, const QString& filePath, bool unsavedWork) {
    m_undo.clear();
    m_mergeGeneration = 0;
    m_filePath = filePath;
    m_state = std::move(state);
    m_cleanJson = materialToJson(m_state.material);
    m_cleanAssets = unsavedWork ? nullptr : m_state.assets; // no clean state to come back to
    notify(MaterialChanged | MapsChanged | ViewsChanged | FileChanged);
}

void MaterialDocument::markSaved(DocumentState saved, const QString& filePath) {
    for (int i = 0; i < m_undo.count(); ++i) {
        // The stack's commands are all StateCommands (edit() is the only way in).
        auto* step = static_cast<StateCommand*>(const_cast<QUndoCommand*>(m_undo.command(i)));
        step->adoptSavedMaps(saved);
    }
    m_filePath = filePath;
    m_state = std::move(saved);
    m_cleanJson = materialToJson(m_state.material);
    m_cleanAssets = m_state.assets;
    ++m_mergeGeneration; // a drag after saving is a new step
    notify(MaterialChanged | FileChanged);
}

void MaterialDocument::setState(const DocumentState& stepState) {
    // An undo step restores the material, never the other viewports' techniques (not history);
    // a viewport whose maps the step took away falls back to the march.
    DocumentState next = stepState;
    next.views = m_state.views;
    for (int v = 1; v < kMaxViewports; ++v) {
        if (!next.canTrace(next.view(v).technique))
            next.setView(v, {Technique::Pom, info(Technique::Pom).defaults});
    }
    Changes what;
    if (materialToJson(next.material) != materialToJson(m_state.material))
        what |= MaterialChanged;
    if (next.assets != m_state.assets || next.unsaved != m_state.unsaved)
        what |= MapsChanged;
    if (next.views != m_state.views)
        what |= ViewsChanged;
    m_state = next;
    notify(what);
}

void MaterialDocument::notify(Changes what) {
    if (what)
        emit changed(what);
    const bool dirty = isDirty();
    if (dirty != m_lastDirty || what.testFlag(FileChanged)) {
        m_lastDirty = dirty;
        emit dirtyChanged(dirty);
    }
}

} // namespace px::studio
