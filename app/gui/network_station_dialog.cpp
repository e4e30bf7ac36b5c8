#include "app/gui/network_station_dialog.h"

#include "app/gui/network_document.h"

#include "model/project/project.h"
#include "model/target/target.h"
#include "network/network_file.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace rung::app {

NetworkStationDialog::NetworkStationDialog(const NetworkDocument *document, QWidget *parent)
    : QDialog(parent)
    , m_document(document) {
    setWindowTitle(tr("Add New Project Station"));
    auto *form = new QFormLayout(this);
    m_name = new QLineEdit(document->freeName(QStringLiteral("plc")), this);
    m_target = new QComboBox(this);
    for (const model::Family family : model::Target::families()) {
        const model::Target &t = model::Target::get(family);
        if (!t.ports.empty()) // a station needs a port a network can use
            m_target->addItem(t.displayName, t.id);
    }
    m_model = new QComboBox(this);
    m_file = new QLineEdit(this);
    auto *browse = new QPushButton(tr("&Browse..."), this);
    auto *fileRow = new QHBoxLayout;
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(browse);
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("&PLC:"), m_target);
    form->addRow(tr("&Model:"), m_model);
    form->addRow(tr("Project &file:"), fileRow);
    m_problem = new QLabel(this);
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020"));
    form->addRow(m_problem);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    form->addRow(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_target, &QComboBox::currentIndexChanged, this, [this] { fillModels(); });
    connect(m_model, &QComboBox::currentIndexChanged, this, [this] { check(); });
    connect(m_name, &QLineEdit::textChanged, this, [this] {
        // The file follows the name until the user chooses one.
        if (!m_fileEdited) {
            const QString folder = m_document->filePath().isEmpty()
                                       ? QDir::homePath()
                                       : QFileInfo(m_document->filePath()).absolutePath();
            m_file->setText(QDir(folder).filePath(m_name->text() + QStringLiteral(".") +
                                                  QLatin1String(model::kProjectExtension)));
        }
        check();
    });
    connect(m_file, &QLineEdit::textEdited, this, [this] {
        m_fileEdited = true;
        check();
    });
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString chosen = QFileDialog::getSaveFileName(this, tr("New Project"), m_file->text(),
                                                            tr("Rung Studio projects (*.rung)"));
        if (!chosen.isEmpty()) {
            m_fileEdited = true;
            m_file->setText(chosen);
            check();
        }
    });
    fillModels();
    emit m_name->textChanged(m_name->text());
}

void NetworkStationDialog::fillModels() {
    m_model->clear();
    if (const model::Target *t = model::Target::byId(target())) {
        for (const model::ModelVariant &m : t->models)
            m_model->addItem(m.name, m.name);
        m_model->setCurrentIndex(m_model->findData(t->defaultModel().name));
    }
    check();
}

void NetworkStationDialog::check() {
    QString why;
    if (!network::validNetworkName(name()))
        why = tr("A name is letters, digits, _ and -, at most 32");
    else if (m_document->freeName(name()) != name())
        why = tr("A station or device is already named \"%1\"").arg(name());
    else if (file().isEmpty())
        why = tr("Choose where the project is saved");
    else if (QFileInfo::exists(file()))
        why = tr("%1 exists already: a new project never overwrites a file").arg(file());
    m_problem->setText(why);
    m_problem->setVisible(!why.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(why.isEmpty());
}

QString NetworkStationDialog::name() const {
    return m_name->text().trimmed();
}
QString NetworkStationDialog::target() const {
    return m_target->currentData().toString();
}
QString NetworkStationDialog::model() const {
    return m_model->currentData().toString();
}
QString NetworkStationDialog::file() const {
    return m_file->text().trimmed();
}

} // namespace rung::app
