#include "widgets/FileDialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>

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
    const QString file =
        QFileDialog::getOpenFileName(parent, title, startIn(kind, fallback), filter);
    rememberChoice(kind, file);
    return file;
}

QString askSaveFile(QWidget* parent, FileKind kind, const QString& title, const QString& suggestion,
                    const QString& filter) {
    const QString folder = lastFolder(kind);
    const QString start = QFileInfo(suggestion).isAbsolute() || folder.isEmpty()
                              ? suggestion
                              : QDir(folder).filePath(suggestion);
    const QString file = QFileDialog::getSaveFileName(parent, title, start, filter);
    rememberChoice(kind, file);
    return file;
}

QString askFolder(QWidget* parent, FileKind kind, const QString& title, const QString& fallback) {
    const QString folder =
        QFileDialog::getExistingDirectory(parent, title, startIn(kind, fallback));
    rememberChoice(kind, folder);
    return folder;
}

} // namespace px::studio
