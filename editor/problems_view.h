#pragma once

// The problems panel: every finding of the checks, sorted by place, with its code and
// severity. Activating one asks to show its place; a finding with a fix offers it. The rows
// are the findings themselves (a model over them): a program with 30,000 findings costs no
// widget item, text or icon of its own per finding.

#include "model/checks/diagnostic.h"

#include <QTreeView>

namespace rung::editor {

class ProblemsModel;

class ProblemsView : public QTreeView {
    Q_OBJECT

public:
    explicit ProblemsView(QWidget *parent = nullptr);

    void setDiagnostics(const std::vector<model::Diagnostic> &diagnostics);
    const model::Diagnostic *diagnosticAt(int row) const;
    int rowCount() const;
    int count(model::Severity severity) const;
    // "Problems (2 errors, 1 warning)", the panel's title.
    QString summary() const;

signals:
    void locate(const rung::model::Diagnostic &diagnostic);
    void applyFix(const rung::model::Diagnostic &diagnostic);

protected:
    void changeEvent(QEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void paintEvent(QPaintEvent *event) override;

private:
    void retranslate();
    ProblemsModel *m_model;
};

} // namespace rung::editor
