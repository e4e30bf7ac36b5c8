#pragma once

// A new station running a new, empty project: its name, the PLC (target and model, from the
// targets' tables) and where the project is saved (a file that does not exist yet, beside the
// network by default).

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace rung::app {

class NetworkDocument;

class NetworkStationDialog : public QDialog {
    Q_OBJECT
public:
    explicit NetworkStationDialog(const NetworkDocument *document, QWidget *parent = nullptr);

    QString name() const;
    QString target() const; // Target::id
    QString model() const;
    QString file() const;

    QLineEdit *nameEdit() const { return m_name; }
    QComboBox *targetBox() const { return m_target; }
    QComboBox *modelBox() const { return m_model; }
    QLineEdit *fileEdit() const { return m_file; }
    QDialogButtonBox *buttons() const { return m_buttons; }
    QLabel *problemLabel() const { return m_problem; }

private:
    void fillModels();
    void check();

    const NetworkDocument *m_document;
    QLineEdit *m_name;
    QComboBox *m_target;
    QComboBox *m_model;
    QLineEdit *m_file;
    QLabel *m_problem;
    QDialogButtonBox *m_buttons;
    bool m_fileEdited = false;
};

} // namespace rung::app
