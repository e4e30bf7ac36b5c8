#pragma once

// File > Export PLCopen XML... and File > Import PLCopen XML... (docs/plcopen.md): the dialogs
// around model/exchange. The import dialog shows what the file holds that the target cannot
// take, element by element with its line, and proposes a free device for each variable
// without one; nothing is left out unless the user says so there.

#include "model/exchange/plcopen.h"

#include <QDialog>

#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QListWidget;
class QTableWidget;

namespace rung::app {

// Asks where, writes the project as PLCopen XML and says what other tools will not know.
// `blocker`: why the program cannot be exported now (a list typed with errors), empty if none.
void exportPlcopenFile(QWidget *parent, const model::Project &project, const QString &name,
                       const QString &projectPath, const QString &blocker);

struct ImportedPlcopen {
    model::Project project;
    QString path;
};
// Asks for a file, then the import dialog; nullopt when cancelled or the file is unreadable
// (the user was told).
std::optional<ImportedPlcopen> importPlcopenFile(QWidget *parent, const model::Target &target,
                                                 const QString &projectPath);

class PlcopenImportDialog : public QDialog {
    Q_OBJECT

public:
    PlcopenImportDialog(const QByteArray &xml, const QString &fileName, const model::Target &target,
                        QWidget *parent = nullptr);

    // The program to open (after Import).
    const model::Project &project() const { return *m_result.project; }
    // Imports again with the target and the devices as they stand in the dialog.
    void refresh();
    // The table of variables without a device: one row each, the device editable.
    QTableWidget *devices() const { return m_devices; }
    QListWidget *issues() const { return m_issues; }
    QCheckBox *leaveOut() const { return m_leaveOut; }
    // What is imported but works otherwise than in the file (PlcopenImport::notes).
    QLabel *notes() const { return m_notes; }
    QComboBox *targetBox() const { return m_target; }
    bool canImport() const;
    // Import: refreshed with the devices as typed; stays open, saying why, while a variable
    // has no device or what is listed is not yet allowed to be left out.
    void accept() override;

private:
    model::DeviceMapping mapping() const;
    const model::Target *target() const;

    QByteArray m_xml;
    QComboBox *m_target;
    QComboBox *m_model;
    QTableWidget *m_devices;
    QListWidget *m_issues;
    QCheckBox *m_leaveOut;
    QLabel *m_summary;
    QLabel *m_notes;
    QPushButton *m_import = nullptr;
    model::PlcopenImport m_result;
    std::map<QString, QString> m_typed; // devices the user typed, by variable
};

} // namespace rung::app
