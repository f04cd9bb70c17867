#include "preview/GlUnavailableDialog.h"

#include <QCoreApplication>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>

namespace px::studio {

GlChoice askAboutMissingGl(const GlProbe& probe, QWidget* parent) {
    QMessageBox box(QMessageBox::Warning,
                    QObject::tr("OpenGL %1.%2 needed").arg(kRequiredGlMajor).arg(kRequiredGlMinor),
                    glUnavailableMessage(probe), QMessageBox::NoButton, parent);
    const bool alreadySoftware = qEnvironmentVariableIsSet("LIBGL_ALWAYS_SOFTWARE");
    QPushButton* software = nullptr;
    if (!alreadySoftware) {
        box.setInformativeText(QObject::tr(
            "Mesa's software renderer (llvmpipe) provides OpenGL 4.5 on any machine: slower, "
            "but every technique works. You can also go on without the live preview: editing, "
            "baking, comparing and exporting still work."));
        software =
            box.addButton(QObject::tr("Restart with Software Rendering"), QMessageBox::AcceptRole);
    } else {
        box.setInformativeText(QObject::tr("Software rendering is already on "
                                           "(LIBGL_ALWAYS_SOFTWARE). You can go on without the "
                                           "live preview."));
    }
    QPushButton* without =
        box.addButton(QObject::tr("Continue Without Preview"), QMessageBox::RejectRole);
    box.addButton(QObject::tr("Quit"), QMessageBox::DestructiveRole);
    box.setDefaultButton(software ? software : without);
    box.exec();
    if (software && box.clickedButton() == software)
        return GlChoice::RestartInSoftware;
    if (box.clickedButton() == without)
        return GlChoice::ContinueWithoutPreview;
    return GlChoice::Quit;
}

bool restartWithSoftwareRendering() {
    QProcess process;
    process.setProgram(QCoreApplication::applicationFilePath());
    process.setArguments(QCoreApplication::arguments().mid(1));
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("LIBGL_ALWAYS_SOFTWARE"), QStringLiteral("1"));
    process.setProcessEnvironment(env);
    return process.startDetached();
}

} // namespace px::studio
