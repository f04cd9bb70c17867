// The package's fragment shader. The shader generator (core/include/parallax/shader) is not in
// this build yet: the package says so instead of shipping a shader that is not the renderer's.

#include "ExportJob.h"

namespace px::exporter {

Status writePackageShader(ExportJob& job, const Material&,
                          std::vector<std::pair<std::string, std::string>>&) {
    job.result.notes.push_back("no fragment shader in the package: this build has no shader "
                               "generator");
    return success();
}

} // namespace px::exporter
