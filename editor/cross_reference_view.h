#pragma once

// The cross reference panel: a filter field over the uses of the program's devices
// (CrossReferenceModel: a device, a prefix or nothing), as a tree. Activating a use shows its
// rung. It refreshes only while it is on screen (setOnScreen), so a large program edits as fast
// with it as without; a very long list stops at the model's limit and says so.

#include <QWidget>

class QLineEdit;
class QTreeView;

namespace rung::editor {

class CrossReferenceModel;
class Document;

class CrossReferenceView : public QWidget {
    Q_OBJECT

public:
    explicit CrossReferenceView(Document *document, QWidget *parent = nullptr);

    QLineEdit *filter() const { return m_filter; }
    QTreeView *tree() const { return m_tree; }
    CrossReferenceModel *model() const { return m_model; }
    void refresh();
    // Whether the user can see it (a dock tab behind another cannot be seen, yet counts as
    // visible); it catches up when it comes on screen.
    void setOnScreen(bool onScreen);

signals:
    void rungActivated(int rung);

protected:
    void changeEvent(QEvent *event) override; // LanguageChange: the headers and the hint
    bool eventFilter(QObject *watched, QEvent *event) override; // the tree's width: fitColumns

private:
    void retranslate();
    void setHint(); // the filter's, with the target's own devices as examples
    // After the rows came anew: a device's uses open when the filter names it or when few
    // devices are listed; the note of the limit spans the columns.
    void arrangeRows();
    // Each column at least as wide as its title, the step as its digits; the device, the use
    // and the instruction share what is left of the tree's width.
    void fitColumns();
    Document *m_document;
    CrossReferenceModel *m_model;
    QLineEdit *m_filter;
    QTreeView *m_tree;
};

} // namespace rung::editor
