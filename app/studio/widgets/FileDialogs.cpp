#include "widgets/FileDialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <utility>

namespace px::studio {

namespace {

QString settingsKey(FileKind kind) {
    static const char* const names[] = {"material",    "map",     "textureFolder", "mesh",
                                        "environment", "picture", "exportFolder"};
    return QStringLiteral("fileDialogs/") + QLatin1String(names[static_cast<int>(kind)]);
}

QString startIn(FileKind kind, const QString& fallback) {
    const QString last = lastFolder(kind);
    return last.isEmpty() ? fallback : last;
}

QString execDialog(QFileDialog& dialog) {
    return dialog.exec() == QDialog::Accepted ? dialog.selectedFiles().value(0) : QString();
}

DialogRunner& runner() {
    static DialogRunner current = execDialog;
    return current;
}

// QFileDialog's static functions, as an object the runner can answer: the same dialog they show
// (native where the platform has one).
QString run(QWidget* parent, const QString& title, const QString& start, const QString& filter,
            QFileDialog::FileMode mode, QFileDialog::AcceptMode accept) {
    QFileDialog dialog(parent, title, start, filter);
    dialog.setFileMode(mode);
    dialog.setAcceptMode(accept);
    if (mode == QFileDialog::Directory)
        dialog.setOption(QFileDialog::ShowDirsOnly);
    return runner()(dialog);
}

} // namespace

QString lastFolder(FileKind kind) {
    const QString folder = QSettings().value(settingsKey(kind)).toString();
    return !folder.isEmpty() && QFileInfo(folder).isDir() ? folder : QString();
}

void rememberChoice(FileKind kind, const QString& chosen) {
    if (chosen.isEmpty())
        return;
    const QFileInfo info(QDir::cleanPath(chosen));
    QString folder;
    if (kind == FileKind::ExportFolder)
        folder = info.absoluteFilePath();
    else
        folder = info.absolutePath(); // a file's folder, or the folder holding a texture folder
    QSettings().setValue(settingsKey(kind), QDir::cleanPath(folder));
}

QString askOpenFile(QWidget* parent, FileKind kind, const QString& title, const QString& filter,
                    const QString& fallback) {
    QString file = run(parent, title, startIn(kind, fallback), filter, QFileDialog::ExistingFile,
                       QFileDialog::AcceptOpen);
    rememberChoice(kind, file);
    return file;
}

QString askSaveFile(QWidget* parent, FileKind kind, const QString& title, const QString& suggestion,
                    const QString& filter) {
    const QString folder = lastFolder(kind);
    const QString start = QFileInfo(suggestion).isAbsolute() || folder.isEmpty()
                              ? suggestion
                              : QDir(folder).filePath(suggestion);
    QString file = run(parent, title, start, filter, QFileDialog::AnyFile, QFileDialog::AcceptSave);
    rememberChoice(kind, file);
    return file;
}

QString askFolder(QWidget* parent, FileKind kind, const QString& title, const QString& fallback) {
    QString folder = run(parent, title, startIn(kind, fallback), {}, QFileDialog::Directory,
                         QFileDialog::AcceptOpen);
    rememberChoice(kind, folder);
    return folder;
}

DialogRunner setDialogRunner(DialogRunner next) {
    return std::exchange(runner(), next ? std::move(next) : DialogRunner(execDialog));
}

} // namespace px::studio
