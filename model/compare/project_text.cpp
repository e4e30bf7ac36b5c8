#include "model/compare/project_text.h"

#include "model/compare/compare.h"

namespace rung::model {

QString projectText(const Project &project) {
    const Target &t = *project.target;
    QStringList lines;
    lines << QStringLiteral("; target: %1").arg(t.id)
          << QStringLiteral("; model: %1").arg(project.model);
    LadderProgram program = project.program;
    program.target = project.target;
    const std::vector<ComparedRung> rungs = comparedRungs(program);
    for (std::size_t r = 0; r < rungs.size(); ++r) {
        lines << QString();
        const QString &comment = program.rungs[r].comment;
        if (!comment.isEmpty())
            for (const QString &line : comment.split(QLatin1Char('\n')))
                lines << QStringLiteral("; ") + line;
        if (!rungs[r].instructions.empty()) {
            for (const Instruction &ins : rungs[r].instructions)
                lines << printInstruction(t, ins);
        } else {
            lines << QStringLiteral("; drawn only (no listing can hold this rung):");
            for (const QString &line : rungs[r].signature.split(QLatin1Char('\n')))
                lines << QStringLiteral(";   ") + line;
        }
    }
    if (!project.symbols.empty()) {
        lines << QString() << QStringLiteral("; symbols:");
        for (const Symbol &s : project.symbols)
            lines << QStringLiteral(";   %1 = %2%3")
                         .arg(formatAddress(t, s.address), s.name,
                              s.comment.isEmpty() ? QString()
                                                  : QStringLiteral("  -- ") + s.comment);
    }
    if (!project.setValues.empty()) {
        lines << QString() << QStringLiteral("; set values:");
        for (const auto &[address, value] : project.setValues)
            lines << QStringLiteral(";   %1 = %2").arg(formatAddress(t, address)).arg(value);
    }
    for (const WatchList &w : project.watchLists) {
        lines << QString() << QStringLiteral("; watch list \"%1\":").arg(w.name);
        for (const QString &d : w.devices)
            lines << (w.format(d) == ValueFormat::Decimal
                          ? QStringLiteral(";   %1").arg(d)
                          : QStringLiteral(";   %1 (%2)").arg(d, valueFormatKey(w.format(d))));
    }
    if (!project.pendingListing.isEmpty()) {
        lines << QString()
              << QStringLiteral("; the instruction list as typed, with errors (pendingListing):");
        for (const QString &line : project.pendingListing.split(QLatin1Char('\n')))
            lines << QStringLiteral(";   ") + line;
    }
    if (!project.pendingSymbols.empty()) {
        lines << QString() << QStringLiteral("; symbol rows not yet symbols (pendingSymbols):");
        for (const PendingSymbol &s : project.pendingSymbols)
            lines << QStringLiteral(";   %1 = %2%3")
                         .arg(s.device, s.name,
                              s.comment.isEmpty() ? QString()
                                                  : QStringLiteral("  -- ") + s.comment);
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace rung::model
