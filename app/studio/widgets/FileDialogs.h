#pragma once
// The editor's file dialogs, each starting in the folder the user last chose a file of its kind
// in (kept in the settings, so across sessions too): a mesh dialog does not open among the
// textures, nor a map dialog in the working directory every time. A folder that no longer exists
// is forgotten, and the dialog starts where `fallback` says (the material's folder, say) or in
// Qt's default.

#include <QString>
#include <functional>

class QFileDialog;
class QWidget;

namespace px::studio {

enum class FileKind { Material, Map, TextureFolder, Mesh, Environment, Picture, ExportFolder };

// Where the next dialog of `kind` starts, empty when none was used yet (or it is gone).
QString lastFolder(FileKind kind);
// `chosen` a file: its folder; a texture folder: the folder holding it (the next set is a
// sibling); an export folder: itself.
void rememberChoice(FileKind kind, const QString& chosen);

// QFileDialog's static functions, started in lastFolder(kind) (else `fallback`) and remembering
// the choice. Empty: cancelled.
QString askOpenFile(QWidget* parent, FileKind kind, const QString& title, const QString& filter,
                    const QString& fallback = {});
// `suggestion`: a file name (put in the remembered folder) or a whole path (kept).
QString askSaveFile(QWidget* parent, FileKind kind, const QString& title, const QString& suggestion,
                    const QString& filter);
QString askFolder(QWidget* parent, FileKind kind, const QString& title,
                  const QString& fallback = {});

// Runs a dialog set up as above and returns the chosen path, empty for Cancel. The default execs
// it; tests answer the real, fully set-up dialog without racing its folder model. Returns the
// previous runner.
using DialogRunner = std::function<QString(QFileDialog&)>;
DialogRunner setDialogRunner(DialogRunner runner);

} // namespace px::studio
