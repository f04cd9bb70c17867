#include "window/BakeDeviceMenu.h"

#include "jobs/BakeRunner.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>

namespace px::studio {

QMenu* makeBakeDeviceMenu(BakeRunner* runner, QWidget* parent) {
    auto* menu = new QMenu(QObject::tr("&Device"), parent);
    menu->setObjectName(QStringLiteral("bake-device"));
    menu->setToolTipsVisible(true);
    auto* group = new QActionGroup(menu);
    const struct {
        BakeDevicePreference preference;
        QString text, tip;
    } choices[] = {
        {BakeDevicePreference::Automatic, QObject::tr("&Automatic"),
         QObject::tr("Cone maps bake on the CPU where the OpenGL renderer is a software "
                     "rasteriser (llvmpipe, SwiftShader...), on the GPU otherwise.")},
        {BakeDevicePreference::Cpu, QObject::tr("&CPU"),
         QObject::tr("Cone maps bake on the CPU, on every core.")},
        {BakeDevicePreference::Gpu, QObject::tr("&GPU"),
         QObject::tr("Cone maps bake on the GPU that draws the viewports, whatever it is.")},
    };
    for (const auto& choice : choices) {
        QAction* a = menu->addAction(choice.text);
        a->setToolTip(choice.tip);
        a->setStatusTip(choice.tip);
        a->setCheckable(true);
        a->setChecked(runner->devicePreference() == choice.preference);
        a->setData(static_cast<int>(choice.preference));
        group->addAction(a);
        QObject::connect(a, &QAction::triggered, runner, [runner, p = choice.preference] {
            runner->setDevicePreference(p);
            saveBakeDevicePreference(p);
        });
    }
    return menu;
}

} // namespace px::studio
