#pragma once

// File > Compare With...: the open program against a file (a project, a listing or a ladder
// text of its PLC), the two ladders side by side rung against rung, the two instruction lists
// side by side, and the report `rungstudio-cli diff` prints. Alt+Down / Alt+Up go to the next
// and the previous change (the keys of WinMerge and Meld); Print prints the ladders with their
// marks, which read in black and white.

#include "model/compare/compare.h"

#include <QDialog>

#include <optional>

class QLabel;
class QPlainTextEdit;
class QTabWidget;
class QTableWidget;

namespace rung::editor {
class CompareView;
}

namespace rung::app {

// A file read for comparing with a program of `target`: a project of that PLC, or a listing /
// ladder text read for it (their own target line wins). nullopt with *error (translated).
std::optional<model::Project> loadForComparison(const QString &path, const model::Target &target,
                                                QString *error);

class CompareWindow : public QDialog {
    Q_OBJECT

public:
    // A is the file (`nameA`), B the open program (`nameB`).
    CompareWindow(const model::Project &a, const QString &nameA, const model::Project &b,
                  const QString &nameB, QWidget *parent = nullptr);

    editor::CompareView *ladder() const { return m_view; }
    QTableWidget *listing() const { return m_list; }
    QPlainTextEdit *report() const { return m_report; }
    QTabWidget *tabs() const { return m_tabs; }
    // The next / previous change in the ladder and the list together.
    void nextChange(bool backwards);
    void print();

    // Asks for a file and shows the comparison with `open` (the window's program).
    static void compareWithFile(QWidget *parent, const model::Project &open,
                                const QString &openName, const QString &projectPath);

private:
    void fillListing();
    void showCurrent(int difference);
    void updateSummary();

    model::Project m_a, m_b;
    QString m_nameA, m_nameB;
    model::Comparison m_comparison;
    QTabWidget *m_tabs;
    editor::CompareView *m_view;
    QTableWidget *m_list;
    QPlainTextEdit *m_report;
    QLabel *m_summary;
    std::vector<int> m_listRowOf; // each difference's heading row in the list
};

} // namespace rung::app
