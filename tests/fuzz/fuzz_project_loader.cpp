// Any bytes as a project file: load, and when it loads, save it to JSON and load that again.
#include "model/checks.h"
#include "model/project.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung::model;
    ProjectError error;
    auto project = projectFromJson(QByteArray(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size)), &error);
    if (project) {
        (void)checkLadder(project->program);
        auto again = projectFromJson(projectToJson(*project), &error);
        if (!again)
            __builtin_trap(); // what we wrote must read back
    }
    return 0;
}
