#include "parallax/eval/EvalControl.h"

namespace px {
namespace {
constexpr const char* kCancelled = "the evaluation was cancelled";
}

Error evaluationCancelled() {
    return Error{kCancelled, ErrorKind::Cancelled, {}};
}

bool isEvaluationCancelled(const Error& error) {
    return error.cancelled();
}

} // namespace px
