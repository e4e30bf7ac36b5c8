#pragma once

// The instruction list's colours: a QScintilla lexer per target that styles mnemonics,
// devices, constants, comments, step numbers, unknown words and the placeholder lines of rungs
// the list cannot express, from the target's instruction table.

#include "model/target/target.h"

#include <Qsci/qscilexercustom.h>

#include <vector>

namespace rung::editor {

class IlLexer : public QsciLexerCustom {
    Q_OBJECT

public:
    // Placeholder: the line that stands for a rung the list cannot express (Document).
    enum Style { Default = 0, Mnemonic, Device, Constant, Comment, StepNumber, Error, Placeholder };

    explicit IlLexer(const model::Target &target, QObject *parent = nullptr);
    ~IlLexer() override;
    const char *language() const override { return "IL"; }
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QFont defaultFont(int style) const override;
    QColor defaultPaper(int style) const override;
    void styleText(int start, int end) override;

    // The style of each character of one line (used by styleText, open for tests).
    std::vector<int> styleLine(const QString &line) const;

private:
    const model::Target &m_target;
};

} // namespace rung::editor
