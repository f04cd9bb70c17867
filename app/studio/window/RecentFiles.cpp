#include "window/RecentFiles.h"

#include <QFileInfo>
#include <QSettings>

namespace px::studio {

namespace {
const QString kKey = QStringLiteral("recentFiles");
}

RecentFiles::RecentFiles(QObject* parent) : RecentFiles(kKey, parent) {}

RecentFiles::RecentFiles(const QString& settingsKey, QObject* parent)
    : QObject(parent), m_key(settingsKey) {
    m_files = QSettings().value(m_key).toStringList();
}

void RecentFiles::add(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_files.removeAll(absolute);
    m_files.prepend(absolute);
    while (m_files.size() > kMaxFiles)
        m_files.removeLast();
    store();
}

void RecentFiles::remove(const QString& path) {
    m_files.removeAll(QFileInfo(path).absoluteFilePath());
    store();
}

void RecentFiles::clear() {
    m_files.clear();
    store();
}

void RecentFiles::store() {
    QSettings().setValue(m_key, m_files);
    emit changed();
}

} // namespace px::studio
