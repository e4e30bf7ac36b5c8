#pragma once

// The listing checks' one pass over a listing (docs/diagnostics.md): what the checks share
// (the listing, the target and model, the source text, the rung spans and forms, the
// findings so far) is the ListChecker; each check and the fixes it makes is defined in the
// file named after it. Internal to model/checks.

#include "model/checks/checks_internal.h"
#include "model/listing/structure.h"

#include <QStringList>

#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace rung::model::detail {

class ListChecker {
public:
    ListChecker(const InstructionList &list, const CheckOptions &options, bool verifyMoves = true)
        : m_verifyMoves(verifyMoves)
        , m_list(list)
        , m_t(*list.target)
        , m_model(options.model ? options.model : &list.target->defaultModel())
        , m_formOnly(options.formOnly)
        , m_parsedLinesOnly(options.parsedLinesOnly)
        , m_source(options.source) {}

    void setForms(bool on) { m_withForms = on; }

    std::vector<Finding> run(); // checks_list.cpp

private:
    Finding &add(const char *code, Severity severity, int index, const QString &message) {
        return addFinding(m_found, m_list, code, severity, index, message);
    }

    // checks_list.cpp: the fix of EN001, which endAndNesting (checks_nesting.cpp) finds.
    void offerEnd();

    const Instruction &at(int i) const { return m_list.instructions[static_cast<std::size_t>(i)]; }
    int size() const { return static_cast<int>(m_list.instructions.size()); }
    QString name(int i) const { return at(i).spec ? at(i).spec->mnemonic : QString(); }

    // The rungs as the converter reads them (model::rungSpans).
    void spans() { m_spans = rungSpans(m_list.instructions); }

    std::pair<int, int> spanOf(int index) const {
        const RungSpan span = model::spanOf(m_spans, index);
        return {span.first, span.last};
    }

    Location location(int i) const {
        Location l;
        l.line = at(i).line;
        l.column = at(i).column;
        return l;
    }

    // The rung holding `index` as the converter writes it back (cached by its span).
    struct SpanForm {
        int first = 0;
        int last = 0;
        RungForm form;
        // Several findings of one rung offer the same rewrite: printed once.
        std::optional<QString> printed;
        // How often each fuzzy form occurs in the rung as written (betterForm), by code.
        std::map<QString, qsizetype> formCounts;
    };

    // checks_blocks_and_stack.cpp: the fuzzy forms, block limits and branch stack, and the
    // rewrites they offer.
    SpanForm &rungForm(int index);
    bool isFuzzy(int index);
    QString printed(const std::vector<Instruction> &instructions) const;
    void offer(Finding &f, int first, int last, const QString &listing, const QString &label);
    void offerCanonical(Finding &f, int index);
    bool betterForm(int first, int last, const std::vector<Instruction> &rewrite, const char *code);
    void blocksAndStack();

    // checks_operands.cpp: the operands' ranges, writability and banks.
    const SystemDevice *driveBySystem(const Address &a);
    void atOperand(Finding &f, int i, const QString &device);
    void atWordOperand(Finding &f, int i, std::size_t k);
    void operands();

    void duplicates();                                      // checks_duplicates.cpp
    void length();                                          // checks_length.cpp
    void structure(const std::vector<Diagnostic> &drawing); // checks_structure.cpp

    bool m_verifyMoves = true;
    bool m_withForms = true;
    const InstructionList &m_list;
    const Target &m_t;
    const ModelVariant *m_model;
    bool m_formOnly = false;
    bool m_parsedLinesOnly = false;
    const QString *m_source = nullptr;
    QStringList m_sourceLines; // split on the first operand finding
    std::vector<RungSpan> m_spans;
    bool m_systemParsed = false;
    std::map<Address, const SystemDevice *> m_systemDriven;
    std::map<int, SpanForm> m_forms; // by the rung's first instruction
    std::vector<Finding> m_found;
};

} // namespace rung::model::detail
