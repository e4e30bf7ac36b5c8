#include "plcopen_exchange.h"

#include "dialogs.h"
#include "file_dialogs.h"

#include "model/project/file_read.h"

#include <QCheckBox>
#include <QColor>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSaveFile>
#include <QTableWidget>
#include <QVBoxLayout>

namespace rung::app {

namespace {

constexpr qint64 kMaxXmlBytes = 64 * 1024 * 1024;

} // namespace

void exportPlcopenFile(QWidget *parent, const model::Project &project, const QString &name,
                       const QString &projectPath, const QString &blocker) {
    if (!blocker.isEmpty()) {
        messageBox(QMessageBox::Critical, parent, PlcopenImportDialog::tr("Cannot export"),
                   blocker);
        return;
    }
    QString path =
        askSaveFile(parent, PlcopenImportDialog::tr("Export PLCopen XML"),
                    fileDialogFolder(projectPath), PlcopenImportDialog::tr("PLCopen XML (*.xml)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".xml");
    const model::PlcopenExport out =
        model::exportPlcopen(project, QFileInfo(name).completeBaseName());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(out.xml) != out.xml.size() ||
        !file.commit()) {
        messageBox(QMessageBox::Critical, parent, PlcopenImportDialog::tr("Cannot export"),
                   PlcopenImportDialog::tr("%1: %2").arg(QDir::toNativeSeparators(path),
                                                         file.errorString()));
        return;
    }
    if (!out.notes.isEmpty())
        messageBox(QMessageBox::Information, parent, PlcopenImportDialog::tr("Export PLCopen XML"),
                   PlcopenImportDialog::tr("%1 is written. Other tools will read it, with these "
                                           "notes:\n\n%2")
                       .arg(QDir::toNativeSeparators(path), out.notes.join(QLatin1Char('\n'))));
}

std::optional<ImportedPlcopen> importPlcopenFile(QWidget *parent, const model::Target &target,
                                                 const QString &projectPath) {
    const QString path =
        askOpenFile(parent, PlcopenImportDialog::tr("Import PLCopen XML"), projectPath,
                    PlcopenImportDialog::tr("PLCopen XML (*.xml);;All files (*)"));
    if (path.isEmpty())
        return std::nullopt;
    QByteArray bytes;
    QString error;
    if (const model::ReadStatus status = model::readAtMost(path, kMaxXmlBytes, &bytes, &error);
        status != model::ReadStatus::Ok) {
        messageBox(QMessageBox::Critical, parent, PlcopenImportDialog::tr("Cannot open the file"),
                   model::readFailure(status, path, kMaxXmlBytes, error));
        return std::nullopt;
    }
    PlcopenImportDialog dialog(bytes, QFileInfo(path).fileName(), target, parent);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return ImportedPlcopen{dialog.project(), path};
}

PlcopenImportDialog::PlcopenImportDialog(const QByteArray &xml, const QString &fileName,
                                         const model::Target &current, QWidget *parent)
    : QDialog(parent)
    , m_xml(xml) {
    setWindowTitle(tr("Import PLCopen XML: %1").arg(fileName));
    auto *layout = new QVBoxLayout(this);
    auto *form = new QFormLayout;
    m_target = new QComboBox;
    m_model = new QComboBox;
    for (model::Family f : model::Target::families())
        m_target->addItem(model::Target::get(f).displayName, model::Target::get(f).id);
    // The PLC a Rung Studio file was written for, else the open program's.
    const model::PlcopenImport first = model::importPlcopen(xml, current, nullptr);
    const model::Target *initial = model::Target::byId(first.fileTarget);
    m_target->setCurrentIndex(m_target->findData((initial ? *initial : current).id));
    form->addRow(tr("PLC family:"), m_target);
    form->addRow(tr("Model:"), m_model);
    layout->addLayout(form);
    auto *devicesLabel = new QLabel(tr("Variables without a device: a free one is proposed; "
                                       "change it where the program needs another."));
    devicesLabel->setWordWrap(true);
    layout->addWidget(devicesLabel);
    m_devices = new QTableWidget(0, 4);
    m_devices->setHorizontalHeaderLabels({tr("Variable"), tr("Type"), tr("Line"), tr("Device")});
    m_devices->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_devices->horizontalHeader()->setStretchLastSection(true);
    m_devices->verticalHeader()->hide();
    layout->addWidget(m_devices);
    auto *issuesLabel = new QLabel(tr("Not imported (element, line and why):"));
    layout->addWidget(issuesLabel);
    m_issues = new QListWidget;
    m_issues->setWordWrap(true);
    layout->addWidget(m_issues);
    m_leaveOut = new QCheckBox(tr("Import the rest and leave out what is listed"));
    layout->addWidget(m_leaveOut);
    m_summary = new QLabel;
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    // What is imported but works otherwise than in the file (an IEC CTU as the PLC's counter).
    m_notes = new QLabel;
    m_notes->setWordWrap(true);
    m_notes->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_notes);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Cancel);
    m_import = buttons->addButton(tr("&Import"), QDialogButtonBox::AcceptRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &PlcopenImportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    auto fillModels = [this] {
        m_model->clear();
        if (const model::Target *t = target())
            for (const model::ModelVariant &m : t->models)
                m_model->addItem(m.name);
        m_model->setCurrentIndex(m_model->count() - 1);
    };
    fillModels();
    connect(m_target, &QComboBox::currentIndexChanged, this, [this, fillModels] {
        m_typed.clear(); // another PLC's devices
        fillModels();
        refresh();
    });
    connect(m_model, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
    connect(m_leaveOut, &QCheckBox::toggled, this, [this] { m_import->setEnabled(canImport()); });
    connect(m_devices, &QTableWidget::itemChanged, this, [this](QTableWidgetItem *item) {
        if (item->column() != 3)
            return;
        QString text = item->text().trimmed();
        text.remove(QStringLiteral("  ") + tr("(no such device)"));
        m_typed[m_devices->item(item->row(), 0)->text()] = text.trimmed();
        m_import->setEnabled(canImport());
    });
    refresh();
    resize(760, 560);
    fitTitle(this);
}

const model::Target *PlcopenImportDialog::target() const {
    return model::Target::byId(m_target->currentData().toString());
}

model::DeviceMapping PlcopenImportDialog::mapping() const {
    model::DeviceMapping m;
    for (const auto &[name, device] : m_typed)
        if (!device.isEmpty())
            m.devices[name] = device;
    return m;
}

void PlcopenImportDialog::refresh() {
    const model::Target *t = target();
    if (!t)
        return;
    const model::ModelVariant *variant = t->model(m_model->currentText());
    // The variables no rule maps stay in the table whatever is typed for them, so that a device
    // given can be changed again.
    const model::PlcopenImport baseline = model::importPlcopen(m_xml, *t, variant);
    for (const model::UnmappedVariable &u : baseline.unmapped)
        if (!m_typed.contains(u.name) && !u.proposed.isEmpty())
            m_typed[u.name] = u.proposed;
    m_result = model::importPlcopen(m_xml, *t, variant, mapping());
    const QSignalBlocker block(m_devices);
    m_devices->setRowCount(0);
    for (const model::UnmappedVariable &u : baseline.unmapped) {
        const int row = m_devices->rowCount();
        m_devices->insertRow(row);
        auto fixed = [](const QString &text) {
            auto *item = new QTableWidgetItem(text);
            item->setFlags(item->flags() & ~Qt::ItemIsEditable);
            return item;
        };
        m_devices->setItem(row, 0, fixed(u.name));
        m_devices->setItem(row, 1, fixed(u.type));
        m_devices->setItem(row, 2, fixed(QString::number(u.line)));
        const auto typed = m_typed.find(u.name);
        auto *device = new QTableWidgetItem(typed != m_typed.end() ? typed->second : QString());
        // A device the target does not have: said on the cell, in words and in red.
        for (const model::ImportIssue &i : m_result.issues)
            if (i.element == QStringLiteral("variable %1").arg(u.name)) {
                device->setForeground(QColor(0xb0, 0x00, 0x20));
                device->setToolTip(i.message);
                device->setText(device->text() + QStringLiteral("  ") + tr("(no such device)"));
            }
        m_devices->setItem(row, 3, device);
    }
    m_issues->clear();
    for (const model::ImportIssue &i : m_result.issues)
        m_issues->addItem(tr("line %1: %2: %3").arg(i.line).arg(i.element, i.message));
    m_leaveOut->setVisible(!m_result.issues.empty());
    m_leaveOut->setChecked(false);
    if (!m_result.project)
        m_summary->setText(tr("The file holds no ladder to import."));
    else if (m_result.complete())
        m_summary->setText(tr("Everything in the file is imported: %n rung(s).", nullptr,
                              static_cast<int>(m_result.project->program.rungs.size())));
    else
        m_summary->setText(tr("%n item(s) of the file are not imported; %1 variable(s) have no "
                              "device yet.",
                              nullptr, static_cast<int>(m_result.issues.size()))
                               .arg(m_result.unmapped.size()));
    m_notes->setVisible(!m_result.notes.isEmpty());
    m_notes->setText(m_result.notes.isEmpty()
                         ? QString()
                         : tr("Imported, but working otherwise than in the file:") +
                               QStringLiteral("\n- ") +
                               m_result.notes.join(QStringLiteral("\n- ")));
    m_import->setEnabled(canImport());
}

bool PlcopenImportDialog::canImport() const {
    if (!m_result.project)
        return false;
    // Every variable needs a device typed (checked on Import); what cannot be imported is left
    // out only when the user says so.
    for (int r = 0; r < m_devices->rowCount(); ++r)
        if (m_devices->item(r, 3)->text().trimmed().isEmpty())
            return false;
    // A device typed that the target does not have leaves its variable unmapped: Import says so.
    return m_result.issues.empty() || m_leaveOut->isChecked();
}

void PlcopenImportDialog::accept() {
    refresh(); // the devices as typed
    if (!m_result.project)
        return;
    if (!m_result.unmapped.empty()) {
        messageBox(QMessageBox::Warning, this, windowTitle(),
                   tr("Some variables still have no device: give each one a device of %1.")
                       .arg(target()->displayName));
        return;
    }
    if (!m_result.issues.empty() && !m_leaveOut->isChecked()) {
        messageBox(QMessageBox::Warning, this, windowTitle(),
                   tr("The file holds what %1 cannot take, listed here. Tick \"%2\" to import "
                      "the rest.")
                       .arg(target()->displayName, m_leaveOut->text().remove(QLatin1Char('&'))));
        return;
    }
    QDialog::accept();
}

} // namespace rung::app
