#pragma once

// The program written out of the window: the ladder as PNG, SVG or PDF (the PDF is the
// printout, with the page header), printing, and the instruction list as text.

#include <QCoreApplication>
#include <QString>

#include "model/checks/diagnostic.h"

#include <vector>

class QPrinter;

namespace rung::editor {
class Document;
}

namespace rung::app {

class ProgramExport {
    Q_DECLARE_TR_FUNCTIONS(rung::app::ProgramExport)

public:
    // `namesFirst`: symbol names in place of the addresses, as the view shows them.
    ProgramExport(const editor::Document &document, bool namesFirst)
        : m_document(document)
        , m_namesFirst(namesFirst) {}

    // By the file's suffix; false with the reason when it cannot be written.
    bool ladder(const QString &path, QString *error) const;
    bool print(QPrinter *printer) const;
    // The instruction list, whole or not at all: while a rung cannot be listed (a bridge) or
    // the list as typed has errors (`typedErrors`), nothing is written and `error` names them,
    // as `rungstudio-cli convert` does. False with the reason, also when it cannot be written.
    bool listing(const QString &path, QString *error,
                 const std::vector<model::Diagnostic> &typedErrors = {}) const;
    // Why listing() would refuse, empty when it would not: asked before a file is chosen.
    QString listingBlockers(const std::vector<model::Diagnostic> &typedErrors = {}) const;

private:
    const editor::Document &m_document;
    bool m_namesFirst;
};

} // namespace rung::app
