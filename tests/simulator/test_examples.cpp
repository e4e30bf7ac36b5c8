// The example projects of File > Examples run in the simulator as a user would start them:
// ladder -> canonical listing -> checks -> compile, the project's set values loaded, inputs
// switched; no check error, no runtime error, and the outputs do something.

#include "model/convert/convert.h"
#include "model/project/project.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <QDirIterator>
#include <QRegularExpression>

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace rung;

namespace {

std::vector<std::string> examplePaths() {
    std::vector<std::string> paths;
    QDirIterator it(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples"),
                    {QStringLiteral("*.rung")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        paths.push_back(it.next().toStdString());
    std::sort(paths.begin(), paths.end());
    return paths;
}

class ExampleSimulation : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(ExampleSimulation, StartsRunsWithoutRuntimeErrorsAndDrivesItsOutputs) {
    model::ProjectError error;
    const auto project = model::loadProject(QString::fromStdString(GetParam()), &error);
    ASSERT_TRUE(project) << error.message.toStdString();
    const model::ToListingResult listing = model::ladderToList(project->program);
    ASSERT_TRUE(listing.ok());
    model::CheckOptions options;
    options.model = project->target->model(project->model);
    const simulator::CompileResult compiled = simulator::prepareProgram(listing.list, options);
    ASSERT_TRUE(compiled.ok()) << (compiled.diagnostics.empty()
                                       ? std::string()
                                       : compiled.diagnostics.front().message.toStdString());
    simulator::Engine engine(compiled.program);
    for (const auto &[address, value] : project->setValues)
        engine.writeSetValue(address, value);

    const model::Target &t = *project->target;
    std::vector<model::Address> inputs;
    std::vector<model::Address> outputs;
    for (const model::Instruction &ins : listing.list.instructions)
        for (const model::Operand &op : ins.operands) {
            if (op.kind != model::Operand::Kind::Device)
                continue;
            const model::Area &area = t.area(op.address.area);
            const model::Op kind = ins.spec->op;
            if (area.physical && !area.writable)
                inputs.push_back(op.address);
            else if (kind != model::Op::Load && kind != model::Op::And && kind != model::Op::Or)
                outputs.push_back(op.address); // what coils, boxes and transfers write
        }
    ASSERT_FALSE(outputs.empty());
    std::mt19937 rng(7);
    std::set<std::pair<std::size_t, std::int64_t>> seen; // (output, bit or value) pairs met
    for (int scan = 0; scan < 20000; ++scan) {
        if (scan % 50 == 0)
            for (const model::Address &in : inputs)
                engine.setBit(in, (rng() & 1u) != 0);
        engine.scan();
        for (std::size_t k = 0; k < outputs.size(); ++k) {
            const model::Address &a = outputs[k];
            const bool isBit = a.bit >= 0 || t.area(a.area).kind == model::AreaKind::Bit;
            seen.emplace(k, isBit ? std::int64_t{engine.bit(a)} : engine.value(a));
        }
    }
    EXPECT_TRUE(engine.runtimeErrors().empty())
        << engine.runtimeErrors().front().message.toStdString();
    bool someOutputChanged = false;
    for (std::size_t k = 0; k < outputs.size(); ++k)
        someOutputChanged =
            someOutputChanged || std::count_if(seen.begin(), seen.end(),
                                               [k](const auto &p) { return p.first == k; }) > 1;
    EXPECT_TRUE(someOutputChanged) << "nothing the program writes changed in 200 s";
}

INSTANTIATE_TEST_SUITE_P(
    Examples, ExampleSimulation, ::testing::ValuesIn(examplePaths()),
    [](const ::testing::TestParamInfo<std::string> &info) {
        QString name = QString::fromStdString(info.param).section(QStringLiteral("/examples/"), 1);
        name.chop(5); // ".rung"
        name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9]")), QStringLiteral("_"));
        return name.toStdString();
    });
