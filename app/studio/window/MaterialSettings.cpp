#include "window/MaterialSettings.h"

#include <QFileInfo>
#include <QUrl>

namespace px::studio {

QString settingsKeyForFile(const char* group, const QString& path) {
    return QString::fromLatin1(group) + QLatin1Char('/') +
           QString::fromLatin1(QUrl::toPercentEncoding(QFileInfo(path).absoluteFilePath()));
}

} // namespace px::studio
