// Any bytes as a project file: load, and when it loads, save it to JSON, load that again and
// check the second save writes the same bytes.
#include "model/checks/checks.h"
#include "model/project/project.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    using namespace rung::model;
    ProjectError error;
    auto project = projectFromJson(
        QByteArray(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size)), &error);
    if (project) {
        (void)checkLadder(project->program);
        const QByteArray written = projectToJson(*project);
        auto again = projectFromJson(written, &error);
        if (!again)
            __builtin_trap(); // what we wrote must read back
        if (projectToJson(*again) != written)
            __builtin_trap(); // and write the same bytes again: the format is stable for diffs
    }
    return 0;
}
