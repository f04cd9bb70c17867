#include "RenderTestSupport.h"

#include <cstdio>

namespace px::test {

HeadlessContext* glContext() {
    static std::unique_ptr<HeadlessContext> context;
    static std::string failure;
    if (!context && failure.empty()) {
        Result<std::unique_ptr<HeadlessContext>> made = HeadlessContext::create();
        if (made)
            context = std::move(*made);
        else
            failure = made.error().message;
        if (!failure.empty())
            std::fprintf(stderr, "%s\n", failure.c_str());
    }
    return context.get();
}

} // namespace px::test
