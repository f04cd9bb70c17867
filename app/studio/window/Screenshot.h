#pragma once
// parallax-studio --screenshot: shows the window with the chosen layout and techniques, waits
// until every viewport has drawn and measured its view, grabs the window and writes a PNG
// (atomically, through QSaveFile).

#include <QSize>
#include <QString>

namespace px::studio {

class MainWindow;
struct StudioOptions;

// Sets up the viewports as the options say (baking the cone maps their techniques need first).
void applyViewOptions(MainWindow& window, const StudioOptions& options);

// Waits for every visible viewport's first frame and figures (at most `timeoutMs`), then
// writes the window's image at the screen's pixel ratio. Returns an error sentence, or empty on
// success; `pixels` gets the image's size.
QString takeScreenshot(MainWindow& window, const QString& file, QSize* pixels = nullptr,
                       int timeoutMs = 180000);

} // namespace px::studio
