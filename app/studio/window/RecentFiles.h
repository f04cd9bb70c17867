#pragma once
// The most recently opened or saved materials (or, under another settings key, the preview's
// meshes), newest first, kept in the user's settings.

#include <QObject>
#include <QStringList>

namespace px::studio {

class RecentFiles : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxFiles = 10;
    explicit RecentFiles(QObject* parent = nullptr);
    RecentFiles(const QString& settingsKey, QObject* parent);

    QStringList files() const { return m_files; }
    void add(const QString& path);
    void remove(const QString& path);
    void clear();

signals:
    void changed();

private:
    void store();
    QString m_key;
    QStringList m_files;
};

} // namespace px::studio
