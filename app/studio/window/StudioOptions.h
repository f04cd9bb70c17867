#pragma once
// The command line of parallax-studio:
//   parallax-studio [FILE.json]
//   parallax-studio --screenshot FILE.png [--layout 1|2|4] [--techniques a,b,c,d]
// plus --sample NAME and --sample-size N for the built-in sample opened without a file, and
// --mesh FILE and --environment sky|FILE for the preview.

#include "parallax/Result.h"
#include "parallax/sample/ProceduralMaps.h"
#include "parallax/trace/Technique.h"

#include <QSize>
#include <QString>
#include <QStringList>
#include <vector>

namespace px::studio {

struct StudioOptions {
    QString file;                      // a material to open; empty: the built-in sample
    QString screenshot;                // render the window into this PNG and exit
    int layout = 0;                    // 0: as it opens (1 viewport; 4 for a screenshot)
    std::vector<Technique> techniques; // viewport 1, 2, ... (1 is the material's)
    ProceduralMap sample = ProceduralMap::Bricks;
    int sampleSize = 512;
    QSize windowSize{1600, 1000}; // of a screenshot, in logical pixels
    QString mesh;                 // a mesh file to show the material on
    QString environment;          // "sky" or an HDR/EXR file to light it with
};

// Parses the arguments (without the program name). Errors are a sentence for stderr.
Result<StudioOptions> parseStudioOptions(const QStringList& arguments);

// The usage text --help prints.
QString studioUsage();

} // namespace px::studio
