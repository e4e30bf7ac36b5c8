#pragma once

// The cross reference: for each device of the program every rung and step that uses it, as a
// contact, a coil or in a box. The filter takes a device ("X0", only its uses), a prefix
// ("X", every input) or nothing (every device). Activating a use shows its rung. It refreshes
// only while it is on screen (setOnScreen), so a large program edits as fast with it as
// without; a very long list stops at kMaxUses and says so.

#include "document.h"

#include <QWidget>

class QLineEdit;
class QTreeWidget;

namespace rung::editor {

class CrossReferenceView : public QWidget {
    Q_OBJECT

public:
    explicit CrossReferenceView(Document *document, QWidget *parent = nullptr);

    QLineEdit *filter() const { return m_filter; }
    QTreeWidget *tree() const { return m_tree; }
    void refresh();
    // Whether the user can see it (a dock tab behind another cannot be seen, yet counts as
    // visible); it catches up when it comes on screen.
    void setOnScreen(bool onScreen);
    static constexpr int kMaxUses = 5000;

signals:
    void rungActivated(int rung);

protected:
    void changeEvent(QEvent *event) override; // LanguageChange: the headers and the hint
    bool eventFilter(QObject *watched, QEvent *event) override; // the tree's width: fitColumns

private:
    void retranslate();
    // Each column at least as wide as its title, the step as its digits; the device, the use
    // and the instruction share what is left of the tree's width.
    void fitColumns();
    Document *m_document;
    QLineEdit *m_filter;
    QTreeWidget *m_tree;
    bool m_stale = true;
    bool m_onScreen = false;
};

} // namespace rung::editor
