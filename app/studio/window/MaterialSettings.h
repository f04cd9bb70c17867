#pragma once
// What the editor remembers about a material file in its own settings, never in the file: how it
// last previewed it (the mesh and its uv set, the environment light). One settings key per file.

#include <QString>

namespace px::studio {

// The key of `group` for `path` (its absolute path, percent-encoded: a path cannot open a settings
// group).
QString settingsKeyForFile(const char* group, const QString& path);

} // namespace px::studio
