#include "window/StudioOptions.h"

#include <QObject>
#include <QSize>

namespace px::studio {

QString studioUsage() {
    return QObject::tr(
        "Usage: parallax-studio [FILE.json]\n"
        "       parallax-studio --screenshot FILE.png [--layout 1|2|4] [--techniques a,b,c,d]\n"
        "\n"
        "Opens a material, or the built-in sample when no file is given.\n"
        "  --screenshot FILE.png   render the window with the material and write a PNG, then exit\n"
        "  --layout 1|2|4          viewports side by side\n"
        "  --techniques a,b,...    the technique of viewport 1, 2, ... (viewport 1 is the "
        "material's)\n"
        "  --size WxH              the window size of a screenshot (default 1600x1000)\n"
        "  --sample NAME           the built-in sample: bricks, stones or rivets\n"
        "  --sample-size N         its maps' size in texels (default 512)\n"
        "  --mesh FILE             show the material on an OBJ or glTF mesh\n"
        "  --environment sky|FILE  light it with the built-in sky or an HDR/EXR\n");
}

Result<StudioOptions> parseStudioOptions(const QStringList& args) {
    StudioOptions o;
    auto value = [&](int& i, const QString& name) -> Result<QString> {
        if (i + 1 >= args.size())
            return Error{name.toStdString() + " needs a value"};
        return args[++i];
    };
    for (int i = 0; i < args.size(); ++i) {
        const QString& a = args[i];
        if (a == QLatin1String("--screenshot")) {
            Result<QString> v = value(i, a);
            if (!v)
                return v.error();
            o.screenshot = *v;
        } else if (a == QLatin1String("--layout")) {
            Result<QString> v = value(i, a);
            if (!v)
                return v.error();
            o.layout = v->toInt();
            if (o.layout != 1 && o.layout != 2 && o.layout != 4)
                return Error{"--layout must be 1, 2 or 4, not \"" + v->toStdString() + "\""};
        } else if (a == QLatin1String("--techniques")) {
            Result<QString> v = value(i, a);
            if (!v)
                return v.error();
            for (const QString& name : v->split(QLatin1Char(','), Qt::SkipEmptyParts)) {
                const std::optional<Technique> t = parseTechnique(name.trimmed().toStdString());
                if (!t)
                    return Error{"unknown technique \"" + name.toStdString() +
                                 "\" (none, normal, offset, steep, pom, relief, secant, cone, "
                                 "relaxed-cone, pyramid, exact)"};
                o.techniques.push_back(*t);
            }
            if (o.techniques.size() > 4)
                return Error{"--techniques names at most 4 techniques, one per viewport"};
        } else if (a == QLatin1String("--size")) {
            Result<QString> v = value(i, a);
            if (!v)
                return v.error();
            const QStringList wh = v->split(QLatin1Char('x'));
            const int w = wh.size() == 2 ? wh[0].toInt() : 0,
                      h = wh.size() == 2 ? wh[1].toInt() : 0;
            if (w < 320 || h < 240 || w > 8192 || h > 8192)
                return Error{"--size must be WxH between 320x240 and 8192x8192, not \"" +
                             v->toStdString() + "\""};
            o.windowSize = QSize(w, h);
        } else if (a == QLatin1String("--sample")) {
            Result<QString> v = value(i, a);
            if (!v)
                return v.error();
            const std::optional<ProceduralMap> kind = parseProceduralMap(v->toStdString());
            if (!kind)
                return Error{"unknown sample \"" + v->toStdString() +
                             "\" (bricks, stones, rivets)"};
            o.sample = *kind;
        } else if (a == QLatin1String("--sample-size")) {
            Result<QString> v = value(i, a);
            if (!v)
                return v.error();
            o.sampleSize = v->toInt();
            if (o.sampleSize < 4 || o.sampleSize > 8192)
                return Error{"--sample-size must be 4..8192, not \"" + v->toStdString() + "\""};
        } else if (a == QLatin1String("--mesh") || a == QLatin1String("--environment")) {
            Result<QString> v = value(i, a);
            if (!v)
                return v.error();
            (a == QLatin1String("--mesh") ? o.mesh : o.environment) = *v;
        } else if (a.startsWith(QLatin1String("--"))) {
            return Error{"unknown option " + a.toStdString() + " (see --help)"};
        } else if (o.file.isEmpty()) {
            o.file = a;
        } else {
            return Error{"more than one file given: " + o.file.toStdString() + ", " +
                         a.toStdString()};
        }
    }
    if (o.layout == 0 && !o.screenshot.isEmpty())
        o.layout = o.techniques.size() > 2 ? 4 : (o.techniques.size() == 2 ? 2 : 4);
    if (o.layout != 0 && static_cast<int>(o.techniques.size()) > o.layout)
        return Error{"--techniques names more techniques than --layout shows viewports"};
    return o;
}

} // namespace px::studio
