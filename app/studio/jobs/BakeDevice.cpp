#include "jobs/BakeDevice.h"

#include <QObject>
#include <QSettings>
#include <QStringList>

namespace px::studio {

namespace {
const QString kSettingsKey = QStringLiteral("bake/device");
const QStringList kNames{QStringLiteral("automatic"), QStringLiteral("cpu"), QStringLiteral("gpu")};
} // namespace

bool isSoftwareRasteriser(const QString& glRenderer) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast", "swiftshader", "software rasterizer",
                             "software rasteriser"})
        if (glRenderer.contains(QLatin1String(name), Qt::CaseInsensitive))
            return true;
    return false;
}

BakeDeviceChoice chooseBakeDevice(BakeDevicePreference preference, const QString& glRenderer,
                                  bool gpuShared) {
    const QString renderer = glRenderer.isEmpty() ? QObject::tr("unknown renderer") : glRenderer;
    switch (preference) {
    case BakeDevicePreference::Cpu:
        return {false, QObject::tr("as chosen in Bake ▸ Device")};
    case BakeDevicePreference::Gpu:
        if (!gpuShared)
            return {false, QObject::tr("chosen: the GPU, but no OpenGL context shares the "
                                       "viewports'")};
        return {true, QObject::tr("%1, as chosen in Bake ▸ Device").arg(renderer)};
    case BakeDevicePreference::Automatic:
        break;
    }
    if (glRenderer.isEmpty()) // nothing probed it (no viewport): no reason to leave the CPU
        return {false, QObject::tr("the GL renderer is unknown")};
    if (isSoftwareRasteriser(glRenderer))
        return {false, QObject::tr("the GPU, %1, is a software rasteriser: the CPU bakes faster")
                           .arg(renderer)};
    if (!gpuShared)
        return {false, QObject::tr("no OpenGL context shares the viewports'")};
    return {true, QObject::tr("%1: a GPU bakes faster than the CPU").arg(renderer)};
}

BakeDevicePreference savedBakeDevicePreference() {
    const qsizetype i = kNames.indexOf(QSettings().value(kSettingsKey).toString());
    return i < 0 ? BakeDevicePreference::Automatic : static_cast<BakeDevicePreference>(i);
}

void saveBakeDevicePreference(BakeDevicePreference preference) {
    QSettings().setValue(kSettingsKey, kNames.at(static_cast<qsizetype>(preference)));
}

} // namespace px::studio
