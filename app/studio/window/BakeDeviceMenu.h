#pragma once
// Bake ▸ Device: where cone bakes run (jobs/BakeDevice.h), automatic (the CPU under a software
// rasteriser, else the GPU), the CPU or the GPU; the choice goes to `runner` and the settings.

class QMenu;
class QWidget;

namespace px::studio {

class BakeRunner;

QMenu* makeBakeDeviceMenu(BakeRunner* runner, QWidget* parent);

} // namespace px::studio
